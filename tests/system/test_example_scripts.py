"""End-to-end runs of example scripts (the slow layer): each script, run as a user
runs it (its own process, or its `main` for the driveshaft), writes what it says.
Their physics is checked in tests/fmu (test_driveline_ssp.py, test_motor_load.py,
test_driveshaft.py) on shorter runs in-process."""

import subprocess
import sys

import numpy as np
from conftest import ROOT, load_example
from ssp_checks import check_ssp_for_every_host

from cardan_joint import results


def test_driveline_ssp_example_writes_the_ssp_both_csvs_and_the_plot(tmp_path):
    run = subprocess.run(
        [sys.executable, str(ROOT / "examples" / "driveline_ssp.py"), "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert run.returncode == 0, run.stderr
    for name in (
        "Driveline.ssp",
        "driveline_ssp_fmpy.csv",
        "driveline_ssp_libcosim.csv",
        "driveline_ssp_ecos.csv",
        "driveline_ssp.png",
    ):
        assert (tmp_path / name).stat().st_size > 0
    check_ssp_for_every_host(tmp_path / "Driveline.ssp")
    for host in ("libcosim", "ecos"):
        rows = results.read_csv(tmp_path / f"driveline_ssp_{host}.csv")
        assert list(rows.dtype.names[:2]) == ["time", "Motor.speed"] and len(rows) == 1001
    assert "ratio 2, step 0.0001 s: DIVERGES" in run.stdout
    assert "ratio 0.5, step 0.001 s: bounded" in run.stdout


def test_motor_load_example_runs_from_the_command_line(fmu_path, tmp_path):
    result = subprocess.run(
        [
            sys.executable,
            str(ROOT / "examples" / "motor_load.py"),
            "--fmu",
            str(fmu_path),
            "--out",
            str(tmp_path),
            "--stop-time",
            "0.2",
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "motor_load.png").stat().st_size > 20_000
    data = results.read_csv(tmp_path / "motor_load.csv")
    assert len(data) == 201 and np.all(np.isfinite(data["input_torque"]))


def test_driveshaft_example_writes_its_tables_and_figure(fmu_path, tmp_path):
    driveshaft = load_example("driveshaft")
    driveshaft.main(
        [
            "--fmu",
            str(fmu_path),
            "--out",
            str(tmp_path),
            "--revolutions",
            "1",
            "--steps",
            "1e-2",
            "1e-3",
            "--phase-errors",
            "0",
            "1",
            "5",
        ]
    )
    for name in ("driveshaft_steps.csv", "driveshaft_phase.csv", "driveshaft.png"):
        assert (tmp_path / name).stat().st_size > 0
