"""`cardan-joint life` and `life_report` (host/life_report.py): a block table's
constant blocks give the catalogue's hand sum, a measured time series gives
what a hand-written FMPy loop over the same samples gives, and a model that
cannot run a cycle is refused by name."""

import math

import numpy as np
import pytest
from conftest import cardan_joint_here

from cardan_joint.host.duty_cycle import read_block_table, read_time_series
from cardan_joint.host.life_report import life_report
from cardan_joint.names import UsageError

# Catalogue constants (docs/life.md), written out here, not read from the package.
K, P, A_MIN_DEG, RATED = 1.5e6, 10.0 / 3.0, 3.0, 1000.0
# (share, rpm, N.m): straight blocks, so the joint's torque is the load, constant.
BLOCKS = ((0.1, 600.0, 900.0), (0.25, 1500.0, 500.0), (0.4, 2400.0, 300.0), (0.25, 3000.0, 150.0))


def hand_life_hours(rpm, torque):
    return K / (A_MIN_DEG * rpm) * (RATED / torque) ** P


def _write_blocks(path, share_column="time_share [%]", blocks=BLOCKS):
    lines = [f"block,{share_column},speed [rpm],torque [N.m],angle [deg]"]
    scale = 100.0 if "%" in share_column else 1.0
    lines += [f"b{i},{q * scale!r},{n!r},{t!r},0" for i, (q, n, t) in enumerate(blocks)]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_constant_blocks_give_the_catalogues_hand_sum(fmu_path, tmp_path):
    cycle = read_block_table(_write_blocks(tmp_path / "blocks.csv"), cycle_time=2.0, step=1e-2)
    report = life_report(cycle, fmu_path)
    per_hour = sum(q / hand_life_hours(n, t) for q, n, t in BLOCKS)
    assert 1.0 / report.b10_hours["joint"] == pytest.approx(per_hour, rel=1e-9, abs=0.0)
    assert report.life_used["joint"] == pytest.approx(2.0 / 3600.0 * per_hour, rel=1e-9, abs=0.0)
    worst = max(range(len(BLOCKS)), key=lambda i: BLOCKS[i][0] / hand_life_hours(*BLOCKS[i][1:]))
    assert report.most_damaging["part"] == f"b{worst}"
    for part, (q, n, t) in zip(report.parts, BLOCKS):
        hand = q * 2.0 / 3600.0 / hand_life_hours(n, t)
        assert part["damage"]["joint"] == pytest.approx(hand, rel=1e-9, abs=0.0)
    assert report.peak_torque == pytest.approx(900.0, rel=1e-12)


def test_revolution_shares_become_time_shares_of_the_hand_sum(fmu_path, tmp_path):
    table = _write_blocks(tmp_path / "blocks.csv", "revolution_share")
    report = life_report(read_block_table(table, cycle_time=1.0, step=1e-2), fmu_path)
    times = [q / n for q, n, _ in BLOCKS]
    per_hour = sum(s / sum(times) / hand_life_hours(n, t) for s, (_, n, t) in zip(times, BLOCKS))
    assert 1.0 / report.b10_hours["joint"] == pytest.approx(per_hour, rel=1e-9, abs=0.0)


def _series(path):
    # Piecewise linear: a run-up, a bend, a torque step; no rate columns.
    path.write_text(
        "time,input_speed,load_torque,bend_angle\n"
        "0,10,100,0.05\n0.05,60,400,0.05\n0.1,160,400,0.15\n0.13,100,250,0.1\n0.2,0,0,0.02\n"
    )
    return path


def _by_hand(fmu, times, rows, unzipdir):
    """life_consumed after each step of an FMU2Slave loop over the samples,
    each step's rates the segment's slope from its first sample."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    description = read_model_description(str(fmu))
    refs = {v.name: v.valueReference for v in description.modelVariables}
    folder = extract(str(fmu), unzipdir=str(unzipdir))
    slave = FMU2Slave(
        guid=description.guid,
        unzipDirectory=folder,
        modelIdentifier=description.coSimulation.modelIdentifier,
        instanceName="by_hand",
    )
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.exitInitializationMode()
    names = ("input_speed", "input_acceleration", "load_torque", "bend_angle", "bend_angle_rate")
    names += ("bend_angle_acceleration",)
    life = []
    for i in range(len(times) - 1):
        h = times[i + 1] - times[i]
        speed, torque, angle = rows[i]
        values = (speed, (rows[i + 1][0] - speed) / h, torque, angle)
        values += ((rows[i + 1][2] - angle) / h, 0.0)
        slave.setReal([refs[n] for n in names], list(values))
        slave.doStep(currentCommunicationPoint=times[i], communicationStepSize=h)
        life.append(slave.getReal([refs["life_consumed"]])[0])
    slave.terminate()
    slave.freeInstance()
    return np.array(life)


def test_a_time_series_run_is_a_hand_written_fmpy_loop_over_its_samples(fmu_path, tmp_path):
    cycle = read_time_series(_series(tmp_path / "series.csv"))
    report = life_report(cycle, fmu_path)
    times = [0.0, 0.05, 0.1, 0.13, 0.2]
    rows = [(10, 100, 0.05), (60, 400, 0.05), (160, 400, 0.15), (100, 250, 0.1), (0, 0, 0.02)]
    hand = _by_hand(fmu_path, times, rows, tmp_path / "unzipped")
    assert np.allclose(report.history["joint life"], hand, rtol=1e-12, atol=0.0)
    assert report.life_used["joint"] == pytest.approx(hand[-1], rel=1e-12)
    assert report.b10_hours["joint"] == pytest.approx(0.2 / 3600.0 / hand[-1], rel=1e-12)


def test_the_command_writes_the_report_and_its_figure(capsys, fmu_path, tmp_path):
    series = _series(tmp_path / "series.csv")
    output = tmp_path / "out" / "life.csv"
    result = cardan_joint_here(capsys, "life", series, "--fmu", fmu_path, "--output", output)
    assert result.returncode == 0, result.stderr
    assert "B10" in result.stdout and "uses most" in result.stdout
    for suffix in (".csv", ".json", ".png"):
        assert output.with_suffix(suffix).stat().st_size > 0


def test_a_compliant_drive_is_refused_by_name(capsys, compliant_joint_fmu_path, tmp_path):
    series = _series(tmp_path / "series.csv")
    with pytest.raises(UsageError, match="CompliantJoint cannot run a duty cycle.*load_torque"):
        life_report(read_time_series(series), compliant_joint_fmu_path)
    output = tmp_path / "life.csv"
    result = cardan_joint_here(
        capsys, "life", series, "--fmu", compliant_joint_fmu_path, "--output", output
    )
    assert result.returncode == 2 and "CompliantJoint cannot run" in result.stderr
    assert not output.exists()


def test_the_propshaft_reports_each_joint_and_refuses_an_angle(propshaft_fmu_path, tmp_path):
    with pytest.raises(UsageError, match="Propshaft takes its working angles from its layout"):
        life_report(read_time_series(_series(tmp_path / "series.csv")), propshaft_fmu_path)
    flat = tmp_path / "flat.csv"
    flat.write_text("time,input_speed [rpm],torque [N.m]\n0,1000,300\n0.1,1000,300\n")
    report = life_report(read_time_series(flat), propshaft_fmu_path)
    assert report.joints == ["joint 1", "joint 2"]
    assert all(report.life_used[j] > 0.0 for j in report.joints)
    assert math.isfinite(report.b10_hours[report.governing_joint])


def test_an_input_start_value_and_a_refused_step_are_named(fmu_path, tmp_path):
    cycle = read_time_series(_series(tmp_path / "series.csv"))
    with pytest.raises(UsageError, match="load_torque"):
        life_report(cycle, fmu_path, start_values={"load_torque": 5.0})
    fast = tmp_path / "fast.csv"
    fast.write_text("time,input_speed,torque,bend_angle\n0,1e6,1,0\n0.1,1e6,1,0\n")
    with pytest.raises(UsageError, match=r"fast.csv: .*input_speed.*t = 0"):
        life_report(read_time_series(fast), fmu_path)
