"""What the type checker is told holds at run time: the models declare exactly
the variables their tables give them, and the checks that replaced `None`
slipping through (a one-sided range, a missing XML element) name what is wrong."""

from xml.etree.ElementTree import Element, SubElement

import pytest

from cardan_joint.fmi import model_description, model_description3
from cardan_joint.framework.values import value_ranges
from cardan_joint.models.inertia_load.model import InertiaLoad
from cardan_joint.models.inertia_load.variables import INERTIA_LOAD
from cardan_joint.models.load.model import Load
from cardan_joint.models.load.variables import LOAD
from cardan_joint.models.motor.model import Motor
from cardan_joint.models.motor.variables import MOTOR
from cardan_joint.models.propshaft import Propshaft
from cardan_joint.models.propshaft.variables import propshaft_table
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint


@pytest.mark.parametrize(
    "model, variables, state",
    [
        (CardanJoint, table, ()),
        (Motor, MOTOR, ()),
        (Load, LOAD, ()),
        (InertiaLoad, INERTIA_LOAD, ()),
    ],
    ids=["joint", "motor", "load", "inertia_load"],
)
def test_models_declare_exactly_their_tables_inputs_and_parameters(model, variables, state):
    # The model's own class and its mixins from the models package (the joint's
    # life parameters are declared by `JointLife`); the framework's are not variables.
    declared = {
        name
        for cls in model.__mro__
        if cls.__module__.startswith("cardan_joint.models")
        for name in cls.__dict__.get("__annotations__", {})
        if not name.startswith("_")
    } - {"table", "life", "load_over_step"}  # a build setting and a layer's hook
    assert declared == {*variables.INPUTS, *variables.PARAMETERS, *state}
    instance = model()
    assert all(isinstance(getattr(instance, name), float) for name in declared)


def test_the_propshafts_declared_variables_are_in_every_layouts_table():
    declared = set(Propshaft.__annotations__)
    for joints in (2, 3):
        names = set(propshaft_table(joints).INPUTS) | set(propshaft_table(joints).PARAMETERS)
        assert declared <= names
        assert all(isinstance(getattr(Propshaft(joints), n), float) for n in declared)


def test_a_checked_variable_with_a_one_sided_range_is_refused_by_name():
    one_sided = table.Variable("torque_limit", "input", "N.m", "a limit", 0.0, None, 0.0, None)
    with pytest.raises(ValueError, match=r"torque_limit \(input\).*min=0.0, max=None"):
        value_ranges({"torque_limit": one_sided}, ("torque_limit",))


def test_a_model_description_without_model_variables_names_the_missing_element():
    root = Element("fmiModelDescription")
    SubElement(root, "CoSimulation")
    with pytest.raises(ValueError, match="<fmiModelDescription> has no <ModelVariables>"):
        model_description.complete(root, table, {})


def test_an_fmi3_variable_without_a_value_reference_is_named():
    root = Element("fmiModelDescription")
    SubElement(root, "CoSimulation")
    SubElement(SubElement(root, "ModelVariables"), "Float64", name="time")
    with pytest.raises(ValueError, match="<Float64> has no valueReference"):
        model_description3.complete(root, table.fmi3_variables(), {}, table)


@pytest.mark.parametrize("version", [2, 3])
def test_a_value_reference_that_is_not_its_variables_position_is_refused(version):
    # Value reference = 1-based position: OMSimulator reads FMI 3.0 dependencies as
    # positions, the standard as value references (fmi/references.py).
    root = Element("fmiModelDescription")
    SubElement(root, "CoSimulation")
    variables = SubElement(root, "ModelVariables")
    # Numbered from 0, as before 1.2.
    SubElement(variables, "Float64", name="input_speed", valueReference="0")
    with pytest.raises(ValueError, match="input_speed has value reference 0, not its position 1"):
        if version == 2:
            model_description.complete(root, table, {})
        else:
            model_description3.complete(root, table.fmi3_variables(), {}, table)
