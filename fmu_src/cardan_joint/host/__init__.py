"""What runs FMUs: simulate, the instance helper, FMU facts, plots, inputs,
libcosim, SSP and systems."""
