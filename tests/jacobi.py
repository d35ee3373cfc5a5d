"""An independent fixed-step Jacobi master on FMPy's low-level API (through
`FmuInstance`), for the driveline SSPs: what both hosts should compute."""

import shutil

import numpy as np

from cardan_joint.host import driveline_system as system
from cardan_joint.host.instance import FmuInstance


def jacobi_master(
    ssp_path, stop_time, h, first_values, connections=system.CONNECTIONS, recorded=system.RECORDED
):
    """An independent fixed-step Jacobi master on the SSP's FMUs: each step every FMU
    gets the connected outputs of the last communication point, steps, and reports;
    `first_values` {"Component.output": value} are the values fed in the first step
    (None: the initial outputs, read after initialization)
    (`connections` and `recorded` name the system's wiring and what it reports;
    every recorded output is read, every connected input set, every FMU stepped)."""
    from fmpy import extract
    from fmpy.ssp.ssd import find_components, read_ssd

    from cardan_joint.host.ssp import fmpy_parameter_set

    unzipped = extract(str(ssp_path))
    parameters = {p.name: float(p.value) for p in fmpy_parameter_set(ssp_path).parameters}
    instances = {}
    try:
        for component in find_components(read_ssd(str(ssp_path)).system):
            name = component.name
            starts = {
                key.split(".", 1)[1]: value
                for key, value in parameters.items()
                if key.startswith(name + ".")
            }
            instances[name] = FmuInstance.open(
                f"{unzipped}/{component.source}", name=name, start_values=starts
            )
        values = dict(first_values) if first_values is not None else {}
        for key in recorded:
            name, variable = key.split(".")
            values.setdefault(key, instances[name].get(variable)[variable])
        rows = {key: [] for key in recorded}
        for k in range(round(stop_time / h)):
            for start, start_connector, end, end_connector in connections:
                instances[end].set(**{end_connector: values[f"{start}.{start_connector}"]})
            for instance in instances.values():
                instance.time = k * h
                instance.step(h)
            for key in recorded:
                name, variable = key.split(".")
                values[key] = instances[name].get(variable)[variable]
                rows[key].append(values[key])
    finally:
        for instance in instances.values():
            instance.close()
        shutil.rmtree(unzipped, ignore_errors=True)
    return {key: np.array(v) for key, v in rows.items()}
