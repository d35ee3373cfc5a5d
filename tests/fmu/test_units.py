"""Units on the command line: the CSV titles each column with its SI unit, every
reader takes the titles with or without units, and `simulate` takes a value in
a unit the variable's display units offer (`20deg`, `1500rpm`), as `sweep` does."""

import math

import pytest
from conftest import cardan_joint_here

from cardan_joint import results
from cardan_joint.host.fmu_info import FmuInfo
from cardan_joint.host.run_inputs import read_input_csv


def test_the_csv_header_carries_each_columns_unit(capsys, fmu_path, tmp_path):
    out = tmp_path / "run.csv"
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--stop-time", "0.01", "--output", out
    )
    assert run.returncode == 0, run.stderr
    header = out.read_text().splitlines()[0].split(",")
    assert header[:2] == ['"time [s]"', '"input_speed [rad/s]"']
    assert '"output_speed [rad/s]"' in header and '"input_torque [N.m]"' in header
    assert '"speed_ratio"' in header  # a ratio has no unit to name
    data, units = results.read_csv_units(out)
    assert data.dtype.names[:2] == ("time", "input_speed") and units["bend_angle"] == "rad"


def test_set_takes_display_units_as_the_sweep_does(capsys, fmu_path, tmp_path):
    out = tmp_path / "run.csv"
    run = cardan_joint_here(
        capsys,
        "simulate",
        "--fmu",
        fmu_path,
        "--stop-time",
        "0.01",
        "--set",
        "bend_angle=20deg",
        "--set",
        "input_speed=1500 rpm",
        "--set",
        "input_acceleration=0rad/s2",
        "--output",
        out,
    )
    assert run.returncode == 0, run.stderr
    rows = results.read_csv(out)
    assert rows["bend_angle"][0] == math.radians(20.0)
    assert rows["input_speed"][0] == pytest.approx(1500 * math.pi / 30, rel=1e-15)


@pytest.mark.parametrize(
    "setting, said",
    [
        ("bend_angle=20degs", "--set bend_angle=20degs: bend_angle takes rad or deg, not 'degs'"),
        ("load_torque=5rpm", "load_torque takes N.m, not 'rpm'"),
        ("bend_angle=deg", "'deg' is not a number (with a unit)"),
    ],
)
def test_a_unit_the_variable_does_not_take_is_refused(capsys, fmu_path, tmp_path, setting, said):
    out = tmp_path / "run.csv"
    args = ("simulate", "--fmu", fmu_path, "--stop-time", "0.01", "--output", out)
    run = cardan_joint_here(capsys, *args, "--set", setting)
    assert run.returncode == 2 and said in run.stderr
    assert not out.exists()


def test_an_input_csv_is_read_with_or_without_units(fmu_path, tmp_path):
    info = FmuInfo.read(fmu_path)
    bare, titled = tmp_path / "bare.csv", tmp_path / "titled.csv"
    bare.write_text("time,bend_angle,input_speed\n0,0.1,10\n1,0.1,10\n")
    titled.write_text(
        '"time [s]","bend_angle [deg]",input_speed [rpm]\n'
        f"0,{math.degrees(0.1)!r},{10 * 30 / math.pi!r}\n1,{math.degrees(0.1)!r},"
        f"{10 * 30 / math.pi!r}\n"
    )
    old, new = read_input_csv(bare, info), read_input_csv(titled, info)
    assert old.dtype.names == new.dtype.names
    for name in old.dtype.names:
        assert new[name] == pytest.approx(old[name], rel=1e-15)
    wrong = tmp_path / "wrong.csv"
    wrong.write_text("time [min],bend_angle\n0,0.1\n")
    with pytest.raises(ValueError, match="time is given in s, not 'min'"):
        read_input_csv(wrong, info)


def test_the_written_csv_reads_back_as_an_input(capsys, fmu_path, tmp_path):
    """A run's CSV (titled with units) drives another run: the readers agree."""
    first, second = tmp_path / "first.csv", tmp_path / "second.csv"
    args = ("simulate", "--fmu", fmu_path, "--stop-time", "0.01", "--set", "bend_angle=0.2")
    assert cardan_joint_here(capsys, *args, "--output", first).returncode == 0
    rows = results.read_csv(first)
    inputs = tmp_path / "inputs.csv"
    results.write_csv(
        rows[["time", "bend_angle"]], inputs, units={"time": "s", "bend_angle": "rad"}
    )
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--input", inputs, "--output", second
    )
    assert run.returncode == 0, run.stderr
    again = results.read_csv(second)
    assert again["time"].tolist() == rows["time"].tolist(), (again["time"], rows["time"])
    assert again["bend_angle"] == pytest.approx(rows["bend_angle"], rel=1e-15)  # FMPy interpolates
