"""The life integral's march spends its evaluations on the panels it takes
(docs/life.md, "Exact over each step"): a zero's search starts from the
torques its panel already has, a zero a panel shows is located once, and a
plain panel inside one that failed is sized from that one's cubic."""

import math
import random

import mpmath
from life_reference import chain_evaluations

from cardan_joint.models.compliant_propshaft.model import CompliantPropshaft
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.physics import life_foresight, life_integral, life_torque, life_zeros
from cardan_joint.physics.life_nodes import COEFFICIENTS, PANEL_FIELDS, panel
from cardan_joint.physics.life_panel import (
    error_budget,
    node_time,
    points_for,
    substitution_power,
    zero_free_log_rho,
)
from cardan_joint.physics.quadrature import GAUSS_NODES, JACOBI_NODES

P = 10.0 / 3.0


def _linear_joints(t, step):
    """Two joints whose torques t - step[k] change sign at step[k], speed 1."""
    return (t - step[0], 1.0, t - step[1], 1.0)


def _legendre(k, x):
    return (1.0, x, 1.5 * x * x - 0.5, (2.5 * x * x - 1.5) * x)[k]


def _composed_reference(cubic, origin, stretch, power, divided):
    """a_0..a_3 on u in [0, 1] of the cubic at x = origin + stretch u^power
    (over u^power if `divided`: the cubic less its value at origin, over x -
    origin, times stretch, by its Taylor terms about origin), by mpmath's
    quadrature at 30 digits."""

    def series(x):
        return sum(cubic[k] * mpmath.legendre(k, x) for k in range(4))

    taylor = mpmath.taylor(series, origin, 3)

    def composed(u):
        y = stretch * u ** int(power)
        if not divided:
            return series(origin + y)
        return stretch * (taylor[1] + y * (taylor[2] + y * taylor[3]))

    def projected(k):
        integral = mpmath.quad(lambda u: mpmath.legendre(k, 2 * u - 1) * composed(u), [0, 1])
        return (2 * k + 1) * float(integral)

    with mpmath.workdps(30):
        return tuple(projected(k) for k in range(4))


def test_a_cubic_composed_with_a_panels_map_has_its_own_legendre_coefficients():
    # A part of the panel (power 1), or one substituted at a zero inside it
    # (power q), and over u^q where the zero is the joint's.
    rng = random.Random(5)
    for _ in range(10):
        cubic = tuple(rng.uniform(-2.0, 2.0) for _ in range(4))
        origin = rng.uniform(-1.0, 1.0)
        stretch = rng.choice((-1.0, 1.0)) * rng.uniform(1e-3, 1.0)
        for power in (1.0, 2.0, 3.0, 6.0):
            for divided in (False, True):
                found = life_foresight._composed(cubic, origin, stretch, power, divided)
                expected = _composed_reference(cubic, origin, stretch, power, divided)
                for k in range(4):
                    assert math.isclose(found[k], expected[k], abs_tol=1e-13)


def test_a_panel_is_foreseen_from_the_plain_panel_about_it():
    # Linear torques are their cubics: the coefficients a panel inside the
    # plain one foresees are those its own values give, plain or substituted
    # at either end (divided by u^q where the zero is the joint's), to the
    # rounding that dividing by u^q next to the zero magnifies.
    zeros, q = (0.3, 0.6), substitution_power(P)
    guide = panel(_linear_joints, zeros, 0.0, 1.0, 0, 0, q, 8, False, (0.3, 0.3), 0.0, 0.0, 0.05,
                  P)  # fmt: skip
    for lo, hi, zero, divides in ((0.3, 0.6, 1, 1), (0.3, 0.6, -1, 2), (0.1, 0.45, 0, 0)):
        taken = panel(_linear_joints, zeros, lo, hi, zero, divides, q, 12, False, (0.3, 0.3), 0.0,
                      0.0, 0.05, P)  # fmt: skip
        foreseen = life_foresight.cubics_foreseen(
            life_foresight.cubics_of(guide), 0.0, 1.0, lo, hi, zero, q, divides
        )
        for k in range(2):
            own = taken[PANEL_FIELDS * k + COEFFICIENTS : PANEL_FIELDS * k + COEFFICIENTS + 4]
            for a, b in zip(foreseen[4 * k : 4 * k + 4], own):
                assert math.isclose(a, b, abs_tol=1e-10)


def test_a_joint_zero_free_where_the_panels_points_need_asks_no_more():
    # The foresight checks each joint's cubic on the ellipse its points need
    # before it solves for the cubic's own reach: the same points as solving
    # for every joint (points_for of the nearer of the singularities and the
    # zeros, a divided joint's taken shorter), at least the panel's.
    rng = random.Random(11)
    budget = error_budget(P)
    for _ in range(2000):
        guide = ()
        for _ in range(2):
            a0 = rng.choice((-1.0, 1.0)) * rng.uniform(0.1, 2.0)
            spread = tuple(
                rng.uniform(-1.0, 1.0) * abs(a0) * rng.choice((0.01, 0.2, 0.6)) for _ in range(3)
            )
            guide = guide + (a0,) + spread
        lo = rng.uniform(0.0, 0.5)
        hi = rng.uniform(lo + 0.01, 1.0)
        zero, divides = rng.choice(((0, 0), (1, 1), (-1, 2)))
        degree, carried = (0.0, 0.0) if zero == 0 else (12.0, 2.0)
        singular = rng.uniform(0.3, 4.0)
        # At least what the singularities ask, as the march sizes it (or what a
        # failed panel asked for).
        points = max(points_for(singular, budget, degree), rng.randint(4, 20))
        found = life_foresight.points_foreseen(guide, 0.0, 1.0, lo, hi, zero, 3.0, divides, points,
                                               singular, budget, degree, carried)  # fmt: skip
        cubics = life_foresight.cubics_foreseen(guide, 0.0, 1.0, lo, hi, zero, 3.0, divides)
        wanted = points
        for k in range(2):
            low = zero_free_log_rho(cubics[4 * k : 4 * k + 4] + (0.0,), 20, False)[0]
            power = degree if k == divides - 1 else carried
            if k == divides - 1:
                low *= life_foresight._DIVIDED_REACH
            wanted = max(wanted, points_for(min(singular, low), budget, power))
        assert found == wanted


def test_a_panel_keeps_the_torques_a_zeros_search_starts_from():
    # Joint 0 changes sign between two nodes: their torques; joint 1 does not
    # in the panel: its first and last nodes' torques.
    points, lo, hi = 7, 0.0, 1.0
    values = panel(_linear_joints, (0.4, 2.0), lo, hi, 0, 0, 3.0, points, False, (0.3, 0.3),
                   0.0, 0.0, 0.05, P)  # fmt: skip
    nodes = GAUSS_NODES[points]
    change = values[1]
    assert nodes[change - 1] < 0.4 < nodes[change]
    assert values[2:4] == (nodes[change - 1] - 0.4, nodes[change] - 0.4)
    joint = values[PANEL_FIELDS : 2 * PANEL_FIELDS]
    assert joint[1] == 0
    assert joint[2:4] == (nodes[0] - 2.0, nodes[-1] - 2.0)
    assert len(joint[COEFFICIENTS:]) == 5


def _vanishing_joint(t, step):
    """One joint whose torque t (t - step) vanishes at 0 and changes sign at step."""
    return (t * (t - step), 1.0)


def test_a_weighted_panels_zero_is_searched_between_its_own_nodes():
    # A Gauss-Jacobi panel substituted at the joint's zero at 0 shows the sign
    # change at 0.45 between two of its nodes: the torques it keeps are those
    # at its own nodes, and the search brackets the zero between them (at
    # Gauss-Legendre's nodes the bracket would miss it).
    points, q = 8, substitution_power(P)
    values = panel(_vanishing_joint, 0.45, 0.0, 1.0, 1, 1, q, points, True, (0.3,), 0.0, 0.0,
                   0.05, P)  # fmt: skip
    times = [node_time(0.0, 1.0, u, 1, q) for u in JACOBI_NODES[points]]
    change = values[1]
    assert times[change - 1] < 0.45 < times[change]
    gauss = [node_time(0.0, 1.0, u, 1, q) for u in GAUSS_NODES[points]]
    assert not gauss[change - 1] < 0.45 < gauss[change]
    assert values[2:4] == (_vanishing_joint(times[change - 1], 0.45)[0],
                           _vanishing_joint(times[change], 0.45)[0])  # fmt: skip
    root, joints, second, _, starting = life_zeros.first_zeros(
        _vanishing_joint, 0.45, values, 1, 0.0, 1.0, 1, 1, q, points, True
    )
    assert math.isclose(root, 0.45, rel_tol=1e-15) and joints == 1 and second == math.inf
    assert starting == 0


def test_each_zero_a_panel_shows_is_located_once_and_the_integral_is_exact(monkeypatch):
    # Both joints' zeros show in the first panel: the march cuts at the first
    # and keeps the second, which no later panel locates again. The integral
    # of 0.3 |t - z|^p over [0, 1] is closed.
    located = []
    root = life_zeros._root

    def counted(torques_at, step, joint, a, b, fa, fb):
        located.append(joint)
        return root(torques_at, step, joint, a, b, fa, fb)

    monkeypatch.setattr(life_zeros, "_root", counted)
    zeros = (0.3, 0.8)
    bends = (0.3, 0.3)
    totals = life_integral.step_integrals(
        _linear_joints, zeros, 1.0, 1.0, 0.0, bends, 0.0, 0.0, 0.05, P, 1e6,
        life_integral.unseen_ahead(bends),
    )  # fmt: skip
    assert sorted(located) == [0, 1]
    for total, zero in zip(totals[:2], zeros):
        exact = 0.3 * (zero ** (P + 1.0) + (1.0 - zero) ** (P + 1.0)) / (P + 1.0)
        assert math.isclose(total, exact, rel_tol=1e-12)


def test_a_step_carries_its_last_plain_panel_to_foresee_the_next_step():
    # Torques t - z without a zero in the step: plain panels to its end. What
    # it carries ahead (the last plain panel's place, in the next step's time,
    # and its cubics) foresees the next step's torques, t + 1 - z on [0, 1]:
    # a_0 = 1.5 - z, a_1 = 0.5 (linear torques are their cubics).
    zeros, bends = (-0.1, 1.2), (0.3, 0.3)
    found = life_integral.step_integrals(
        _linear_joints, zeros, 1.0, 1.0, 0.0, bends, 0.0, 0.0, 0.05, P, 1e6,
        life_integral.unseen_ahead(bends),
    )  # fmt: skip
    ahead = found[2:]
    assert ahead[0] < ahead[1] == 0.0
    foreseen = life_foresight.cubics_foreseen(ahead[2:], ahead[0], ahead[1], 0.0, 1.0, 0, 3.0, 0)
    for k, zero in enumerate(zeros):
        expected = (1.5 - zero, 0.5, 0.0, 0.0)
        for a, b in zip(foreseen[4 * k : 4 * k + 4], expected):
            assert math.isclose(a, b, abs_tol=1e-12)


def _bump_first(t, step):
    """A torque whose zeros lie near t = 0.1 only, speed 1 - t / 0.9."""
    return (1.0 + 0.5 * math.exp(-(((t - 0.1) / 0.03) ** 2)), 1.0 - t / 0.9)


def test_a_step_whose_last_plain_panel_took_the_fewest_points_carries_nothing():
    # The first piece (to the speed's zero at 0.9) needs many points about the
    # bump; the second takes the fewest: an earlier panel carried ahead would
    # make the next step pay for foresight that foresees nothing.
    bends = (0.3,)
    found = life_integral.step_integrals(
        _bump_first, (), 1.0, 1.0, -1.0 / 0.9, bends, 0.0, 0.0, 0.05, P, 1e6,
        life_integral.unseen_ahead(bends),
    )  # fmt: skip
    assert found[1] == found[2]


def _evaluations(steps):
    """Torque evaluations per 1 ms step at 1000 rad/s (the benchmarks' point)."""
    calls = []
    original = life_torque.input_torque

    def counted(*args):
        calls.append(None)
        return original(*args)

    life_torque.input_torque = counted
    try:
        joint = CardanJoint(input_speed=1000.0, input_acceleration=5.0, bend_angle=0.3,
                            bend_angle_rate=0.01, load_torque=50.0)  # fmt: skip
        for _ in range(steps):
            assert joint.step(1e-3) is None
    finally:
        life_torque.input_torque = original
    return len(calls) / steps


def test_the_march_at_1000_rad_per_s_spends_few_evaluations_besides_its_panels():
    # A zero about every other step: 79 evaluations a step before the march
    # kept its panels' torques and zeros and sized panels from the failed one
    # about them; 58.7 before it foresaw the panels substituted at a zero
    # (56.4), 54.0 with the divided torque's reach foreseen shorter; the
    # accepted panels alone take about 48.
    assert _evaluations(300) < 55.0


def test_the_compliant_propshaft_without_a_mean_torque_spends_few_evaluations(monkeypatch):
    # The output shaft turns with the input: the spring carries no mean torque
    # and the joints' torques cross zero every few steps. 27.4 evaluations a
    # step before, up to 353 in one; 25.2, up to 293, with a substituted
    # panel's points carried into the plain panels after it; 24.2, up to 199,
    # before the panels substituted at one joint's zero were foreseen (20.2,
    # up to 157): the other joint's zero, near, asked them for more points
    # or a halving once taken; 16.7, up to 141, with the bound exact where
    # it was loose and zeros located as exactly as their panels need; 13.9
    # (13.4 over 2,000 steps), up to 141, with each step's first panel
    # foreseen from the last step's last plain panel (before, a 4-point
    # probe failed on most steps and was taken again with 5 to 9 points).
    calls = chain_evaluations(monkeypatch)
    # As a host steps it: each 1 ms step from the same inputs.
    drive = CompliantPropshaft(2)
    counts = []
    for _ in range(300):
        calls.clear()
        drive.run(drive.time, 1e-3, (100.0, 5.0, 100.0, 5.0))
        counts.append(len(calls))
    assert sum(counts) / len(counts) < 15.0
    assert max(counts) < 150
