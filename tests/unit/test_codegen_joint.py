"""The joint's generated C step (`step.joint_step` through `cardan_joint.codegen`)
gives the Python step's bits: every output, the moved inputs, the clock and the
exact angle, and the same decision to take or refuse the step, over random
operating points up to 1000 rad/s; and a mutated generator is caught."""

import ast
import inspect
import math
import random

import pytest
from generated_c import CStep, bits

from cardan_joint.codegen import expressions, generate
from cardan_joint.models.universal_joint import model
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.step import MOVED, STATE, joint_step

THREE_DEGREES = math.radians(3.0)


NAMES = tuple(inspect.signature(joint_step).parameters)
AT = {name: k for k, name in enumerate(NAMES)}


def operating_point(rng: random.Random) -> list:
    """joint_step's arguments: speeds to 1000 rad/s both ways, loads of both signs,
    3 deg crossings, long steps, speed reversals, massive crosses, many turns."""
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
    }
    for k in (1, 2, 3):  # a light or a massive cross
        point[f"crosspiece_inertia_{k}"] = rng.choice([rng.uniform(0, 0.01), rng.uniform(0.5, 5)])
    return [point[name] for name in NAMES]


def refusable(rng: random.Random, point: list) -> list:
    """A point some of whose values are at or beyond a limit, or not numbers."""
    name = rng.choice(NAMES[AT["input_speed"] : AT["load_torque"] + 1] + ("h", "max_bend_angle"))
    point[AT[name]] = rng.choice([math.nan, math.inf, -math.inf, 2e5, -2e5, 1e300, 0.0, -1e-3])
    if rng.random() < 0.3:  # the bend exactly at its guard: refused, by a strict <
        point[AT["bend_angle"]] = point[AT["max_bend_angle"]]
    return point


def cases(seed: int, count: int):
    rng = random.Random(seed)
    for _ in range(count):
        point = operating_point(rng)
        yield refusable(rng, point) if rng.random() < 0.25 else point


@pytest.fixture(scope="module")
def c_step(tmp_path_factory):
    return CStep(generate(joint_step, "joint_step"), tmp_path_factory.mktemp("joint_step"))


def mismatches(c_step, points) -> tuple[int, int, int]:
    """(cases whose bits or decision differ, steps taken, steps refused)."""
    differ = taken = 0
    points = list(points)
    for point in points:
        python = joint_step(*point)
        differ += bits(python) != bits(c_step(*point))
        taken += python is not None
    return differ, taken, len(points) - taken


def test_the_generated_step_gives_the_python_steps_bits(c_step):
    differ, taken, refused = mismatches(c_step, cases(32, 20_000))
    assert differ == 0
    assert taken > 10_000 and refused > 2_000, (taken, refused)


def test_a_long_run_of_the_generated_step_keeps_the_python_steps_bits(c_step):
    """2,000 steps from each start, each one from the state the last one left."""
    rng = random.Random(7)
    first_state, first_input = AT["turns"], AT["input_speed"]
    for _ in range(10):
        point = operating_point(rng)
        point[AT["parameters_valid"]] = True
        point[AT["bend_angle"] : AT["bend_angle_acceleration"] + 1] = [0.1, 0.0, 0.0]
        point[AT["h"]] = 1e-3
        for _ in range(2_000):
            python, c = joint_step(*point), c_step(*point)
            assert bits(python) == bits(c), point
            if python is None:
                break
            # The next step starts from the clock, state and inputs this one left.
            point[AT["time"]] += 1e-3
            point[first_state:first_input] = python[: len(STATE)]
            point[first_input : first_input + MOVED - len(STATE)] = python[len(STATE) : MOVED]


# Mutations of the generator the bit test must notice: the grouping of Python's
# tree dropped (C's precedence then reassociates a - (b - c)), a strict
# comparison made loose (the bend at its guard then passes), a product made a sum.
MUTANTS = {
    "no parentheses": ("parenthesized", lambda text: text),
    "< as <=": ("COMPARE", {**expressions.COMPARE, ast.Lt: "<="}),
    "* as +": ("BINARY", {**expressions.BINARY, ast.Mult: "+"}),
}


@pytest.mark.parametrize("mutant", MUTANTS)
def test_a_mutated_generator_fails_the_bit_test(mutant, monkeypatch, tmp_path):
    name, replacement = MUTANTS[mutant]
    monkeypatch.setattr(expressions, name, replacement)
    mutated = CStep(generate(joint_step, "joint_step"), tmp_path, strict=False)
    differ, _, _ = mismatches(mutated, cases(32, 2_000))
    assert differ > 0, mutant


def test_the_models_step_is_the_translated_definition(monkeypatch):
    """CardanJoint.run takes its step from `joint_step` itself, not from a copy."""
    calls = []

    def counted(*arguments):
        calls.append(arguments)
        return joint_step(*arguments)

    monkeypatch.setattr(model, "joint_step", counted)
    joint = CardanJoint(life=False)
    outputs, moved = joint.run(0.0, 1e-3, (10.0, 0.0, 0.2, 0.0, 0.0, 5.0))
    assert len(calls) == 1
    taken = joint_step(*calls[0])
    assert bits(outputs) == bits(taken[MOVED:])
    assert bits(moved) == bits(taken[len(STATE) : MOVED])
