"""The `cardan-joint` command, run as a user runs it (separate processes)."""

import csv
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def cardan_joint(*args, cwd=ROOT):
    return subprocess.run([sys.executable, "-m", "cardan_joint.cli", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd)


@pytest.fixture(scope="module")
def built_fmu(tmp_path_factory):
    dest = tmp_path_factory.mktemp("cli_build")
    run = cardan_joint("build", "--dest", dest, "--name", "CliJoint", "--set", "bend_angle=0.2")
    assert run.returncode == 0, run.stderr
    fmu = dest / "CliJoint.fmu"
    assert fmu.is_file()
    return fmu


def read_rows(path):
    with open(path, newline="") as stream:
        return list(csv.DictReader(stream))


def test_console_script_is_installed():
    assert (Path(sys.executable).parent / "cardan-joint").is_file()


def test_simulate_from_constant_inputs(built_fmu, tmp_path):
    out = tmp_path / "run.csv"
    run = cardan_joint("simulate", "--fmu", built_fmu, "--set", "input_speed=20",
                       "--set", "crosspiece_inertia_2=0.01", "--stop-time", "0.2",
                       "--step", "1e-3", "--output", out)
    assert run.returncode == 0, run.stderr
    rows = read_rows(out)
    assert len(rows) == 201
    assert float(rows[0]["input_speed"]) == 20.0
    assert float(rows[0]["bend_angle"]) == 0.2            # the build's start value
    assert out.with_suffix(".png").stat().st_size > 0


def test_simulate_from_an_input_csv(built_fmu, tmp_path):
    inputs = tmp_path / "inputs.csv"
    inputs.write_text("time,input_speed,input_acceleration,bend_angle\n"
                      "0,10,10,0.1\n0.5,15,10,0.3\n")
    out, plot = tmp_path / "csv_run.csv", tmp_path / "plots" / "csv_run.png"
    run = cardan_joint("simulate", "--fmu", built_fmu, "--input", inputs, "--set",
                       "load_torque=50", "--output", out, "--plot", plot,
                       "--plot-variables", "output_speed", "input_torque")
    assert run.returncode == 0, run.stderr
    rows = read_rows(out)
    assert float(rows[-1]["time"]) == pytest.approx(0.5)       # the CSV's last time
    assert float(rows[250]["input_speed"]) == pytest.approx(12.5)
    assert float(rows[-1]["load_torque"]) == 50.0
    assert plot.stat().st_size > 0


@pytest.mark.parametrize("args, named", [
    (("--set", "bend_angle=1.5"), "bend_angle"),               # refused by the FMU's guard
    (("--set", "bend_angel=0.5"), "bend_angel"),               # no such variable
    (("--set", "output_speed=1"), "output_speed"),             # not settable
    (("--set", "load_torque=abc"), "load_torque"),
])
def test_bad_input_exits_non_zero_naming_the_variable(built_fmu, tmp_path, args, named):
    run = cardan_joint("simulate", "--fmu", built_fmu, "--stop-time", "0.1",
                       "--output", tmp_path / "bad.csv", *args)
    assert run.returncode != 0
    assert named in run.stderr
    assert "Traceback" not in run.stderr


def test_bad_input_csv_column_is_named(built_fmu, tmp_path):
    inputs = tmp_path / "typo.csv"
    inputs.write_text("time,input_sped\n0,1\n1,2\n")
    run = cardan_joint("simulate", "--fmu", built_fmu, "--input", inputs,
                       "--output", tmp_path / "bad.csv")
    assert run.returncode != 0 and "input_sped" in run.stderr
    assert "Traceback" not in run.stderr


def test_missing_fmu_is_a_message_not_a_traceback(tmp_path):
    run = cardan_joint("simulate", "--fmu", tmp_path / "none.fmu")
    assert run.returncode != 0 and "does not exist" in run.stderr
    assert "Traceback" not in run.stderr


def test_sweep_subcommand_runs_the_shared_sweep(built_fmu, tmp_path):
    run = cardan_joint("sweep", "--serial", "--fmu", built_fmu, "--bend-angles", "5",
                       "--speeds", "1000", "--distributions", "T1", "--revolutions", "1",
                       "--steps-per-revolution", "36", "--out", tmp_path, "--no-progress")
    assert run.returncode == 0, run.stderr
    rows = read_rows(tmp_path / "design_sweep.csv")
    assert [r["status"] for r in rows] == ["ok"]
    assert (tmp_path / "design_sweep.png").stat().st_size > 0
