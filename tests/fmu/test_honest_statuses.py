"""Issue 33 (and 35's state handles): statuses that mean what they say, FMI 2.0 and 3.0.
A string that is not UTF-8, a state Set refuses, bytes Deserialize refuses, a state
passed where its address belongs: each is Error with a message, and the instance lives."""

import ctypes
import json

import pytest
from robustness_support import all_reals

from cardan_joint.host.instance import FmuInstance, status_of

NOT_UTF8 = b"\xff\xfe"


@pytest.fixture(params=[2, 3], ids=["fmi2", "fmi3"])
def joint(request, model_description, unzipped_fmu, fmi3_description, fmi3_unzipped):
    description, folder = (
        (model_description, unzipped_fmu)
        if request.param == 2
        else (fmi3_description, fmi3_unzipped)
    )
    messages: list = []
    instance = FmuInstance(description, folder, name="honest", messages=messages)
    instance.messages = messages
    yield instance
    instance.close()


def _set_string(joint, reference, text: bytes) -> int:
    fmu = joint.fmu
    vr, value = (ctypes.c_uint32 * 1)(reference), (ctypes.c_char_p * 1)(text)
    if joint.fmi3:
        return status_of(fmu.fmi3SetString, fmu.component, vr, 1, value, 1)
    return status_of(fmu.fmi2SetString, fmu.component, vr, 1, value)


def test_a_string_that_is_not_utf8_is_an_error_naming_the_variable_and_the_instance_lives(joint):
    joint.step(0.01)
    before = all_reals(joint)
    reference = joint.references["input_speed"]
    assert _set_string(joint, reference, NOT_UTF8) == 3  # Error, not Fatal
    message = joint.messages[-1][2]
    assert "input_speed" in message and "ignored" in message
    if not joint.fmi3:  # FMI 2.0 reaches Python: the bytes are named
        assert "not UTF-8" in message and "ff fe" in message
    assert all_reals(joint) == before
    joint.step(0.01)  # the next doStep works


def _state_without(joint, key):
    state = joint.get_state()
    data = json.loads(joint.serialize_state(state))
    joint.free_state(state)
    del data[key]
    return json.dumps(data).encode()


def test_a_refused_set_state_leaves_every_value_as_it_was(joint):
    """The runtime joins FMPy's Python: the state handle is the slave's own dict,
    which the test empties of its start time after taking it."""
    joint.set(input_speed=40.0)
    joint.step(0.1)
    saved = joint.get_state()
    joint.step(0.1)
    before = all_reals(joint)
    del ctypes.cast(saved, ctypes.py_object).value["start_time"]
    assert status_of(joint.set_state, saved) == 3
    assert "keeps its state" in joint.messages[-1][2]
    assert "start_time" in joint.messages[-1][2]
    assert all_reals(joint) == before
    joint.free_state(saved)
    joint.step(0.01)


@pytest.mark.parametrize(
    "damage, words",
    [
        (lambda joint: b"not a state at all", "JSONDecodeError"),
        (lambda joint: b"[1, 2]", "not a serialized FMU state of this project"),
        (lambda joint: _state_without(joint, "start_time"), "start_time"),
        (lambda joint: _state_without(joint, "model"), "another version of the FMU"),
    ],
    ids=["garbage", "no-dict", "no-start-time", "no-model"],
)
def test_deserialize_refuses_what_set_would_refuse_and_names_why(joint, damage, words):
    joint.step(0.05)
    data = damage(joint)
    before = all_reals(joint)
    fmu = joint.fmu
    state = ctypes.c_void_p()
    byte = ctypes.c_uint8 if joint.fmi3 else ctypes.c_char
    buffer = (byte * len(data)).from_buffer_copy(data)
    deserialize = fmu.fmi3DeserializeFMUState if joint.fmi3 else fmu.fmi2DeSerializeFMUstate
    status = status_of(deserialize, fmu.component, buffer, len(data), ctypes.byref(state))
    assert status == 3 and not state.value
    message = joint.messages[-1][2]
    function = "fmi3DeserializeFMUState" if joint.fmi3 else "fmi2DeSerializeFMUstate"
    assert f"{function} refused the bytes" in message and words in message
    assert all_reals(joint) == before
    joint.step(0.05)


def test_a_state_passed_where_its_address_belongs_is_refused_by_name(joint):
    """fmusim 0.0.39 frees with Free*FMUState(S, FMUState), not &FMUState."""
    state = joint.get_state()
    fmu = joint.fmu
    free = fmu.fmi3FreeFMUState if joint.fmi3 else fmu.fmi2FreeFMUstate
    handle = ctypes.cast(state, ctypes.POINTER(ctypes.c_void_p))
    assert status_of(free, fmu.component, handle) == 3
    message = joint.messages[-1][2]
    assert "itself where the address" in message and "fmusim 0.0.39" in message
    assert f"{state.value:x}" in message
    joint.set_state(state)  # the state is still the instance's, and whole
    joint.free_state(state)
    joint.step(0.01)
