"""Speed-ratio fluctuation of a propshaft, its equivalent single-joint angle,
and the yoke phasing that minimizes it.

At constant input speed omega_0 = 1 the chain gives the ratio r = omega_N/omega_0
as the output speed and dr/dgamma_0 as the output acceleration, both in closed
form. Every joint's ratio has period pi in its pin angle, and gamma_k(gamma_0 +
pi) = gamma_k(gamma_0) + pi, so r has period pi: one half revolution holds
every extremum. The extrema are the sign changes of dr/dgamma_0, bracketed on a
fine grid and bisected to 6e-12 rad; r is stationary there, so its error is
quadratic in the root's (~1e-22): exact to rounding.
"""

import math

from .chain import chain
from .geometry import Layout, plane_angle, wrapped

_GRID = 512  # samples per half revolution; extrema closer than pi/512 merge
_BISECTIONS = 30  # bracket pi/512 / 2**30 = 6e-12 rad
_SEARCH_GRID = 24  # phasings per shaft in the multi-joint search, over [0, pi)
_SEARCH_SAMPLES = 64  # input angles per half revolution in that search


def ratio_and_slope(geometry: Layout, angle):
    """(omega_N/omega_0, its derivative in gamma_0) at input angle(s) `angle`."""
    state = chain(geometry, angle, 1.0, 0.0)
    return state.speeds[-1], state.accelerations[-1]


def speed_ratio_extrema(geometry: Layout):
    """(min, max) of omega_N/omega_0 over one input revolution at constant input speed.

    Plain floats: the FMU evaluates this (once per layout) on the standard library
    alone, and a loop over the 513 samples costs no more than numpy's arrays here."""
    step = math.pi / _GRID
    grid = [k * step for k in range(_GRID)] + [math.pi]
    samples = [ratio_and_slope(geometry, angle) for angle in grid]
    values = [ratio for ratio, _ in samples]
    for k in range(_GRID):
        low_slope, high_slope = samples[k][1], samples[k + 1][1]
        if _sign(low_slope) * _sign(high_slope) < 0:
            low, high = grid[k], grid[k + 1]
            for _ in range(_BISECTIONS):
                middle = 0.5 * (low + high)
                if _sign(ratio_and_slope(geometry, middle)[1]) == _sign(low_slope):
                    low = middle
                else:
                    high = middle
            values.append(ratio_and_slope(geometry, 0.5 * (low + high))[0])
    return min(values), max(values)


def _sign(value: float) -> int:
    return (value > 0.0) - (value < 0.0)


def speed_ratio_fluctuation(geometry: Layout) -> float:
    """max - min of omega_N/omega_0 over one input revolution at constant input speed."""
    low, high = speed_ratio_extrema(geometry)
    return high - low


def equivalent_angle(fluctuation: float) -> float:
    """The single-joint angle beta whose fluctuation tan(beta) sin(beta) equals
    `fluctuation`: sin^2 b / cos b = f gives cos b = 2 / (f + sqrt(f^2 + 4)), and
    sin b = sqrt(f cos b) keeps full precision at small f."""
    if not fluctuation > 0.0:
        return 0.0
    cosine = 2.0 / (fluctuation + math.sqrt(fluctuation * fluctuation + 4.0))
    return math.atan2(math.sqrt(fluctuation * cosine), cosine)


def best_phasing(geometry: Layout, rounds: int = 2):
    """(phasings phi_1..phi_{N-1}, the fluctuation they leave).

    Two joints: phi = the signed angle between the joint planes about the
    intermediate shaft, modulo pi (to [0, pi)): the second joint's pin then sits
    where it undoes the first (Fischer & Paul's zero "relative phase angle"),
    exact cancellation for equal working angles, the least residual otherwise
    (tests check it against a brute-force search). More joints: no closed form;
    every combination of 24 phasings per shaft is scored at once on a coarse
    sample of the ratio, and the best is refined one phasing at a time by golden
    section on the exact fluctuation, `rounds` times.
    """
    count = len(geometry.phases)
    if count == 1:
        phase = wrapped(plane_angle(geometry, 1)) % math.pi
        best = geometry.with_phases((phase,))
        return best.phases, speed_ratio_fluctuation(best)
    phases = list(_coarse_search(geometry, count))
    for _ in range(rounds):
        for k in range(count):
            phases[k] = _best_single(geometry, phases, k)
    best = geometry.with_phases(phases)
    return best.phases, speed_ratio_fluctuation(best)


def _coarse_search(geometry, count):
    """The best grid point of the phasings, scored by max - min of the ratio on a
    coarse sample (one vectorized chain over every combination: numpy, imported
    here because this design search never runs inside an FMU)."""
    import numpy as np

    values = np.arange(_SEARCH_GRID) * (math.pi / _SEARCH_GRID)
    combos = np.stack(np.meshgrid(*([values] * count), indexing="ij"), -1).reshape(-1, count)
    angles = np.linspace(0.0, math.pi, _SEARCH_SAMPLES, endpoint=False)[None, :]
    trial = geometry._replace(phases=tuple(combos[:, [k]] for k in range(count)))
    ratio = ratio_and_slope(trial, angles + np.zeros((len(combos), 1)))[0]
    spread = ratio.max(axis=1) - ratio.min(axis=1)
    return tuple(float(v) for v in combos[int(np.argmin(spread))])


def _best_single(geometry, phases, k, iterations=40):
    def cost(value):
        trial = list(phases)
        trial[k] = value
        return speed_ratio_fluctuation(geometry.with_phases(trial))

    step = math.pi / _SEARCH_GRID
    low, high = phases[k] - step, phases[k] + step
    golden = (math.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = high - golden * (high - low), low + golden * (high - low)
    f1, f2 = cost(x1), cost(x2)
    for _ in range(iterations):
        if f1 < f2:
            high, x2, f2 = x2, x1, f1
            x1 = high - golden * (high - low)
            f1 = cost(x1)
        else:
            low, x1, f1 = x1, x2, f2
            x2 = low + golden * (high - low)
            f2 = cost(x2)
    candidates = [(cost(phases[k]), phases[k]), (f1, x1), (f2, x2)]
    return min(candidates)[1] % math.pi
