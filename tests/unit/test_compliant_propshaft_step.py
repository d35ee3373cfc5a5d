"""The CompliantPropshaft's written step (`models/compliant_propshaft/step.py`):
its run takes each step from the entry, and a step past any input's range is
left to the model's checks, which refuse it as the spring layer does (its C is
checked against it in test_codegen_models.py)."""

import copy
import math

import pytest

from cardan_joint.framework.refusal import Refusal
from cardan_joint.framework.stepped import SteppedModel
from cardan_joint.models.compliant_propshaft import model
from cardan_joint.models.compliant_propshaft.entries import STEPS
from cardan_joint.models.compliant_propshaft.model import CompliantPropshaft
from cardan_joint.models.compliant_propshaft.step import compliant_state_names
from cardan_joint.models.compliant_propshaft.variables import compliant_propshaft_table

INPUTS = compliant_propshaft_table(2).INPUTS
GOOD = (100.0, 10.0, 99.0, 10.0)


@pytest.mark.parametrize("value", [math.nan, "just past its range"])
@pytest.mark.parametrize("name", INPUTS)
def test_each_input_past_its_limit_is_refused_by_the_models_checks(name, value):
    shaft = CompliantPropshaft(2)
    if value == "just past its range":
        value = -math.nextafter(shaft.table.BY_NAME[name].max, math.inf)
    shaft.run(0.0, 1e-3, GOOD)
    layer = copy.deepcopy(shaft)
    inputs = dict(zip(INPUTS, GOOD))
    inputs[name] = value
    refusal = shaft.run(shaft.time, 1e-3, tuple(inputs.values()))
    assert isinstance(refusal, Refusal) and refusal.variable == name, refusal
    assert repr(refusal) == repr(SteppedModel.run(layer, layer.time, 1e-3, tuple(inputs.values())))


@pytest.mark.parametrize("joints", sorted(STEPS))
def test_the_models_step_is_the_translated_definition(joints, monkeypatch):
    """run takes its step, each joint's Miner's sum and the lag included, from
    the entry itself; the state it keeps is the entry's."""
    calls: list = []
    entry = STEPS[joints]

    def counted(*arguments):
        calls.append(arguments)
        return entry(*arguments)

    monkeypatch.setitem(model.STEPS, joints, counted)
    shaft = CompliantPropshaft(joints, torsional_stiffness=2e3)
    layer = copy.deepcopy(shaft)
    for k in range(3):
        inputs = (100.0 + k, 10.0, 99.0, 0.0)
        outputs, _ = shaft.run(shaft.time, 1e-3, inputs)
        expected, _ = SteppedModel.run(layer, layer.time, 1e-3, inputs)
        assert outputs == expected  # the checked step in Python: the same bits
    assert len(calls) == 3
    assert len(shaft.step_state()) == len(compliant_state_names(joints))
    assert shaft.step_state()[-3] == shaft._lag != 0.0
    assert shaft.rigid._life[0][0] > 0.0
