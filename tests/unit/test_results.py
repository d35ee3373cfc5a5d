"""The one results I/O module and the units: exact round trips, clear errors."""

import math

import numpy as np
import pytest

from cardan_joint import results, units
from cardan_joint.models.universal_joint import variables as table


def test_csv_round_trip_is_exact_in_fmpys_format(tmp_path):
    rng = np.random.default_rng(1)
    data = results.structured(
        {
            "time": np.sort(rng.random(500)),
            "x": rng.standard_normal(500) * 10.0 ** rng.integers(-300, 300, 500),
            "y": [math.pi, -0.0, 5e-324, 1e308, 0.1] * 100,
        }
    )
    path = results.write_csv(data, tmp_path / "deep" / "run.csv")
    assert path.read_text().splitlines()[0] == '"time","x","y"'  # FMPy's header
    back = results.read_csv(path)
    assert back.dtype.names == data.dtype.names
    for name in data.dtype.names:
        assert back[name].tobytes() == data[name].tobytes()


def test_a_hand_written_csv_with_spaces_reads(tmp_path):
    path = tmp_path / "inputs.csv"
    path.write_text("time, input_speed\n0, 1.5\n1, 2\n")
    data = results.read_csv(path)
    assert data.dtype.names == ("time", "input_speed")
    assert data["input_speed"].tolist() == [1.5, 2.0]


@pytest.mark.parametrize(
    "text, named",
    [
        ("time,speed\n0,1\n1,abc\n", "line 3, column 'speed': 'abc' is not a number"),
        ("time,speed\n", "no data rows"),
        ("", "not a table"),
        ("time,speed\n0,1\n1,2,3\n", "not a table"),
    ],
)
def test_a_bad_csv_is_refused_naming_where(tmp_path, text, named):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(results.ResultFileError, match="bad.csv") as error:
        results.read_csv(path)
    assert named in str(error.value)


def test_rows_with_text_and_gaps_are_written(tmp_path):
    path = results.write_rows(
        [{"coupling": "hold", "step": 0.1}, {"coupling": "ahead", "step": 0.01, "order": 2.0}],
        tmp_path / "rows.csv",
    )
    back = results.read_table(path)
    assert list(back["coupling"]) == ["hold", "ahead"] and math.isnan(back["order"][0])


def test_unit_names_say_their_direction():
    assert 90 * units.DEG_TO_RAD == math.pi / 2 and math.pi * units.RAD_TO_DEG == 180
    assert 30 * units.RPM_TO_RAD_PER_S == pytest.approx(math.pi, rel=1e-15)
    assert math.pi * units.RAD_PER_S_TO_RPM == pytest.approx(30, rel=1e-15)
    # The FMU's display units use the same factors.
    assert dict(table.UNITS["rad/s"].display)["rpm"] == units.RAD_PER_S_TO_RPM
    assert dict(table.UNITS["rad"].display)["deg"] == units.RAD_TO_DEG


def test_units_in_the_header_are_written_and_read_with_or_without_them(tmp_path):
    data = {"time": [0.0, 0.5], "output_speed": [1.0, 2.0], "speed_ratio": [1.0, 1.5]}
    units = {"time": "s", "output_speed": "rad/s", "speed_ratio": "1"}
    titled = results.write_csv(data, tmp_path / "titled.csv", units=units)
    bare = results.write_csv(data, tmp_path / "bare.csv")
    assert titled.read_text().splitlines()[0] == '"time [s]","output_speed [rad/s]","speed_ratio"'
    assert bare.read_text().splitlines()[0] == '"time","output_speed","speed_ratio"'
    for path in (titled, bare):
        read = results.read_csv(path)
        assert read.dtype.names == ("time", "output_speed", "speed_ratio")
        assert read["output_speed"].tolist() == [1.0, 2.0]
    assert results.read_csv_units(titled)[1] == {"time": "s", "output_speed": "rad/s"}
    assert results.read_csv_units(bare)[1] == {}


def test_a_name_given_twice_with_and_without_a_unit_is_refused(tmp_path):
    path = tmp_path / "twice.csv"
    path.write_text("time,x,x [m]\n0,1,2\n")
    with pytest.raises(results.ResultFileError, match="column 'x' appears twice"):
        results.read_csv(path)
