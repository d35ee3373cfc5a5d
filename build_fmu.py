"""Build dist/UniversalJoint.fmu and check it with FMPy's validator.

    python build_fmu.py [--dest DIR] [--name MODEL] [--set NAME=VALUE ...] [--cross-check]

Exits non-zero, with the validator's problems, if the FMU is not valid.
--cross-check also writes DIR/cross-check/fmus/2.0/cs/linux64/cardan_joint/<version>/UniversalJoint/
(the FMU with its reference run, in the fmi-cross-check layout).
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent / "fmu_src"))

from cardan_joint.build import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
