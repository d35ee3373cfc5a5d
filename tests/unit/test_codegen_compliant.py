"""The CompliantJoint's generated C step (`compliant_joint.step.compliant_joint_step`
through `cardan_joint.codegen`) gives the Python step's bits: every output, the
moved inputs, the exact angle, Miner's sum and the lag, and the same decision
to take or refuse the step, over random operating points up to 1000 rad/s; a
mutated generator is caught. The Python step is the model's own step, which
takes a step exactly when the model's checks do and gives the bits the spring
layer (`CompliantDrive.step` and `outputs`) gives."""

import copy
import inspect
import math
import random

import pytest
from generated_c import CStep, bits, mismatches
from test_codegen_joint import MUTANTS, operating_point
from test_codegen_joint import cases as joint_cases

from cardan_joint.codegen import expressions, generate
from cardan_joint.framework.refusal import Refusal
from cardan_joint.framework.stepped import SteppedModel
from cardan_joint.models.compliant_joint import model
from cardan_joint.models.compliant_joint.model import CompliantJoint
from cardan_joint.models.compliant_joint.step import STATE, compliant_joint_step
from cardan_joint.models.compliant_joint.variables import COMPLIANT_JOINT
from cardan_joint.models.universal_joint.step import joint_life_step

NAMES = tuple(inspect.signature(compliant_joint_step).parameters)
AT = {name: k for k, name in enumerate(NAMES)}
JOINT_NAMES = tuple(inspect.signature(joint_life_step).parameters)
CASES = 1_500  # life's Python step costs up to a second on a long step at 1000 rad/s
INPUTS = NAMES[AT["input_speed"] : AT["bend_angle_acceleration"] + 1]
assert INPUTS == COMPLIANT_JOINT.INPUTS


def compliant_point(rng: random.Random) -> list:
    """compliant_joint_step's arguments: the joint's operating points (speeds to
    1000 rad/s both ways, 3 deg crossings, long steps, speed reversals, massive
    crosses, many turns, any life rule), an output shaft a little slower or
    faster, reversed or still, a lag and spring that load the joint either way."""
    point = dict(zip(JOINT_NAMES, operating_point(rng)))
    speed, h = point["input_speed"], point["h"]
    point["output_speed"] = rng.choice(
        [speed + rng.uniform(-5.0, 5.0), -speed, 0.0, rng.uniform(-1e3, 1e3)]
    )
    point["output_acceleration"] = rng.choice(
        [point["input_acceleration"], 0.0, rng.uniform(-1e4, 1e4), -2.0 * speed / h]
    )
    point["lag"] = rng.choice([0.0, rng.uniform(-0.5, 0.5), rng.uniform(-1e3, 1e3)])
    point["twist_angle_start"] = rng.uniform(-0.1, 0.1)
    point["torsional_stiffness"] = rng.choice([1e4, 10.0 ** rng.uniform(-2.0, 7.0)])
    point["torsional_damping"] = rng.choice([0.0, 5.0, 10.0 ** rng.uniform(-2.0, 4.0)])
    return [point[name] for name in NAMES]


def refusable(rng: random.Random, point: list) -> list:
    """A point some of whose values are at or beyond a limit, or not numbers:
    the joint's inputs, the output shaft's, the step size, the bend's guard,
    and a twist changing by more than 1e15 rad over a long step."""
    name = rng.choice(INPUTS + ("h", "max_bend_angle"))
    values = [math.nan, math.inf, -math.inf, 2e5, -2e5, 1.5e8, -1.5e8, 1e300, 0.0, -1e-3]
    point[AT[name]] = rng.choice(values)
    draw = rng.random()
    if draw < 0.2:  # the bend exactly at its guard: refused, by a strict <
        point[AT["bend_angle"]] = point[AT["max_bend_angle"]]
    elif draw < 0.4:  # only the twist's change is past its limit (near it, either side)
        point[AT["input_speed"]] = point[AT["input_acceleration"]] = 0.0
        point[AT["output_speed"]], point[AT["output_acceleration"]] = 0.0, -1e8
        point[AT["h"]] = rng.choice([4.4e3, 4.5e3, 5e3])
    return point


def cases(seed: int, count: int):
    return joint_cases(seed, count, compliant_point, refusable)


@pytest.fixture(scope="module")
def c_step(tmp_path_factory):
    name = compliant_joint_step.__name__
    return CStep(generate(compliant_joint_step, name), tmp_path_factory.mktemp(name))


def test_the_generated_step_gives_the_python_steps_bits(c_step):
    differ, taken, refused = mismatches(compliant_joint_step, c_step, cases(32, CASES))
    assert differ == 0
    assert taken > CASES // 3 and refused > CASES // 10, (taken, refused)


def test_the_twist_limit_alone_decides_some_steps(c_step):
    """Steps refused by the twist's change only, and steps just within it, both ways."""
    decisions = set()
    for h in (4.4e3, 5e3):
        point = compliant_point(random.Random(3))
        point[AT["parameters_valid"]] = True
        point[AT["bend_angle"] : AT["bend_angle_acceleration"] + 1] = [0.1, 0.0, 0.0]
        point[AT["input_speed"] : AT["output_acceleration"] + 1] = [0.0, 0.0, 0.0, -1e8]
        point[AT["h"]] = h
        python = compliant_joint_step(*point)
        assert bits(python) == bits(c_step(*point))
        decisions.add(python is None)
    assert decisions == {True, False}


def test_a_long_run_of_the_generated_step_keeps_the_python_steps_bits(c_step):
    """1,000 steps from each start, each one from the state the last one left:
    Miner's sum and the lag grow step by step, the spring loads both ways."""
    rng = random.Random(7)
    first_state, first_input = AT["turns"], AT["input_speed"]
    for _ in range(10):
        point = compliant_point(rng)
        point[AT["parameters_valid"]] = True
        point[AT["bend_angle"] : AT["bend_angle_acceleration"] + 1] = [0.1, 0.0, 0.0]
        point[AT["h"]] = 1e-3
        for _ in range(1_000):
            python, c = compliant_joint_step(*point), c_step(*point)
            assert bits(python) == bits(c), point
            if python is None:
                break
            point[AT["time"]] += 1e-3
            point[first_state : first_state + len(STATE)] = python[: len(STATE)]
            moved = python[len(STATE) : len(STATE) + len(INPUTS)]
            point[first_input : first_input + len(moved)] = moved


@pytest.mark.parametrize("mutant", MUTANTS)
def test_a_mutated_generator_fails_the_bit_test(mutant, monkeypatch, tmp_path):
    name, replacement = MUTANTS[mutant]
    monkeypatch.setattr(expressions, name, replacement)
    mutated = CStep(generate(compliant_joint_step, "mutated"), tmp_path, strict=False)
    differ, _, _ = mismatches(compliant_joint_step, mutated, cases(32, CASES // 10))
    assert differ > 0, mutant


def random_model(rng: random.Random) -> tuple[CompliantJoint, float, tuple]:
    """A CompliantJoint part way into a run, a step size and the next inputs."""
    point = dict(zip(NAMES, compliant_point(rng)))
    parameters = {name: point[name] for name in NAMES[AT["yoke_phase"] :]}
    parameters["yoke_phase"] = rng.uniform(-4.0, 4.0)
    joint = CompliantJoint(**parameters)
    joint.run(0.0, 1e-3, tuple(point[name] for name in INPUTS))
    if rng.random() < 0.3:
        point = dict(zip(NAMES, refusable(rng, [point[name] for name in NAMES])))
    return joint, point["h"], tuple(point[name] for name in INPUTS)


def test_the_models_step_takes_and_refuses_as_its_checks_and_spring_layer():
    """The model's step (`compliant_joint_step`) against the spring layer's own
    step (the checks, `CompliantDrive.step`, `outputs`): the same refusals,
    outputs, moved inputs and state, bit for bit."""
    rng = random.Random(11)
    refused = 0
    for _ in range(300):
        joint, h, inputs = random_model(rng)
        layer = copy.deepcopy(joint)
        new, old = joint.run(joint.time, h, inputs), SteppedModel.run(layer, layer.time, h, inputs)
        if isinstance(old, Refusal):
            refused += 1
            assert isinstance(new, Refusal) and repr(new) == repr(old), (new, old)
            continue
        assert not isinstance(new, Refusal), new
        assert bits(new[0]) == bits(old[0]) and bits(new[1]) == bits(old[1])
        assert bits(joint.step_state()) == bits(layer.step_state())
    assert 30 < refused < 200, refused


@pytest.mark.parametrize("name", INPUTS)
@pytest.mark.parametrize("value", [math.nan, -math.inf, 1e300, "just past its range"])
def test_each_input_past_its_limit_is_refused_by_the_models_checks(name, value):
    """Each input at a bad value: the model's step leaves it to the checks,
    which refuse it as the spring layer does."""
    inputs = dict(zip(INPUTS, (100.0, 10.0, 99.0, 10.0, 0.2, 0.1, 0.0)))
    joint = CompliantJoint()
    if value == "just past its range":
        high = joint.max_bend_angle if name == "bend_angle" else COMPLIANT_JOINT.BY_NAME[name].max
        value = -math.nextafter(high, math.inf)
    joint.run(0.0, 1e-3, tuple(inputs.values()))
    layer = copy.deepcopy(joint)
    inputs[name] = value
    refusal = joint.run(joint.time, 1e-3, tuple(inputs.values()))
    assert isinstance(refusal, Refusal) and refusal.variable == name, refusal
    assert repr(refusal) == repr(SteppedModel.run(layer, layer.time, 1e-3, tuple(inputs.values())))


def test_the_models_step_is_the_translated_definition(monkeypatch):
    """CompliantJoint.run takes its step, Miner's sum and the lag included,
    from `compliant_joint_step` itself; the state it keeps is the step's."""
    calls: list = []

    def counted(*arguments):
        calls.append(arguments)
        return compliant_joint_step(*arguments)

    monkeypatch.setattr(model, "compliant_joint_step", counted)
    joint = CompliantJoint(torsional_stiffness=2e3)
    for k in range(3):
        outputs, moved = joint.run(k * 0.1, 0.1, (300.0, 0.0, 290.0, 50.0, 0.2, 0.0, 0.0))
    assert len(calls) == 3
    taken = compliant_joint_step(*calls[-1])
    state = len(STATE)
    assert bits(outputs) == bits(taken[state + len(moved) :])
    assert bits(moved) == bits(taken[state : state + len(moved)])
    assert bits(joint.step_state()) == bits(taken[:state])
    assert joint.rigid.life_consumed > 0.0 and joint._lag != 0.0
