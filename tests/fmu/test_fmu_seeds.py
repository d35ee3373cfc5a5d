"""The seeds' numbers reproduced by the FMU (co-simulated with FMPy), not only by the package."""

import math

import numpy as np
import pytest
from fmpy import simulate_fmu
from test_seeds import DISTRIBUTIONS, MAKER_TABLE, truncated

from cardan_joint.host.instance import FmuInstance


def _parabola_peak(x, y):
    k = int(np.argmax(y))
    (x0, x1, _), (y0, y1, y2) = x[k - 1 : k + 2], y[k - 1 : k + 2]
    denominator = y0 - 2 * y1 + y2
    shift = 0.5 * (y0 - y2) / denominator
    return x1 + shift * (x1 - x0), y1 - 0.25 * (y0 - y2) * shift


@pytest.mark.parametrize("bend_deg, error_deg, at_deg", MAKER_TABLE)
def test_maker_table_by_the_fmu(fmu_without_life_path, bend_deg, error_deg, at_deg):
    # One rad/s for a quarter turn, sampled every 1e-4 rad: 15,708 steps, on the
    # build without life (the subject is the angle; life would cost x4 a step).
    result = simulate_fmu(
        str(fmu_without_life_path),
        stop_time=math.pi / 2,
        output_interval=1e-4,
        start_values={"input_speed": 1.0, "bend_angle": math.radians(bend_deg)},
        output=["input_angle", "cardan_error"],
    )
    at, peak = _parabola_peak(result["input_angle"], result["cardan_error"])
    assert error_deg in (truncated(math.degrees(peak)), round(math.degrees(peak), 3))
    assert round(math.degrees(at), 1) == at_deg


@pytest.mark.parametrize("alpha", [2 * math.pi / 7, 2 * math.pi / 5])
def test_tataru_extremes_and_mean_by_the_fmu(fmu_path, model_description, unzipped_fmu, alpha):
    # omega1 = 10 rad/s for 1 s; steps land on phi1 = k pi/2, where the extremes are.
    w1 = 10.0
    joint = FmuInstance(
        model_description, unzipped_fmu, start_values={"input_speed": w1, "bend_angle": alpha}
    )
    quarter = math.pi / 2 / w1
    try:
        speeds = [joint.get("output_speed")["output_speed"]]
        for _ in range(6):  # 6 quarter turns < 1 s
            for _ in range(10):
                joint.step(quarter / 10)
            speeds.append(joint.get("output_speed")["output_speed"])
    finally:
        joint.close()
    w_max, w_min = w1 / math.cos(alpha), w1 * math.cos(alpha)
    np.testing.assert_allclose(speeds, [w_max, w_min] * 3 + [w_max], rtol=1e-12)
    assert math.isclose(
        (speeds[0] + speeds[1]) / 2,
        w1 * (1 + math.cos(alpha) ** 2) / (2 * math.cos(alpha)),
        rel_tol=1e-12,
    )
    sampled = simulate_fmu(
        str(fmu_path),
        stop_time=1.0,
        output_interval=1e-3,
        start_values={"input_speed": w1, "bend_angle": alpha},
        output=["output_speed"],
    )["output_speed"]
    assert w_min * (1 - 1e-14) <= sampled.min() and sampled.max() <= w_max * (1 + 1e-14)


PAPER = {"input_speed": 0.5, "bend_angle": math.pi / 6, "yoke_phase": math.pi / 2}


def _paper_run(fmu_path, inertia):
    start = dict(PAPER, **{f"crosspiece_inertia_{k}": i for k, i in enumerate(inertia, start=1)})
    return simulate_fmu(
        str(fmu_path), stop_time=4 * math.pi / 0.5, output_interval=0.01, start_values=start
    )


def test_paper_identities_by_the_fmu(fmu_path):
    r = _paper_run(fmu_path, (0.026, 0.026, 0.026))
    np.testing.assert_allclose(
        r["crosspiece_angular_velocity_2"] ** 2 + r["crosspiece_angular_velocity_3"] ** 2,
        0.25,
        rtol=1e-14,
    )
    q = np.array([r[f"crosspiece_quaternion_{k}"] for k in range(4)])
    psi = r["input_angle"] + math.pi / 2
    np.testing.assert_allclose(q[0] ** 2 + q[1] ** 2, np.cos(psi / 2) ** 2, atol=1e-14)
    np.testing.assert_allclose(np.sum(q * q, axis=0), 1.0, atol=1e-15)
    # Sign continuity across the run: consecutive quaternions never flip.
    assert np.min(np.sum(q[:, 1:] * q[:, :-1], axis=0)) > 0.99
    # The paper's formula (1): omega2 = cos(a) w1 / (1 - sin^2(a) sin^2(w1 t)).
    expected = math.cos(math.pi / 6) * 0.5 / (1 - 0.25 * np.sin(0.5 * r["time"]) ** 2)
    np.testing.assert_allclose(r["output_speed"], expected, rtol=1e-12)


def test_paper_m3_vanishes_by_the_fmu_for_i1_equal_i3_equal_half_i2(fmu_path):
    r = _paper_run(fmu_path, (0.013, 0.026, 0.013))
    assert np.max(np.abs(r["crosspiece_torque_3"])) < 1e-17
    assert np.max(np.abs(r["crosspiece_torque_1"])) > 1e-5


def test_paper_energy_distributions_by_the_fmu(fmu_path):
    # Same central inertia I0 for T1..T4: energies differ in mean and swing, as in
    # the paper's figure 8; each matches the package's closed form.
    from test_seeds import paper_response

    means = {}
    for name, inertia in DISTRIBUTIONS.items():
        r = _paper_run(fmu_path, inertia)
        expected = paper_response(r["time"], inertia).crosspiece_kinetic_energy
        np.testing.assert_allclose(r["crosspiece_kinetic_energy"], expected, rtol=1e-12)
        means[name] = float(np.mean(r["crosspiece_kinetic_energy"]))
    assert len({round(m, 8) for m in means.values()}) == 4
