"""The build is a library call too: it leaves the caller's process as it found it."""

import sys

from cardan_joint.build import build


def test_a_build_leaves_no_module_of_its_staged_copy_behind(tmp_path):
    before = set(sys.modules)
    build(tmp_path, validate=False)
    # pythonfmu imports the staged script and its hashed package to read the
    # model; a second build in this process must not pick them up.
    staged = [
        name
        for name in set(sys.modules) - before
        if name.split(".")[0].startswith(("cardan_joint_", "universaljoint_"))
    ]
    assert staged == []
    assert (tmp_path / "UniversalJoint.fmu").stat().st_size > 0
