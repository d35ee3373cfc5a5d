"""The FMI 3.0 FMU: the same model as the FMI 2.0 one, through pythonfmu3."""

import numpy as np
import pytest

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint import variables as table

GROUPS = table.fmi3_variables()
ARRAYS = {"crosspiece_quaternion": 4, "crosspiece_angular_velocity": 3, "crosspiece_torque": 3}
INPUT_LAWS = ("input_speed", "bend_angle", "load_torque")


def test_fmpy_validates_it_and_reads_every_unit_and_display_unit(fmi3_path, fmi3_description):
    from fmpy.validation import validate_fmu

    assert validate_fmu(str(fmi3_path)) == []
    md = fmi3_description
    assert md.fmiVersion == "3.0"
    units = {u.name: u for u in md.unitDefinitions}
    assert set(units) == set(table.UNITS)
    for name, unit in table.UNITS.items():
        base = units[name].baseUnit
        assert {k: getattr(base, k) for k, _ in unit.exponents} == dict(unit.exponents)
        assert [(d.name, float(d.factor)) for d in units[name].displayUnits] == list(unit.display)
    variables = {v.name: v for v in md.modelVariables}
    assert variables["time"].causality == "independent"
    assert [v.name for v in md.modelVariables[1:]] == [g.name for g in GROUPS]
    for group in GROUPS:
        v = variables[group.name]
        assert (v.type, v.causality, v.variability) == (
            "Float64",
            group.causality,
            group.variability,
        )
        assert (v.unit, v.displayUnit, v.description) == (
            group.unit,
            group.display_unit,
            group.description,
        )
        assert tuple(None if x is None else float(x) for x in (v.min, v.max, v.start)) == (
            group.min,
            group.max,
            group.start,
        )
        if v.displayUnit:
            assert v.displayUnit in [d.name for d in units[v.unit].displayUnits]
        size = int(v.dimensions[0].start) if v.dimensions else 1
        assert size == ARRAYS.get(group.name, 1) == len(group.rows)
    structure = {u.variable.name: u for u in md.outputs}
    assert list(structure) == [g.name for g in GROUPS if g.causality == "output"]
    for group in GROUPS:
        if group.causality == "output":
            assert sorted(d.name for d in structure[group.name].dependencies) == sorted(
                group.depends_on
            )
    assert [u.variable.name for u in md.initialUnknowns] == list(structure)
    assert (
        md.defaultExperiment.startTime,
        md.defaultExperiment.stopTime,
        md.defaultExperiment.stepSize,
    ) == ("0.0", "2.0", "0.001")
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    assert md.coSimulation.canHandleVariableCommunicationStepSize


def test_log_categories_are_those_of_the_fmi2_fmu(fmi3_description, model_description):
    assert [c.name for c in fmi3_description.logCategories] == [
        c.name for c in model_description.logCategories
    ]


def _polynomial_laws(rng, horizon):
    """Random quadratic input laws over [0, horizon]: value, rate and acceleration at t."""
    scale = np.array([1.0, 1.0 / horizon, 1.0 / horizon**2])
    c = {
        "input_speed": rng.uniform(-300, 300, 3) * scale,
        "bend_angle": rng.uniform(-0.4, 0.4, 3) * scale,  # stays inside the guard
        "load_torque": rng.uniform(-500, 500, 3) * scale,
    }

    def inputs(t):
        s, b, load = (np.polynomial.polynomial.polyval(t, c[n]) for n in INPUT_LAWS)
        ds, db = (
            np.polynomial.polynomial.polyval(t, np.polynomial.polynomial.polyder(c[n]))
            for n in ("input_speed", "bend_angle")
        )
        ddb = 2.0 * c["bend_angle"][2]
        return dict(
            input_speed=s,
            input_acceleration=ds,
            bend_angle=b,
            bend_angle_rate=db,
            bend_angle_acceleration=ddb,
            load_torque=load,
        )

    return inputs


def _same(a, b):
    return a == b or abs(a - b) <= 1e-15 * max(abs(a), abs(b))


@pytest.mark.parametrize(
    "seed, step_size, steps", [(1, 1e-3, 300), (2, 0.01, 150), (3, 0.1, 40), (4, 0.37, 20)]
)
def test_every_output_equals_the_fmi2_fmus_at_every_point(
    model_description, unzipped_fmu, fmi3_description, fmi3_unzipped, seed, step_size, steps
):
    rng = np.random.default_rng(seed)
    inputs = _polynomial_laws(rng, steps * step_size)
    parameters = dict(
        yoke_phase=rng.uniform(-3, 3),
        input_angle_start=rng.uniform(-10, 10),
        crosspiece_inertia_2=rng.uniform(0.01, 0.1),
    )
    joints = [
        FmuInstance(md, unzipped, name=f"same{seed}", start_values=parameters)
        for md, unzipped in ((model_description, unzipped_fmu), (fmi3_description, fmi3_unzipped))
    ]
    try:
        for k in range(steps + 1):
            values = {n: float(v) for n, v in inputs(k * step_size).items()}
            for joint in joints:
                joint.set(**values)
            fmi2, fmi3 = (joint.get_flat_outputs() for joint in joints)
            assert list(fmi3) == list(table.OUTPUTS)
            different = [n for n in table.OUTPUTS if not _same(fmi2[n], fmi3[n])]
            assert not different, (k, [(n, fmi2[n], fmi3[n]) for n in different])
            for joint in joints:
                joint.step(step_size)
    finally:
        for joint in joints:
            joint.close()
