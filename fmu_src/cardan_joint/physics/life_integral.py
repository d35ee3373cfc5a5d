"""The life rate's integral over one step (docs/life.md, "Exact over each step").

The integrand A(t) |w(t)| |T(t)|^p is smooth except at the step's events: the
speed's zero and the bend crossing +-A_min (closed forms) and the torque's
zeros (located as the panels meet them, as exactly as a panel substituted
there needs: `life_zeros`). The step is cut at
each event and every piece between them is covered by Gauss-Legendre panels
(`life_panel`), marching from its start: a panel whose error bound asks for
more points than it has is taken again with them, or cut at the torque's
sign change it shows (`life_zeros`, which keeps the next zero it shows for
later), or halved; a panel inside a plain one that failed, plain or
substituted at a zero, takes the points that one's cubic foresees
(`life_foresight`), as a step's first panel takes the points that the
last step's last plain panel foresees (`ahead`, carried in the step state).
So a piece costs one panel unless it is longer
than the torque's singularities' reach, and each event costs its location
and a few panels more.

The joints of a chain share the march (`step_integrals`): each panel's
nodes serve every joint's integrand, so the chain is evaluated once per node
for all of them (`life_nodes`); a panel is taken when every joint's bound
holds, with the most points any joint asks for, and cut at the first zero of
any joint's torque. A single joint is the case N = 1 (`step_integral`).

Pure Python over floats and tuples, no state; the torques are a module-level
function `torques_at(t, step)` -> (T_1, w_1, ..., T_N, w_N), each joint's
torque and input speed t s into the step.
"""

import math

from .life_foresight import cubics_of, points_foreseen
from .life_nodes import (
    filled,
    panel,
    scales_raised,
    totals_added,
    verdict,
)
from .life_panel import (
    error_budget,
    longest_panel,
    points_for,
    rule_sizing,
    singular_log_rho,
    substitution_power,
)
from .life_zeros import first_zeros
from .quadrature import MAX_POINTS

# Below 1 mrad of bend the torque's singularities are practically out of reach.
FLAT_REACH = math.acosh(1e3)
# Panels tried per step: a step over thousands of turns ends with one panel
# for what is left, less exactly (docs/life.md).
_MAX_ATTEMPTS = 4096
# A panel this short against the step is taken as it is.
_SHORTEST = 1e-13
# A panel that the plain panel about it foresees to need a cut is halved
# before it is taken, down to this share of that panel (`points_foreseen`):
# the foresight reads only a cubic, so it halves no further unseen.
_UNSEEN_HALVING = 0.25


def _first_root_after(t, limit, c0, c1, c2):
    """The smallest root of c0 + c1 x + c2 x^2 in (t, limit), else `limit`."""
    if c2 == 0.0:
        if c1 == 0.0:
            return limit
        first, second = -c0 / c1, limit
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc < 0.0:
            return limit
        q = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
        if q == 0.0:
            first, second = 0.0, limit
        else:
            first, second = q / c2, c0 / q
    if t < first < limit:
        limit = first
    if t < second < limit:
        limit = second
    return limit


def next_kink(t, h, w1, a1, bends, rb, ab, min_angle):
    """The first point after t where an angle or the speed factor has a kink:
    the speed's zero, a bend (`bends[k]` + rb t + ab t^2 / 2) crossing
    +-A_min; else the step's end h."""
    end = _first_root_after(t, h, w1, a1, 0.0)
    for k in range(len(bends)):
        end = _first_root_after(t, end, bends[k] - min_angle, rb, 0.5 * ab)
        end = _first_root_after(t, end, bends[k] + min_angle, rb, 0.5 * ab)
    return end


def singularity_time(w1, a1, h, reach):
    """How far in time the torque's singularities lie from any point of the
    step: |w| tau + |a1| tau^2 / 2 = reach at the fastest speed of the step."""
    fastest = max(abs(w1), abs(w1 + a1 * h))
    acc = abs(a1)
    if acc != 0.0:
        return 2.0 * reach / (fastest + math.sqrt(fastest * fastest + 2.0 * acc * reach))
    if fastest != 0.0:
        return reach / fastest
    return math.inf


def unseen_ahead(bends):
    """`step_integrals`' `ahead` before any step: no panel to foresee from."""
    ahead = (0.0, 0.0)
    for _ in range(len(bends)):
        ahead = ahead + (0.0, 0.0, 0.0, 0.0)
    return ahead


def step_integrals(torques_at, step, h, w1, a1, bends, rb, ab, min_angle, p, reach, ahead):
    """Each joint's integral over a step of `h` s of A_k(t) |w_k(t)|
    |T_k(t)|^p, A_k = max(|b_k(t)|, `min_angle`): the life rate's variable
    part (`life.step_damage` scales it), for the joints of a chain at once;
    then the `ahead` the next step takes.

    `torques_at(t, step)`: (T_1, w_1, ..., T_N, w_N) t s into the step; joint
    k's bend `bends[k]` + rb t + ab t^2 / 2 as the joints step it; w1 + a1 t
    the input speed, which places the speed's zero and, with `reach` (the
    torques' singularities' imaginary input angle, `life.singularity_reach`),
    sizes the panels. `ahead`: (lo, hi, each joint's a_0..a_3) of the last
    plain panel the step before took, in this step's time (`unseen_ahead`
    if none): the first panel's points are foreseen from its cubics, which
    saves taking it twice (a guess: the verdict judges it all the same)."""
    tau = singularity_time(w1, a1, h, reach)
    q = substitution_power(p)
    gamma = q * (p + 1.0) - 1.0
    budget = error_budget(p)
    joints = len(bends)
    # zero_lo, zero_end, zero_later: the joints (one bit each) whose torque's
    # zero is at t, at `end`, at `later` (a zero past `end` that a cut showed,
    # else inf). What each joint's bound is asked against: `scales_raised`.
    totals = filled(bends, 0.0)
    scales = filled(bends, -1.0)
    t, zero_lo = 0.0, 0
    end, zero_end = next_kink(0.0, h, w1, a1, bends, rb, ab, min_angle), 0
    later, zero_later = math.inf, 0
    # The last plain panel that failed, on [guide_lo, guide_hi]: it foresees
    # the points of the plain panels within it; before one fails, the last
    # step's last plain panel (`ahead`, before the step) foresees the first.
    guide = ahead[2:]
    guide_lo, guide_hi = ahead[0], ahead[1]
    # The last plain panel taken, [last_lo, last_hi] (none while equal, or
    # if it took the fewest points): the next step's `ahead`.
    last = ahead[2:]
    last_lo, last_hi = 0.0, 0.0
    length, points, substituted = h, 0, False
    for _ in range(_MAX_ATTEMPTS):
        if t >= h:
            return totals + (last_lo - h, last_hi - h) + last
        hi = t + length
        if hi >= end or end - hi < 0.25 * length:
            hi = end
        zero = 1 if zero_lo != 0 else -1 if zero_end != 0 and hi == end else 0
        if zero_lo != 0 and zero_end != 0 and hi == end:
            # A panel substitutes at one end only; two zeros an ulp apart leave
            # no middle: the ulp between them is taken plainly (its share is nil).
            middle = 0.5 * (t + end)
            hi, zero = (middle, 1) if middle > t else (end, 0)
        divides = zero_lo if zero > 0 else zero_end if zero < 0 else 0
        weighted, stretch, degree, sized = rule_sizing(zero, divides, joints, q, gamma, budget)
        longest = longest_panel(tau, sized, degree, stretch)
        # Before a zero the substituted panel takes its longest against it and
        # plain panels the rest: a plain panel ending next to the zero would see
        # it within its ellipse and ask for many points. (A panel that starts
        # where the rest ended may exceed the longest by a rounding.)
        if hi - t > longest and not (zero < 0 and end - longest <= t):
            hi = end - longest if zero < 0 else t + longest
            zero = 1 if zero_lo != 0 else 0
            divides = zero_lo if zero > 0 else 0
            weighted, stretch, degree, sized = rule_sizing(zero, divides, joints, q, gamma, budget)
            hi = min(hi, t + longest_panel(tau, sized, degree, stretch))
        singular = singular_log_rho(hi - t, tau, stretch)
        # A substituted panel's points carry the substitution's: a plain one's
        # are not like them, nor the other way round.
        least = points_for(singular, sized, degree)
        n = max(points if (zero != 0) == substituted else 0, least)
        # A panel inside the last plain panel that failed is foreseen from it,
        # plain or substituted at a zero: next to a zero, another joint's zero
        # near it asks a substituted panel for more points or a halving.
        carried = q - 1.0 if zero != 0 else 0.0
        inside = guide_lo <= t and hi <= guide_hi
        if inside or (t == 0.0 and zero == 0 and guide_lo < guide_hi <= 0.0):
            foreseen = points_foreseen(guide, guide_lo, guide_hi, t, hi, zero, q, divides, n,
                                       singular, sized, degree, carried)  # fmt: skip
            # Halved unseen only inside: the last step's cubic, extrapolated,
            # foresees a cut less well than a halving costs.
            if (
                inside
                and foreseen > MAX_POINTS
                and hi - t >= _UNSEEN_HALVING * (guide_hi - guide_lo)
            ):
                length = 0.5 * (hi - t)
                continue
            if foreseen <= MAX_POINTS:
                n = max(n, foreseen)
        n = min(n, MAX_POINTS)
        values = panel(torques_at, step, t, hi, zero, divides, q, n, weighted, bends, rb, ab,
                       min_angle, p)  # fmt: skip
        scales = scales_raised(scales, totals, values)
        failing, wanted = verdict(values, scales, n, sized, degree, carried, singular, divides)
        if failing == 0 or hi - t <= _SHORTEST * h:
            totals = totals_added(totals, values)
            if zero == 0 and n > least:
                last = cubics_of(values)
                last_lo, last_hi = t, hi
            elif zero == 0:
                # Its torque's zeros asked for no more points than the
                # singularities: the next step foresees nothing, and spares
                # the foresight's cost.
                last_lo, last_hi = 0.0, 0.0
            # The next panel starts from this one's points and twice its
            # length: a piece's panels are alike.
            length = 2.0 * (hi - t)
            t, zero_lo = hi, divides if zero < 0 else 0
            if t == end:  # a new piece: its panels start from the longest again
                end, zero_end = next_kink(t, h, w1, a1, bends, rb, ab, min_angle), 0
                if later < end:
                    end, zero_end, later, zero_later = later, zero_later, math.inf, 0
                length, points = h, 0
            continue
        if zero == 0:
            guide = cubics_of(values)
            guide_lo, guide_hi = t, hi
        if wanted != 0:
            length, points, substituted = hi - t, wanted, zero != 0
            continue
        root, zeros, second, others, starting = first_zeros(
            torques_at, step, values, failing, t, hi, zero, divides, q, n, weighted
        )
        if (zero_lo | starting) != zero_lo:
            # A torque that vanishes where the panel starts (a step from rest
            # at a dead centre): its zero is t, where the panel substitutes.
            zero_lo = zero_lo | starting
        elif root <= hi:
            # The next zero the panel showed stays known: no panel need show it again.
            if second < later:
                later, zero_later = second, others
            end, zero_end = root, zeros
        else:
            length = 0.5 * (hi - t)
    # A step over thousands of turns: what is left in one panel, less exactly.
    if t < h:
        totals = totals_added(
            totals,
            panel(torques_at, step, t, h, 0, 0, q, MAX_POINTS, False, bends, rb, ab, min_angle, p),
        )
    return totals + (last_lo - h, last_hi - h) + last


def step_integral(torque_at, step, h, w1, a1, b, rb, ab, min_angle, p, reach):
    """The integral over a step of `h` s of A(t) |w(t)| |T(t)|^p, A = max(|b(t)|,
    `min_angle`) for one joint: `step_integrals` with N = 1, `torque_at(t,
    step)` giving (T, w) t s into the step; the bend b + rb t + ab t^2 / 2."""
    ahead = unseen_ahead((b,))
    return step_integrals(torque_at, step, h, w1, a1, (b,), rb, ab, min_angle, p, reach, ahead)[0]
