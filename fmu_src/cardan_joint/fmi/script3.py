"""pythonfmu3 script of a model's FMU (FMI 3.0 co-simulation): the one template
for every model.

`build_fmu.py --fmi-version 3` writes the model's copy of this file into the FMU
under a module name unique to the build (the class renamed to the model, its
folder, build settings and start values written in), and rewrites the import
below to the copy of `cardan_joint` it ships, so two FMUs of this project never
share code in one process.

The FMU's runtime imports this module once per process (an ordinary import)
and constructs the one class below at every instantiation and reset
(tests/fmu/test_fmi3.py instantiates it many times in one process).
"""

from pythonfmu3 import Fmi3Slave

from cardan_joint.fmi.slave3 import ModelSlave3


# pythonfmu3's builder finds the slave class by a regular expression that wants
# `Fmi3Slave` itself among the bases named on this line.
class ModelFmu(ModelSlave3, Fmi3Slave):
    model_folder = ""  # the model's folder under models/
    build_settings = {}
    start_overrides = {}
    fmi3_arrays = False
