"""examples/driveline_resonance.py: the twist peak of a slow run-up lies at the
predicted input speed omega_n / 2, within 3 %."""

import math

import pytest
from conftest import load_example
from session_files import shared

resonance = load_example("driveline_resonance")


@pytest.fixture(scope="module")
def run_up(compliant_joint_fmu_path, inertia_load_fmu_path, pytestconfig, tmp_path_factory):
    # A short run-up around the resonance at the example's rate: coarse, but the
    # peak's position only needs the envelope near it. Run once for all workers.
    low, high = 0.85 * resonance.PREDICTED, 1.15 * resonance.PREDICTED
    joint, load = str(compliant_joint_fmu_path), str(inertia_load_fmu_path)
    return shared(
        pytestconfig,
        tmp_path_factory,
        "resonance_run_up",
        lambda _: resonance.run_up(joint, load, low, high),
    )


def test_twist_peak_lies_within_three_percent_of_half_the_natural_frequency(run_up):
    assert resonance.PREDICTED == pytest.approx(math.sqrt(2000.0 / 0.5) / 2)
    speed = resonance.resonance_speed(run_up)
    assert abs(speed / resonance.PREDICTED - 1) < 0.03, speed
    # A peak, not the end of a rising flank: the amplitude falls on both sides.
    speeds, amplitude = resonance.envelope(run_up)
    assert amplitude.max() > 2 * amplitude[0] and amplitude.max() > 2 * amplitude[-1]


def test_figures_are_written(run_up, tmp_path):
    for plot, name in ((resonance.plot_run_up, "a.png"), (resonance.plot_orders, "b.png")):
        assert plot(run_up, tmp_path / name).stat().st_size > 10_000
