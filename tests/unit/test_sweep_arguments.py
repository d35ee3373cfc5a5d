"""A sweep checks every argument before its first case, and summarizes its
failures by cause: no FMU needed (the settings are checked before the FMU)."""

import pandas as pd
import pytest
from conftest import cardan_joint

from cardan_joint import sweep
from cardan_joint.names import UsageError
from cardan_joint.sweep import command


@pytest.mark.parametrize(
    "settings, named",
    [
        ({"input_speeds_rpm": (1000.0, -5.0)}, "input speeds [1000.0, -5.0] (--speeds)"),
        ({"input_speeds_rpm": (0.0,)}, "(--speeds) must each be a finite number > 0 rpm"),
        ({"revolutions": 0}, "revolutions 0 (--revolutions) must be a whole number >= 1"),
        ({"steps_per_revolution": 0}, "steps per revolution 0 (--steps-per-revolution)"),
        ({"total_inertia": -0.039}, "I0 = -0.039 kg.m2 (--i0) must be a finite number > 0"),
        ({"bend_angles_deg": ()}, "bend angles [] (--bend-angles)"),
        ({"distributions": ("T9",)}, "inertia distributions ['T9'] (--distributions)"),
        ({"max_bend_angle_deg": 0.0}, "max bend angle 0.0 deg (--max-bend-angle)"),
        ({"load_torque": float("nan")}, "load torque nan N.m (--load-torque)"),
    ],
)
def test_a_setting_no_case_could_run_with_is_refused_by_name(settings, named):
    with pytest.raises(UsageError) as error:
        sweep.SweepSpec(**settings)
    assert named in str(error.value)


def test_every_problem_is_named_at_once():
    with pytest.raises(UsageError, match=r"--speeds.*; .*--revolutions"):
        sweep.SweepSpec(input_speeds_rpm=(-1.0,), revolutions=0)


@pytest.mark.parametrize(
    "args, named",
    [
        (("--workers", "0"), "--workers 0: a LocalCluster needs at least 1 worker"),
        (("--serial", "--revolutions", "0"), "revolutions 0 (--revolutions)"),
        (("--serial", "--steps-per-revolution", "0"), "(--steps-per-revolution)"),
        (("--serial", "--speeds", "-1000"), "input speeds [-1000.0] (--speeds)"),
        (("--compare", "--repeat", "0"), "--repeat 0"),
    ],
)
def test_the_command_refuses_before_any_case(tmp_path, args, named):
    run = cardan_joint("sweep", "--fmu", tmp_path / "never_read.fmu", "--out", tmp_path, *args)
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert named in run.stderr
    assert list(tmp_path.iterdir()) == []  # nothing computed or written


def test_a_corrupt_fmu_is_named_before_any_case(tmp_path):
    fmu = tmp_path / "broken.fmu"
    fmu.write_text("not a zip archive")
    run = cardan_joint("sweep", "--serial", "--fmu", fmu, "--out", tmp_path / "out")
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert f"{fmu} is not a readable FMU: not a zip archive" in run.stderr


def _rows(*failures):
    ok = {"status": "ok", "message": "", "peak_output_acceleration": 1.0}
    rows = [{"bend_angle_deg": 5.0, "input_speed_rpm": 1000.0, "inertia_distribution": "T1", **ok}]
    for bend, speed, message in failures:
        rows.append(
            {
                "bend_angle_deg": bend,
                "input_speed_rpm": speed,
                "inertia_distribution": "T2",
                "status": "failed",
                "message": message,
            }
        )
    return (
        pd.DataFrame(rows)
        .reindex(columns=sweep.store.COLUMNS)
        .assign(beyond_acceleration_limit=False)
    )


def test_failures_are_summarized_by_cause_naming_the_cases():
    guard = "input bend_angle = {} rad ({} deg) is not below the limit max_bend_angle"
    table = _rows(
        (85.0, 1000.0, guard.format(1.48, 85)),
        (95.0, 2000.0, guard.format(1.65, 95)),
        (10.0, 3000.0, "FileNotFoundError: [Errno 2] No such file"),
    )
    lines = command._summary(table)
    assert lines[0] == "1 ok, 3 failed; 0 beyond 1000 rad/s2"
    assert len(lines) == 3  # the two guard refusals are one cause
    assert lines[1].startswith("  2 failed (85 deg, 1000 rpm, T2; 95 deg, 2000 rpm, T2)")
    assert "e.g. 85 deg, 1000 rpm, T2: input bend_angle = 1.48 rad" in lines[1]
    assert lines[2].startswith("  1 failed (10 deg, 3000 rpm, T2), e.g.")
