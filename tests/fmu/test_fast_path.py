"""The runtime's side of the fast path (fmi/native/fast_path.c): in a host the
FMU's Real values are served in C; a step in Python is the slave's do_step
between the calls that keep the slave and the arrays in step, the outputs it
gives served from the arrays; an instance whose slave cannot be claimed keeps
plain forwarding, and both give the same values, statuses and messages, bit
for bit.

The slave's Python is observed in this process (FMPy loads the FMU here):
its classes are those of the FMU's own copy of cardan_joint, reached through
the script module pythonfmu imported."""

import ctypes
import math
import struct
import sys
from pathlib import Path

import pytest
from robustness_support import GOOD

from cardan_joint.fmi.slave3 import TIME_REFERENCE
from cardan_joint.host.instance import ExtractedFMU, status_of
from cardan_joint.models.universal_joint import variables as table

PLAIN_ENTRIES = {
    2: ("set_real", "get_real", "do_step"),
    3: ("set_float64", "get_float64", "do_step"),
}
LAST_SUCCESSFUL_TIME, TERMINATED = 2, 3  # fmi2StatusKind


@pytest.fixture(autouse=True)
def python_step(monkeypatch):
    """Every step in Python: the default build's generated step would take every
    step in C (test_generated_step.py)."""
    monkeypatch.setenv("CARDAN_JOINT_FMU_PYTHON_STEP", "1")


@pytest.fixture(scope="module", params=[2, 3], ids=["fmi2", "fmi3"])
def extracted(request):
    fmu_path = request.getfixturevalue("fmu_path" if request.param == 2 else "fmi3_path")
    with ExtractedFMU(fmu_path) as fmu:
        fmu.version = request.param
        yield fmu


def slave_classes(extracted):
    """The FMU copy's slave class and its FastPath, once an instance made pythonfmu
    import the script."""
    module = (Path(extracted.directory) / "resources" / "slavemodule.txt").read_text().strip()
    script = sys.modules[module]
    slave = next(v for v in vars(script).values() if isinstance(v, type) and v.__module__ == module)
    return slave, next(c for c in slave.__mro__ if c.__name__ == "FastPath")


def model_class(slave_class):
    """The physics class of the FMU copy's model: a step in Python enters it once
    (`run`)."""
    package = next(c for c in slave_class.__mro__ if c.__name__ == "FastPath").__module__
    package = package.rsplit(".fmi.", 1)[0]
    module = sys.modules[f"{package}.models.{slave_class.model_folder}.model"]
    own = [v for v in vars(module).values() if isinstance(v, type)]
    running = [v for v in own if v.__module__ == module.__name__ and hasattr(v, "run")]
    # The model's own class: no other that runs derives from it (a compliant
    # drive's base runs too).
    return next(v for v in running if not any(issubclass(o, v) for o in running if o is not v))


def count_entries(monkeypatch, slave_class, names, counts=None):
    """Count the calls of these methods of the FMU's slave (found on its class at call
    time), into `counts` if given."""
    counts = {} if counts is None else counts
    counts.update(dict.fromkeys(names, 0))
    for name in names:
        owner = next(c for c in slave_class.__mro__ if name in vars(c))
        original = vars(owner)[name]

        def counted(self, *args, _original=original, _name=name):
            counts[_name] += 1
            return _original(self, *args)

        monkeypatch.setattr(owner, name, counted)
    return counts


def bits(values):
    """The exact doubles (an FMI 3 array's elements in order)."""
    flat = [x for v in values for x in (v if isinstance(v, list) else [v])]
    return struct.pack(f"{len(flat)}d", *flat)


def test_a_step_enters_do_step_once_and_values_never(extracted, monkeypatch):
    """Each step in Python is one call of the slave, fast_do_step, which takes the
    written inputs, runs do_step (one run of the model) and stores (fast_load and
    fast_store are not called besides: the runtime binds fast_do_step when it
    claims the slave, so only the reset's new slave shows its call); the outputs
    it gave are read from the arrays, not evaluated again."""
    with extracted.instance("warm-up"):
        pass
    slave_class, _ = slave_classes(extracted)
    with extracted.instance("fast") as fast:
        set_values, get_values, do_step = plain = PLAIN_ENTRIES[extracted.version]
        one_call = ("fast_do_step", "fast_load", "fast_store")
        counts = count_entries(monkeypatch, slave_class, (*plain, "fast_outputs", *one_call))
        count_entries(monkeypatch, model_class(slave_class), ("run",), counts)
        for k in range(50):
            fast.set(**{**GOOD, "load_torque": 80.0 + k})
            fast.step(1e-3)
            outputs = fast.get_flat_outputs()
        stepped = {set_values: 0, get_values: 0, "fast_outputs": 0}
        taken = {**dict.fromkeys(one_call[1:], 50), "fast_do_step": 0, do_step: 50, "run": 50}
        assert counts == {**stepped, **taken}
        assert all(math.isfinite(v) for v in outputs.values())
        # A reset builds a new slave: the loader finds it and keeps the fast path.
        fast.fmu.reset()
        if fast.fmi3:
            fast.fmu.enterInitializationMode(startTime=0.0)
        else:
            fast.fmu.setupExperiment(startTime=0.0)
            fast.fmu.enterInitializationMode()
        fast.fmu.exitInitializationMode()
        fast.set(**GOOD)
        fast.step(1e-3)
        fast.get_outputs()
        assert (counts["fast_do_step"], counts[do_step], counts["run"]) == (1, 51, 51)


def step_status(instance, step=1e-3):
    """A step's status and what the host learns of it: FMI 2 asks afterwards
    (FMPy's simulate_fmu does after a refused step; pythonfmu's doStep keeps it),
    FMI 3's doStep answers it (the last successful time)."""
    fmu = instance.fmu
    if instance.fmi3:
        flags = [ctypes.c_bool(True) for _ in range(3)]
        last = ctypes.c_double(-1.0)
        status = fmu.dll.fmi3DoStep(
            fmu.component,
            ctypes.c_double(instance.time),
            ctypes.c_double(step),
            False,
            *map(ctypes.byref, flags),
            ctypes.byref(last),
        )
        if status == 0:
            instance.time += step
        return status, [flag.value for flag in flags], bits([last.value])
    status = instance.try_step(step)
    return status, bits([fmu.getRealStatus(LAST_SUCCESSFUL_TIME)]), fmu.getBooleanStatus(TERMINATED)


def scenario(instance):
    """Every kind of call the fast path serves or steps around, and what each gave:
    values as bits, statuses and messages."""
    seen = []
    outputs = instance.outputs
    record = seen.append
    fmu = instance.fmu
    instance.set(max_bend_angle=1.2)  # a parameter in initialization mode: forwarded
    record(bits(instance.values(*outputs)))
    record(instance.exit_initialization_mode())
    if not instance.fmi3:
        record(bits([fmu.getRealStatus(LAST_SUCCESSFUL_TIME)]))  # NaN before any step
    for k in range(20):
        instance.set(**{**GOOD, "input_speed": 12.0 + 0.5 * k, "bend_angle": 0.3 + 0.01 * k})
        record(step_status(instance))
        record(bits(instance.values(*table.INPUTS, *outputs)))  # moved inputs too
    instance.set(bend_angle=0.5)  # one input, then a read: direct feedthrough
    record(bits(instance.values("output_speed", "bend_angle")))
    instance.set(bend_angle=2.0)  # beyond the guard: outputs held, warned at each read
    record(bits(instance.values(*outputs)))
    record(bits(instance.values("output_angle")))
    record(step_status(instance))  # refused: the state stays
    record(instance.try_set(yoke_phase=0.3))  # a fixed parameter after initialization
    # An invalid load: only a read of an output that depends on it warns.
    instance.set(bend_angle=0.4, load_torque=math.nan)
    record(bits(instance.values("output_angle", "output_speed")))
    record(bits(instance.values("input_torque")))
    instance.set(load_torque=GOOD["load_torque"])
    state = instance.get_state()
    record(step_status(instance))  # taken again after a refused one
    record(bits(instance.values(*outputs)))
    serialized = instance.serialize_state(state)
    instance.set_state(state)
    record(bits(instance.values(*table.INPUTS, *outputs)))
    restored = instance.deserialize_state(serialized)
    record(instance.try_step(2e-3))
    instance.set_state(restored)
    record(instance.try_step(1e-3))
    record(bits(instance.values(*table.INPUTS, *outputs)))
    instance.free_state(state)
    instance.free_state(restored)
    # Forwarded: FMI 2's read of a variable it does not have, FMI 3's time.
    if instance.fmi3:
        record(bits(fmu.getFloat64([TIME_REFERENCE])))
    else:
        record(status_of(fmu.getReal, [len(table.VARIABLES) + 3]))
    return seen


def test_a_refused_fmu_state_leaves_the_outputs_served_as_they_were(extracted, monkeypatch):
    """The runtime joins FMPy's Python: the state handle is the slave's own dict,
    emptied of its start time after it was taken. The refused set changes
    nothing: the next read is served from the arrays, nothing evaluated again."""
    with extracted.instance("warm-up"):
        pass
    slave_class, _ = slave_classes(extracted)
    counts = count_entries(monkeypatch, slave_class, ("fast_outputs", "fast_store"))
    with extracted.instance("refused") as instance:
        instance.set(**GOOD)
        instance.step(1e-3)
        saved = instance.get_state()
        instance.step(1e-3)
        before = bits(instance.values(*table.INPUTS, *instance.outputs))
        seen = dict(counts)
        del ctypes.cast(saved, ctypes.py_object).value["start_time"]
        assert status_of(instance.set_state, saved) == 3
        assert bits(instance.values(*table.INPUTS, *instance.outputs)) == before
        assert counts == seen
        instance.free_state(saved)


def test_plain_calls_when_the_slave_has_no_fast_path_give_the_same_bits(extracted, monkeypatch):
    with extracted.instance("warm-up"):
        pass
    slave_class, fast_path = slave_classes(extracted)
    set_values, get_values, do_step = plain_entries = PLAIN_ENTRIES[extracted.version]
    fast_messages, plain_messages = [], []
    with extracted.instance("same", exit_initialization=False, messages=fast_messages) as fast:
        counts = count_entries(monkeypatch, slave_class, plain_entries)
        fast_run = scenario(fast)
        fast_counts = dict(counts)
    monkeypatch.delattr(fast_path, "fast_layout")  # the runtime then calls get_real & co.
    with extracted.instance("same", exit_initialization=False, messages=plain_messages) as plain:
        counts = count_entries(monkeypatch, slave_class, plain_entries)
        plain_run = scenario(plain)
        plain_counts = dict(counts)
    # The fast instance forwarded only the parameter set, the read of a
    # variable it does not have and the steps.
    assert fast_counts == {set_values: 1, get_values: 1, do_step: 24}
    assert plain_counts[do_step] == 24 and plain_counts[set_values] >= 24
    assert fast_run == plain_run
    assert fast_messages == plain_messages
    assert any(status == 1 and "held" in text for status, _, text in fast_messages)
    assert any(status == 3 for status, _, _ in fast_messages)  # the refused step
    # The reads of the outputs the load leaves alone did not warn (fast_get
    # passes the indices it reads): one warning of the load, at its read.
    assert sum("load_torque" in text for _, _, text in fast_messages) == 1, fast_messages


def test_each_input_write_reaches_the_slave_to_the_bit(extracted, monkeypatch):
    """The inputs cross as a tuple of the known array's doubles: 0.0 then -0.0,
    or the smallest change, reaches the slave as written."""
    with extracted.instance("warm-up"):
        pass
    slave_class, _ = slave_classes(extracted)
    model = model_class(slave_class)
    original, seen = model.run, []

    def recording(self, time, h, inputs):
        seen.append(inputs)
        return original(self, time, h, inputs)

    monkeypatch.setattr(model, "run", recording)
    written = (0.0, -0.0, -0.0, 5e-324, -0.1)
    with extracted.instance("bits") as fast:
        for value in written:
            fast.set(**{**GOOD, "bend_angle_acceleration": value})
            fast.step(1e-3)
    column = table.INPUTS.index("bend_angle_acceleration")
    assert bits(inputs[column] for inputs in seen) == bits(written)
