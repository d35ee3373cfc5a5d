"""Issue 27: trunnion bearing forces and catalogue life of the joint (docs/life.md).

Bearing forces against an independent 3-D construction of the yoke torques
(mpmath: the cross's orientation from the pins' definitions, its angular
momentum differentiated in time, the trunnion conditions solved); the damage
against mpmath's adaptive quadrature of the catalogue rate (`life_reference`).
"""

import json
import math
import random

import mpmath as mp
import pytest
from life_reference import case_of, damage, damage_quadpack

from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.physics.life import life_rate, life_rule, step_damage
from cardan_joint.physics.life_torque import input_torque
from cardan_joint.physics.response import JointResponse, kernel

RULE = life_rule(1000.0, 1.5e6, 10.0 / 3.0, math.radians(3.0))


def _yoke_torques(psi0, b0, w, a, rb, ab, inertia, load):
    """tau1, tau2 (world frame) at t = 0 from the geometry alone."""
    I = [mp.mpf(x) for x in inertia]

    def frame(t):
        psi = psi0 + w * t + a * t * t / 2
        b = b0 + rb * t + ab * t * t / 2
        p1 = mp.matrix([mp.cos(psi), mp.sin(psi), 0])
        z2 = mp.matrix([mp.sin(b), 0, mp.cos(b)])
        n = mp.matrix([z2[1] * p1[2] - z2[2] * p1[1], z2[2] * p1[0] - z2[0] * p1[2],
                       z2[0] * p1[1] - z2[1] * p1[0]])  # fmt: skip
        p2 = n / mp.norm(n)
        p3 = mp.matrix([p1[1] * p2[2] - p1[2] * p2[1], p1[2] * p2[0] - p1[0] * p2[2],
                        p1[0] * p2[1] - p1[1] * p2[0]])  # fmt: skip
        return p1, p2, p3, z2

    def momentum(t):  # world angular momentum R I Omega, Omega = vee(R^T R')
        R = frame(t)[:3]
        dR = [[mp.diff(lambda s, k=k, i=i: frame(s)[k][i], t) for i in range(3)] for k in range(3)]
        # Omega_i = p_j . dp_k for (i, j, k) cyclic
        Om = [
            sum(R[2][i] * dR[1][i] for i in range(3)),
            sum(R[0][i] * dR[2][i] for i in range(3)),
            sum(R[1][i] * dR[0][i] for i in range(3)),
        ]
        return [sum(R[k][i] * I[k] * Om[k] for k in range(3)) for i in range(3)]

    with mp.workdps(40):
        M = [mp.diff(lambda s, i=i: momentum(s)[i], 0) for i in range(3)]
        p1, p2, p3, z2 = frame(mp.mpf(0))
        # Unknowns tau1 (3), tau2 (3): tau1 + tau2 = M, tau1 . p1 = 0, tau2 . p2 = 0,
        # -tau2 . z2 = T_L.
        A = mp.zeros(6, 6)
        rhs = mp.zeros(6, 1)
        for i in range(3):
            A[i, i] = A[i, i + 3] = 1
            rhs[i] = M[i]
            A[3, i] = p1[i]
            A[4, i + 3] = p2[i]
            A[5, i + 3] = -z2[i]
        rhs[5] = load
        x = mp.lu_solve(A, rhs)
        return [float(x[i]) for i in range(3)], [float(x[i + 3]) for i in range(3)]


def _random_case(rng):
    inertia = tuple(rng.uniform(0.0, 0.1) for _ in range(3))
    return dict(
        psi=rng.uniform(-4, 4),
        b=rng.uniform(-1.2, 1.2),
        w=rng.uniform(-300, 300),
        a=rng.uniform(-1e4, 1e4),
        rb=rng.uniform(-5, 5),
        ab=rng.uniform(-100, 100),
        inertia=inertia,
        load=rng.uniform(-500, 500),
    )


def _joint_at(case, **extra):
    joint = CardanJoint(
        input_speed=case["w"],
        input_acceleration=case["a"],
        bend_angle=case["b"],
        bend_angle_rate=case["rb"],
        bend_angle_acceleration=case["ab"],
        load_torque=case["load"],
        input_angle_start=case["psi"],
        crosspiece_inertia_1=case["inertia"][0],
        crosspiece_inertia_2=case["inertia"][1],
        crosspiece_inertia_3=case["inertia"][2],
        **extra,
    )
    return joint, dict(zip(joint.table.OUTPUTS, joint.outputs()))


@pytest.mark.parametrize("seed", range(12))
def test_bearing_forces_equal_an_independent_3d_construction(seed):
    case = _random_case(random.Random(seed))
    radius = 0.02 + 0.01 * seed
    _, out = _joint_at(case, bearing_radius=radius)
    tau1, tau2 = _yoke_torques(
        *(case[k] for k in ("psi", "b", "w", "a", "rb", "ab", "inertia", "load"))
    )
    for name, tau in (("input_bearing_force", tau1), ("output_bearing_force", tau2)):
        expected = math.sqrt(sum(x * x for x in tau)) / (2.0 * radius)
        assert out[name] == pytest.approx(expected, rel=1e-9, abs=1e-9 * abs(case["load"]) / radius)


@pytest.mark.parametrize("seed", range(6))
def test_with_a_massless_cross_both_yokes_load_their_bearings_equally(seed):
    case = {**_random_case(random.Random(100 + seed)), "inertia": (0.0, 0.0, 0.0)}
    _, out = _joint_at(case)
    assert out["input_bearing_force"] == pytest.approx(
        out["output_bearing_force"], rel=1e-13, abs=0.0
    )


def test_the_reduced_torque_is_the_kernels():
    # The kernel's own parts: its bits with a massive cross; T_L cos b / D, the
    # same closed form, without one.
    rng = random.Random(5)
    for _ in range(2000):
        c = _random_case(rng)
        inertia = c["inertia"] if rng.random() < 0.7 else (0.0, 0.0, 0.0)
        args = (c["psi"], c["b"], c["w"], c["a"], c["rb"], c["ab"], *inertia, c["load"])
        full = JointResponse._make(kernel(math, *args, 1.0))
        reduced = input_torque(c["psi"], math.sin(c["b"]), math.cos(c["b"]), *args[2:])
        if any(inertia):
            assert reduced == full.input_torque
        else:
            assert reduced == pytest.approx(full.input_torque, rel=1e-14, abs=0.0)


# Steps crossing the 3-degree floor, torque reversals from the cross's inertia,
# speed reversals and ramps: (inputs, step size, steps).
QUADRATURE_CASES = [
    # bend ramping through +-3 deg, massless cross
    (dict(w=150.0, a=0.0, b=-0.08, rb=2.0, ab=0.0, inertia=(0.0, 0.0, 0.0), load=300.0), 0.02, 5),
    # bend parabola crossing the floor twice, speed ramp
    (
        dict(w=80.0, a=900.0, b=0.06, rb=-3.0, ab=60.0, inertia=(0.01, 0.02, 0.03), load=-250.0),
        0.01,
        4,
    ),
    # no load: the inertia torque reverses twice a turn
    (dict(w=220.0, a=0.0, b=0.5, rb=0.0, ab=0.0, inertia=(0.08, 0.04, 0.05), load=0.0), 0.01, 4),
    # load and inertia torque of one size: reversals at a strong bend
    (
        dict(w=-140.0, a=0.0, b=0.74, rb=0.0, ab=0.0, inertia=(0.1, 0.04, 0.08), load=-100.0),
        0.01,
        3,
    ),
    # one-panel steps (the common path): a strong ramp near the lock-up's reach,
    # and the inertia's torque alone at almost no bend (its own scale, not D's)
    (
        dict(
            psi=-6.4329354798088945,
            w=-278.66885309290313,
            a=19373.776019856676,
            b=0.8609855257054899,
            rb=0.0,
            ab=0.0,
            inertia=(0.03768729354612184, 0.03936117889936878, 0.00037454350111273407),
            load=76.43714422301719,
        ),  # fmt: skip
        1e-4,
        1,
    ),
    (
        dict(
            psi=-0.9383257949738866,
            w=180.86344713565205,
            a=0.0,
            b=0.0012895870192714432,
            rb=0.9575373690109501,
            ab=0.0,
            inertia=(0.025926308668315648, 0.09883281760179047, 0.007879659775856153),
            load=0.0,
        ),  # fmt: skip
        1e-3,
        1,
    ),
    # speed reversal inside a step under strong acceleration
    (
        dict(w=-228.0, a=6040.0, b=0.98, rb=4.0, ab=-44.0, inertia=(0.07, 0.0004, 0.019), load=0.0),
        0.05,
        1,
    ),
]


@pytest.mark.parametrize("inputs, h, steps", QUADRATURE_CASES)
def test_life_consumed_equals_an_adaptive_quadrature_of_the_catalogue_rate(inputs, h, steps):
    joint, _ = _joint_at({"psi": 0.3, **inputs})
    expected = 0.0
    for _ in range(steps):
        expected += damage(case_of(joint), h, RULE)
        assert joint.step(h) is None
        got = dict(zip(joint.table.OUTPUTS, joint.outputs()))["life_consumed"]
        assert got == pytest.approx(expected, rel=1e-9, abs=0.0)


@pytest.mark.parametrize("inertia", [(0.0, 0.0, 0.0), (0.02, 0.03, 0.05)])
def test_constant_torque_speed_and_angle_consume_t_over_3600_life_hours(inertia):
    # A straight joint: the torque is the load, the angle the 3-degree floor.
    w, load, h, steps = 157.0, 640.0, 1e-3, 2000
    joint, _ = _joint_at(
        dict(psi=0.0, w=w, a=0.0, b=0.0, rb=0.0, ab=0.0, inertia=inertia, load=load)
    )
    for _ in range(steps):
        assert joint.step(h) is None
    out = dict(zip(joint.table.OUTPUTS, joint.outputs()))
    life_hours = RULE.constant / (3.0 * w * 30.0 / math.pi) * (RULE.rated_torque / load) ** (10 / 3)
    assert out["life_rate"] == pytest.approx(1.0 / life_hours, rel=1e-13, abs=0.0)
    assert out["life_consumed"] == pytest.approx(
        steps * h / (3600.0 * life_hours), rel=1e-12, abs=0.0
    )
    assert life_rate(0.0, w, 0.1, RULE) == life_rate(load, 0.0, 0.1, RULE) == 0.0


def test_saving_restoring_and_serializing_mid_run_continues_bit_identically():
    case = dict(
        psi=0.1, w=120.0, a=30.0, b=0.3, rb=0.1, ab=0.0, inertia=(0.02, 0.03, 0.04), load=80.0
    )
    joint, _ = _joint_at(case)
    for _ in range(7):
        joint.step(0.01)
    saved = json.loads(json.dumps(joint.state()))
    tail = []
    for _ in range(5):
        joint.step(0.01)
        tail.append(joint.outputs())
    other, _ = _joint_at({**case, "load": -5.0})
    other.restore(saved)
    again = []
    for _ in range(5):
        other.step(0.01)
        again.append(other.outputs())
    assert again == tail
    assert saved["life_consumed"] > 0.0


@pytest.mark.parametrize("name", ["bearing_radius", "rated_torque"])
@pytest.mark.parametrize("value", [0.0, -1.0])
def test_a_non_positive_radius_or_rated_torque_is_refused_by_name(name, value):
    joint = CardanJoint(**{name: value})
    problem = joint.parameter_problem()
    assert problem is not None and problem.variable == name and problem.value == value
    assert name in problem.message and "parameter" in problem.message
    assert joint.step(1e-3) is not None
    # Outputs stay readable: the joint's own, and no load or life without a radius or rating.
    out = dict(zip(joint.table.OUTPUTS, joint.outputs()))
    assert math.isfinite(out["output_speed"]) and math.isnan(out["life_rate"])


def test_without_life_the_joint_gives_the_same_numbers_and_lacks_only_the_life_rows():
    with_life, without = CardanJoint(load_torque=50.0), CardanJoint(False, load_torque=50.0)
    for _ in range(20):
        with_life.step(1e-3)
        without.step(1e-3)
    assert with_life.outputs()[: len(without.outputs())] == without.outputs()
    assert set(with_life.table.OUTPUTS) - set(without.table.OUTPUTS) == {
        "input_bearing_force",
        "output_bearing_force",
        "life_rate",
        "life_consumed",
    }
    assert "life_consumed" not in without.state()


def test_two_torque_zeros_an_ulp_apart_leave_no_panel_of_zero_length():
    """A speed reversal with the bend crossing A_min at both ends of a long step
    at 1000 rad/s puts two torque zeros an ulp apart: the ulp between them is
    taken as it is (it once divided by its zero length)."""
    rule = life_rule(1000.0, 748562516.5098299, 1.6294291263585228, 0.05235987755982989)
    case = (5.0144300866675975 + 4.255872885703014, -0.05235987755982989, 1000.0, -1000.0,
            0.05235987755982989, 0.0, (0.004186995240441173, 0.0036225531104528874,
            4.816940636013518), -50.0)  # fmt: skip
    psi, b, w, a, rb, ab, inertia, load = case
    got = step_damage(rule, 2.0, psi, b, w, a, rb, ab, inertia, load)
    # 318 turns in one step: QUADPACK's own default limits are not 1e-9 there.
    assert got == pytest.approx(damage_quadpack(case, 2.0, rule), rel=2e-2, abs=0.0)


def test_a_joint_without_torque_takes_its_steps_and_consumes_no_life():
    # |T|^p at T = 0 is 0 (its logarithm is never taken): a massless cross, no load.
    joint = CardanJoint(input_speed=100.0, bend_angle=0.3, load_torque=0.0,
                        crosspiece_inertia_1=0.0, crosspiece_inertia_2=0.0,
                        crosspiece_inertia_3=0.0)  # fmt: skip
    for _ in range(5):
        assert joint.step(1e-3) is None
    assert dict(zip(joint.table.OUTPUTS, joint.outputs()))["life_consumed"] == 0.0
