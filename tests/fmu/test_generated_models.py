"""The Motor's, the Load's and the InertiaLoad's steps in their FMUs, generated
from each model's written step (docs/codegen.md), FMI 2.0 and 3.0: over random
runs (parameters set in initialization mode, now and then out of range; inputs
from the variable table, now and then out of range or not a number; long
steps; reads; FMU states got, set back and serialized) the FMU gives the same
bits, statuses and messages with its step in C as with
CARDAN_JOINT_FMU_PYTHON_STEP=1, and the steps taken in C never enter Python."""

import math
import random

import pytest
from step_cases import input_value, parameters
from test_fast_path import bits, count_entries, model_class, slave_classes

from cardan_joint.host.instance import ExtractedFMU
from cardan_joint.models import discover

MODELS = ("Motor", "Load", "InertiaLoad")
STEP_SIZES = (1e-4, 1e-3, 1e-3, 0.01, 0.5, 10.0, 0.0, math.nan)


@pytest.fixture(
    scope="module",
    params=[(key, version) for key in MODELS for version in (2, 3)],
    ids=lambda param: f"{param[0]}-fmi{param[1]}",
)
def extracted(request, built):
    key, version = request.param
    with ExtractedFMU(built(model=key, fmi_version=version)) as fmu:
        fmu.version = version
        fmu.table = discover()[key].table()
        with fmu.instance("warm-up"):  # pythonfmu imports the script
            pass
        yield fmu


def random_run(table, seed: int):
    def run(instance):
        rng = random.Random(seed)
        instance.set(**parameters(rng, table))  # in initialization mode
        seen = [instance.exit_initialization_mode()]
        states: list = []
        steps: list = []  # each step's status
        for _ in range(300):
            if rng.random() < 0.4:
                instance.set(**{n: input_value(rng, table.BY_NAME[n], 0.05) for n in table.INPUTS})
            status = instance.try_step(rng.choice(STEP_SIZES))
            seen.append(status)
            steps.append(status)
            if rng.random() < 0.5:  # a read after the step, or the next step at once
                seen.append(bits(instance.values(*table.INPUTS, *instance.outputs)))
            draw = rng.random()
            if draw < 0.05:
                states.append(instance.get_state())
            elif draw < 0.07 and states:
                instance.set_state(rng.choice(states))
                seen.append(bits(instance.values(*instance.outputs)))
            elif draw < 0.08 and states:
                serialized = instance.serialize_state(rng.choice(states))
                states.append(instance.deserialize_state(serialized))
                instance.set_state(states[-1])
        for state in states:
            instance.free_state(state)
        return seen, steps

    return run


@pytest.mark.parametrize("seed", range(4))
def test_random_runs_give_the_same_bits_statuses_and_messages_in_c(extracted, monkeypatch, seed):
    slave_class, _ = slave_classes(extracted)
    outcomes = []
    for python_step in ("0", "1"):
        monkeypatch.setenv("CARDAN_JOINT_FMU_PYTHON_STEP", python_step)
        counts = count_entries(monkeypatch, model_class(slave_class), ("run",))
        messages: list = []
        with extracted.instance("same", exit_initialization=False, messages=messages) as instance:
            outcomes.append((random_run(extracted.table, seed)(instance), messages, counts["run"]))
    (c_run, c_messages, c_runs), (python_run, python_messages, python_runs) = outcomes
    assert c_run == python_run
    assert c_messages == python_messages
    # With the step in Python every step enters it; in C only the refused ones,
    # which the slave names (as Error).
    _, steps = c_run
    refused = sum(1 for status in steps if status != 0)
    assert python_runs == len(steps) and c_runs == refused, (c_runs, python_runs, refused)
    assert all(status in (0, 3) for status in steps)
    assert sum(1 for status, _, _ in c_messages if status == 3) >= refused
    # Steps are taken unless the run's parameters are out of range (said at once).
    assert refused < len(steps) or "parameter" in c_messages[0][2], c_messages[:1]
