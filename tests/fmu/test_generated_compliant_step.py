"""The CompliantJoint's generated step in the FMU's runtime (docs/codegen.md):
the default build takes every step it can in C, without entering Python, and
gives the same bits, statuses and messages as the same FMU stepping in Python,
FMI 2.0 and 3.0: over every kind of call the runtime serves (steps, reads of
moved inputs, a read after an input write, refusals, FMU states got, set and
serialized, the twist's watch, a reset) and over random runs with refusals, FMU states
set back, long steps and loads of both signs."""

import math
import random

import pytest
from test_fast_path import bits, count_entries, model_class, slave_classes
from test_generated_step import both
from test_generated_step import random_run as joint_random_run

from cardan_joint.host.instance import ExtractedFMU
from cardan_joint.models.compliant_joint.variables import COMPLIANT_JOINT as table


@pytest.fixture(scope="module", params=[2, 3], ids=["fmi2", "fmi3"])
def extracted(request, built):
    with ExtractedFMU(built("CompliantJoint", fmi_version=request.param)) as fmu:
        fmu.version = request.param
        with fmu.instance("warm-up"):  # pythonfmu imports the script
            pass
        yield fmu


GOOD = dict(input_speed=100.0, input_acceleration=0.0, output_speed=99.0,
            output_acceleration=0.0, bend_angle=0.3, bend_angle_rate=0.0)  # fmt: skip


def scenario(instance):
    """Every kind of call, and what each gave: values as bits, statuses (the
    messages are compared apart)."""
    seen = []
    record = seen.append
    outputs = instance.outputs
    instance.set(twist_angle_warning=0.05, torsional_stiffness=2e3)  # parameters, forwarded
    record(instance.exit_initialization_mode())
    for k in range(20):  # the spring winds past its stated twist: warned once
        instance.set(**{**GOOD, "input_speed": 100.0 + k, "bend_angle": 0.3 + 0.01 * k})
        record(instance.try_step(1e-3))
        record(bits(instance.values(*table.INPUTS, *outputs)))  # moved inputs too
    instance.set(output_speed=90.0)  # one input, then a read: direct feedthrough
    record(bits(instance.values("output_torque", "twist_angle")))
    instance.set(output_speed=math.nan)  # only a read of what depends on it warns
    record(bits(instance.values("output_angle", "twist_angle")))
    record(bits(instance.values("output_torque")))
    record(instance.try_step(1e-3))  # refused: the state stays
    instance.set(output_speed=-99.0)  # the spring's load reverses
    state = instance.get_state()
    for _ in range(3):
        record(instance.try_step(1e-3))  # taken again after a refused one
    record(bits(instance.values(*outputs)))
    serialized = instance.serialize_state(state)
    instance.set_state(state)
    record(bits(instance.values(*table.INPUTS, *outputs)))
    restored = instance.deserialize_state(serialized)
    record(instance.try_step(2e-3))
    instance.set_state(restored)
    record(instance.try_step(0.5))  # a long step
    record(bits(instance.values(*table.INPUTS, *outputs)))
    instance.free_state(state)
    instance.free_state(restored)
    fmu = instance.fmu  # a reset: the state from the parameters again, then steps in C
    fmu.reset()
    if instance.fmi3:
        fmu.enterInitializationMode(startTime=0.0)
    else:
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    instance.time = 0.0
    instance.set(**GOOD)
    record(instance.try_step(1e-3))
    record(bits(instance.values(*table.INPUTS, *outputs)))
    return seen


def test_every_kind_of_call_gives_the_python_steps_bits_and_messages(extracted, monkeypatch):
    (c_run, c_messages, c_counts), (python_run, python_messages, python_counts) = both(
        extracted, monkeypatch, scenario
    )
    assert c_run == python_run
    assert c_messages == python_messages
    watched = [m for m in c_messages if m[1] == "logWatch"]
    # The twist first (then, as the load grows, the torque and life).
    assert watched[0][0] == 1 and watched[0][2].startswith("twist_angle"), c_messages
    # In C: every taken step (the refused one goes to the slave, which says why).
    assert python_counts["run"] == python_counts["do_step"] == 27, (python_counts, c_counts)
    assert c_counts["run"] == c_counts["do_step"] == 1 and c_counts["fast_sync"] >= 3


def random_inputs(rng: random.Random) -> dict:
    """Speeds to 1000 rad/s both ways, an output shaft a little slower or faster,
    reversed or still (the spring loads either way), a bend that crosses 3 deg
    or reaches its guard, speed reversals, and now and then a value out of
    range or not a number."""
    speed = rng.choice([rng.uniform(-1000.0, 1000.0), rng.uniform(-2.0, 2.0), 0.0])
    values = {
        "input_speed": speed,
        "input_acceleration": rng.choice([0.0, rng.uniform(-1e4, 1e4), -2e3 * speed]),
        "output_speed": rng.choice([speed + rng.uniform(-3.0, 3.0), -speed, 0.0]),
        "output_acceleration": rng.choice([0.0, rng.uniform(-1e4, 1e4)]),
        "bend_angle": rng.choice([rng.uniform(-0.75, 0.75), -math.radians(3.0)]),
        "bend_angle_rate": rng.choice([0.0, rng.uniform(-2.0, 2.0), 2 * math.radians(3.0)]),
        "bend_angle_acceleration": rng.uniform(-20.0, 20.0),
    }
    if rng.random() < 0.05:
        values[rng.choice(list(values))] = rng.choice([math.nan, math.inf, 2e9])
    return values


def random_run(seed: int):
    return joint_random_run(seed, random_inputs, table.INPUTS)


@pytest.mark.parametrize("seed", [1, 2])
def test_random_runs_give_the_python_steps_bits_and_messages(extracted, monkeypatch, seed):
    (c_run, c_messages, c_counts), (python_run, python_messages, python_counts) = both(
        extracted, monkeypatch, random_run(seed)
    )
    assert c_run == python_run
    assert c_messages == python_messages
    assert c_counts["run"] < python_counts["run"] / 2, (c_counts, python_counts)
    assert any(status == 3 for status, _, _ in c_messages)  # some steps were refused


def test_the_python_step_switch_gives_the_same_run(extracted, monkeypatch):
    """CARDAN_JOINT_FMU_PYTHON_STEP=1 keeps every step in Python: the same
    statuses, messages and values as the steps in C, which never enter it."""
    slave_class, _ = slave_classes(extracted)
    outcomes = []
    for python_step in ("0", "1"):
        monkeypatch.setenv("CARDAN_JOINT_FMU_PYTHON_STEP", python_step)
        counts = count_entries(monkeypatch, model_class(slave_class), ("run",))
        messages: list = []
        with extracted.instance("switch", exit_initialization=False, messages=messages) as i:
            outcomes.append((random_run(3)(i), messages, counts["run"]))
    (c_run, c_messages, c_runs), (python_run, python_messages, python_runs) = outcomes
    assert c_run == python_run and c_messages == python_messages
    assert c_runs < python_runs / 2 and python_runs == 300, (c_runs, python_runs)
