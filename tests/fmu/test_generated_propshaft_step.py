"""The Propshaft's generated step in the FMU's runtime (docs/codegen.md): the
default build (2 joints, life on) and the 3- and 4-joint builds take every step
they can in C, without entering Python, and give the same bits, statuses and
messages as the same FMU stepping in Python (its slave offering no step state,
or CARDAN_JOINT_FMU_PYTHON_STEP=1), FMI 2.0 and 3.0: random runs with refusals,
FMU states set back and serialized, long steps, speed reversals, loads of both
signs past the rated torque (warned once), and a reset."""

import math
import random

import pytest
from test_fast_path import bits, count_entries, model_class, slave_classes

from cardan_joint.host.instance import ExtractedFMU

BUILDS = {2: (), 3: ("--joints", "3"), 4: ("--joints", "4")}
INPUTS = ("input_speed", "input_acceleration", "load_torque")
COUNTED = ("fast_sync", "do_step")


@pytest.fixture(
    scope="module",
    params=[(version, joints) for joints in BUILDS for version in (2, 3)],
    ids=lambda param: f"fmi{param[0]}-{param[1]}-joints",
)
def extracted(request, built):
    version, joints = request.param
    path = built(model="Propshaft", fmi_version=version, settings=BUILDS[joints])
    with ExtractedFMU(path) as fmu:
        fmu.version = version
        with fmu.instance("warm-up"):  # pythonfmu imports the script
            pass
        yield fmu


def random_inputs(rng: random.Random) -> dict:
    """Speeds to 1000 rad/s both ways, reversals, loads of both signs past the
    rated 1000 N.m, now and then a value out of range or not a number."""
    speed = rng.choice([rng.uniform(-1000.0, 1000.0), rng.uniform(-2.0, 2.0), 0.0])
    values = {
        "input_speed": speed,
        "input_acceleration": rng.choice([0.0, rng.uniform(-1e4, 1e4), -2e3 * speed]),
        "load_torque": rng.choice([rng.uniform(-3000.0, 3000.0), -50.0, 0.0]),
    }
    if rng.random() < 0.05:
        values[rng.choice(INPUTS)] = rng.choice([math.nan, math.inf, 2e9])
    return values


def random_run(seed: int, steps: int = 100, inputs=INPUTS, inputs_of=random_inputs):
    """A run of `steps` random steps: `inputs_of(rng)` the `inputs` of each."""

    def run(instance):
        rng = random.Random(seed)
        seen = [instance.exit_initialization_mode()]
        states = []
        for _ in range(steps):
            instance.set(**inputs_of(rng))
            seen.append(instance.try_step(rng.choice([1e-4, 1e-3, 1e-3, 0.01, 0.1])))
            if rng.random() < 0.5:  # a read after the step, or the next step at once
                seen.append(bits(instance.values(*inputs, *instance.outputs)))
            draw = rng.random()
            if draw < 0.05:
                states.append(instance.get_state())
            elif draw < 0.08 and states:
                restored = instance.deserialize_state(instance.serialize_state(rng.choice(states)))
                instance.set_state(restored)
                instance.free_state(restored)
                seen.append(bits(instance.values(*instance.outputs)))
        seen.append(bits(instance.values(*instance.outputs)))
        for state in states:
            instance.free_state(state)
        return seen

    return run


def three_ways(extracted, monkeypatch, run):
    """run(instance) with the generated step, with the slave offering no step
    state and with CARDAN_JOINT_FMU_PYTHON_STEP=1: (results, messages, calls of
    the model's run and of the slave's fast_sync and do_step) each."""
    slave_class, fast_path = slave_classes(extracted)
    outcomes = []
    for way in ("generated", "no state", "environment"):
        if way == "no state":
            monkeypatch.delattr(fast_path, "fast_state_size")
        monkeypatch.setenv("CARDAN_JOINT_FMU_PYTHON_STEP", "1" if way == "environment" else "0")
        counts = count_entries(monkeypatch, slave_class, COUNTED)
        count_entries(monkeypatch, model_class(slave_class), ("run",), counts)
        messages: list = []
        with extracted.instance("same", exit_initialization=False, messages=messages) as instance:
            outcomes.append((run(instance), messages, dict(counts)))
    return outcomes


@pytest.mark.parametrize("seed", [1, 2])
def test_random_runs_give_the_python_steps_bits_and_messages(extracted, monkeypatch, seed):
    generated, no_state, environment = three_ways(extracted, monkeypatch, random_run(seed))
    assert generated[0] == no_state[0] == environment[0]
    assert generated[1] == no_state[1] == environment[1]
    assert generated[2]["run"] < no_state[2]["run"] / 2, (generated[2], no_state[2])
    assert any(status == 3 for status, _, _ in generated[1])  # some steps refused
    # Past the rated torque: the watch warned of the input torque (once, and
    # again after an FMU state set back from before it).
    assert any("input_torque" in text for _, category, text in generated[1]
               if category == "logWatch")  # fmt: skip


def reset(instance) -> None:
    """fmi2Reset / fmi3Reset, then initialization again from time 0."""
    fmu = instance.fmu
    fmu.reset()
    if instance.fmi3:
        fmu.enterInitializationMode(startTime=0.0)
    else:
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    instance.time = 0.0


def test_a_reset_keeps_the_generated_step(extracted, monkeypatch):
    """After a reset the runtime hands the new state over and steps in C again,
    from the start, as in Python."""

    def run(instance):
        seen = [instance.exit_initialization_mode()]
        for _ in range(2):
            for k in range(20):
                instance.set(input_speed=300.0 + k, input_acceleration=50.0, load_torque=-400.0)
                seen.append(instance.try_step(1e-3))
            seen.append(bits(instance.values(*INPUTS, *instance.outputs)))
            reset(instance)
        return seen

    generated, no_state, environment = three_ways(extracted, monkeypatch, run)
    assert generated[:2] == no_state[:2] == environment[:2]
    assert generated[2]["run"] == 0 and environment[2]["run"] == 40
