"""The built FMU: FMPy's validator, units, variability, structure, metadata."""

from fmpy.validation import validate_fmu

from cardan_joint.models.universal_joint import variables as table

# models/universal_joint/README.md's interface table, in its order.
PHYSICS_NAMES = {
    "input": (
        "input_speed input_acceleration bend_angle bend_angle_rate "
        "bend_angle_acceleration load_torque"
    ).split(),
    "parameter": (
        "yoke_phase input_angle_start crosspiece_inertia_1 crosspiece_inertia_2 "
        "crosspiece_inertia_3 max_bend_angle bearing_radius rated_torque life_constant "
        "life_exponent life_min_angle"
    ).split(),
    "output": (
        "input_angle output_angle output_speed output_acceleration cardan_error "
        "speed_ratio crosspiece_angular_velocity_1 crosspiece_angular_velocity_2 "
        "crosspiece_angular_velocity_3 crosspiece_torque_1 crosspiece_torque_2 "
        "crosspiece_torque_3 crosspiece_kinetic_energy crosspiece_quaternion_0 "
        "crosspiece_quaternion_1 crosspiece_quaternion_2 crosspiece_quaternion_3 "
        "input_torque input_yoke_moment output_yoke_moment input_bearing_force "
        "output_bearing_force life_rate life_consumed"
    ).split(),
}
PHYSICS_UNITS = {
    "input_speed": "rad/s",
    "input_acceleration": "rad/s2",
    "bend_angle": "rad",
    "bend_angle_rate": "rad/s",
    "bend_angle_acceleration": "rad/s2",
    "load_torque": "N.m",
    "yoke_phase": "rad",
    "input_angle_start": "rad",
    "max_bend_angle": "rad",
    "input_angle": "rad",
    "output_angle": "rad",
    "output_speed": "rad/s",
    "output_acceleration": "rad/s2",
    "cardan_error": "rad",
    "speed_ratio": "1",
    "crosspiece_kinetic_energy": "J",
    "input_torque": "N.m",
    "input_yoke_moment": "N.m",
    "output_yoke_moment": "N.m",
    "bearing_radius": "m",
    "rated_torque": "N.m",
    "life_min_angle": "rad",
    "input_bearing_force": "N",
    "output_bearing_force": "N",
    "life_rate": "1/h",
    "life_consumed": "1",
}


def test_fmpy_validator_reports_no_problem(fmu_path):
    assert validate_fmu(str(fmu_path)) == []


def test_interface_is_exactly_physics_md(model_description):
    for causality, names in PHYSICS_NAMES.items():
        assert [
            v.name for v in model_description.modelVariables if v.causality == causality
        ] == names
    assert len(model_description.modelVariables) == sum(map(len, PHYSICS_NAMES.values()))
    by_name = {v.name: v for v in model_description.modelVariables}
    for name, unit in PHYSICS_UNITS.items():
        assert by_name[name].unit == unit
    for k in (1, 2, 3):
        assert by_name[f"crosspiece_inertia_{k}"].unit == "kg.m2"
        assert by_name[f"crosspiece_angular_velocity_{k}"].unit == "rad/s"
        assert by_name[f"crosspiece_torque_{k}"].unit == "N.m"
    for k in range(4):
        assert by_name[f"crosspiece_quaternion_{k}"].unit == "1"


def test_every_real_has_a_defined_unit_and_a_description(model_description):
    units = {u.name: u for u in model_description.unitDefinitions}
    for v in model_description.modelVariables:
        assert v.type == "Real"
        assert v.description, v.name
        assert v.unit in units, v.name
        if v.displayUnit:
            assert v.displayUnit in [d.name for d in units[v.unit].displayUnits], v.name


def test_display_units_deg_and_rpm(model_description):
    units = {u.name: u for u in model_description.unitDefinitions}
    deg = {d.name: d for d in units["rad"].displayUnits}["deg"]
    rpm = {d.name: d for d in units["rad/s"].displayUnits}["rpm"]
    assert abs(deg.factor * 3.141592653589793 - 180.0) < 1e-12
    assert abs(rpm.factor * 2 * 3.141592653589793 - 60.0) < 1e-12
    assert units["rad"].baseUnit.rad == 1
    assert (units["N.m"].baseUnit.kg, units["N.m"].baseUnit.m, units["N.m"].baseUnit.s) == (
        1,
        2,
        -2,
    )
    by_name = {v.name: v for v in model_description.modelVariables}
    for v in model_description.modelVariables:
        if v.unit == "rad":
            assert v.displayUnit == "deg", v.name
    for name in ("input_speed", "output_speed", "crosspiece_angular_velocity_1"):
        assert by_name[name].displayUnit == "rpm"


def test_variability_initial_and_limits(model_description):
    for v in model_description.modelVariables:
        if v.causality == "parameter":
            assert (v.variability, v.initial) == ("fixed", "exact"), v.name
            assert v.start is not None
        elif v.causality == "input":
            assert v.variability == "continuous" and v.start is not None, v.name
        else:
            assert (v.variability, v.initial) == ("continuous", "calculated"), v.name
    by_name = {v.name: v for v in model_description.modelVariables}
    assert float(by_name["max_bend_angle"].max) == table.HALF_PI
    for k in (1, 2, 3):
        assert float(by_name[f"crosspiece_inertia_{k}"].min) == 0.0
    assert float(by_name["crosspiece_kinetic_energy"].min) == 0.0


def test_model_structure_lists_outputs_and_initial_unknowns_with_dependencies(model_description):
    outputs = [v for v in model_description.modelVariables if v.causality == "output"]
    assert [u.variable for u in model_description.outputs] == outputs
    assert [u.variable for u in model_description.initialUnknowns] == outputs
    deps = {u.variable.name: {d.name for d in u.dependencies} for u in model_description.outputs}
    assert deps["input_angle"] == set()
    assert deps["output_speed"] == {"input_speed", "bend_angle", "bend_angle_rate"}
    assert "load_torque" not in deps["output_acceleration"]
    assert "load_torque" in deps["input_torque"]


def test_metadata_and_capabilities(model_description):
    md = model_description
    assert md.modelName == "UniversalJoint"
    assert md.author and md.version and md.license
    assert md.defaultExperiment.stopTime and md.defaultExperiment.stepSize
    cs = md.coSimulation
    assert cs.modelIdentifier == "UniversalJoint"
    assert cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    assert cs.canHandleVariableCommunicationStepSize
