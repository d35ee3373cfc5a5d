"""Issue 27 in the built FMUs: the bearing and life outputs in FMI 2.0 and 3.0
equal the physics model's bit for bit, and life_consumed is part of the FMU
state (get, set, serialize)."""

import math
import random

import pytest
from life_reference import case_of, damage_quadpack, random_fast_step

from cardan_joint.host.instance import ExtractedFMU, FmuInstance
from cardan_joint.models import discover
from cardan_joint.models.propshaft import Propshaft
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.physics.life import life_rule

LIFE = ("input_bearing_force", "output_bearing_force", "life_rate", "life_consumed")
START = dict(crosspiece_inertia_2=0.05, rated_torque=400.0, bearing_radius=0.02)
# A speed ramp, the bend crossing 3 degrees and a load reversing through zero.
STEPS = [
    dict(input_speed=50.0 + 2.0 * k, input_acceleration=200.0, bend_angle=0.04 - 0.002 * k,
         bend_angle_rate=-0.2, load_torque=300.0 - 40.0 * k)
    for k in range(30)
]  # fmt: skip
H = 0.01


def _run(joint, steps):
    trace = []
    for values in steps:
        joint.set(**values)
        joint.step(H)
        outputs = joint.get_outputs()
        trace.append(tuple(outputs[n] for n in LIFE))
    return trace


def _model_run(steps):
    joint = CardanJoint(**START)
    trace = []
    for values in steps:
        for name, value in values.items():
            setattr(joint, name, value)
        assert joint.step(H) is None
        outputs = dict(zip(joint.table.OUTPUTS, joint.outputs()))
        trace.append(tuple(outputs[n] for n in LIFE))
    return trace


def test_fmi2_and_fmi3_give_the_models_life_bit_for_bit(
    model_description, unzipped_fmu, fmi3_description, fmi3_unzipped
):
    expected = _model_run(STEPS)
    assert expected[-1][3] > 0.0
    for md, unzipped in ((model_description, unzipped_fmu), (fmi3_description, fmi3_unzipped)):
        joint = FmuInstance(md, unzipped, name="life", start_values=START)
        try:
            assert _run(joint, STEPS) == expected
        finally:
            joint.close()


def test_life_consumed_is_saved_restored_and_serialized_bit_for_bit(
    model_description, unzipped_fmu
):
    joint = FmuInstance(model_description, unzipped_fmu, name="saved", start_values=START)
    fresh = FmuInstance(model_description, unzipped_fmu, name="fresh", start_values=START)
    try:
        _run(joint, STEPS[:10])
        saved = joint.get_state()
        serialized = joint.serialize_state(saved)
        first = _run(joint, STEPS[10:])
        joint.set_state(saved)
        assert _run(joint, STEPS[10:]) == first
        state = fresh.deserialize_state(serialized)
        fresh.set_state(state)
        fresh.free_state(state)
        assert _run(fresh, STEPS[10:]) == first
        joint.free_state(saved)
    finally:
        joint.close()
        fresh.close()


RULE = life_rule(1000.0, 1.5e6, 10.0 / 3.0, math.radians(3.0))
INPUTS = ("input_speed", "input_acceleration", "bend_angle", "bend_angle_rate",
          "bend_angle_acceleration", "load_torque")  # fmt: skip


def test_fast_random_steps_consume_the_adaptive_quadratures_damage_in_fmi2_and_fmi3(built):
    # Issue 32: random steps at 200-1000 rad/s, a massive cross, loads of both
    # signs; each FMU's life_consumed after one step within 1e-9 of QUADPACK's.
    rng = random.Random(4)
    steps = [random_fast_step(rng) for _ in range(6)]
    expected = [damage_quadpack(case_of(CardanJoint(**values)), h, RULE) for values, h in steps]
    for version in (2, 3):
        with ExtractedFMU(built("UniversalJoint", version)) as fmu:
            for (values, h), damage in zip(steps, expected):
                parameters = {k: v for k, v in values.items() if k not in INPUTS}
                joint = fmu.instance(f"fast{version}", start_values=parameters)
                try:
                    joint.set(**{k: values[k] for k in INPUTS})
                    joint.step(h)
                    consumed = joint.get_outputs()["life_consumed"]
                finally:
                    joint.close()
                assert abs(consumed - damage) <= 1e-9 * damage, (version, values, h)


# The Propshaft: each joint's life outputs (`joint_k_`), FMI 2.0 = FMI 3.0 = the model.
PROPSHAFT_START = dict(shaft_1_top_angle=0.12, rated_torque=500.0, bearing_radius=0.025)
PROPSHAFT_STEPS = [
    dict(input_speed=120.0 - 9.0 * k, input_acceleration=-900.0, load_torque=200.0 - 30.0 * k)
    for k in range(20)
]
PROPSHAFT_LIFE = tuple(f"joint_{k}_{name}" for k in (1, 2) for name in LIFE)


def _propshaft_model_run(steps):
    shaft = Propshaft(2, **PROPSHAFT_START)
    trace = []
    for values in steps:
        for name, value in values.items():
            setattr(shaft, name, value)
        assert shaft.step(H) is None
        outputs = dict(zip(shaft.table.OUTPUTS, shaft.outputs()))
        trace.append(tuple(outputs[n] for n in PROPSHAFT_LIFE))
    return trace


def _propshaft_run(shaft, steps):
    trace = []
    for values in steps:
        shaft.set(**values)
        shaft.step(H)
        outputs = shaft.get_outputs()
        trace.append(tuple(outputs[n] for n in PROPSHAFT_LIFE))
    return trace


def test_the_propshafts_joints_give_the_models_life_in_fmi2_and_fmi3_with_their_state(built):
    expected = _propshaft_model_run(PROPSHAFT_STEPS)
    assert min(expected[-1][3::4]) > 0.0
    for version in (2, 3):
        with ExtractedFMU(built("Propshaft", version)) as fmu:
            shaft = fmu.instance(f"propshaft{version}", start_values=PROPSHAFT_START)
            try:
                assert _propshaft_run(shaft, PROPSHAFT_STEPS[:8]) == expected[:8]
                saved = shaft.serialize_state(shaft.get_state())
                assert _propshaft_run(shaft, PROPSHAFT_STEPS[8:]) == expected[8:]
                shaft.set_state(shaft.deserialize_state(saved))
                assert _propshaft_run(shaft, PROPSHAFT_STEPS[8:]) == expected[8:]
            finally:
                shaft.close()


JOINTED = sorted(key for key, spec in discover().items() if spec.owner == "joint")


@pytest.mark.parametrize("key", JOINTED)
def test_every_jointed_model_has_the_life_outputs_in_fmi2_and_fmi3_bit_for_bit(key, built):
    traces = []
    for version in (2, 3):
        with ExtractedFMU(built(key, version)) as fmu:
            names = [v.name for v in fmu.model_description.modelVariables]
            life = [n for n in names if n.endswith(LIFE)]
            # One of each of the four per joint (a propshaft's joints: `joint_k_`).
            assert len(life) % 4 == 0 and {n[-len(s) :] for n in life for s in LIFE if
                                            n.endswith(s)} == set(LIFE)  # fmt: skip
            instance = fmu.instance(f"{key}{version}")
            try:
                trace = []
                for k in range(12):
                    instance.set(input_speed=60.0 + 5.0 * k, input_acceleration=500.0)
                    instance.step(0.01)
                    trace.append(tuple(instance.get_outputs().items()))
                traces.append(trace)
            finally:
                instance.close()
    assert traces[0] == traces[1]
    consumed = [v for n, v in traces[0][-1] if n.endswith("life_consumed")]
    assert consumed and min(consumed) > 0.0
