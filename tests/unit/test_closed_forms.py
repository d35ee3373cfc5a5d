"""Every closed form of `joint_response` against computer algebra (tests/symbolic.py)
and, for the yoke reactions, against a direct linear solve of the trunnion conditions."""

import math

import mpmath
import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from symbolic import derived, frame
from tolerance import assert_close

from cardan_joint.physics import joint_response, max_cardan_error, roll_angle

GUARD = math.radians(85.0)
angles = st.floats(-20.0, 20.0)
# The 40-digit reference cannot resolve the cardan error below a bend of ~1e-20;
# tiny bends have their own test against a higher-precision reference.
bends = st.one_of(st.just(0.0), st.floats(1e-4, GUARD), st.floats(-GUARD, -1e-4))
speeds = st.floats(-300.0, 300.0)
accelerations = st.floats(-2e3, 2e3)
bend_rates = st.floats(-5.0, 5.0)
bend_accelerations = st.floats(-50.0, 50.0)
inertias = st.tuples(*[st.floats(0.0, 2.0)] * 3)
loads = st.floats(-1e3, 1e3)


def _scales(w1, a1, rb, ab):
    speed = abs(w1) + abs(rb) + 1e-3
    acceleration = w1 * w1 + abs(a1) + rb * rb + abs(ab) + abs(w1 * rb) + 1e-3
    return speed, acceleration


@settings(max_examples=100, deadline=None)
@given(angles, bends, speeds, accelerations, bend_rates, bend_accelerations)
def test_kinematics_and_angular_velocity_match_computer_algebra(psi, beta, w1, a1, rb, ab):
    r = joint_response(psi, beta, w1, a1, rb, ab)
    ref = derived(psi, beta, w1, a1, rb, ab)
    speed, acceleration = _scales(w1, a1, rb, ab)
    assert_close(
        r.cardan_error, ref["cardan_error"], 1e-12, max_cardan_error(beta) + 1e-28, "cardan error"
    )
    assert_close(r.speed_ratio, ref["speed_ratio"], 1e-12, what="speed ratio")
    assert_close(r.output_speed, ref["output_speed"], 1e-12, speed, "output speed")
    assert_close(
        r.output_acceleration,
        ref["output_acceleration"],
        1e-11,
        acceleration,
        "output acceleration",
    )
    for k in (1, 2, 3):
        assert_close(r[4 + k - 1], ref[f"omega_{k}"], 1e-12, speed, f"Omega{k}")
        assert_close(
            getattr(r, f"crosspiece_angular_acceleration_{k}"),
            ref[f"domega_{k}"],
            1e-11,
            acceleration,
            f"dOmega{k}",
        )


def _body_torque_reference(psi, beta, w1, a1, rb, ab, inertia):
    ref = derived(psi, beta, w1, a1, rb, ab)
    with mpmath.workdps(40):
        w = [ref[f"omega_{k}"] for k in (1, 2, 3)]
        dw = [ref[f"domega_{k}"] for k in (1, 2, 3)]
        i = [mpmath.mpf(x) for x in inertia]
        moment = [i[k] * w[k] for k in range(3)]
        gyro = [
            w[1] * moment[2] - w[2] * moment[1],
            w[2] * moment[0] - w[0] * moment[2],
            w[0] * moment[1] - w[1] * moment[0],
        ]
        torque = [i[k] * dw[k] + gyro[k] for k in range(3)]
        energy = sum(i[k] * w[k] ** 2 for k in range(3)) / 2
    return torque, energy


@settings(max_examples=100, deadline=None)
@given(angles, bends, speeds, accelerations, bend_rates, bend_accelerations, inertias, loads)
def test_euler_torques_energy_and_yoke_reactions(psi, beta, w1, a1, rb, ab, inertia, load):
    r = joint_response(psi, beta, w1, a1, rb, ab, inertia, load)
    speed, acceleration = _scales(w1, a1, rb, ab)
    torque, energy = _body_torque_reference(psi, beta, w1, a1, rb, ab, inertia)
    torque_scale = max(inertia) * acceleration + 1e-9
    for k in (1, 2, 3):
        assert_close(
            getattr(r, f"crosspiece_torque_{k}"), torque[k - 1], 1e-11, torque_scale, f"M{k}"
        )
    assert_close(
        r.crosspiece_kinetic_energy,
        energy,
        1e-12,
        max(inertia) * speed**2 + 1e-300,
        "kinetic energy",
    )

    # Yoke reactions: the six trunnion/balance equations solved as they stand.
    R = np.array(frame(psi, beta).tolist(), dtype=float)
    p1, p2 = R[:, 0], R[:, 1]
    z, y, z2 = np.eye(3)[2], np.eye(3)[1], np.array([math.sin(beta), 0.0, math.cos(beta)])
    M_fixed = R @ np.array([float(m) for m in torque])
    A = np.zeros((6, 6))
    A[0:3, 0:3] = A[0:3, 3:6] = np.eye(3)
    A[3, 0:3], A[4, 3:6], A[5, 3:6] = p1, p2, -z2
    tau = np.linalg.solve(A, np.concatenate([M_fixed, [0.0, 0.0, load]]))
    tau1, tau2 = tau[:3], tau[3:]
    scale = abs(load) / math.cos(beta) + torque_scale / math.cos(beta) ** 2
    assert_close(r.input_torque, tau1 @ z, 1e-9, scale, "input torque")
    assert_close(
        r.input_yoke_moment, np.linalg.norm(tau1 - (tau1 @ z) * z), 1e-9, scale, "input yoke moment"
    )
    assert_close(
        r.output_yoke_moment,
        np.linalg.norm(tau2 - (tau2 @ z2) * z2),
        1e-9,
        scale,
        "output yoke moment",
    )
    assert_close(r.hinge_torque, tau2 @ y, 1e-9, scale, "hinge torque")


def _quaternion_of(R):
    """Shepperd's method; sign left to the caller."""
    trace = R[0, 0] + R[1, 1] + R[2, 2]
    candidates = [trace, R[0, 0], R[1, 1], R[2, 2]]
    k = int(np.argmax(candidates))
    if k == 0:
        q0 = math.sqrt(1 + trace) / 2
        q = [
            q0,
            (R[2, 1] - R[1, 2]) / (4 * q0),
            (R[0, 2] - R[2, 0]) / (4 * q0),
            (R[1, 0] - R[0, 1]) / (4 * q0),
        ]
    elif k == 1:
        q1 = math.sqrt(1 + 2 * R[0, 0] - trace) / 2
        q = [
            (R[2, 1] - R[1, 2]) / (4 * q1),
            q1,
            (R[0, 1] + R[1, 0]) / (4 * q1),
            (R[0, 2] + R[2, 0]) / (4 * q1),
        ]
    elif k == 2:
        q2 = math.sqrt(1 + 2 * R[1, 1] - trace) / 2
        q = [
            (R[0, 2] - R[2, 0]) / (4 * q2),
            (R[0, 1] + R[1, 0]) / (4 * q2),
            q2,
            (R[1, 2] + R[2, 1]) / (4 * q2),
        ]
    else:
        q3 = math.sqrt(1 + 2 * R[2, 2] - trace) / 2
        q = [
            (R[1, 0] - R[0, 1]) / (4 * q3),
            (R[0, 2] + R[2, 0]) / (4 * q3),
            (R[1, 2] + R[2, 1]) / (4 * q3),
            q3,
        ]
    return np.array(q)


@settings(max_examples=300, deadline=None)
@given(angles, bends)
def test_quaternion_is_the_crosspiece_matrix_with_a_continuous_sign(psi, beta):
    r = joint_response(psi, beta, 0.0)
    q = np.array(r[11:15])
    expected = _quaternion_of(np.array(frame(psi, beta).tolist(), dtype=float))
    # Continuity fixes the sign: q is the rotation psi about z followed by a roll
    # below 90 deg, so it leans towards the pure z rotation by psi.
    if expected[0] * math.cos(psi / 2) + expected[3] * math.sin(psi / 2) < 0:
        expected = -expected
    assert np.max(np.abs(q - expected)) < 1e-12
    assert abs(q @ q - 1.0) < 1e-14


@settings(max_examples=200, deadline=None)
@given(angles, bends)
def test_roll_angle_is_the_rotation_about_the_input_pin(psi, beta):
    R = np.array(frame(psi, beta).tolist(), dtype=float)
    # R = Rz(psi) Rx(rho): the third column is (sin psi sin rho, -cos psi sin rho, cos rho).
    rho = roll_angle(psi, beta)
    assert abs(R[2, 2] - math.cos(rho)) < 1e-13
    assert abs(math.sin(psi) * R[0, 2] - math.cos(psi) * R[1, 2] - math.sin(rho)) < 1e-13


def test_cardan_error_keeps_relative_precision_at_tiny_bend():
    for beta in (1e-3, 1e-5, 1e-7):
        ref = derived(0.7, beta, 1.0)["cardan_error"]
        assert_close(
            joint_response(0.7, beta, 1.0).cardan_error,
            ref,
            1e-13,
            what=f"cardan error at bend {beta}",
        )
