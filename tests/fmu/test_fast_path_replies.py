"""What the runtime makes of the slave's replies on the fast path
(fmi/native/fast_values.c's take_reply): numbers converted as Python converts
them, a step's reply of another shape said as an error; FMI 2.0 and 3.0."""

from robustness_support import GOOD
from test_fast_path import bits, extracted, model_class, python_step, slave_classes, step_status

__all__ = ["extracted", "python_step"]  # the fixtures, as test_fast_path makes them


def test_a_malformed_step_reply_is_an_error(extracted, monkeypatch):
    """fast_do_step's reply is (do_step's result, the store's reply): one of
    another length is said and the step is not taken (its result unread)."""
    with extracted.instance("warm-up"):
        pass
    _, fast_path = slave_classes(extracted)
    original = fast_path.fast_do_step

    def three_items(self, *args):
        return (*original(self, *args), None)

    monkeypatch.setattr(fast_path, "fast_do_step", three_items)
    messages = []
    with extracted.instance("malformed", messages=messages) as instance:
        instance.set(**GOOD)
        status, *_ = step_status(instance)
    assert status == 3
    assert any("the slave's fast_do_step failed" in text for _, _, text in messages), messages


def test_a_reply_of_other_numbers_than_floats_is_converted_as_python_does(extracted, monkeypatch):
    """The reply is read through the C API: outputs given as an int and a float
    subclass reach the host as float() makes them."""
    with extracted.instance("warm-up"):
        pass
    slave_class, _ = slave_classes(extracted)
    model = model_class(slave_class)
    original, given = model.run, []

    class Subclassed(float):
        pass

    def other_numbers(self, time, h, inputs):
        outputs, moved = original(self, time, h, inputs)
        outputs = (round(outputs[0] * 1e6), Subclassed(outputs[1]), *outputs[2:])
        given.append(outputs)
        return outputs, moved

    monkeypatch.setattr(model, "run", other_numbers)
    with extracted.instance("numbers") as fast:
        fast.set(**GOOD)
        fast.step(1e-3)
        read = list(fast.get_flat_outputs().values())
    assert isinstance(given[0][0], int) and given[0][0] != 0
    assert bits(read[:2]) == bits([float(given[0][0]), float(given[0][1])])
