"""The driveline SSP and the FMI 3.0 UniversalJoint in OMSimulator, as written.

OMSimulator is no test extra: its PyPI package (omsimulator 3.0.0.post198) is an
8.9 kB source archive with no program in it; its build (`build_helpers.py`)
downloads the program from build.openmodelica.org, which this project's machines
do not reach (pip install ends in "Failed to resolve 'build.openmodelica.org'"),
and no Debian package carries it. These tests run when $OMSIMULATOR names an
OMSimulator executable (a build of its public sources; docs/cosimulation.md says
what was measured), and say so when skipped.
"""

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

from cardan_joint.host import driveline_system as system
from cardan_joint.host.simulate import simulate
from cardan_joint.models.universal_joint import variables as table

OMSIMULATOR = os.environ.get("OMSIMULATOR", "")
pytestmark = pytest.mark.skipif(
    not (OMSIMULATOR and Path(OMSIMULATOR).is_file()),
    reason="no OMSimulator executable named by $OMSIMULATOR",
)


def _run(path, folder: Path, *options: str):
    """OMSimulator on `path` in `folder`; its result {column: values}, one row per time."""
    import pandas as pd

    result = folder / "result.csv"
    run = subprocess.run(
        [OMSIMULATOR, str(path), f"--resultFile={result.name}", *options],
        capture_output=True,
        text=True,
        cwd=folder,
        timeout=600,
    )
    output = run.stdout + run.stderr
    assert run.returncode == 0, output
    noisy = [line for line in output.splitlines() if line.startswith(("warning", "error"))]
    assert noisy == [], output
    rows = pd.read_csv(result).groupby("time").last().reset_index()  # last row per time
    return {name.split(".", 2)[-1]: rows[name].to_numpy() for name in rows.columns}


def test_the_driveline_ssp_runs_with_every_parameter_and_differs_from_fmpy_by_the_first_step(
    motor_fmu_path, load_fmu_path, propshaft_fmu_path, tmp_path
):
    fmus = {"Motor": motor_fmu_path, "Drive": propshaft_fmu_path, "Load": load_fmu_path}
    differences = {}
    for h in (1e-3, 5e-4):
        folder = tmp_path / f"h{h}"
        folder.mkdir()
        ssp = system.write_driveline_ssp(folder / "Driveline.ssp", fmus, stop_time=0.2, step_size=h)
        rows = _run(ssp, folder, "--stopTime=0.2")  # its CLI runs 1 s unless told
        assert np.allclose(rows["time"], np.arange(len(rows["time"])) * h, rtol=0, atol=1e-12)
        speed = rows["Motor.speed"]
        # The motor's set (120 N.m stall, its no-load speed) reached the FMU.
        expected = 120.0 * (1 - speed / system.MOTOR_PARAMETERS["no_load_speed"])
        np.testing.assert_allclose(rows["Motor.motor_torque"], expected, rtol=0, atol=1e-8)
        fmpy_rows = system.run_fmpy(ssp, 0.2, h)
        differences[h] = float(np.max(np.abs(speed[1:] - fmpy_rows["Motor.speed"])))
    # OMSimulator resolves the algebraic loop and starts from consistent outputs,
    # FMPy from zeros: a first-step impulse, halving with the step (0.58 rad/s at 1 ms).
    assert 1.9 < differences[1e-3] / differences[5e-4] < 2.1, differences


def test_the_fmi3_joint_gives_every_output_to_a_host_that_reads_one_value_at_a_time(
    fmi3_scalar_path, tmp_path
):
    rows = _run(fmi3_scalar_path, tmp_path, "--stopTime=0.1")
    ours = simulate(fmi3_scalar_path, stop_time=0.1, output_interval=1e-3)
    for name in table.OUTPUTS:
        # OMSimulator's CSV holds about 12 significant digits.
        np.testing.assert_allclose(rows[name], ours[name], rtol=1e-10, atol=1e-12, err_msg=name)


def test_the_fmi3_joint_in_the_loop_gives_the_fmi2_systems_result(
    fmu_path, fmi3_scalar_path, motor_fmu_path, load_fmu_path, tmp_path
):
    # OMSimulator orders a loop by the FMI 3.0 <Dependencies>, which it reads as 1-based
    # positions: with value reference = position (fmi/references.py) it reads what the
    # standard does, and the FMI 3.0 joint's system is the FMI 2.0 one's.
    rows = {}
    for version, joint in ((2, fmu_path), (3, fmi3_scalar_path)):
        folder = tmp_path / f"fmi{version}"
        folder.mkdir()
        fmus = {"Motor": motor_fmu_path, system.DRIVE_INSTANCE: joint, "Load": load_fmu_path}
        ssp = system.write_driveline_ssp(
            folder / "Driveline.ssp", fmus, "UniversalJoint", stop_time=0.2
        )
        rows[version] = _run(ssp, folder, "--stopTime=0.2")
    for key in system.RECORDED:
        np.testing.assert_allclose(rows[3][key], rows[2][key], rtol=1e-9, atol=1e-9, err_msg=key)
