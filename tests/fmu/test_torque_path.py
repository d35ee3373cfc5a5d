"""Torque path (issue 3): power balances, the massless limits, the secondary
couples' closed forms and peaks, and the FMU against a rigid multibody
Newton-Euler reference (tests/reference/multibody.py)."""

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from reference.multibody import simulate_multibody, state_quantities
from symbolic import derived

from cardan_joint.host.instance import FmuInstance
from cardan_joint.physics import joint_response

GUARD = math.radians(85.0)
angles = st.floats(-20.0, 20.0)
bends = st.one_of(st.just(0.0), st.floats(1e-3, GUARD), st.floats(-GUARD, -1e-3))
inertias = st.tuples(*[st.floats(0.0, 1.0)] * 3)


def energy_rate(psi, beta, w1, a1, rb, ab, inertia):
    """dE/dt from the computer-algebra angular velocity and its rate."""
    ref = derived(psi, beta, w1, a1, rb, ab)
    with mpmath.workdps(40):
        return float(
            sum(
                mpmath.mpf(i) * ref[f"omega_{k}"] * ref[f"domega_{k}"]
                for k, i in enumerate(inertia, start=1)
            )
        )


@settings(max_examples=100, deadline=None)
@given(angles, bends, st.floats(-100, 100), st.floats(-500, 500), inertias, st.floats(-1e3, 1e3))
def test_power_balance_at_constant_bend(psi, beta, w1, a1, inertia, load):
    r = joint_response(psi, beta, w1, a1, 0.0, 0.0, inertia, load)
    balance = r.input_torque * w1 - load * r.output_speed
    expected = energy_rate(psi, beta, w1, a1, 0.0, 0.0, inertia)
    scale = (abs(load) + max(inertia) * (w1 * w1 + abs(a1))) * abs(w1) / math.cos(beta) ** 4
    assert abs(balance - expected) <= 1e-11 * scale + 1e-300


@settings(max_examples=100, deadline=None)
@given(
    angles,
    bends,
    st.floats(-100, 100),
    st.floats(-500, 500),
    st.floats(-3, 3),
    st.floats(-30, 30),
    inertias,
    st.floats(-1e3, 1e3),
)
def test_energy_balance_with_a_moving_bend_includes_the_hinge_power(
    psi, beta, w1, a1, rb, ab, inertia, load
):
    r = joint_response(psi, beta, w1, a1, rb, ab, inertia, load)
    balance = r.input_torque * w1 - load * r.output_speed + rb * r.hinge_torque
    expected = energy_rate(psi, beta, w1, a1, rb, ab, inertia)
    speed = abs(w1) + abs(rb)
    scale = (
        (abs(load) + max(inertia) * (speed * speed + abs(a1) + abs(ab)))
        * speed
        / math.cos(beta) ** 4
    )
    assert abs(balance - expected) <= 1e-11 * scale + 1e-300


@pytest.mark.parametrize("beta", np.radians([5.0, 20.0, 45.0, 70.0]))
def test_massless_cross_swings_the_input_torque_between_load_cos_and_load_over_cos(beta):
    psi = np.linspace(0, 2 * math.pi, 100001)
    load = 250.0
    r = joint_response(psi, beta, 10.0, load_torque=load)
    t1 = r.input_torque
    np.testing.assert_allclose(t1 * 10.0, load * r.output_speed, rtol=1e-13)
    assert math.isclose(t1.max(), load / math.cos(beta), rel_tol=1e-12)
    assert math.isclose(t1.min(), load * math.cos(beta), rel_tol=1e-9)
    # Secondary couples: T1 tan(b) |sin psi| and T_L tan(b) |cos psi2|.
    psi2 = psi + r.cardan_error
    np.testing.assert_allclose(
        r.input_yoke_moment,
        t1 * math.tan(beta) * np.abs(np.sin(psi)),
        rtol=1e-12,
        atol=1e-12 * load,
    )
    np.testing.assert_allclose(
        r.output_yoke_moment,
        load * math.tan(beta) * np.abs(np.cos(psi2)),
        rtol=1e-12,
        atol=1e-12 * load,
    )
    # Peaks relative to the input torque: the input yoke's couple is T1 tan(b) |sin psi|,
    # so its ratio peaks at tan(b) (psi = 90 deg). The output yoke's ratio is
    # tan(b) |cos psi| sqrt(D): sin(b) at psi = 0, which is its peak up to 45 deg;
    # beyond 45 deg the peak moves off the bend plane and is 1 / (2 cos b).
    assert math.isclose((r.input_yoke_moment / t1).max(), math.tan(beta), rel_tol=1e-9)
    output_peak = math.sin(beta) if beta <= math.pi / 4 else 1 / (2 * math.cos(beta))
    assert math.isclose((r.output_yoke_moment / t1).max(), output_peak, rel_tol=1e-8)


def test_fmu_matches_the_multibody_reactions_along_a_driven_trajectory(
    model_description, unzipped_fmu
):
    # A motor (J1) drives a load inertia (J2) through the joint against a
    # speed-dependent external torque. The multibody reference integrates it;
    # the FMU is fed the reference's speed and, at the FMU's own input angle,
    # the acceleration and load the Newton-Euler system gives for that state.
    beta, phase, inertia = math.radians(35.0), 0.4, (0.02, 0.03, 0.045)
    J1, J2 = 0.05, 0.3
    motor = lambda t: 40.0 + 20.0 * math.sin(3.0 * t)
    external = lambda t: 15.0
    h, n = 0.01, 60
    times = np.arange(n + 1) * h
    trajectory = simulate_multibody(
        times, beta, inertia, J1, J2, motor, external, gamma1_0=0.3, omega1_0=12.0, yoke_phase=phase
    )
    joint = FmuInstance(
        model_description,
        unzipped_fmu,
        start_values=dict(
            bend_angle=beta,
            yoke_phase=phase,
            input_angle_start=0.3,
            crosspiece_inertia_1=inertia[0],
            crosspiece_inertia_2=inertia[1],
            crosspiece_inertia_3=inertia[2],
        ),
    )
    try:
        for k, t in enumerate(times):
            gamma1 = joint.get("input_angle")["input_angle"]
            # Stays near the run: the FMU integrates the fed speed as a polynomial,
            # which misses the jerk term (h^3/6 per step) of the true trajectory.
            assert abs(gamma1 - trajectory["input_angle"][k]) < 0.05
            omega1 = float(trajectory["input_speed"][k])
            state = state_quantities(
                t, gamma1, omega1, beta, inertia, J1, J2, motor, external, phase
            )
            joint.set(
                input_speed=omega1,
                input_acceleration=state["input_acceleration"],
                load_torque=state["load_torque"],
            )
            out = joint.get(
                "input_torque",
                "input_yoke_moment",
                "output_yoke_moment",
                "output_speed",
                "output_acceleration",
            )
            scale = abs(state["load_torque"]) / math.cos(beta) + abs(state["input_torque"])
            for name in ("input_torque", "input_yoke_moment", "output_yoke_moment"):
                assert abs(out[name] - state[name]) <= 1e-9 * scale, (
                    name,
                    t,
                    out[name],
                    state[name],
                )
            assert math.isclose(out["output_speed"], state["output_speed"], rel_tol=1e-12)
            assert abs(out["output_acceleration"] - state["output_acceleration"]) <= 1e-9 * (
                abs(state["output_acceleration"]) + omega1 * omega1
            )
            if k < n:
                joint.step(h)
    finally:
        joint.close()
