"""Duty cycles read from files (host/duty_cycle.py): units in the headers,
rates derived as each segment's slope, blocks as steps, mistakes named."""

import math

import numpy as np
import pytest

from cardan_joint.host.duty_cycle import read_block_table, read_duty_cycle, read_time_series
from cardan_joint.names import UsageError


def _file(tmp_path, text, name="cycle.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_a_series_in_display_units_is_read_in_si_with_each_segments_slope(tmp_path):
    path = _file(
        tmp_path,
        "time [s],input_speed [rpm],input_torque [kN.m],bend_angle [deg]\n"
        "0,0,1,0\n0.5,300,2,10\n2,300,2,4\n",
    )
    cycle = read_time_series(path)
    rpm, deg = math.pi / 30.0, math.pi / 180.0
    assert np.allclose(cycle.inputs["input_speed"], [0.0, 300 * rpm], rtol=1e-15)
    assert np.allclose(cycle.inputs["input_acceleration"], [600 * rpm, 0.0], rtol=1e-15)
    assert np.allclose(cycle.inputs["bend_angle_rate"], [20 * deg, -4 * deg], rtol=1e-15)
    assert np.all(cycle.inputs["bend_angle_acceleration"] == 0.0)
    assert list(cycle.inputs["load_torque"]) == [1000.0, 2000.0]  # held at the sample
    assert list(cycle.steps) == [0.5, 1.5] and cycle.seconds == 2.0


def test_given_rates_are_taken_as_they_are(tmp_path):
    path = _file(tmp_path, "time,input_speed,input_acceleration,torque\n0,1,7,5\n1,2,0,5\n")
    assert list(read_time_series(path).inputs["input_acceleration"]) == [7.0]


def test_spans_name_the_times_their_steps_cover(tmp_path):
    rows = "".join(f"{t},10,1\n" for t in range(11))
    cycle = read_time_series(_file(tmp_path, "time,input_speed,torque\n" + rows), spans=5)
    assert cycle.labels == ("0-2 s", "2-4 s", "4-6 s", "6-8 s", "8-10 s")
    assert list(cycle.part) == [0, 0, 1, 1, 2, 2, 3, 3, 4, 4]


def test_blocks_last_their_share_of_the_cycle_in_equal_steps(tmp_path):
    path = _file(
        tmp_path,
        "block,time_share [%],speed [rpm],torque [N.m],angle [deg]\n"
        "low,25,1000,400,0\nhigh,75,3000,200,5\n",
    )
    cycle = read_duty_cycle(path, cycle_time=4.0, step=0.3)
    assert cycle.kind == "blocks" and cycle.labels == ("low", "high")
    assert math.fsum(cycle.steps[cycle.part == 0]) == pytest.approx(1.0, rel=1e-15)
    assert math.fsum(cycle.steps[cycle.part == 1]) == pytest.approx(3.0, rel=1e-15)
    assert cycle.steps.max() <= 0.3
    assert set(cycle.inputs["bend_angle"][cycle.part == 1]) == {5 * math.pi / 180.0}


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("block,time_share,speed,torque [N.m]\na,1,100,5\n", "'speed': give its unit"),
        ("time_share,speed [rpm],torque\n0.5,100,5\n", "add up to 1"),
        ("time_share,speed [deg],torque\n1,100,5\n", "column 'speed' in [deg]: give it in"),
        ("revolution_share,speed [rpm],torque\n1,0,5\n", "revolution share needs a speed"),
        ("time,input_speed\n0,1\n1,1\n", "one torque column"),
        ("time,input_speed,torque\n0,1,1\n0,1,1\n", "must rise"),
        ("time,input_sped,torque\n0,1,1\n1,1,1\n", "unknown column 'input_sped'"),
        ("time,input_speed,torque\n0,1,1\n1,x,1\n", "no number"),
    ],
)
def test_mistakes_are_named(tmp_path, text, words):
    with pytest.raises(UsageError, match=words.replace("[", r"\[").replace("]", r"\]")):
        read_duty_cycle(_file(tmp_path, text))


def test_a_block_table_with_no_unit_on_its_speed_is_refused(tmp_path):
    with pytest.raises(UsageError, match="give its unit"):
        read_block_table(_file(tmp_path, "time_share,speed,torque\n1,100,5\n"))


def test_a_parquet_series_reads_as_its_csv(tmp_path):
    pd = pytest.importorskip("pandas")
    pytest.importorskip("pyarrow")
    text = (
        "time,input_speed [rpm],load_torque,bend_angle [deg]\n0,0,10,1\n0.5,600,20,2\n1,600,5,2\n"
    )
    csv = _file(tmp_path, text)
    pd.read_csv(csv).to_parquet(tmp_path / "cycle.parquet")
    from_csv, from_parquet = read_time_series(csv), read_duty_cycle(tmp_path / "cycle.parquet")
    assert from_parquet.kind == "time series"
    for name, values in from_csv.inputs.items():
        assert list(from_parquet.inputs[name]) == list(values), name
