"""What a user of `cardan_joint.host.simulate` sees: nothing on a clean run, and each
distinct warning once."""

import warnings

import numpy as np
import pytest

from cardan_joint.host.simulate import simulate


def test_a_run_with_some_inputs_given_prints_nothing(fmu_path, capfd):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = simulate(
            fmu_path,
            stop_time=0.1,
            output_interval=1e-3,
            inputs={"input_speed": 10.0, "bend_angle": 0.5},
        )
    assert capfd.readouterr() == ("", "")  # FMPy's "missing input" lines included
    assert result["time"][-1] == pytest.approx(0.1)


@pytest.mark.parametrize(
    "given, left_to_the_fmu",
    [
        ({"bend_angle": 0.3}, {"input_speed": 5.0, "input_acceleration": 3.0}),
        (
            {"input_speed": 5.0},
            {"bend_angle": 0.3, "bend_angle_rate": 0.1, "bend_angle_acceleration": 0.2},
        ),
    ],
)
def test_inputs_left_out_keep_what_the_fmu_does_with_them(fmu_path, given, left_to_the_fmu):
    """An input given no signal is carried along its rate, as when no one sets any input."""
    recorded = ["input_speed", "bend_angle", "output_angle", "output_speed"]
    completed = simulate(
        fmu_path,
        stop_time=0.5,
        output_interval=1e-2,
        inputs=given,
        start_values=left_to_the_fmu,
        output=recorded,
    )
    carried = simulate(
        fmu_path,
        stop_time=0.5,
        output_interval=1e-2,
        start_values={**given, **left_to_the_fmu},
        output=recorded,
    )
    assert np.ptp(completed[next(iter(left_to_the_fmu))]) > 0.05  # it moved
    for name in recorded:
        np.testing.assert_allclose(completed[name], carried[name], rtol=1e-12, atol=1e-12)


def test_warnings_are_folded_per_distinct_message(fmu_path, monkeypatch):
    import fmpy

    def fake_simulate_fmu(fmu, stop_time, logger, **options):
        for text in (b"a held", b"b held", b"a held", b"b held", b"a held"):
            logger(None, None, 1, b"logStatusWarning", text)
        result = np.zeros(2, dtype=[("time", float)])
        result["time"] = (0.0, stop_time)
        return result

    monkeypatch.setattr(fmpy, "simulate_fmu", fake_simulate_fmu)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        simulate(fmu_path, stop_time=1.0, output_interval=0.5)
    assert [str(w.message) for w in caught] == [
        "UniversalJoint: a held (3 times)",
        "UniversalJoint: b held (2 times)",
    ]
