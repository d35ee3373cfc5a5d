"""pythonfmu script of a model's FMU (FMI 2.0): the one template for every model.

`build_fmu.py` writes the model's copy of this file into the FMU under a module
name unique to the build (the class renamed to the model, its folder, build
settings and start values written in), and rewrites the import below to the
copy of `cardan_joint` it ships, so two FMUs of this project never share code in
one process.
"""

import ctypes

from cardan_joint.fmi.slave import ModelSlave

# pythonfmu 0.7.0's loader re-runs this file at every fmi2Instantiate and then
# releases one reference too many to this module's namespace (it Py_DECREFs the
# borrowed result of PyModule_GetDict). Taking one reference per run keeps the
# count right; without it the namespace is freed after a few instantiations and
# the host process crashes. An extra reference (when imported otherwise) only
# keeps the namespace alive.
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))


class ModelFmu(ModelSlave):
    model_folder = ""  # the model's folder under models/
    build_settings = {}
    start_overrides = {}
