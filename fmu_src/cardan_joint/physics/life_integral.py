"""The life rate's integral over any step (docs/life.md, "Exact over each step").

Split where the rate has kinks (the speed's zero, the bend crossing +-A_min,
the torque's sign changes, found from the sampled nodes and located to the
last bits), each piece integrated by Gauss-Lobatto panels whose number and
order follow from how far the torque's singularities lie from the step in
time; next to a torque zero a panel substitutes t = t0 + L u^q, which makes
|T|^p smooth. `life.step_damage` sends here the steps its one-panel rule
cannot take. Pure Python, standard library only.
"""

import math

from .quadrature import lobatto_rule, panel_nodes

# Relative accuracy each panel is sized for (the contract asks 1e-9 per step).
_TARGET_DIGITS = 13.0 * math.log(10.0)
_MAX_NODES = 9
# The inertia's torque changes sign about twice a turn: panels short enough
# (in imaginary input angle) that their nodes see each sign change.
_INERTIA_REACH = 0.5
# A step over thousands of turns (far beyond any co-simulation step) is
# integrated with this many panels at most, then less exactly (docs/life.md).
_MAX_PANELS = 1024
_MAX_ZEROS = 256
# Substitution t = a + L u^q at a torque zero: |T|^p ~ |t - a|^p becomes
# u^(q (p + 1) - 1), smooth enough for the panel's rule with `_ZERO_NODES` more
# nodes than the smooth part asks (the power is no polynomial: 3.9e-9 relative
# without them in a compliant joint's step whose spring torque crosses zero;
# tests/unit/test_compliant_life.py).
_SMOOTH_POWER = 8.0
_ZERO_NODES = 4
# Below 1 mrad of bend the torque's singularities are practically out of reach.
FLAT_REACH = math.acosh(1e3)


def _roots_in(c0, c1, c2, h):
    """Roots of c0 + c1 t + c2 t^2 strictly inside (0, h)."""
    if c2 == 0.0:
        roots = (-c0 / c1,) if c1 else ()
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc < 0.0:
            return ()
        q = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
        roots = (q / c2, c0 / q) if q else (0.0,)
    return tuple(t for t in roots if 0.0 < t < h)


def _kinks(h, w1, a1, b, rb, ab, min_angle):
    """Where the rate is not smooth: the speed's zero and the bend crossing +-A_min."""
    points = {0.0, h}
    if a1:
        points.update(_roots_in(w1, a1, 0.0, h))
    for level in (min_angle, -min_angle):
        points.update(_roots_in(b - level, rb, 0.5 * ab, h))
    return sorted(points)


def _nodes_for(a, b, w1, a1, reach):
    """(panels, Lobatto points) for [a, b] (no speed reversal inside): the torque's
    singularities lie `reach` away in imaginary input angle, so `tau` s away in
    time where the speed is highest (|w| tau + |a1| tau^2 / 2 = reach); the
    Bernstein-ellipse bound then gives the points for 1e-12."""
    fastest = max(abs(w1 + a1 * a), abs(w1 + a1 * b))
    acc = abs(a1)
    if acc:
        tau = 2.0 * reach / (fastest + math.sqrt(fastest * fastest + 2.0 * acc * reach))
    else:
        tau = reach / fastest if fastest else math.inf
    panels = 1
    while True:
        ratio = 0.5 * (b - a) / (panels * tau)
        # log(rho), rho = 1/ratio + sqrt(1/ratio^2 + 1) the ellipse's parameter.
        log_rho = math.asinh(1.0 / ratio) if ratio else math.inf
        points = 2 + math.ceil(0.5 * _TARGET_DIGITS / log_rho) if log_rho < math.inf else 3
        if points <= _MAX_NODES or panels >= _MAX_PANELS:
            return panels, min(max(points, 3), _MAX_NODES)
        panels *= 2


class _Integrand:
    """rate(t) / scale: A(t) |w(t)| |T(t)|^p over one step."""

    def __init__(self, torque_at, w1, a1, b, rb, ab, min_angle, exponent, speed_at=None):
        self.torque_at = torque_at
        self.w1, self.a1, self.b, self.rb, self.ab = w1, a1, b, rb, ab
        self.min_angle, self.p = min_angle, exponent
        self.speed = speed_at or (lambda t: w1 + a1 * t)

    def parts(self, t):
        torque = self.torque_at(t)
        angle = max(abs(self.b + t * (self.rb + 0.5 * self.ab * t)), self.min_angle)
        return torque, angle * abs(self.speed(t)) * abs(torque) ** self.p


def _root(torque_at, a, b, fa, fb):
    """A sign change of the torque in (a, b), to the last bits (Illinois)."""
    for _ in range(200):
        if b - a <= 4e-16 * max(abs(a), abs(b)) or fa == 0.0 or fb == 0.0:
            break
        m = (a * fb - b * fa) / (fb - fa)
        if not a < m < b:
            m = 0.5 * (a + b)
        fm = torque_at(m)
        if (fm < 0.0) == (fa < 0.0):
            a, fa = m, fm
            fb *= 0.5
        else:
            b, fb = m, fm
            fa *= 0.5
    return b if abs(fb) < abs(fa) else a


def _panel(f, a, b, points, zero_at):
    """The rule on [a, b], substituted at an end where the torque vanishes."""
    length = b - a
    if zero_at is None:
        nodes, weights = lobatto_rule(points)
        return 0.5 * length * sum(w * f.parts(t)[1] for t, w in panel_nodes(nodes, weights, a, b))
    nodes, weights = lobatto_rule(points + _ZERO_NODES)
    q = max(2.0, math.ceil(_SMOOTH_POWER / (f.p + 1.0)))
    total = 0.0
    for x, w in zip(nodes, weights):
        u = 0.5 * (x + 1.0)
        if u == 0.0:
            continue
        t = zero_at + math.copysign(length * u**q, (b + a) - 2.0 * zero_at)
        total += w * q * u ** (q - 1.0) * f.parts(t)[1]
    return 0.5 * length * total


def _from_samples(f, times, values, panels, points, width):
    """Lobatto panels summed from the torque already sampled at their nodes
    (panel ends shared), so a step without a torque zero evaluates it once per node."""
    _, weights = lobatto_rule(points)
    per, last = points - 1, len(times) - 1
    total = 0.0
    for i, (t, torque) in enumerate(zip(times, values)):
        k = i % per
        w = weights[k] if i and i != last else weights[0]
        if k == 0 and 0 < i < last:
            w = weights[0] + weights[-1]
        angle = max(abs(f.b + t * (f.rb + 0.5 * f.ab * t)), f.min_angle)
        total += w * angle * abs(f.speed(t)) * abs(torque) ** f.p
    return 0.5 * width * total


def _segment(f, a, b, reach, massless):
    """The integral over [a, b], a stretch without kinks of the angle and speed:
    the torque's sign changes located first (each panel's nodes seen), then
    the stretches between them integrated."""
    cuts = [a, b]
    if not massless:  # T = T_L cos b / D keeps its sign: no zero to find
        panels, points = _nodes_for(a, b, f.w1, f.a1, reach)
        nodes, _ = lobatto_rule(points)
        times, values = [a], [f.torque_at(a)]
        for k in range(panels):
            lo, hi = a + (b - a) * k / panels, a + (b - a) * (k + 1) / panels
            for t, _ in panel_nodes(nodes, nodes, lo, hi)[1:]:
                times.append(t)
                values.append(f.torque_at(t))
        times[-1] = b
        changes = [
            (t0, t1, v0, v1)
            for t0, t1, v0, v1 in zip(times, times[1:], values, values[1:])
            if (v0 < 0.0) != (v1 < 0.0) and v0 and v1
        ]
        # No sign change, or more than a step of any co-simulation meets (a step
        # over thousands of turns): the sampled torques are the rule's nodes.
        if not changes or len(changes) > _MAX_ZEROS:
            return _from_samples(f, times, values, panels, points, (b - a) / panels)
        cuts += [_root(f.torque_at, *change) for change in changes]
        cuts.sort()
    total = 0.0
    for k, (lo, hi) in enumerate(zip(cuts, cuts[1:])):
        zero_lo, zero_hi = k > 0, k < len(cuts) - 2
        # The substitution at a zero halves the smooth part's reach in u.
        near = reach * 0.5 if zero_lo or zero_hi else reach
        panels, points = _nodes_for(lo, hi, f.w1, f.a1, near)
        edges = [lo + (hi - lo) * j / panels for j in range(panels)] + [hi]
        for j, (x0, x1) in enumerate(zip(edges, edges[1:])):
            first, last = j == 0 and zero_lo, j == panels - 1 and zero_hi
            if first and last:
                mid = 0.5 * (x0 + x1)
                total += _panel(f, x0, mid, points, x0) + _panel(f, mid, x1, points, x1)
            else:
                total += _panel(f, x0, x1, points, x0 if first else x1 if last else None)
    return total


def life_increment(
    torque_at, h, w1, a1, b, rb, ab, inertia, min_angle, exponent, speed_at=None, peak=0.0
) -> float:
    """The integral over a step of `h` s of A(t) |w(t)| |T(t)|^p, A = max(|b(t)|,
    `min_angle`): the life rate's variable part (`life.step_damage` scales it).

    `torque_at(t)`: T t s into the step (`life_torque.torque_over_step`); the
    bend b + rb t + ab t^2 / 2 as the joint steps it; the speed w1 + a1 t, or
    `speed_at(t)` for a joint behind others (a propshaft's: its sign is the
    input's, w1 + a1 t still sizes the panels). `peak`: a larger bend whose
    singularities the torque also has (a propshaft's other joints); `inertia`:
    every inertia that can turn the torque over (all zero: T keeps its sign)."""
    f = _Integrand(torque_at, w1, a1, b, rb, ab, min_angle, exponent, speed_at)
    peak = max(peak, abs(b), abs(b + h * (rb + 0.5 * ab * h)))
    if ab and 0.0 < -rb / ab < h:
        peak = max(peak, abs(b - 0.5 * rb * rb / ab))
    # D = 0 at cos(psi) = +-1 / sin(b): an imaginary input angle acosh(1/|sin b|) away.
    reach = math.acosh(1.0 / math.sin(peak)) if peak > 1e-3 else FLAT_REACH
    massless = not any(inertia)
    if not massless:
        # The inertia's torque changes sign about twice a turn: panels short
        # enough that their nodes see each sign change.
        reach = min(reach, _INERTIA_REACH)
    cuts = _kinks(h, w1, a1, b, rb, ab, min_angle)
    return sum(_segment(f, lo, hi, reach, massless) for lo, hi in zip(cuts, cuts[1:]))
