"""The propshafts' joints share their life integral's nodes (docs/life.md): a
random search of single steps of 2-4 joint propshafts, rigid under a held
load of either sign and compliant under the spring, against QUADPACK between
each joint's own kinks (its torque's sign changes by dense sampling and
brentq, the speed's zero), the rate straight from the catalogue formula of
the chain at each instant. Massless crosses and shafts make every joint's
torque proportional to the load: their zeros fall on the same instant. The
single joint is the march's case of one: its pieces after a torque zero end
at the speed's own zero."""

import math
import random

import numpy as np
from life_reference import chain_evaluations, chain_over_step, damage_quadpack
from scipy.integrate import quad
from scipy.optimize import brentq

from cardan_joint.models.compliant_propshaft.model import CompliantPropshaft
from cardan_joint.models.propshaft import Propshaft
from cardan_joint.physics.life import life_rule, step_damage


def _sign_changes(f, h, samples=2001):
    ts = np.linspace(0.0, h, samples)
    values = [f(t) for t in ts]
    return [
        brentq(f, t0, t1, xtol=1e-300, rtol=1e-15, maxiter=500)
        for t0, t1, v0, v1 in zip(ts, ts[1:], values, values[1:])
        if v0 * v1 < 0.0
    ]


def _reference(shaft, h, spring=None):
    """(each joint's damage over the next step of `h` s by QUADPACK, the
    torque zeros of all joints in it); the load
    `spring(t, free chain)` if given, else the held one."""
    w0, a0 = shaft.input_speed, shaft.input_acceleration
    rule = shaft._life_rule
    state = chain_over_step(shaft, spring)

    damages, zeros = [], 0
    for k, beta in enumerate(shaft.layout.working_angles):

        def rate(t, k=k, beta=beta):
            s = state(t)
            speed = s.speeds[k - 1] if k else w0 + a0 * t
            degrees = max(abs(beta), rule.min_angle) * 180.0 / math.pi
            rpm = abs(speed) * 30.0 / math.pi
            torque = abs(s.torques[k]) / rule.rated_torque
            return degrees * rpm / rule.constant * torque**rule.exponent

        changes = _sign_changes(lambda t, k=k: state(t).torques[k], h)
        zeros += len(changes)
        kinks = [0.0, h, *changes]
        if a0 and 0.0 < -w0 / a0 < h:
            kinks.append(-w0 / a0)
        kinks = sorted(kinks)
        total = sum(
            quad(rate, lo, hi, epsabs=0.0, epsrel=1e-13, limit=500)[0]
            for lo, hi in zip(kinks, kinks[1:])
        )
        damages.append(total / 3600.0)
    return damages, zeros


def _random_shaft(rng, compliant: bool):
    joints = rng.choice((2, 3, 4))
    massless = rng.random() < 0.3
    values = dict(
        input_angle_start=rng.uniform(-4.0, 4.0),
        input_speed=rng.choice((-1.0, 1.0)) * rng.uniform(100.0, 1000.0),
        input_acceleration=rng.uniform(-2e3, 2e3),
        shaft_0_side_angle=math.radians(rng.uniform(-12.0, 12.0)),
        shaft_1_top_angle=math.radians(rng.uniform(-10.0, 10.0)),
        shaft_1_yoke_phase=rng.uniform(-0.5, 0.5),
    )
    for k in (1, 2, 3):
        values[f"crosspiece_inertia_{k}"] = 0.0 if massless else rng.uniform(0.005, 0.1)
    for k in range(1, joints):
        values[f"shaft_{k}_inertia"] = 0.0 if massless else rng.uniform(0.0, 0.1)
    if not compliant:
        values["load_torque"] = rng.choice((-1.0, 1.0)) * rng.uniform(1.0, 2000.0)
        return Propshaft(joints, **values)
    speed = values["input_speed"]
    return CompliantPropshaft(
        joints, **values, output_speed=speed + rng.uniform(-5.0, 5.0),
        output_acceleration=rng.uniform(-2e3, 2e3), torsional_stiffness=rng.uniform(1e2, 1e4),
        torsional_damping=rng.uniform(0.0, 5.0),
    )  # fmt: skip


def _spring_of(drive):
    shaft = drive.rigid
    k, c, shift = drive.torsional_stiffness, drive.torsional_damping, shaft._shifts[-1]
    lag, wo, ao = drive._lag, drive.output_speed, drive.output_acceleration
    slip, slip_rate = shaft.input_speed - wo, shaft.input_acceleration - ao

    def spring(t, free):
        twist = free.offsets[-1] - shift + lag + slip * t + 0.5 * slip_rate * t * t
        return k * twist + c * (free.speeds[-1] - (wo + ao * t))

    return spring


def test_random_chain_steps_consume_each_joints_adaptive_quadrature_damage_to_1e_9():
    rng = random.Random(32)
    zeros = 0
    for case in range(60):
        compliant = case % 2 == 1
        model = _random_shaft(rng, compliant)
        shaft = model.rigid if compliant else model
        h = 10.0 ** rng.uniform(-4.0, -2.5)
        expected, found = _reference(shaft, h, _spring_of(model) if compliant else None)
        assert model.step(h) is None
        out = dict(zip(model.table.OUTPUTS, model.outputs()))
        for k, want in enumerate(expected, start=1):
            got = out[f"joint_{k}_life_consumed"]
            assert abs(got - want) <= 1e-9 * want, (case, k, got, want)
        zeros += found
    # The search meets the joints' torque zeros, not only smooth steps.
    assert zeros > 30, zeros


def test_the_speeds_reversal_after_a_torque_zero_cuts_the_step_where_the_speed_vanishes():
    # A joint whose torque changes sign before its speed reverses in the same
    # step: the piece after the zero ends at the speed's zero from the input's
    # own acceleration (a march that took another number for it there missed
    # the reversal by up to 3e-5 of the damage).
    rule = life_rule(1000.0, 1.5e6, 10.0 / 3.0, math.radians(3.0))
    inertia = (0.05, 0.04, 0.06)
    cases = [
        (0.08154213212058187, 4.089575299810714, -0.3898680996125431, -237.0020523437695,
         4637.99769863428, -16.764436417242923),
        (0.07275570833612059, 5.867476918406378, 0.4865748639041815, 135.8177626970458,
         -2180.6951283050157, 4.485728282798355),
    ]  # fmt: skip
    for h, psi, bend, speed, acceleration, load in cases:
        assert 0.0 < -speed / acceleration < h
        got = step_damage(rule, h, psi, bend, speed, acceleration, 0.0, 0.0, inertia, load)
        case = (psi, bend, speed, acceleration, 0.0, 0.0, inertia, load)
        want = damage_quadpack(case, h, rule)
        assert abs(got - want) <= 1e-9 * want, (got, want)


def test_a_steady_chain_from_a_dead_centre_takes_its_zeros_at_once_and_exactly(monkeypatch):
    # Both shafts at 30 rad/s, no acceleration, from the dead centre where
    # every torque vanishes: the torques start from their rounding (a zero
    # 1e-14 s before the step, which no node's sign shows) and the joints'
    # zeros fall 2e-14 s apart. A march that took neither as the zero it is
    # halved towards it until it ran out of panels: 81,000 evaluations in
    # such steps, 1,630 a step on average.
    calls = chain_evaluations(monkeypatch)
    drive = CompliantPropshaft(2)
    inputs = (30.0, 0.0, 30.0, 0.0)
    drive.set_inputs(inputs)
    for step in range(60):
        expected = _reference(drive.rigid, 1e-3, _spring_of(drive))[0] if step < 3 else None
        consumed = [dict(zip(drive.table.OUTPUTS, drive.outputs()))[f"joint_{k}_life_consumed"]
                    for k in (1, 2)]  # fmt: skip
        calls.clear()
        drive.run(drive.time, 1e-3, inputs)
        assert len(calls) < 100, (step, len(calls))
        if expected is not None:
            out = dict(zip(drive.table.OUTPUTS, drive.outputs()))
            for k, want in enumerate(expected, start=1):
                got = out[f"joint_{k}_life_consumed"] - consumed[k - 1]
                assert abs(got - want) <= 1e-9 * want, (step, k, got, want)
