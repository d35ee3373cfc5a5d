"""Issue 27 item 3 in the Propshaft: each joint's bearing forces, life rate and
life consumed (`joint_k_`), the single joint's rule on each joint with its own
input shaft's speed and torque.

The damage against mpmath's adaptive quadrature of the catalogue rate, whose
kinks (torque zeros) are found by dense sampling and brentq (`life_reference`'s
way, not the FMU's panels); the rate at each instant from the chain, which
tests/unit/test_propshaft_physics.py checks against independent constructions.
"""

import json
import math
import re

import mpmath
import numpy as np
import pytest
from life_reference import chain_evaluations, chain_over_step
from scipy.optimize import brentq

from cardan_joint.models.compliant_propshaft.model import CompliantPropshaft
from cardan_joint.models.propshaft import Propshaft
from cardan_joint.physics.life import life_rule

RULE = life_rule(1000.0, 1.5e6, 10.0 / 3.0, math.radians(3.0))
D = math.radians


def _outputs(shaft):
    return dict(zip(shaft.table.OUTPUTS, shaft.outputs()))


def _reference_damages(shaft, h, spring=None):
    """Each joint's damage over the next step of `h` s, from the catalogue rate
    in degrees and rpm integrated by mpmath between the torque's sign changes;
    the load `spring(t, free chain)` if given (a compliant layer's), else held."""
    w0, a0 = shaft.input_speed, shaft.input_acceleration
    state = chain_over_step(shaft, spring)

    damages = []
    for k, beta in enumerate(shaft.layout.working_angles):

        def torque(t, k=k):
            return state(t).torques[k]

        def rate(t, k=k, beta=beta):
            s = state(t)
            speed = s.speeds[k - 1] if k else w0 + a0 * t
            degrees = max(beta, RULE.min_angle) * 180.0 / math.pi
            rpm = abs(speed) * 30.0 / math.pi
            return (
                degrees
                * rpm
                / RULE.constant
                * (abs(s.torques[k]) / RULE.rated_torque) ** (RULE.exponent)
            )

        ts = np.linspace(0.0, h, 2001)
        values = [torque(t) for t in ts]
        kinks = [0.0, h] + [
            brentq(torque, t0, t1, xtol=1e-300, rtol=1e-15)
            for t0, t1, v0, v1 in zip(ts, ts[1:], values, values[1:])
            if v0 * v1 < 0.0
        ]
        if a0 and 0.0 < -w0 / a0 < h:
            kinks.append(-w0 / a0)
        with mpmath.workdps(25):
            total = mpmath.quad(lambda t: rate(float(t)), sorted(kinks), maxdegree=8)
        damages.append(float(total) / 3600.0)
    return damages


CASES = [
    # a 2-joint shaft at strong angles, massless: the cardan torque fluctuation
    (2, dict(shaft_0_side_angle=D(12.0), shaft_2_side_angle=D(4.0), load_torque=400.0,
             crosspiece_inertia_1=0.0, crosspiece_inertia_2=0.0, crosspiece_inertia_3=0.0,
             shaft_1_inertia=0.0, input_speed=150.0, input_acceleration=800.0), 0.01, 3),
    # 3 joints, no load: the inertias' torque reverses every joint's torque
    (3, dict(shaft_1_top_angle=D(9.0), load_torque=0.0, input_speed=-220.0,
             input_acceleration=0.0, shaft_2_yoke_phase=D(30.0)), 0.005, 3),
    # the speed reverses inside the step
    (2, dict(load_torque=-150.0, input_speed=3.0, input_acceleration=-200.0), 0.03, 1),
]  # fmt: skip


@pytest.mark.parametrize("joints, values, h, steps", CASES)
def test_each_joints_life_consumed_equals_an_adaptive_quadrature(joints, values, h, steps):
    shaft = Propshaft(joints, **values)
    expected = [0.0] * joints
    for _ in range(steps):
        expected = [e + d for e, d in zip(expected, _reference_damages(shaft, h))]
        assert shaft.step(h) is None
        out = _outputs(shaft)
        for k in range(1, joints + 1):
            got = out[f"joint_{k}_life_consumed"]
            assert abs(got - expected[k - 1]) <= 1e-9 * expected[k - 1], k
    assert min(expected) > 0.0


def test_straight_and_steady_every_joint_consumes_t_over_3600_life_hours():
    # Every shaft straight: each joint at the 3-degree floor, its torque the load.
    straight = {f"shaft_{k}_side_angle": 0.0 for k in range(4)}
    w, load, h, steps = 157.0, 640.0, 1e-3, 500
    shaft = Propshaft(3, input_speed=w, load_torque=load, **straight)
    for _ in range(steps):
        assert shaft.step(h) is None
    out = _outputs(shaft)
    hours = RULE.constant / (3.0 * w * 30.0 / math.pi) * (RULE.rated_torque / load) ** (10 / 3)
    for k in (1, 2, 3):
        assert out[f"joint_{k}_life_rate"] == pytest.approx(1.0 / hours, rel=1e-13, abs=0.0)
        assert out[f"joint_{k}_life_consumed"] == pytest.approx(
            steps * h / (3600.0 * hours), rel=1e-12, abs=0.0
        )


def test_a_massless_cross_loads_both_yokes_of_each_joint_equally():
    shaft = Propshaft(3, shaft_1_top_angle=D(7.0), load_torque=250.0, input_speed=90.0,
                      input_acceleration=300.0, crosspiece_inertia_1=0.0,
                      crosspiece_inertia_2=0.0, crosspiece_inertia_3=0.0)  # fmt: skip
    shaft.step(0.013)
    out = _outputs(shaft)
    for k in (1, 2, 3):
        into, out_of = out[f"joint_{k}_input_bearing_force"], out[f"joint_{k}_output_bearing_force"]
        assert into == pytest.approx(out_of, rel=1e-13, abs=0.0) and into > 0.0


def test_saving_restoring_and_serializing_mid_run_continues_bit_identically():
    shaft = Propshaft(3, shaft_1_top_angle=D(5.0), load_torque=120.0, input_speed=80.0)
    for _ in range(5):
        shaft.step(0.01)
    saved = json.loads(json.dumps(shaft.state()))
    tail = []
    for _ in range(4):
        shaft.step(0.01)
        tail.append(shaft.outputs())
    other = Propshaft(3, load_torque=-7.0)
    other.restore(saved)
    again = []
    for _ in range(4):
        other.step(0.01)
        again.append(other.outputs())
    assert again == tail and min(saved["life_consumed"]) > 0.0


def test_without_life_the_propshaft_gives_the_same_numbers_and_lacks_only_the_life_rows():
    with_life, without = Propshaft(3, load_torque=50.0), Propshaft(3, False, load_torque=50.0)
    for _ in range(10):
        with_life.step(1e-3)
        without.step(1e-3)
    assert with_life.outputs()[: len(without.outputs())] == without.outputs()
    extra = set(with_life.table.OUTPUTS) - set(without.table.OUTPUTS)
    assert extra == {
        f"joint_{k}_{name}"
        for k in (1, 2, 3)
        for name in ("input_bearing_force", "output_bearing_force", "life_rate", "life_consumed")
    }


def test_under_a_spring_each_joints_life_consumed_equals_an_adaptive_quadrature():
    drive = CompliantPropshaft(3, shaft_1_top_angle=D(8.0), input_speed=130.0,
                               input_acceleration=600.0, output_speed=127.0,
                               output_acceleration=1500.0, torsional_stiffness=3e3)  # fmt: skip
    shaft, h = drive.rigid, 0.01
    expected = [0.0] * 3
    k, c, shift = drive.torsional_stiffness, drive.torsional_damping, shaft._shifts[-1]
    for _ in range(3):
        lag, wo, ao = drive._lag, drive.output_speed, drive.output_acceleration
        slip, slip_rate = shaft.input_speed - wo, shaft.input_acceleration - ao

        def spring(t, free, lag=lag, wo=wo, ao=ao, slip=slip, slip_rate=slip_rate):
            twist = free.offsets[-1] - shift + lag + slip * t + 0.5 * slip_rate * t * t
            return k * twist + c * (free.speeds[-1] - (wo + ao * t))

        expected = [e + d for e, d in zip(expected, _reference_damages(shaft, h, spring))]
        assert drive.step(h) is None
        out = dict(zip(drive.table.OUTPUTS, drive.outputs()))
        for j in (1, 2, 3):
            got = out[f"joint_{j}_life_consumed"]
            assert abs(got - expected[j - 1]) <= 1e-9 * expected[j - 1], j
    assert min(expected) > 0.0


def _benchmark_steps(drive, steps, calls):
    """(outputs, chain evaluations) of each of `steps` 1 ms steps at the
    benchmarks' point, as a host steps it."""
    seen = []
    for _ in range(steps):
        calls.clear()
        drive.run(drive.time, 1e-3, (100.0, 5.0, 100.0, 5.0))
        seen.append((drive.outputs(), len(calls)))
    return seen


def test_a_restored_drive_foresees_its_next_steps_as_the_saved_one_does(monkeypatch):
    # Life carries what it foresees the next step's first panel from (the
    # last plain panel's place and cubic) in the state: restored, the drive
    # takes the same panels, so the same evaluations and bits; without it
    # the first step would take its probe again.
    calls = chain_evaluations(monkeypatch)
    drive = CompliantPropshaft(2)
    _benchmark_steps(drive, 30, calls)
    saved = json.loads(json.dumps(drive.state()))
    assert len(saved["rigid"]["life_ahead"]) == 2 + 4 * 2
    tail = _benchmark_steps(drive, 10, calls)
    other = CompliantPropshaft(2)
    other.restore(saved)
    assert _benchmark_steps(other, 10, calls) == tail
    forgotten = {**saved, "rigid": {**saved["rigid"]}}
    del forgotten["rigid"]["life_ahead"]  # a state saved before life kept it
    other.restore(forgotten)
    first = _benchmark_steps(other, 1, calls)[0]
    assert first[1] > tail[0][1]


@pytest.mark.parametrize(
    "ahead, why",
    [([0.0] * 9, "9 values in the state, 10 here"), ([math.nan] + [0.0] * 9, "finite values only")],
)
def test_a_state_whose_life_ahead_is_malformed_is_refused_and_changes_nothing(ahead, why):
    shaft = Propshaft(2, load_torque=120.0, input_speed=80.0)
    shaft.step(0.01)
    saved = json.loads(json.dumps(shaft.state()))
    before = json.dumps(shaft.state())
    with pytest.raises(ValueError, match=f"life_ahead: .*{re.escape(why)}"):
        shaft.restore({**saved, "life_ahead": ahead})
    assert json.dumps(shaft.state()) == before


def test_a_step_whose_panels_took_the_fewest_points_carries_nothing_ahead(monkeypatch):
    # A held load at the benchmarks' point: one 4-point panel a step, the
    # fewest the singularities ask for, so its zeros asked for nothing and
    # the next step spares the foresight (it cost the Propshaft's step 0.5 k
    # instructions a step). Under the spring, whose torque's zeros ask for
    # more, most steps carry their last plain panel.
    calls = chain_evaluations(monkeypatch)
    shaft, drive, carried = Propshaft(2), CompliantPropshaft(2), 0
    for _ in range(20):
        calls.clear()
        shaft.run(shaft.time, 1e-3, (100.0, 5.0, 50.0))
        assert len(calls) == 4
        start, end = shaft._ahead[:2]
        assert start == end
        drive.run(drive.time, 1e-3, (100.0, 5.0, 100.0, 5.0))
        start, end = drive.rigid._ahead[:2]
        carried += start < end
    assert carried > 15
