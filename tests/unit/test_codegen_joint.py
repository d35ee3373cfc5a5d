"""The joint's generated C step (`step.joint_step` through `cardan_joint.codegen`)
gives the Python step's bits: every output, the moved inputs, the clock and the
exact angle, and the same decision to take or refuse the step, over random
operating points up to 1000 rad/s; and a mutated generator is caught."""

import ast
import math
import random

import pytest
from generated_c import CStep, bits

from cardan_joint.codegen import expressions, generate
from cardan_joint.models.universal_joint import model
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.step import MOVED, STATE, joint_step

THREE_DEGREES = math.radians(3.0)


def operating_point(rng: random.Random) -> list:
    """joint_step's arguments: speeds to 1000 rad/s both ways, loads of both signs,
    3 deg crossings, long steps, speed reversals, massive crosses, many turns."""
    max_bend = rng.choice([0.3, 0.7, 1.2, 1.5])
    h = rng.choice([1e-4, 1e-3, 0.01, 0.1, 0.5, 2.0, 10.0])
    speed = rng.choice([rng.uniform(-1000.0, 1000.0), rng.uniform(-5.0, 5.0), 0.0, 1000.0])
    acceleration = rng.choice([0.0, rng.uniform(-1e4, 1e4), -2.0 * speed / h])  # a reversal
    beta = rng.uniform(-0.9, 0.9) * max_bend
    rate, bend_acceleration = rng.uniform(-1.0, 1.0), rng.uniform(-10.0, 10.0)
    if rng.random() < 0.3:  # the bend crosses 3 deg inside the step
        beta, rate, bend_acceleration = -THREE_DEGREES, 2.0 * THREE_DEGREES / h, 0.0
    load = rng.choice([rng.uniform(-2000.0, 2000.0), -50.0, 0.0])
    turns = rng.choice([0, rng.randint(-(10**6), 10**6), 10**9])
    fraction, fraction_error = rng.uniform(0.0, 2.0 * math.pi), rng.uniform(-1e-16, 1e-16)
    phase = [rng.randint(-3, 3), rng.uniform(0.0, 2.0 * math.pi), rng.uniform(-1e-16, 1e-16)]
    inertia = [rng.choice([rng.uniform(0.0, 0.01), rng.uniform(0.5, 5.0)]) for _ in range(3)]
    return [
        rng.uniform(0.0, 100.0), h, speed, acceleration, beta, rate, bend_acceleration, load,
        turns, fraction, fraction_error, *phase, *inertia, max_bend, rng.random() > 0.03,
    ]  # fmt: skip


def refusable(rng: random.Random, point: list) -> list:
    """A point some of whose values are at or beyond a limit, or not numbers."""
    k = rng.choice([1, 2, 3, 4, 5, 6, 7, 17])
    point[k] = rng.choice([math.nan, math.inf, -math.inf, 2e5, -2e5, 1e300, 0.0, -1e-3])
    if rng.random() < 0.3:  # the bend exactly at its guard: refused, by a strict <
        point[4] = point[17]
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
    for _ in range(10):
        point = operating_point(rng)
        point[-1] = True
        point[4], point[5], point[6] = 0.1, 0.0, 0.0  # a bend that stays below its guard
        point[3] = 0.0 if abs(point[2]) * 1e-3 > 1.0 else point[3]
        for _ in range(2_000):
            point[1] = 1e-3
            python, c = joint_step(*point), c_step(*point)
            assert bits(python) == bits(c), point
            if python is None:
                break
            # The next step starts from the clock, angle and inputs this one left.
            point[0], point[8], point[9], point[10] = python[:STATE]
            point[2:8] = python[STATE:MOVED]


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
    assert bits(outputs) == bits(taken[MOVED:]) and bits(moved) == bits(taken[STATE:MOVED])
