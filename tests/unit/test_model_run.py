"""The FMU's step on the physics (`run`, which the slave's do_step calls): the
joint's written step gives `step` then `outputs` to the bit, refusals included,
and every model's positional inputs follow its table."""

import math
import random
import struct

from cardan_joint.models import discover

# A joint near its limits: steps that are taken, refused (bend reaching the guard,
# a bend peak inside the step, out-of-range or NaN inputs, bad step sizes).
INPUTS = ("input_speed", "input_acceleration", "bend_angle", "bend_angle_rate")


def bits(values):
    return struct.pack(f"{len(values)}d", *values)


def model_of(key, **values):
    spec = discover()[key]
    return spec.make(spec.default_settings, **values)


def random_inputs(rng, model):
    values = list(model.inputs())
    for i, value in enumerate(values):
        draw = rng.random()
        if draw < 0.03:
            values[i] = math.nan
        elif draw < 0.06:
            values[i] = 1e300
        else:
            values[i] = value + rng.uniform(-0.3, 0.3) * max(1.0, abs(value))
    return tuple(values)


def test_run_is_step_then_outputs_to_the_bit_for_every_model():
    rng = random.Random(24)
    for key in discover():
        inline, plain = model_of(key), model_of(key)
        outcomes = {True: 0, False: 0}
        for k in range(300):
            inputs = random_inputs(rng, plain)
            h = rng.choice([1e-3, 0.05, 0.3, -1e-3, math.nan]) if k % 17 == 0 else 1e-3
            result = inline.run(plain.time, h, inputs)
            plain.set_inputs(inputs)
            problem = plain.step(h)
            if problem:
                assert result == problem, (key, k)
            else:
                outputs, moved = result
                assert bits(outputs) == bits(plain.outputs()), (key, k)
                assert bits(moved) == bits(plain.inputs()), (key, k)
            outcomes[problem is None] += 1
            assert inline.state() == plain.state() or math.nan in inputs, (key, k)
            if problem:  # start the next one from valid inputs again
                inline.set_inputs(model_of(key).inputs())
                plain.set_inputs(model_of(key).inputs())
        assert outcomes[True] > 50 and outcomes[False] > 10, (key, outcomes)


def test_positional_inputs_follow_the_table():
    for key in discover():
        model = model_of(key)
        names = model.table.INPUTS
        values = tuple(0.001 * (i + 1) for i in range(len(names)))
        model.set_inputs(values)
        assert tuple(getattr(model, n) for n in names) == values == model.inputs(), key
