"""The slave's side of the runtime's fast path (fmi/fast_path.py) against
setReal, doStep and getReal.

Two slaves of each model take the same random inputs, one through the normal
accessors, one as the runtime drives it when the step is the slave's: inputs
written into a C array of doubles (passed as a tuple), a step one call of
`fast_do_step` (the inputs when written, do_step, the store: a taken step's
outputs served from it), `fast_outputs` for a read that follows a write (or a
refused step), `fast_store` after any other call. Their outputs must agree bit for
bit, and so must their statuses and every message they log: refused steps,
held outputs, ignored parameters, FMU states set back.
"""

import math
import random
import struct

import pytest
from pythonfmu.enums import Fmi2Status

from cardan_joint.fmi.references import FIRST_VALUE_REFERENCE
from cardan_joint.fmi.slave import ModelSlave
from cardan_joint.fmi.slave3 import ModelSlave3


class CardanJointSlave(ModelSlave):
    model_folder = "universal_joint"


class PropshaftSlave(ModelSlave):
    model_folder = "propshaft"


class MotorSlave(ModelSlave):
    model_folder = "motor"


class LoadSlave(ModelSlave):
    model_folder = "load"


class CardanJointSlave3(ModelSlave3):
    model_folder = "universal_joint"


SLAVES = (CardanJointSlave, PropshaftSlave, MotorSlave, LoadSlave)
STEP = 1e-3


def bits(values):
    return [struct.pack("=d", v) for v in values]


class Loader:
    """What the runtime does with a slave: its values in two C arrays, the
    inputs passed as a tuple, each reply written back (fast_path.c)."""

    def __init__(self, slave):
        self.slave = slave
        layout = slave.fast_layout()
        self.inputs = layout["inputs"]
        self.known = [math.nan] * layout["known_size"]
        self.outputs = [math.nan] * layout["outputs"]
        self.written = False  # the slave has not taken the written inputs yet
        assert self.store() == Fmi2Status.ok  # (fresh: the outputs array is current)

    def take(self, reply, *arrays):
        """fast_values.c's take_reply: a bare status, or (status, values, ...)
        into `arrays` (names of this loader's lists), in order."""
        if not isinstance(reply, tuple):
            return reply
        status, *parts = reply
        values = [value for part in parts for value in part]
        assert len(values) == sum(len(getattr(self, name)) for name in arrays)
        for name in arrays:
            array = getattr(self, name)
            array[:], values = values[: len(array)], values[len(array) :]
        return status

    def given(self):
        return tuple(self.known[: self.inputs])

    def store(self, reply=None):  # `reply`: as fast_do_step hands it back
        self.fresh = False
        reply = self.slave.fast_store() if reply is None else reply
        return self.take(reply, "known", "outputs")

    def set_inputs(self, values):
        self.known[: len(values)] = values
        self.fresh = False
        self.written = True

    def step(self, time, step_size):
        """fast_values.c's fast_step, the step the slave's: one fast_do_step,
        given the inputs when written."""
        given = self.given() if self.written else None
        self.written = False
        answer, store_reply = self.slave.fast_do_step(time, step_size, given)
        taken = answer is True or getattr(answer, "status", None) == 0
        stored = self.store(store_reply)
        self.fresh = taken and stored == Fmi2Status.ok
        return Fmi2Status.ok if taken else Fmi2Status.error

    def evaluate(self, indices=None):
        self.written = False
        reply = self.slave.fast_outputs(self.given(), indices)
        return self.take(reply, "outputs")

    def read(self, indices=None):
        """getReal of flat `indices` (None: every output), as fast_get serves it."""
        if not self.fresh:
            self.fresh = self.evaluate(indices) == Fmi2Status.ok
        first = self.slave._refs.first_output
        values = self.known + self.outputs
        chosen = range(first, first + len(self.outputs)) if indices is None else indices
        return [values[i] if i < first else self.outputs[i - first] for i in chosen]


def messages(slave):
    return [(m.status, m.msg) for m in slave.log_queue]


def random_inputs(rng, table):
    """Mostly valid inputs near the start values; now and then NaN or out of range."""
    values = []
    for name in table.INPUTS:
        variable = table.BY_NAME[name]
        high = variable.max if variable.max is not None else 10.0
        draw = rng.random()
        if draw < 0.05:
            values.append(math.nan)
        elif draw < 0.1:
            values.append(2.0 * high + 1.0)
        else:
            values.append((variable.start or 0.0) + rng.uniform(-1.0, 1.0) * min(1.0, 0.01 * high))
    return values


def references(flat):
    """The FMI 2 value references of flat indices (value reference = 1-based position)."""
    return [i + FIRST_VALUE_REFERENCE for i in flat]


def initialized(cls):
    slave = cls(instance_name="fast")
    slave.setup_experiment(0.0)
    slave.exit_initialization_mode()
    return slave


@pytest.mark.parametrize("cls", SLAVES, ids=lambda cls: cls.__name__)
def test_the_arrays_give_the_normal_paths_outputs_statuses_and_messages(cls):
    rng = random.Random(21)
    normal, fast = initialized(cls), initialized(cls)
    loader = Loader(fast)
    refs, table = normal._refs, normal.table
    known = references(range(refs.first_output))
    assert bits(loader.known) == bits(normal.get_real(known))
    (parameter,) = references([refs.first_output - 1])  # set after initialization: ignored
    saved = {}
    time = 0.0
    outcomes = {True: 0, False: 0}
    for step in range(120):
        inputs = random_inputs(rng, table)
        normal.set_real(references(refs.all_inputs), inputs)
        loader.set_inputs(inputs)
        if step % 7 == 3:  # a read between the write and the step: direct feedthrough
            assert bits(loader.read()) == bits(normal.get_real(references(refs.all_outputs)))
        taken = normal.do_step(time, STEP)
        assert loader.step(time, STEP) == (Fmi2Status.ok if taken else Fmi2Status.error)
        outcomes[taken] += 1
        time += STEP if taken else 0.0
        assert bits(loader.read()) == bits(normal.get_real(references(refs.all_outputs))), step
        # The inputs the step moved, stored: the next step starts from them.
        assert bits(loader.given()) == bits(normal.get_real(references(refs.all_inputs))), step
        if step == 40:
            saved = {"normal": normal._get_fmu_state(), "fast": fast._get_fmu_state()}
        if step == 60:
            for slave in (normal, fast):
                slave.set_real([parameter], [1.0])
            loader.store()
        if step == 80:
            normal._set_fmu_state(saved["normal"])
            fast._set_fmu_state(saved["fast"])
            loader.store()
            time = normal._model.time
        assert messages(fast) == messages(normal), step
    assert bits(loader.known) == bits(normal.get_real(known))
    # The run went through taken and refused steps, held outputs and the ignored parameter.
    logged = {status for status, _ in messages(normal)}
    assert outcomes[True] > 50 and outcomes[False] > 5, outcomes
    assert {Fmi2Status.warning, Fmi2Status.error} <= logged


def test_a_refused_step_writes_no_outputs_and_held_outputs_are_not_kept():
    slave = initialized(CardanJointSlave)
    loader = Loader(slave)
    assert loader.step(0.0, STEP) == Fmi2Status.ok
    taken = list(loader.outputs)
    bend = slave._refs.names.index("bend_angle")
    inputs = list(loader.given())
    inputs[bend] = 1.5  # beyond the 80 deg guard
    loader.set_inputs(inputs)
    assert loader.step(STEP, STEP) == Fmi2Status.error
    assert slave._model.time == STEP
    # Held at the last valid inputs, and said so at every read, as getReal does.
    for reads in (1, 2):
        assert loader.evaluate() == Fmi2Status.warning
        warnings = [m for m in slave.log_queue if m.status == Fmi2Status.warning]
        assert len(warnings) == reads and "bend_angle" in warnings[-1].msg
        assert bits(loader.outputs) == bits(taken)
    loader.known[bend] = 0.2
    assert loader.evaluate() == Fmi2Status.ok


def test_an_internal_fault_is_an_error_status_with_a_message():
    slave = initialized(CardanJointSlave)
    loader = Loader(slave)
    slave._model.input_speed = "fast"  # no float: the step fails inside
    assert slave.do_step(0.0, STEP) is False
    assert "internal error in do_step" in slave.log_queue[-1].msg
    assert slave.fast_outputs(None) == Fmi2Status.error
    assert "internal error in fast_outputs" in slave.log_queue[-1].msg
    assert slave.fast_load(None) == Fmi2Status.error
    assert "internal error in fast_load" in slave.log_queue[-1].msg
    assert slave.fast_load(loader.given()) == Fmi2Status.ok


def test_the_layout_is_the_flat_index_and_the_same_for_fmi3():
    layout = CardanJointSlave.fast_layout()
    table = CardanJointSlave.table
    assert layout["names"] == [v.name for v in table.VARIABLES]
    assert layout["known_size"] == layout["first_output"] == layout["inputs"] + layout["parameters"]
    assert layout["names"][layout["first_output"] :] == list(table.OUTPUTS)
    assert layout["inputs"] == len(table.INPUTS) == 6 and layout["outputs"] == len(table.OUTPUTS)
    assert CardanJointSlave3.fast_layout() == layout


def test_the_fmi3_slave_steps_the_same_through_the_arrays():
    from pythonfmu3.enums import Fmi3Status

    def started():
        slave = CardanJointSlave3(instance_name="fast3")
        slave.enter_initialization_mode()
        slave.exit_initialization_mode()
        return slave

    rng = random.Random(3)
    normal, fast = started(), started()
    loader = Loader(fast)
    refs, table = normal._refs, normal.table
    statuses = set()
    for step in range(60):
        inputs = random_inputs(rng, table)
        normal._set_flat(refs.all_inputs, inputs, "fmi3SetFloat64")
        loader.set_inputs(inputs)
        status = loader.step(step * STEP, STEP)
        assert status == normal.do_step(step * STEP, STEP).status
        statuses.add(status)
        assert bits(loader.read()) == bits(normal._get_flat(refs.all_outputs)), step
        assert messages(fast) == messages(normal), step
    assert statuses == {Fmi3Status.ok, Fmi3Status.error}


@pytest.mark.parametrize("path", ["plain", "fast"])
def test_only_an_output_that_depends_on_an_invalid_input_warns(path):
    """An input out of range: a read of outputs that do not depend on it (their
    declared dependencies) gives their values without a warning; a read that
    holds one dependent output warns once, in either path."""
    slave = initialized(CardanJointSlave)
    loader = Loader(slave)
    refs, table = slave._refs, slave.table
    flat = {name: i for i, name in enumerate(refs.names)}
    assert loader.step(0.0, STEP) == Fmi2Status.ok
    bad = [0.4 if name != "load_torque" else 1e12 for name in table.INPUTS]  # beyond its range
    slave.set_real(references(refs.all_inputs), bad)
    loader.set_inputs(bad)
    independent = [
        flat[name] for name in table.OUTPUTS if "load_torque" not in table.BY_NAME[name].depends_on
    ]
    dependent = [flat["input_torque"]]
    assert len(independent) > 10 and flat["life_consumed"] in independent

    def read(indices):
        before = len(slave.log_queue)
        values = slave.get_real(references(indices)) if path == "plain" else loader.read(indices)
        return values, [m for m in slave.log_queue[before:] if m.status == Fmi2Status.warning]

    values, warnings = read(independent)
    assert warnings == []
    # Following the valid inputs: as a slave given only those.
    clean = initialized(CardanJointSlave)
    assert clean.do_step(0.0, STEP)
    clean.set_real(
        references(refs.all_inputs), [0.4 if n != "load_torque" else 0.0 for n in table.INPUTS]
    )
    assert bits(values) == bits(clean.get_real(references(independent)))
    for indices in (dependent, independent + dependent, None):
        values, warnings = read(indices if indices is not None else refs.all_outputs)
        assert len(warnings) == 1 and "load_torque" in warnings[0].msg
