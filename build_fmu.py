"""Build an FMU (dist/UniversalJoint.fmu by default) and check it with FMPy's validator.

    python build_fmu.py [--model MODEL] [--dest DIR] [--name NAME] [--set NAME=VALUE ...]
                        [--cross-check]

Exits non-zero, with the validator's problems, if the FMU is not valid.
--cross-check also writes DIR/cross-check/fmus/2.0/cs/linux64/cardan_joint/<version>/<MODEL>/
(the FMU with the reference run its model's folder declares, in the fmi-cross-check layout).
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent / "fmu_src"))

from cardan_joint.build import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
