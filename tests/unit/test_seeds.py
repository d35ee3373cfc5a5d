"""The seeds' reference numbers (models/universal_joint/README.md) reproduced by the physics
package.
tests/fmu/test_fmu_seeds.py reproduces the same numbers through the FMU."""

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from cardan_joint.physics import (
    cardan_error,
    joint_response,
    max_cardan_error,
    output_speed,
    roll_angle,
)

# Maker's page (seed 002): (bend, max cardan error deg (truncated), at input angle deg)
MAKER_TABLE = [(10.0, 0.438, 44.8), (20.0, 1.782, 44.1), (30.0, 4.117, 42.9)]


def truncated(value, digits=3):
    return math.floor(value * 10**digits) / 10**digits


@pytest.mark.parametrize("bend_deg, error_deg, at_deg", MAKER_TABLE)
def test_maker_table(bend_deg, error_deg, at_deg):
    beta = math.radians(bend_deg)
    best = minimize_scalar(
        lambda g: -cardan_error(g, beta),
        bounds=(0.0, math.pi / 2),
        method="bounded",
        options={"xatol": 1e-12},
    )
    peak = math.degrees(cardan_error(best.x, beta))
    # The model page calls the table truncated; that holds for 10 deg (0.43857 -> 0.438)
    # but 20 deg (1.78168) is printed rounded (1.782). Either 3-decimal reading
    # of our value must give the maker's number.
    assert error_deg in (truncated(peak), round(peak, 3))
    assert round(math.degrees(best.x), 1) == at_deg
    # The maker's closed form for the amplitude is the same number.
    assert math.isclose(math.degrees(max_cardan_error(beta)), peak, rel_tol=1e-10)
    # And the error is odd about the pin in the bend plane: -peak a quarter turn on.
    assert math.isclose(math.degrees(cardan_error(math.pi - best.x, beta)), -peak, rel_tol=1e-10)


def test_maker_ten_degrees_against_40_digit_arithmetic():
    # models/universal_joint/README.md quotes 0.43857 deg; the maker's own formula gives
    # 0.4385614 deg (computed here at 40 digits), which the page prints truncated as 0.438.
    import mpmath

    with mpmath.workdps(40):
        b = mpmath.radians(10)
        exact = mpmath.degrees(mpmath.atan((1 - mpmath.cos(b)) / (2 * mpmath.sqrt(mpmath.cos(b)))))
    assert math.isclose(
        math.degrees(max_cardan_error(math.radians(10))), float(exact), rel_tol=1e-15
    )
    assert f"{float(exact):.7f}" == "0.4385614"


@pytest.mark.parametrize("alpha", [2 * math.pi / 7, 2 * math.pi / 5])
def test_tataru_extremes_and_mean(alpha):
    w1 = 10.0
    phi1 = np.array([0.0, math.pi / 2, math.pi, 3 * math.pi / 2])
    w3 = output_speed(phi1, alpha, w1)
    np.testing.assert_allclose(w3, [w1 / math.cos(alpha), w1 * math.cos(alpha)] * 2, rtol=1e-14)
    t = np.linspace(0.0, 1.0, 100001)
    sampled = output_speed(w1 * t, alpha, w1)
    assert sampled.max() <= w1 / math.cos(alpha) * (1 + 1e-15)
    assert sampled.min() >= w1 * math.cos(alpha) * (1 - 1e-15)
    mean = (w3[0] + w3[1]) / 2
    assert math.isclose(
        mean, w1 * (1 + math.cos(alpha) ** 2) / (2 * math.cos(alpha)), rel_tol=1e-14
    )


# Mityushov & Misyura (seed 001): omega1 = 0.5 rad/s, alpha = pi/6, yoke phase 90 deg.
W1, ALPHA, PHASE = 0.5, math.pi / 6, math.pi / 2
I0 = 0.039
DISTRIBUTIONS = {
    "T1": (2 / 3 * I0, 2 / 3 * I0, 2 / 3 * I0),
    "T2": (1 / 3 * I0, 4 / 3 * I0, 1 / 3 * I0),
    "T3": (5 / 6 * I0, 1 / 3 * I0, 5 / 6 * I0),
    "T4": (7 / 9 * I0, 1 / 9 * I0, 10 / 9 * I0),
}


def paper_response(t, inertia=(0.026, 0.026, 0.026)):
    return joint_response(W1 * t + PHASE, ALPHA, W1, inertia=inertia)


def test_paper_formula_1_is_the_phase_90_convention():
    t = np.linspace(0, 20, 2001)
    expected = math.cos(ALPHA) / (1 - math.sin(ALPHA) ** 2 * np.sin(W1 * t) ** 2) * W1
    np.testing.assert_allclose(paper_response(t).output_speed, expected, rtol=1e-14)


def test_paper_speed_identity():
    r = paper_response(np.linspace(0, 30, 3001))
    np.testing.assert_allclose(
        r.crosspiece_angular_velocity_2**2 + r.crosspiece_angular_velocity_3**2, W1**2, rtol=1e-14
    )


def test_paper_quaternion_identities():
    t = np.linspace(0, 30, 3001)
    r = paper_response(t)
    q0, q1, q2, q3 = r[11:15]
    psi = W1 * t + PHASE
    rho = roll_angle(psi, ALPHA)
    np.testing.assert_allclose(q0**2 + q1**2, np.cos(psi / 2) ** 2, atol=1e-15)
    np.testing.assert_allclose(q2**2 + q3**2, np.sin(psi / 2) ** 2, atol=1e-15)
    np.testing.assert_allclose(q0**2 + q3**2, np.cos(rho / 2) ** 2, atol=1e-15)
    np.testing.assert_allclose(q1**2 + q2**2, np.sin(rho / 2) ** 2, atol=1e-15)
    # The paper's roll law (3), gamma = pi/2 - atan(tan(alpha) cos(theta)), is our
    # roll measured from the other arm, with the pitch theta = psi - pi/2.
    np.testing.assert_allclose(
        math.pi / 2 - rho,
        math.pi / 2 - np.arctan(math.tan(ALPHA) * np.cos(psi - math.pi / 2)),
        atol=1e-15,
    )


def test_paper_torques_with_equal_inertias_are_inertia_times_angular_acceleration():
    r = paper_response(np.linspace(0, 30, 301))
    for k in (1, 2, 3):
        np.testing.assert_allclose(
            getattr(r, f"crosspiece_torque_{k}"),
            0.026 * getattr(r, f"crosspiece_angular_acceleration_{k}"),
            atol=1e-17,
        )


def test_paper_m3_vanishes_for_i1_equal_i3_equal_half_i2():
    r = paper_response(np.linspace(0, 30, 301), (0.02, 0.04, 0.02))
    assert np.max(np.abs(r.crosspiece_torque_3)) < 1e-18


@pytest.mark.parametrize("name", DISTRIBUTIONS)
def test_paper_kinetic_energy_oscillates_between_closed_form_bounds(name):
    i1, i2, i3 = DISTRIBUTIONS[name]
    assert math.isclose((i1 + i2 + i3) / 2, I0)
    t = np.linspace(0, 4 * math.pi / W1, 40001)  # one input revolution and more
    energy = paper_response(t, (i1, i2, i3)).crosspiece_kinetic_energy
    # At constant speed and bend, Omega3 = w1 cos(a)/sqrt(D), Omega2^2 = w1^2 - Omega3^2,
    # Omega1^2 = w2^2 - Omega3^2: with the pin in the bend plane (D = cos^2 a) and
    # normal to it (D = 1) the energy takes these two values.
    c = math.cos(ALPHA)
    in_plane = 0.5 * (i1 * (W1 / c) ** 2 * (1 - c * c) + i3 * W1**2)
    normal = 0.5 * (i2 * W1**2 * (1 - c * c) + i3 * (W1 * c) ** 2)
    assert math.isclose(
        min(energy.max(), max(in_plane, normal)), max(in_plane, normal), rel_tol=1e-9
    ) or energy.max() >= max(in_plane, normal) * (1 - 1e-9)
    assert energy.min() <= min(in_plane, normal) * (1 + 1e-9)
    # Period: half an input revolution (the joint's twice-per-turn swing).
    half_turn = len(t) // 4
    np.testing.assert_allclose(energy[:half_turn], energy[2 * half_turn : 3 * half_turn], rtol=1e-9)
