"""The CompliantPropshaft's generated step in the FMU's runtime (docs/codegen.md):
the default build (2 joints, life on) and the 3- and 4-joint builds take every
step they can in C, without entering Python, and give the same bits, statuses
and messages as the same FMU stepping in Python (its slave offering no step
state, or CARDAN_JOINT_FMU_PYTHON_STEP=1), FMI 2.0 and 3.0: random runs with
refusals, FMU states set back and serialized, long steps, speed reversals, the
spring's torque of both signs, and a reset."""

import math
import random

import pytest
from test_fast_path import bits
from test_generated_propshaft_step import BUILDS, random_run, reset, three_ways

from cardan_joint.host.instance import ExtractedFMU

INPUTS = ("input_speed", "input_acceleration", "output_speed", "output_acceleration")


@pytest.fixture(
    scope="module",
    params=[(version, joints) for joints in BUILDS for version in (2, 3)],
    ids=lambda param: f"fmi{param[0]}-{param[1]}-joints",
)
def extracted(request, built):
    version, joints = request.param
    path = built(model="CompliantPropshaft", fmi_version=version, settings=BUILDS[joints])
    with ExtractedFMU(path) as fmu:
        fmu.version = version
        with fmu.instance("warm-up"):  # pythonfmu imports the script
            pass
        yield fmu


def random_inputs(rng: random.Random) -> dict:
    """Speeds to 1000 rad/s both ways, reversals, an output shaft a little
    slower or faster (the spring winds both ways), now and then a value out of
    range or not a number."""
    speed = rng.choice([rng.uniform(-1000.0, 1000.0), rng.uniform(-2.0, 2.0), 0.0])
    values = {
        "input_speed": speed,
        "input_acceleration": rng.choice([0.0, rng.uniform(-1e4, 1e4), -2e3 * speed]),
        "output_speed": speed * rng.uniform(0.95, 1.05),
        "output_acceleration": rng.choice([0.0, rng.uniform(-1e3, 1e3)]),
    }
    if rng.random() < 0.05:
        values[rng.choice(INPUTS)] = rng.choice([math.nan, math.inf, 2e9])
    return values


@pytest.mark.parametrize("seed", [1, 2])
def test_random_runs_give_the_python_steps_bits_and_messages(extracted, monkeypatch, seed):
    run = random_run(seed, inputs=INPUTS, inputs_of=random_inputs)
    generated, no_state, environment = three_ways(extracted, monkeypatch, run)
    assert generated[0] == no_state[0] == environment[0]
    assert generated[1] == no_state[1] == environment[1]
    assert generated[2]["run"] < no_state[2]["run"] / 2, (generated[2], no_state[2])
    assert any(status == 3 for status, _, _ in generated[1])  # some steps refused


def test_a_reset_keeps_the_generated_step(extracted, monkeypatch):
    """After a reset the runtime hands the new state over and steps in C again,
    from the start, as in Python."""

    def run(instance):
        seen = [instance.exit_initialization_mode()]
        for _ in range(2):
            for k in range(20):
                instance.set(input_speed=300.0 + k, input_acceleration=50.0,
                             output_speed=299.0 + k, output_acceleration=40.0)  # fmt: skip
                seen.append(instance.try_step(1e-3))
            seen.append(bits(instance.values(*INPUTS, *instance.outputs)))
            reset(instance)
        return seen

    generated, no_state, environment = three_ways(extracted, monkeypatch, run)
    assert generated[:2] == no_state[:2] == environment[:2]
    assert generated[2]["run"] == 0 and environment[2]["run"] == 40
