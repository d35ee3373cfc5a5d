"""`--fmi3-arrays` is an FMI 3.0 build option: asked of an FMI 2.0 build it is
refused before anything is built."""

import pytest

from cardan_joint.build import builder, command


def test_the_command_refuses_fmi3_arrays_without_fmi_version_3(tmp_path, capsys):
    with pytest.raises(SystemExit) as exit_info:
        command.main(["--fmi3-arrays", "--dest", str(tmp_path)])
    assert exit_info.value.code == 2
    assert "--fmi3-arrays needs --fmi-version 3" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_the_builder_refuses_fmi3_arrays_for_fmi_2(tmp_path):
    with pytest.raises(builder.BuildError, match="FMI 3 arrays need FMI 3, not FMI 2"):
        builder.build(tmp_path, fmi_version=2, fmi3_arrays=True)
    assert list(tmp_path.iterdir()) == []


def test_the_fmi3_slave_lays_out_scalars_unless_told_arrays():
    from pythonfmu3 import Fmi3Slave

    from cardan_joint.fmi.slave3 import ModelSlave3

    def groups(arrays):
        attributes = {"model_folder": "universal_joint", "fmi3_arrays": arrays}
        return type("Fmu", (ModelSlave3, Fmi3Slave), attributes).GROUPS

    scalars, arrays = groups(False), groups(True)
    assert all(len(g.rows) == 1 for g in scalars)
    assert [len(g.rows) for g in arrays if len(g.rows) > 1] == [3, 3, 4]
    assert [r.name for g in scalars for r in g.rows] == [r.name for g in arrays for r in g.rows]
