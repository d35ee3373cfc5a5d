"""Variable tables of the compliant drives: a rigid drive's table (the
UniversalJoint's, a Propshaft's) with a torsional spring-damper at its output.

`compliant_table(rigid)` derives one from the rigid table, so the kinematics'
rows (names, units, ranges, descriptions) are written once: the rigid
`load_torque` input gives way to the output shaft's motion (`output_speed`,
`output_acceleration`, from the load side), the spring's parameters join, and
the rigid output motion becomes the kinematic output the spring is wound by.
Outputs that depended on the load torque now depend on what sets the spring's
torque. Pure data: the physics reads its defaults and ranges here.
"""

from ...units import DRIVELINE_UNITS
from ...variable_schema import _IN, _OUT, _PAR, Variable, VariableTable
from ..universal_joint import variables as joint_table

# fmt: off
_OUTPUT_SHAFT = (
    Variable("output_speed", _IN, "rad/s", "Output shaft speed omega_o (from the load side)",
             0.0, "rpm", -1e5, 1e5),
    Variable("output_acceleration", _IN, "rad/s2", "Output shaft acceleration d(omega_o)/dt",
             0.0, "rpm/s", -1e8, 1e8),
)
_SPRING = (
    Variable("twist_angle_start", _PAR, "rad", "Spring twist (kinematic output angle - output "
             "shaft angle) at the start time", 0.0, "deg", -1e6, 1e6),
    Variable("torsional_stiffness", _PAR, "N.m/rad", "Torsional stiffness k of the spring "
             "between the kinematic output and the output shaft", 1e4, None, 1e-9, 1e12),
    Variable("torsional_damping", _PAR, "N.m.s/rad", "Torsional damping c in parallel with the "
             "spring", 5.0, None, 0.0, 1e9),
)
# The twist the spring's maker states: past it the FMU warns once (a watch, see
# spec.py); the default lies beyond any wind-up a run reaches, so it never warns.
_STATED_TWIST = Variable("twist_angle_warning", _PAR, "rad", "Largest |twist_angle| without "
                         "a warning (the spring's stated twist)", 1e6, "deg", 0.0, 1e15)
# fmt: on
_KINEMATIC = ("output_speed", "output_acceleration", "output_angle")


def _spring_outputs(twist_deps, torque_deps):
    # fmt: off
    return (
        Variable("twist_angle", _OUT, "rad", "Spring twist: kinematic output angle - "
                 "output_angle", display_unit="deg", depends_on=twist_deps),
        Variable("output_torque", _OUT, "N.m", "Torque on the output shaft, k twist_angle + "
                 "c (kinematic_output_speed - output_speed)", depends_on=torque_deps),
        Variable("kinematic_output_speed", _OUT, "rad/s", "Output speed of the rigid drive "
                 "for the input motion (the spring's driven end)", display_unit="rpm",
                 depends_on=torque_deps[:-1]),
        Variable("spring_energy", _OUT, "J", "Energy stored in the spring, k twist_angle^2 / 2",
                 min=0.0, depends_on=twist_deps),
    )
    # fmt: on


def compliant_table(rigid=joint_table) -> VariableTable:
    """The compliant drive's table from its rigid drive's table."""
    by_name = rigid.BY_NAME
    inputs = []
    for name in rigid.INPUTS:
        if name != "load_torque":
            inputs.append(by_name[name])
        if name == "input_acceleration":
            inputs.extend(_OUTPUT_SHAFT)
    parameters = []
    for name in rigid.PARAMETERS:
        parameters.append(by_name[name])
        if name == "input_angle_start":
            parameters.extend(_SPRING)
    parameters.append(_STATED_TWIST)  # last: the rigid drive's references stay as they were
    # The spring's torque follows the kinematic output (its angle and speed) and
    # the output shaft's speed; so does all that took the load torque.
    kinematic = [i for i in rigid.INPUTS if i in by_name["output_speed"].depends_on]
    twist_deps = tuple(i for i in rigid.INPUTS if i in by_name["output_angle"].depends_on)
    torque_deps = tuple(dict.fromkeys(twist_deps + tuple(kinematic) + ("output_speed",)))
    outputs = [by_name["input_angle"]]
    outputs.append(
        Variable("output_angle", _OUT, "rad", "Output shaft angle: the integral of "
                 "output_speed", display_unit="deg")
    )  # fmt: skip
    outputs.extend(_spring_outputs(twist_deps, torque_deps))
    for name in rigid.OUTPUTS:
        if name in _KINEMATIC or name == "input_angle":
            continue
        row = by_name[name]
        if "load_torque" in row.depends_on:
            deps = dict.fromkeys(d for d in row.depends_on if d != "load_torque")
            deps.update(dict.fromkeys(torque_deps))
            row = Variable(**{**row.__dict__, "depends_on": tuple(deps)})
        outputs.append(row)
    variables = (*inputs, *parameters, *outputs)
    used = dict.fromkeys(v.unit for v in variables)
    return VariableTable(variables, {u: DRIVELINE_UNITS[u] for u in used})


COMPLIANT_JOINT = compliant_table()
