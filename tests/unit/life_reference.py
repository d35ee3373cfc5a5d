"""An independent reference for the life integral: the catalogue rate from the
joint's full response kernel at each instant, integrated between kinks found
by dense sampling and scipy's brentq by mpmath's adaptive tanh-sinh quadrature
(`damage`) or QUADPACK's adaptive Gauss-Kronrod (`damage_quadpack`, faster: the
random searches). Not the FMU's panels, error bound, root finder or torque."""

import math

import mpmath
import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

from cardan_joint.models.propshaft import chain
from cardan_joint.physics.response import JointResponse, joint_response

_T1 = JointResponse._fields.index("input_torque")


def random_fast_step(rng):
    """(a joint's start values, a step size): 200-1000 rad/s either way, a
    massive cross, a load of either sign, the bend and speed ramped."""

    def signed(low, high):
        return rng.choice((-1.0, 1.0)) * rng.uniform(low, high)

    return dict(
        input_angle_start=rng.uniform(-4.0, 4.0),
        input_speed=signed(200.0, 1000.0),
        input_acceleration=rng.uniform(-2e3, 2e3),
        bend_angle=signed(0.02, 0.9),
        bend_angle_rate=rng.uniform(-2.0, 2.0),
        bend_angle_acceleration=rng.uniform(-50.0, 50.0),
        crosspiece_inertia_1=rng.uniform(0.01, 0.1),
        crosspiece_inertia_2=rng.uniform(0.01, 0.1),
        crosspiece_inertia_3=rng.uniform(0.01, 0.1),
        load_torque=signed(10.0, 2000.0),
    ), 10.0 ** rng.uniform(-4.5, -2.5)


def case_of(joint):
    """A joint's inputs now as the reference takes them (its public attributes)."""
    psi = joint.input_angle + joint.yoke_phase
    inertia = tuple(getattr(joint, f"crosspiece_inertia_{k}") for k in (1, 2, 3))
    bend = (joint.bend_angle, joint.bend_angle_rate, joint.bend_angle_acceleration)
    speed, acceleration = joint.input_speed, joint.input_acceleration
    return (psi, bend[0], speed, acceleration, bend[1], bend[2], inertia, joint.load_torque)


def torque(t, case):
    """T1 at t; the case's load a number, or a function of t (a spring's torque)."""
    psi, b, w, a, rb, ab, inertia, load = case
    if callable(load):
        load = load(t)
    return float(
        joint_response(
            psi + w * t + 0.5 * a * t * t,
            b + rb * t + 0.5 * ab * t * t,
            w + a * t,
            a,
            rb + ab * t,
            ab,
            inertia,
            load,
        )[_T1]
    )


def rate(t, case, rule):
    """1/L_h at t, straight from the catalogue formula (degrees, rpm)."""
    psi, b, w, a, rb, ab, inertia, load = case
    angle_deg = max(abs(b + rb * t + 0.5 * ab * t * t), rule.min_angle) * 180.0 / math.pi
    rpm = abs(w + a * t) * 60.0 / (2.0 * math.pi)
    T = abs(torque(t, case))
    if rpm == 0.0 or T == 0.0:
        return 0.0
    return angle_deg * rpm / rule.constant * (T / rule.rated_torque) ** rule.exponent


def _sign_changes(f, h, samples=4001):
    ts = np.linspace(0.0, h, samples)
    values = [f(t) for t in ts]
    roots = []
    for t0, t1, v0, v1 in zip(ts, ts[1:], values, values[1:]):
        if v0 == 0.0:
            roots.append(t0)
        elif v0 * v1 < 0.0:
            roots.append(brentq(f, t0, t1, xtol=1e-300, rtol=1e-15, maxiter=500))
    return roots


def _kinks(case, h, rule):
    psi, b, w, a, rb, ab, inertia, load = case
    kinks = [0.0, h]
    kinks += _sign_changes(lambda t: torque(t, case), h)
    kinks += _sign_changes(lambda t: w + a * t, h)
    for level in (rule.min_angle, -rule.min_angle):
        kinks += _sign_changes(lambda t, c=b - level: c + rb * t + 0.5 * ab * t * t, h)
    return sorted({k for k in kinks if 0.0 <= k <= h})


def damage(case, h, rule):
    """Miner's damage over [0, h]: the integral of rate / 3600."""
    kinks = _kinks(case, h, rule)
    with mpmath.workdps(30):
        total = mpmath.quad(lambda t: rate(float(t), case, rule), kinks, maxdegree=10)
    return float(total) / 3600.0


def damage_quadpack(case, h, rule):
    """`damage` by QUADPACK between the same kinks, asked for 1e-13 relative."""
    kinks = _kinks(case, h, rule)
    total = 0.0
    for lo, hi in zip(kinks, kinks[1:]):
        total += quad(lambda t: rate(t, case, rule), lo, hi, epsabs=0.0, epsrel=1e-13, limit=500)[0]
    return total / 3600.0


def chain_over_step(shaft, spring=None):
    """A propshaft's chain t s into its next step, the input shaft at constant
    acceleration: a function of t; the load `spring(t, free chain)` if given
    (a compliant layer's), else the held one."""
    _, fraction, error = shaft._angle
    w0, a0 = shaft.input_speed, shaft.input_acceleration
    crosspiece = tuple(getattr(shaft, f"crosspiece_inertia_{k}") for k in (1, 2, 3))
    inertias = [getattr(shaft, f"shaft_{k}_inertia") for k in range(1, shaft.joints)]

    def state(t):
        angle = fraction + (error + (w0 * t + 0.5 * a0 * t * t))
        load = shaft.load_torque
        if spring:
            load = spring(t, chain(shaft.layout, angle, w0 + a0 * t, a0, crosspiece, inertias))
        return chain(shaft.layout, angle, w0 + a0 * t, a0, crosspiece, inertias, load)

    return state


def chain_evaluations(monkeypatch) -> list:
    """A list that gains an item at each chain evaluation life's march makes
    in a propshaft's step (`step_integrals`' torques), from now on."""
    from cardan_joint.models.propshaft import step as propshaft_step

    calls: list = []
    original = propshaft_step.step_integrals

    def counting(torques_at, step, *rest):
        def counted(t, at):
            calls.append(None)
            return torques_at(t, at)

        return original(counted, step, *rest)

    monkeypatch.setattr(propshaft_step, "step_integrals", counting)
    return calls
