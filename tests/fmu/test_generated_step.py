"""The generated step in the FMU's runtime (docs/codegen.md): a build whose
model step the generator translates (the joint, with life and without) takes
every step it can in C, without entering Python, and gives the same bits,
statuses and messages as the same FMU stepping in Python, FMI 2.0 and 3.0: over
every kind of call the fast path serves (test_fast_path's scenario) and
over random runs with refusals, FMU states set back, long steps and loads past
the rated torque (warned once)."""

import math
import random

import pytest
from test_fast_path import bits, count_entries, model_class, scenario, slave_classes

from cardan_joint.host.instance import ExtractedFMU, status_of
from cardan_joint.models.universal_joint import variables as table

BUILDS = {"no-life": ("--no-life",), "life": ()}
COUNTED = ("fast_sync", "do_step")


@pytest.fixture(
    scope="module",
    params=[(version, build) for build in BUILDS for version in (2, 3)],
    ids=lambda param: f"fmi{param[0]}-{param[1]}",
)
def extracted(request, built):
    version, build = request.param
    with ExtractedFMU(built(fmi_version=version, settings=BUILDS[build])) as fmu:
        fmu.version = version
        with fmu.instance("warm-up"):  # pythonfmu imports the script
            pass
        yield fmu


def both(extracted, monkeypatch, run):
    """run(instance) with the generated step and with every step in Python (the
    slave then offers no step state, so the runtime keeps its step in Python):
    (results, messages, calls of the model's run and of the slave's methods)."""
    slave_class, fast_path = slave_classes(extracted)
    outcomes = []
    for generated in (True, False):
        if not generated:
            monkeypatch.delattr(fast_path, "fast_state_size")
        counts = count_entries(monkeypatch, slave_class, COUNTED)
        count_entries(monkeypatch, model_class(slave_class), ("run",), counts)
        messages: list = []
        with extracted.instance("same", exit_initialization=False, messages=messages) as instance:
            outcomes.append((run(instance), messages, dict(counts)))
    return outcomes


def test_every_kind_of_call_gives_the_python_steps_bits_and_messages(extracted, monkeypatch):
    (c_run, c_messages, c_counts), (python_run, python_messages, python_counts) = both(
        extracted, monkeypatch, scenario
    )
    assert c_run == python_run
    assert c_messages == python_messages
    # In C: every taken step (the refused one goes to the slave, which says why);
    # the slave caught up before each call that needs its state.
    assert python_counts == {"run": 24, "fast_sync": 0, "do_step": 24}
    assert c_counts["run"] == c_counts["do_step"] == 1 and c_counts["fast_sync"] >= 3


def random_inputs(rng: random.Random) -> dict:
    """Speeds to 1000 rad/s both ways, loads of both signs, a bend that crosses
    3 deg or reaches its guard (0.7 rad by default), speed reversals, and now
    and then a value out of range or not a number."""
    speed = rng.choice([rng.uniform(-1000.0, 1000.0), rng.uniform(-2.0, 2.0), 0.0])
    values = {
        "input_speed": speed,
        "input_acceleration": rng.choice([0.0, rng.uniform(-1e4, 1e4), -2e3 * speed]),
        "bend_angle": rng.choice([rng.uniform(-0.75, 0.75), -math.radians(3.0)]),
        "bend_angle_rate": rng.choice([0.0, rng.uniform(-2.0, 2.0), 2 * math.radians(3.0)]),
        "bend_angle_acceleration": rng.uniform(-20.0, 20.0),
        "load_torque": rng.choice([rng.uniform(-3000.0, 3000.0), -50.0]),
    }
    if rng.random() < 0.05:
        values[rng.choice(list(values))] = rng.choice([math.nan, math.inf, 2e9])
    return values


def random_run(seed: int, inputs_of=random_inputs, inputs=table.INPUTS):
    """A run of 300 steps of `inputs_of`'s random `inputs` (the joint's by default)."""

    def run(instance):
        rng = random.Random(seed)
        seen = [instance.exit_initialization_mode()]
        states = []
        for _ in range(300):
            instance.set(**inputs_of(rng))
            seen.append(instance.try_step(rng.choice([1e-4, 1e-3, 1e-3, 0.01, 0.5])))
            if rng.random() < 0.5:  # a read after the step, or the next step at once
                seen.append(bits(instance.values(*inputs, *instance.outputs)))
            draw = rng.random()
            if draw < 0.05:
                states.append(instance.get_state())
            elif draw < 0.08 and states:
                instance.set_state(rng.choice(states))
                seen.append(bits(instance.values(*instance.outputs)))
        for state in states:
            instance.free_state(state)
        return seen

    return run


@pytest.mark.parametrize("seed", [1, 2])
def test_random_runs_give_the_python_steps_bits_and_messages(extracted, monkeypatch, seed):
    (c_run, c_messages, c_counts), (python_run, python_messages, python_counts) = both(
        extracted, monkeypatch, random_run(seed)
    )
    assert c_run == python_run
    assert c_messages == python_messages
    assert c_counts["run"] < python_counts["run"] / 2, (c_counts, python_counts)
    # Some steps were refused (logged as Error, the status they return).
    assert any(status == 3 for status, _, _ in c_messages)


@pytest.fixture(scope="module", params=[2, 3], ids=["fmi2", "fmi3"])
def with_life(request, built):
    with ExtractedFMU(built(fmi_version=request.param)) as fmu:
        fmu.version = request.param
        yield fmu


def test_a_load_past_the_rated_torque_warns_once_with_the_c_step(with_life, monkeypatch):
    """The watches of the default build, with its step in C: the step that
    passes rated_torque is taken in C, the slave warns once (Warning, logWatch)
    and the run goes on in C; the same statuses, messages and values as with
    CARDAN_JOINT_FMU_PYTHON_STEP=1."""
    slave_class, _ = slave_classes(with_life)

    def run(instance):
        seen = [instance.exit_initialization_mode()]
        instance.set(input_speed=100.0, bend_angle=0.3, load_torque=500.0)
        for k in range(30):
            if k == 10:
                instance.set(load_torque=-2500.0)  # past the 1000 N.m rating, either sign
            seen.append(instance.try_step(1e-3))
            seen.append(bits(instance.values("input_torque", "life_consumed")))
        return seen

    outcomes = []
    for python_step in ("0", "1"):
        monkeypatch.setenv("CARDAN_JOINT_FMU_PYTHON_STEP", python_step)
        counts = count_entries(monkeypatch, model_class(slave_class), ("run",))
        messages: list = []
        with with_life.instance("watched", exit_initialization=False, messages=messages) as i:
            outcomes.append((run(i), messages, counts["run"]))
    (c_run, c_messages, c_runs), (python_run, python_messages, python_runs) = outcomes
    assert c_run == python_run and c_messages == python_messages
    watched = [m for m in c_messages if m[1] == "logWatch"]
    assert len(watched) == 1 and "input_torque" in watched[0][2], c_messages
    assert watched[0][0] == 1  # a Warning: the step stands
    assert (c_runs, python_runs) == (0, 30)


def test_a_slave_that_cannot_catch_up_leaves_the_instance_in_the_error_state(
    extracted, monkeypatch
):
    """The steps taken in C are handed to a slave whose fast_sync raises: every
    later call but reset and free is refused with Error and says why, rather than
    act on a slave behind the host; a reset makes a new slave that steps again
    (and catches up before terminate)."""
    _, fast_path = slave_classes(extracted)

    def behind(self, *args):
        raise RuntimeError("a slave that cannot take the state")

    monkeypatch.setattr(fast_path, "fast_sync", behind)
    messages: list = []
    with extracted.instance("behind", messages=messages) as instance:
        instance.set(input_speed=100.0, bend_angle=0.3)
        assert instance.try_step(1e-3) == 0  # in C: the slave is behind
        instance.set(load_torque=5.0)
        assert status_of(instance.values, "input_torque") == 3  # the slave is asked
        assert "could not take the state of the steps taken in C" in messages[-1][2]
        reset = f"fmi{3 if instance.fmi3 else 2}Reset"
        for call in (
            lambda: instance.try_step(1e-3),
            lambda: status_of(instance.values, "input_torque"),
            lambda: status_of(instance.get_state),
            lambda: instance.try_set(input_speed=1.0),
        ):
            del messages[:]
            assert call() == 3
            assert (
                len(messages) == 1
                and "after an error that left the slave out of step" in (messages[0][2])
            ), messages
            assert f"{reset} to start again" in messages[0][2]
        monkeypatch.undo()  # the new slave takes the state again
        instance.fmu.reset()
        if instance.fmi3:
            instance.fmu.enterInitializationMode(startTime=0.0)
        else:
            instance.fmu.setupExperiment(startTime=0.0)
            instance.fmu.enterInitializationMode()
        instance.fmu.exitInitializationMode()
        instance.time = 0.0
        instance.set(input_speed=100.0, bend_angle=0.3)
        assert instance.try_step(1e-3) == 0
        assert math.isfinite(instance.values("output_speed")[0])


def test_a_step_state_beyond_the_arrays_is_refused_and_the_slave_called_plainly(
    extracted, monkeypatch
):
    """A slave that says its step state holds 2**61 values (its arrays' sizes
    would wrap around): the runtime says so and calls the slave plainly, with
    the same values as the generated step."""
    _, fast_path = slave_classes(extracted)

    def run(instance):
        instance.set(input_speed=100.0, bend_angle=0.3, load_torque=50.0)
        return [instance.try_step(1e-3), bits(instance.values(*instance.outputs))]

    with extracted.instance("sized") as instance:
        expected = run(instance)
    monkeypatch.setattr(fast_path, "fast_state_size", lambda self: 2**61)
    messages: list = []
    with extracted.instance("sized", messages=messages) as instance:
        assert run(instance) == expected
    assert (
        "a step state of 2305843009213693952) is beyond what the runtime's arrays take"
        in (messages[0][2])
    ), messages
    assert messages[0][0] == 1
