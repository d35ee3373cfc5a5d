"""The joint's generated C step (`step.joint_step` and, with life,
`step.joint_life_step` through `cardan_joint.codegen`) gives the Python step's
bits: every output (bearing forces and life too), the moved inputs, the exact
angle and Miner's sum, and the same decision to take or refuse the step, over
random operating points up to 1000 rad/s; and a mutated generator is caught."""

import ast
import inspect
import math
import random

import pytest
from generated_c import CStep, bits, mismatches

from cardan_joint.codegen import expressions, generate
from cardan_joint.models.universal_joint import model
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.step import (
    LIFE_STATE,
    MOVED,
    STATE,
    joint_life_step,
    joint_step,
)
from cardan_joint.physics.life import rate_scale

THREE_DEGREES = math.radians(3.0)
STEPS = {"without life": joint_step, "with life": joint_life_step}
# Random cases per step: life's Python step costs up to a second on a long step
# at 1000 rad/s.
CASES = {"without life": 20_000, "with life": 1_500}
STATES = {"without life": STATE, "with life": LIFE_STATE}


NAMES = tuple(inspect.signature(joint_life_step).parameters)  # every step's, in order
AT = {name: k for k, name in enumerate(NAMES)}


def arguments_of(step, point: list) -> list:
    """The point's values of `step`'s parameters, in order."""
    return [point[AT[name]] for name in inspect.signature(step).parameters]


def operating_point(rng: random.Random) -> list:
    """joint_life_step's arguments: speeds to 1000 rad/s both ways, loads of both
    signs, 3 deg crossings, long steps, speed reversals, massive crosses, many
    turns, Miner's sum anywhere, life rules of any exponent."""
    max_bend = rng.choice([0.3, 0.7, 1.2, 1.5])
    h = rng.choice([1e-4, 1e-3, 0.01, 0.1, 0.5, 2.0, 10.0])
    speed = rng.choice([rng.uniform(-1000.0, 1000.0), rng.uniform(-5.0, 5.0), 0.0, 1000.0])
    beta, rate = rng.uniform(-0.9, 0.9) * max_bend, rng.uniform(-1.0, 1.0)
    bend_acceleration = rng.uniform(-10.0, 10.0)
    if rng.random() < 0.3:  # the bend crosses 3 deg inside the step
        beta, rate, bend_acceleration = -THREE_DEGREES, 2.0 * THREE_DEGREES / h, 0.0
    point = {
        "time": rng.uniform(0.0, 100.0),
        "h": h,
        "turns": rng.choice([0, rng.randint(-(10**6), 10**6), 10**9]),
        "fraction": rng.uniform(0.0, 2.0 * math.pi),
        "fraction_error": rng.uniform(-1e-16, 1e-16),
        "phase_turns": rng.randint(-3, 3),
        "phase_fraction": rng.uniform(0.0, 2.0 * math.pi),
        "phase_error": rng.uniform(-1e-16, 1e-16),
        "parameters_valid": rng.random() > 0.03,
        "input_speed": speed,
        "input_acceleration": rng.choice([0.0, rng.uniform(-1e4, 1e4), -2.0 * speed / h]),
        "bend_angle": beta,
        "bend_angle_rate": rate,
        "bend_angle_acceleration": bend_acceleration,
        "load_torque": rng.choice([rng.uniform(-2000.0, 2000.0), -50.0, 0.0]),
        "yoke_phase": 0.0,
        "input_angle_start": 0.0,
        "max_bend_angle": max_bend,
        "life_consumed": rng.choice([0.0, rng.uniform(0.0, 2.0)]),
        "life_consumed_error": rng.uniform(-1e-17, 1e-17),
        "bearing_radius": rng.uniform(0.01, 0.1),
        "rated_torque": rng.choice([1000.0, rng.uniform(10.0, 5000.0)]),
        "life_constant": rng.choice([1.5e6, rng.uniform(1e3, 1e9)]),
        "life_exponent": rng.choice([10.0 / 3.0, 3.0, rng.uniform(1.0, 10.0)]),
        "life_min_angle": rng.choice([THREE_DEGREES, 0.0, rng.uniform(0.0, 0.2)]),
    }
    for k in (1, 2, 3):  # a light or a massive cross
        point[f"crosspiece_inertia_{k}"] = rng.choice([rng.uniform(0, 0.01), rng.uniform(0.5, 5)])
    # The rule's scale, which the state carries from `start`.
    point["life_rate_scale"] = rate_scale(
        point["rated_torque"], point["life_constant"], point["life_exponent"]
    )
    return [point[name] for name in NAMES]


def refusable(rng: random.Random, point: list) -> list:
    """A point some of whose values are at or beyond a limit, or not numbers."""
    name = rng.choice(NAMES[AT["input_speed"] : AT["load_torque"] + 1] + ("h", "max_bend_angle"))
    point[AT[name]] = rng.choice([math.nan, math.inf, -math.inf, 2e5, -2e5, 1e300, 0.0, -1e-3])
    if rng.random() < 0.3:  # the bend exactly at its guard: refused, by a strict <
        point[AT["bend_angle"]] = point[AT["max_bend_angle"]]
    return point


def cases(seed: int, count: int, point_of=None, refused=None):
    """Random points (`operating_point`'s, or `point_of`'s), a quarter of them
    made refusable (`refusable`, or `refused`)."""
    rng = random.Random(seed)
    for _ in range(count):
        point = (point_of or operating_point)(rng)
        yield (refused or refusable)(rng, point) if rng.random() < 0.25 else point


@pytest.fixture(scope="module", params=STEPS)
def stepped(request, tmp_path_factory):
    """(the Python step, its C, the step's key)."""
    step = STEPS[request.param]
    c = CStep(generate(step, step.__name__), tmp_path_factory.mktemp(step.__name__))
    return step, c, request.param


def step_cases(step, seed: int, count: int):
    """`cases` as the step's arguments."""
    return (arguments_of(step, point) for point in cases(seed, count))


def test_the_generated_step_gives_the_python_steps_bits(stepped):
    step, c_step, key = stepped
    count = CASES[key]
    differ, taken, refused = mismatches(step, c_step, step_cases(step, 32, count))
    assert differ == 0
    assert taken > count // 2 and refused > count // 10, (taken, refused)


def test_a_long_run_of_the_generated_step_keeps_the_python_steps_bits(stepped):
    """1,000 steps from each start, each one from the state the last one left
    (with life: Miner's sum grows step by step, loads of both signs)."""
    step, c_step, key = stepped
    rng = random.Random(7)
    first_state, first_input = AT["turns"], AT["input_speed"]
    state = len(STATES[key])
    for _ in range(10):
        point = operating_point(rng)
        point[AT["parameters_valid"]] = True
        point[AT["bend_angle"] : AT["bend_angle_acceleration"] + 1] = [0.1, 0.0, 0.0]
        point[AT["h"]] = 1e-3
        for _ in range(1_000):
            arguments = arguments_of(step, point)
            python, c = step(*arguments), c_step(*arguments)
            assert bits(python) == bits(c), point
            if python is None:
                break
            # The next step starts from the clock, state and inputs this one left.
            point[AT["time"]] += 1e-3
            given = python[:state]
            point[first_state : first_state + state] = given
            moved = python[state : state + MOVED - len(STATE)]
            point[first_input : first_input + len(moved)] = moved


# Mutations of the generator the bit test must notice: the grouping of Python's
# tree dropped (C's precedence then reassociates a - (b - c)), a strict
# comparison made loose (the bend at its guard then passes), a product made a sum.
MUTANTS = {
    "no parentheses": ("parenthesized", lambda text: text),
    "< as <=": ("COMPARE", {**expressions.COMPARE, ast.Lt: "<="}),
    "* as +": ("BINARY", {**expressions.BINARY, ast.Mult: "+"}),
}


@pytest.mark.parametrize("key", STEPS)
@pytest.mark.parametrize("mutant", MUTANTS)
def test_a_mutated_generator_fails_the_bit_test(mutant, key, monkeypatch, tmp_path):
    name, replacement = MUTANTS[mutant]
    monkeypatch.setattr(expressions, name, replacement)
    step = STEPS[key]
    mutated = CStep(generate(step, step.__name__), tmp_path, strict=False)
    differ, _, _ = mismatches(step, mutated, step_cases(step, 32, CASES[key] // 10))
    assert differ > 0, mutant


def recorded(monkeypatch, step) -> list:
    """The argument lists of every call the model makes of `step` (by its name)."""
    calls: list = []

    def counted(*arguments):
        calls.append(arguments)
        return step(*arguments)

    monkeypatch.setattr(model, step.__name__, counted)
    return calls


def test_the_models_step_is_the_translated_definition(monkeypatch):
    """CardanJoint.run takes its step from `joint_step` itself, not from a copy."""
    calls = recorded(monkeypatch, joint_step)
    joint = CardanJoint(life=False)
    outputs, moved = joint.run(0.0, 1e-3, (10.0, 0.0, 0.2, 0.0, 0.0, 5.0))
    assert len(calls) == 1
    taken = joint_step(*calls[0])
    assert bits(outputs) == bits(taken[MOVED:])
    assert bits(moved) == bits(taken[len(STATE) : MOVED])


def test_the_models_step_with_life_is_the_translated_definition(monkeypatch):
    """With life on, CardanJoint.run takes its step, Miner's sum included, from
    `joint_life_step`; the sum it keeps is the step's."""
    calls = recorded(monkeypatch, joint_life_step)
    joint = CardanJoint(life=True)
    for k in range(3):
        outputs, moved = joint.run(k * 0.1, 0.1, (300.0, 0.0, 0.2, 0.0, 0.0, -500.0))
    assert len(calls) == 3
    taken = joint_life_step(*calls[-1])
    state = len(LIFE_STATE)
    assert bits(outputs) == bits(taken[state + len(moved) :])
    assert bits(moved) == bits(taken[state : state + len(moved)])
    assert bits(joint.step_state()) == bits(taken[:state])
    assert joint.life_consumed > 0.0
    assert outputs[-1] == joint.life_consumed + joint.life_consumed_error
