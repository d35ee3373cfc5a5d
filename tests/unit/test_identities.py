"""The model page's identities (models/universal_joint/README.md) as properties over random
bend angles, phases and rates, and scalar/array agreement of the vectorized physics."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from cardan_joint.physics import (
    degree_of_unevenness,
    joint_response,
    max_cardan_error,
    output_angle,
)

GUARD = math.radians(85.0)
angles = st.floats(-50.0, 50.0)
bends = st.floats(-GUARD, GUARD)
speeds = st.floats(-300.0, 300.0)
rates = st.floats(-5.0, 5.0)


@settings(max_examples=500, deadline=None)
@given(angles, bends, speeds, st.floats(-1e3, 1e3), rates, st.floats(-50, 50))
def test_omega2_squared_plus_omega3_squared_is_input_speed_squared(psi, beta, w1, a1, rb, ab):
    r = joint_response(psi, beta, w1, a1, rb, ab)
    lhs = r.crosspiece_angular_velocity_2**2 + r.crosspiece_angular_velocity_3**2
    assert abs(lhs - w1 * w1) <= 1e-13 * (w1 * w1 + 1e-300)


@settings(max_examples=500, deadline=None)
@given(angles, bends, speeds, st.floats(-1e3, 1e3))
def test_omega1_squared_plus_omega3_squared_is_output_speed_squared_at_constant_bend(
    psi, beta, w1, a1
):
    r = joint_response(psi, beta, w1, a1)
    lhs = r.crosspiece_angular_velocity_1**2 + r.crosspiece_angular_velocity_3**2
    assert abs(lhs - r.output_speed**2) <= 1e-12 * (r.output_speed**2 + 1e-300)


@settings(max_examples=500, deadline=None)
@given(angles, bends, speeds, st.tuples(*[st.floats(0.0, 1.0)] * 3))
def test_m3_at_constant_speed_and_bend(psi, beta, w1, inertia):
    i1, i2, i3 = inertia
    r = joint_response(psi, beta, w1, 0.0, 0.0, 0.0, inertia)
    w_1, w_2 = r.crosspiece_angular_velocity_1, r.crosspiece_angular_velocity_2
    expected = (i2 - i1 - i3) * w_1 * w_2
    assert abs(r.crosspiece_torque_3 - expected) <= 1e-11 * (
        max(inertia) * w1 * w1 / math.cos(beta) ** 4 + 1e-300
    )
    # The paper's distribution I1 = I3 = I2/2 makes M3 vanish whatever the speed.
    balanced = joint_response(psi, beta, w1, 0.0, 0.0, 0.0, (i2 / 2, i2, i2 / 2))
    assert abs(balanced.crosspiece_torque_3) <= 1e-12 * (
        i2 * w1 * w1 / math.cos(beta) ** 4 + 1e-300
    )


@settings(max_examples=500, deadline=None)
@given(angles, bends)
def test_speed_ratio_swings_between_cos_beta_and_its_inverse(psi, beta):
    ratio = joint_response(psi, beta, 1.0).speed_ratio
    c = math.cos(beta)
    assert c * (1 - 1e-15) <= ratio <= (1 / c) * (1 + 1e-15)


@settings(max_examples=500, deadline=None)
@given(angles, bends)
def test_cardan_error_is_bounded_by_its_closed_form_amplitude(psi, beta):
    assert (
        abs(joint_response(psi, beta, 1.0).cardan_error)
        <= max_cardan_error(beta) * (1 + 1e-14) + 1e-300
    )


@settings(max_examples=200, deadline=None)
@given(bends)
def test_degree_of_unevenness_is_the_speed_swing(beta):
    psi = np.linspace(0.0, math.pi, 2001)
    # The extremes sit at psi = 0 and pi/2 (Tataru's phi1 = 0, pi/2).
    swing = joint_response(np.array([0.0, math.pi / 2]), beta, 1.0).output_speed
    assert math.isclose(
        swing[0] - swing[1], degree_of_unevenness(beta), rel_tol=1e-12, abs_tol=1e-15
    )
    sampled = joint_response(psi, beta, 1.0).output_speed
    assert sampled.max() <= swing[0] * (1 + 1e-15) and sampled.min() >= swing[1] * (1 - 1e-15)


def test_output_angle_is_continuous_over_many_turns_without_branch_jumps():
    gamma1 = np.linspace(-40.0, 40.0, 400001)
    for beta in (0.1, 0.8, 1.4):
        gamma2 = output_angle(gamma1, beta, 0.3)
        steps = np.diff(gamma2)
        # Largest possible increment: the speed ratio's maximum times the grid step.
        assert steps.max() <= (gamma1[1] - gamma1[0]) / math.cos(beta) * (1 + 1e-9)
        assert steps.min() > 0


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_vectorized_response_equals_scalar_loop(seed):
    rng = np.random.default_rng(seed)
    n = 64
    args = (
        rng.uniform(-20, 20, n),
        rng.uniform(-1.4, 1.4, n),
        rng.uniform(-100, 100, n),
        rng.uniform(-1e3, 1e3, n),
        rng.uniform(-3, 3, n),
        rng.uniform(-30, 30, n),
    )
    inertia = tuple(rng.uniform(0, 1, (3, n)))
    load = rng.uniform(-100, 100, n)
    sign = rng.choice([-1.0, 1.0], n)
    vector = joint_response(*args, inertia, load, sign)
    for k in range(n):
        scalar = joint_response(
            *(float(a[k]) for a in args),
            tuple(float(i[k]) for i in inertia),
            float(load[k]),
            float(sign[k]),
        )
        assert type(scalar.output_speed) is float
        # math and numpy round differently in the last bit of sin/cos/atan.
        np.testing.assert_allclose(np.array(scalar), np.array(vector)[:, k], rtol=1e-12, atol=1e-12)


def test_arrays_broadcast_against_scalars():
    r = joint_response(np.linspace(0, 6, 7)[:, None], np.array([0.1, 0.2, 0.3]), 10.0)
    assert r.output_speed.shape == (7, 3)


def test_large_arrays_are_evaluated_in_blocks_with_identical_results():
    from cardan_joint.physics.response import kernel

    rng = np.random.default_rng(5)
    psi = rng.uniform(-20, 20, (300, 1))
    beta = rng.uniform(-1.3, 1.3, (1, 70))  # 21000 samples by broadcasting
    inertia = (rng.uniform(0, 1, (300, 1)), 0.2, 0.3)
    blocked = joint_response(psi, beta, 30.0, 5.0, 0.1, -0.2, inertia, 7.0, -1.0)
    whole = kernel(np, psi, beta, 30.0, 5.0, 0.1, -0.2, *inertia, 7.0, -1.0)
    for name, a, b in zip(blocked._fields, blocked, whole):
        assert np.shape(a) == (300, 70), name
        np.testing.assert_array_equal(a, np.broadcast_to(b, (300, 70)), err_msg=name)
