"""pythonfmu script of a model's FMU (FMI 2.0): the one template for every model.

`build_fmu.py` writes the model's copy of this file into the FMU under a module
name unique to the build (the class renamed to the model, its folder, build
settings and start values written in), and rewrites the import below to the
copy of `cardan_joint` it ships, so two FMUs of this project never share code in
one process.
"""

from cardan_joint.fmi.slave import ModelSlave


class ModelFmu(ModelSlave):
    model_folder = ""  # the model's folder under models/
    build_settings = {}
    start_overrides = {}
