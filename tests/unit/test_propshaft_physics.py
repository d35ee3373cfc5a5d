"""The propshaft physics against the independent 3-D construction
(tests/reference/propshaft.py), its cancellation cases, the phasing helper,
the power balance, the angle checks and the refusals."""

import math

import numpy as np
import pytest
from reference.propshaft import PropshaftReference
from tolerance import assert_close

from cardan_joint.models.propshaft import (
    Propshaft,
    angle_report,
    best_phasing,
    chain,
    equivalent_angle,
    layout,
    max_operating_angle,
    plane_angle,
    speed_ratio_fluctuation,
)
from cardan_joint.models.propshaft.chain import joint_forward
from cardan_joint.physics.response import JointResponse, kernel, pose_of
from cardan_joint.units import RPM_TO_RAD_PER_S

D = math.radians
LIMIT = D(15.0)


def random_layout(seed, joints):
    rng = np.random.default_rng(seed)
    return dict(
        side=list(rng.uniform(-LIMIT, LIMIT, joints + 1)),
        top=list(rng.uniform(-LIMIT, LIMIT, joints + 1)),
        phases=list(rng.uniform(-math.pi, math.pi, joints - 1)),
        shafts=list(rng.uniform(0.0, 0.5, joints - 1)),
        cross=tuple(rng.uniform(0.0, 0.05, 3)),
    )


def reference_of(case):
    return PropshaftReference(
        case["side"], case["top"], case["phases"], case["shafts"], case["cross"]
    )


@pytest.mark.parametrize("seed, joints", [(1, 2), (2, 2), (3, 3), (4, 4)])
def test_chain_matches_the_3d_construction(seed, joints):
    case = random_layout(seed, joints)
    geometry = layout(case["side"], case["top"], case["phases"])
    reference = reference_of(case)
    rng = np.random.default_rng(seed + 100)
    for _ in range(3):
        angle, speed, acc, load = (
            rng.uniform(-7, 7),
            rng.uniform(-300, 300),
            rng.uniform(-5e3, 5e3),
            rng.uniform(-500, 500),
        )
        offsets = reference.start_offsets(angle)
        ref = reference.at(angle, speed, acc, load, offsets)
        got = chain(geometry, angle, speed, acc, case["cross"], case["shafts"], load)
        speed_scale = abs(speed)
        acc_scale = speed * speed + abs(acc)
        for k in range(joints):
            assert abs(angle + got.offsets[k] - ref["angles"][k]) < 1e-13 * (1 + abs(angle))
            assert_close(got.speeds[k], ref["speeds"][k], 1e-12, speed_scale, f"omega_{k + 1}")
            assert_close(
                got.accelerations[k], ref["accelerations"][k], 1e-12, acc_scale, f"alpha_{k + 1}"
            )
        torque_scale = abs(load) + sum(case["shafts"]) * acc_scale
        assert_close(got.input_torque, ref["input_torque"], 1e-12, torque_scale, "input torque")
        assert_close(got.kinetic_energy, ref["kinetic_energy"], 1e-12, None, "energy")
    assert_close(
        speed_ratio_fluctuation(geometry),
        reference.speed_ratio_fluctuation(),
        1e-9,
        None,
        "speed_ratio_fluctuation",
    )


def test_a_joints_forward_pass_is_the_kernels_to_the_bit():
    # The chain's forward pass takes each joint's kernel outputs it needs from
    # the kernel's own parts at the bend's sine and cosine (taken once a
    # step): the same bits as the whole kernel at no load.
    rng = np.random.default_rng(3)
    fields = JointResponse._fields
    for _ in range(2000):
        psi, beta = rng.uniform(-20.0, 20.0), rng.uniform(-1.4, 1.4)
        w, a = rng.uniform(-1e3, 1e3), rng.uniform(-1e4, 1e4)
        I1, I2, I3 = (float(x) for x in rng.uniform(0.0, 0.1, 3))
        r = kernel(math, psi, beta, w, a, 0.0, 0.0, I1, I2, I3, 0.0, 1.0)
        sb, cb = math.sin(beta), math.cos(beta)
        s, c = pose_of(math, psi, sb, cb)[2:4]
        tangent, *got = joint_forward(math, s, c, sb, cb, w, a, I1, I2, I3)
        names = ("cardan_error", "output_speed", "output_acceleration",
                 "crosspiece_kinetic_energy", "input_torque", "speed_ratio")  # fmt: skip
        assert (math.atan(tangent), *got) == tuple(r[fields.index(name)] for name in names)


def test_power_balance_holds_exactly():
    """T_in omega_0 = T_L omega_N + dE/dt along a motion (dE/dt by a 4th-order
    central difference of the chain's own energy)."""
    case = random_layout(7, 3)
    geometry = layout(case["side"], case["top"], case["phases"])
    speed0, acc, load = 40.0, 30.0, 120.0

    def state(t):
        return chain(
            geometry,
            0.4 + t * (speed0 + 0.5 * acc * t),
            speed0 + acc * t,
            acc,
            case["cross"],
            case["shafts"],
            load,
        )

    for t in (0.0, 0.013, 0.2):
        h = 1e-4
        energy_rate = (
            8 * (state(t + h).kinetic_energy - state(t - h).kinetic_energy)
            - (state(t + 2 * h).kinetic_energy - state(t - 2 * h).kinetic_energy)
        ) / (12 * h)
        now = state(t)
        speed = speed0 + acc * t
        assert_close(
            now.input_torque * speed,
            load * now.speeds[-1] + energy_rate,
            1e-9,
            load * abs(speed),
            f"power at t={t}",
        )


@pytest.mark.parametrize("outer", [(3.0, 3.0), (3.0, -3.0)], ids=["Z", "W"])
def test_coplanar_equal_in_phase_layouts_cancel_and_90_degrees_does_not(outer):
    side = [D(outer[0]), 0.0, D(outer[1])]
    top = [0.0, 0.0, 0.0]
    assert speed_ratio_fluctuation(layout(side, top, [0.0])) < 1e-12
    single = math.tan(D(3.0)) * math.sin(D(3.0))
    assert speed_ratio_fluctuation(layout(side, top, [math.pi / 2])) > 1.9 * single


def test_compound_equal_angles_cancel_only_at_the_helpers_phasing():
    # Joint 1 bends in the side view, joint 2 in a plane 60 deg away, both 4 deg.
    beta, tilt = D(4.0), D(60.0)
    side = [0.0, 0.0, math.atan(math.tan(beta) * math.cos(tilt))]
    top = [math.atan(math.tan(beta)), 0.0, math.atan(math.tan(beta) * math.sin(tilt))]
    side[0], top[0] = 0.0, 0.0
    side[1], top[1] = -beta, 0.0
    side[2] = side[1] + 0.0
    # Output shaft: 4 deg from shaft 1 in a plane turned by `tilt` about it.
    d1 = np.array([math.cos(beta), 0.0, -math.sin(beta)])
    normal = np.array([0.0, 1.0, 0.0])
    turned = normal * math.cos(tilt) + np.cross(d1, normal) * math.sin(tilt)
    d2 = d1 * math.cos(beta) + np.cross(turned, d1) * math.sin(beta)
    side[2], top[2] = math.atan(d2[2] / d2[0]), math.atan(d2[1] / d2[0])
    geometry = layout(side, top, [0.0])
    assert geometry.working_angles[0] == pytest.approx(geometry.working_angles[1], abs=1e-15)
    assert abs(abs(plane_angle(geometry, 1)) - tilt) < 1e-12
    phases, left = best_phasing(geometry)
    assert left < 1e-12
    assert speed_ratio_fluctuation(geometry.with_phases(phases)) < 1e-12
    assert speed_ratio_fluctuation(geometry) > 1e-3
    assert phases[0] == pytest.approx(plane_angle(geometry, 1) % math.pi, abs=1e-15)


@pytest.mark.parametrize("seed", [11, 12])
def test_two_joint_phasing_matches_a_brute_force_search(seed):
    """Unequal working angles in different planes: a grid over [0, pi) refined by
    scipy's bounded scalar minimizer finds no lower fluctuation than the helper's."""
    from scipy.optimize import minimize_scalar

    case = random_layout(seed, 2)
    geometry = layout(case["side"], case["top"], [0.0])
    phases, left = best_phasing(geometry)

    def cost(phase):
        return speed_ratio_fluctuation(geometry.with_phases([phase]))

    grid = np.linspace(0.0, math.pi, 61)
    start = grid[int(np.argmin([cost(p) for p in grid]))]
    brute = minimize_scalar(
        cost, bounds=(start - grid[1], start + grid[1]), method="bounded", options={"xatol": 1e-10}
    )
    assert left <= brute.fun + 1e-12
    assert abs(math.remainder(phases[0] - brute.x, math.pi)) < 1e-4
    assert cost(phases[0] + 0.01) > left and cost(phases[0] - 0.01) > left


def test_three_joint_phasing_is_no_worse_than_any_grid_point():
    case = random_layout(21, 3)
    geometry = layout(case["side"], case["top"], [0.0, 0.0])
    phases, left = best_phasing(geometry)
    grid = np.linspace(0.0, math.pi, 13)
    coarse = min(speed_ratio_fluctuation(geometry.with_phases([a, b])) for a in grid for b in grid)
    assert left <= coarse + 1e-12


def test_one_straight_joint_leaves_the_single_joint_fluctuation():
    beta = D(7.0)
    geometry = layout([beta, 0.0, 0.0], [0.0, 0.0, 0.0], [0.4])
    single = math.tan(beta) * math.sin(beta)
    assert_close(speed_ratio_fluctuation(geometry), single, 1e-13)
    assert_close(equivalent_angle(single), beta, 1e-15)
    assert equivalent_angle(1e-20) == pytest.approx(1e-10, rel=1e-12)
    assert equivalent_angle(0.0) == 0.0


def test_angle_checks_on_hand_made_layouts():
    clean = angle_report(layout([D(2), 0.0, D(2)], [0, 0, 0], [0.0]), 3000 * RPM_TO_RAD_PER_S)
    assert clean.warnings == () and clean.max_operating_angle is None
    small = angle_report(layout([D(0.3), 0.0, D(0.3)], [0, 0, 0], [0.0]), 0.0)
    assert [w for w in small.warnings if "below 0.5 deg" in w] and len(small.warnings) == 2
    unequal = angle_report(layout([D(2), 0.0, D(3.5)], [0, 0, 0], [0.0]), 0.0)
    assert any("differ by more than 1 deg" in w for w in unequal.warnings)
    fast = angle_report(layout([D(4.5), 0.0, D(4.5)], [0, 0, 0], [0.0]), 4000 * RPM_TO_RAD_PER_S)
    assert any("exceeds the maximum operating angle" in w for w in fast.warnings)
    assert not angle_report(
        layout([D(4.1), 0.0, D(4.1)], [0, 0, 0], [0.0]), 4000 * RPM_TO_RAD_PER_S
    ).warnings
    residual = angle_report(layout([D(4), 0.0, D(4)], [0, 0, 0], [math.pi / 2]), 0.0)
    assert any("exceeds 0.0027" in w for w in residual.warnings)
    assert any(
        "above the table" in w
        for w in angle_report(
            layout([D(1), 0.0, D(1)], [0, 0, 0], [0.0]), 6000 * RPM_TO_RAD_PER_S
        ).warnings
    )
    limit, _ = max_operating_angle(4250 * RPM_TO_RAD_PER_S)
    assert limit == pytest.approx(D(3.95), rel=1e-12)
    assert max_operating_angle(5000 * RPM_TO_RAD_PER_S)[0] == pytest.approx(D(3.2), rel=1e-12)
    assert max_operating_angle(3499 * RPM_TO_RAD_PER_S)[0] is None


def test_angles_stay_exact_over_a_million_revolutions():
    """A run past a million revolutions: every output equals the chain at the
    exactly reduced input angle (no drift in the angle, no loss in the offsets)."""
    import mpmath

    start, speed, h = 2e6 * math.pi + 0.3, 377.0, 0.01
    # Without life: the angles are the subject, and the life integral over 0.6 of
    # a turn a step with its torque zeros would cost seconds for nothing here.
    shaft = Propshaft(
        2, life=False, shaft_2_top_angle=D(5), input_angle_start=start, input_speed=speed
    )
    for _ in range(500):
        shaft.step(h)
    with mpmath.workdps(50):
        exact = mpmath.mpf(start) + 500 * mpmath.mpf(h) * speed
        reduced = float(exact % (2 * mpmath.pi))
    expected = chain(shaft.layout, reduced, speed, 0.0, (0.026,) * 3, [0.02], 0.0)
    values = shaft.outputs()
    assert abs(values[0] - float(exact)) <= 2e-9  # one ulp of the absolute angle
    # Absolute angles of 6e6 rad resolve 1e-9 rad: the offsets survive to that.
    assert abs((values[1] - values[0]) - expected.offsets[0]) < 2e-9
    assert abs((values[4] - values[0]) - expected.offsets[1]) < 2e-9
    assert_close(values[2], expected.speeds[0], 1e-13)
    assert_close(values[5], expected.speeds[1], 1e-13)
    assert_close(values[6], expected.accelerations[1], 1e-12, speed * speed)
