"""The Propshaft's generated C step (`step.propshaft_<N>_step` through
`cardan_joint.codegen`, N = 2, 3, 4 joints, life on) gives the Python step's
bits: every output (each joint's bearing forces and life included), the moved
inputs, the exact angle, each joint's Miner's sum and the constants the state
carries, and the same decision to take or refuse the step, over random layouts
and operating points up to 1000 rad/s; and a mutated generator is caught."""

import inspect
import math
import random

import pytest
from generated_c import CStep, bits, mismatches
from test_codegen_joint import MUTANTS

from cardan_joint.codegen import expressions, generate
from cardan_joint.models.propshaft import model
from cardan_joint.models.propshaft.entries import STEPS
from cardan_joint.models.propshaft.model import Propshaft
from cardan_joint.models.propshaft.step import ahead_names, state_names
from cardan_joint.models.propshaft.variables import propshaft_table
from cardan_joint.physics.life_integral import unseen_ahead

JOINTS = (2, 3, 4)
CASES = {2: 300, 3: 150, 4: 150}  # the Python step integrates N chains of N joints a node
LAYOUTS = 6  # random layouts per number of joints (each costs a fluctuation search)


def random_propshaft(rng: random.Random, joints: int) -> Propshaft:
    """A layout with working angles up to ~25 deg, any phasing, light or massive
    crosses and shafts, any life rule."""
    values: dict = {"max_working_angle": 0.6}
    for k in range(joints + 1):
        values[f"shaft_{k}_side_angle"] = rng.uniform(-0.2, 0.2)
        values[f"shaft_{k}_top_angle"] = rng.choice([0.0, rng.uniform(-0.2, 0.2)])
    for k in range(1, joints):
        values[f"shaft_{k}_yoke_phase"] = rng.choice([0.0, rng.uniform(-4.0, 4.0), 1e6])
        values[f"shaft_{k}_inertia"] = rng.choice([0.0, rng.uniform(0.0, 0.1), 5.0])
    for k in (1, 2, 3):
        values[f"crosspiece_inertia_{k}"] = rng.choice([rng.uniform(0, 0.01), rng.uniform(0.5, 5)])
    values["input_angle_start"] = rng.uniform(-100.0, 100.0)
    values["bearing_radius"] = rng.uniform(0.01, 0.1)
    values["rated_torque"] = rng.choice([1000.0, rng.uniform(10.0, 5000.0)])
    values["life_constant"] = rng.choice([1.5e6, rng.uniform(1e3, 1e9)])
    values["life_exponent"] = rng.choice([10.0 / 3.0, 3.0, rng.uniform(1.0, 10.0)])
    values["life_min_angle"] = rng.choice([math.radians(3.0), 0.0, rng.uniform(0.0, 0.2)])
    return Propshaft(joints, **values)


def operating_point(rng: random.Random, state: tuple, joints: int) -> list:
    """(time, h, state, inputs): speeds to 1000 rad/s both ways, loads of both
    signs, long steps, speed reversals, many turns, Miner's sums anywhere."""
    h = rng.choice([1e-4, 1e-3, 1e-3, 0.01, 0.1, 0.5])
    speed = rng.choice([rng.uniform(-1000.0, 1000.0), rng.uniform(-5.0, 5.0), 0.0, 1000.0])
    acceleration = rng.choice([0.0, rng.uniform(-1e4, 1e4), -2.0 * speed / h])
    load = rng.choice([rng.uniform(-2000.0, 2000.0), -50.0, 0.0])
    angle = (rng.choice([0, rng.randint(-(10**6), 10**6), 10**9]), rng.uniform(0.0, 2 * math.pi),
             rng.uniform(-1e-16, 1e-16))  # fmt: skip
    sums = tuple(rng.choice([0.0, rng.uniform(0.0, 2.0)]) if k % 2 == 0 else
                 rng.uniform(-1e-17, 1e-17) for k in range(2 * joints))  # fmt: skip
    valid = state[3] and rng.random() > 0.03
    middle = state[4 : len(state) - 2 * joints - len(ahead_names(joints))]
    return [rng.uniform(0.0, 100.0), h, *angle, valid, *middle, *sums, *random_ahead(rng, joints),
            speed, acceleration, load]  # fmt: skip


def random_ahead(rng: random.Random, joints: int) -> tuple:
    """What life carries ahead (`ahead_names`): none, or a last plain panel
    before the step, at its start or short of it, with any cubic."""
    if rng.random() < 0.3:
        return unseen_ahead(range(joints))
    hi = rng.choice([0.0, -rng.uniform(0.0, 1e-2)])
    ahead: tuple = (hi - rng.uniform(1e-6, 0.1), hi)
    for _ in range(joints):
        a0 = rng.uniform(-2000.0, 2000.0)
        ahead += (a0, *(a0 * rng.uniform(-1.0, 1.0) * rng.choice([0.01, 0.3]) for _ in range(3)))
    return ahead


def refusable(rng: random.Random, point: list) -> list:
    """A point some of whose values are at or beyond a limit, or not numbers."""
    where = rng.choice([1, -3, -2, -1])  # h or an input
    point[where] = rng.choice([math.nan, math.inf, -math.inf, 2e5, -2e5, 1e300, 0.0, -1e-3, 2e9])
    return point


def cases(seed: int, joints: int, count: int):
    rng = random.Random(seed)
    shafts = [random_propshaft(rng, joints) for _ in range(LAYOUTS)]
    states = [shaft.step_state() for shaft in shafts]
    for _ in range(count):
        point = operating_point(rng, rng.choice(states), joints)
        yield refusable(rng, point) if rng.random() < 0.2 else point


@pytest.fixture(scope="module", params=JOINTS, ids=lambda n: f"{n}-joints")
def stepped(request, tmp_path_factory):
    """(the Python step, its C, the number of joints)."""
    step = STEPS[request.param]
    c = CStep(generate(step, step.__name__), tmp_path_factory.mktemp(step.__name__))
    return step, c, request.param


def test_the_entries_take_the_state_and_inputs_by_name():
    for joints, step in STEPS.items():
        names = tuple(inspect.signature(step).parameters)
        inputs = tuple(propshaft_table(joints).INPUTS)
        assert names == ("time", "h", *state_names(joints), *inputs)
        assert len(Propshaft(joints).step_state()) == len(state_names(joints))


def test_the_generated_step_gives_the_python_steps_bits(stepped):
    step, c_step, joints = stepped
    count = CASES[joints]
    differ, taken, refused = mismatches(step, c_step, cases(32 + joints, joints, count))
    assert differ == 0
    assert taken > count // 2 and refused > count // 10, (taken, refused)


def test_a_long_run_of_the_generated_step_keeps_the_python_steps_bits(stepped):
    """300 steps from each start, each one from the state the last one left
    (Miner's sums grow step by step, loads of both signs)."""
    step, c_step, joints = stepped
    rng = random.Random(7)
    state = len(state_names(joints))
    for point in list(cases(5, joints, 4)):
        point[1], point[5] = 1e-3, True
        point[-3:] = [rng.uniform(-300.0, 300.0), rng.uniform(-100.0, 100.0), -300.0]
        for _ in range(300):
            python, c = step(*point), c_step(*point)
            assert bits(python) == bits(c), point
            assert python is not None
            point[0] += 1e-3
            point[2 : 2 + state] = python[:state]
            point[-3:] = python[state : state + 3]


@pytest.mark.parametrize("mutant", MUTANTS)
def test_a_mutated_generator_fails_the_bit_test(mutant, monkeypatch, tmp_path):
    name, replacement = MUTANTS[mutant]
    monkeypatch.setattr(expressions, name, replacement)
    step = STEPS[3]
    mutated = CStep(generate(step, step.__name__), tmp_path, strict=False)
    differ, _, _ = mismatches(step, mutated, cases(32, 3, 40))
    assert differ > 0, mutant


def test_the_models_step_is_the_translated_definition(monkeypatch):
    """Propshaft.run takes its step, the Miner's sums included, from its entry."""
    calls: list = []
    original = STEPS[3]

    def counted(*arguments):
        calls.append(arguments)
        return original(*arguments)

    monkeypatch.setitem(model.STEPS, 3, counted)
    shaft = Propshaft(3)
    for k in range(3):
        outputs, moved = shaft.run(k * 0.1, 0.1, (300.0, 0.0, -500.0))
    assert len(calls) == 3
    taken = original(*calls[-1])
    state = len(state_names(3))
    assert bits(outputs) == bits(taken[state + 3 :])
    assert bits(moved) == bits(taken[state : state + 3])
    assert bits(shaft.step_state()) == bits(taken[:state])
    assert bits(outputs) == bits(shaft.outputs())
    assert all(total > 0.0 for total, _ in shaft._life)
