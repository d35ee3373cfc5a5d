"""Physics apart from plumbing: the physics package imports no FMI stack."""

import subprocess
import sys


def test_physics_imports_neither_pythonfmu_nor_fmpy():
    check = (
        "import sys, cardan_joint.physics as p; p.CardanJoint().outputs(); "
        "print(sorted(m for m in sys.modules if m.split('.')[0] in "
        "('pythonfmu', 'fmpy', 'matplotlib', 'dask', 'libcosimpy')))"
    )
    run = subprocess.run([sys.executable, "-c", check], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "[]"
