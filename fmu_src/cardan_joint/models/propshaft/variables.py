"""The Propshaft FMU's variable table, for N joints (models/propshaft/README.md).

Same style and units as the joint's table (`variables`): the inputs are the
UniversalJoint's own rows, so a master connects either FMU the same way.
Pure data: no FMI import.
"""

from dataclasses import replace
from functools import cache

from ...units import DEG_TO_RAD, JOINT_UNITS, LIFE_UNITS, TUBE_UNITS
from ...variable_schema import _OUT, _PAR, Variable, VariableTable
from ..universal_joint import variables as joint
from ..universal_joint.variables import HALF_PI

_SPEED = ("input_speed",)
_ACCELERATION = ("input_speed", "input_acceleration")
_TORQUE = _ACCELERATION + ("load_torque",)
JOINTS = (2, 3, 4)


def _default_side_angle(shaft: int) -> float:
    # A parallel (Z) layout: every joint works at 2.5 deg, consecutive joints
    # cancel pairwise.
    return (2.0 if shaft % 2 == 0 else -0.5) * DEG_TO_RAD


def _geometry(joints):
    rows = []
    for k in range(joints + 1):
        which = "input" if k == 0 else "output" if k == joints else "intermediate"
        rows.append(
            Variable(
                f"shaft_{k}_side_angle",
                _PAR,
                "rad",
                f"Side-view angle of shaft "
                f"{k} ({which}), in the x-z plane, positive rising along x",
                _default_side_angle(k),
                "deg",
                -HALF_PI,
                HALF_PI,
            )
        )
        rows.append(
            Variable(
                f"shaft_{k}_top_angle",
                _PAR,
                "rad",
                f"Top-view angle of shaft {k} ({which}), in the x-y plane, positive toward +y",
                0.0,
                "deg",
                -HALF_PI,
                HALF_PI,
            )
        )
    for k in range(1, joints):
        rows.append(
            Variable(
                f"shaft_{k}_yoke_phase",
                _PAR,
                "rad",
                f"Yoke phasing of shaft {k}: "
                f"angle of its joint-{k + 1} yoke from its joint-{k} yoke, about "
                f"the shaft (0: both yokes in one plane)",
                0.0,
                "deg",
                -1e15,
                1e15,
            )
        )
        rows.append(
            Variable(
                f"shaft_{k}_inertia",
                _PAR,
                "kg.m2",
                f"Polar moment of inertia of intermediate shaft {k}",
                0.02,
                None,
                0.0,
                1e6,
            )
        )
    return rows


def _outputs(joints):
    rows = [Variable("input_angle", _OUT, "rad", "Input shaft angle gamma_0", display_unit="deg")]
    for k in range(1, joints):
        rows += [
            Variable(
                f"shaft_{k}_angle",
                _OUT,
                "rad",
                f"Angle gamma_{k} of intermediate shaft {k} (continuous)",
                display_unit="deg",
            ),
            Variable(
                f"shaft_{k}_speed",
                _OUT,
                "rad/s",
                f"Speed of intermediate shaft {k}",
                display_unit="rpm",
                depends_on=_SPEED,
            ),
            Variable(
                f"shaft_{k}_acceleration",
                _OUT,
                "rad/s2",
                f"Acceleration of intermediate shaft {k}",
                display_unit="rpm/s",
                depends_on=_ACCELERATION,
            ),
        ]
    rows += [
        Variable(
            "output_angle",
            _OUT,
            "rad",
            f"Output shaft angle gamma_{joints} (continuous)",
            display_unit="deg",
        ),
        Variable(
            "output_speed",
            _OUT,
            "rad/s",
            "Output shaft speed",
            display_unit="rpm",
            depends_on=_SPEED,
        ),
        Variable(
            "output_acceleration",
            _OUT,
            "rad/s2",
            "Output shaft acceleration",
            display_unit="rpm/s",
            depends_on=_ACCELERATION,
        ),
        Variable(
            "input_torque",
            _OUT,
            "N.m",
            "Torque the input shaft must supply (load, "
            "intermediate shafts' and crosspieces' inertia)",
            depends_on=_TORQUE,
        ),
        Variable(
            "kinetic_energy",
            _OUT,
            "J",
            "Kinetic energy of the intermediate shafts and the crosspieces",
            min=0.0,
            depends_on=_SPEED,
        ),
    ]
    rows += [
        Variable(
            f"joint_{k}_working_angle",
            _OUT,
            "rad",
            f"Working angle of joint {k}, arccos(d_{k - 1} . d_{k})",
            display_unit="deg",
            min=0.0,
        )
        for k in range(1, joints + 1)
    ]
    rows += [
        Variable(
            "speed_ratio_fluctuation",
            _OUT,
            "1",
            "max - min of output/input speed over one input revolution at constant input speed",
            min=0.0,
        ),
        Variable(
            "equivalent_angle",
            _OUT,
            "rad",
            "Single-joint angle with the same fluctuation (tan b sin b = speed_ratio_fluctuation)",
            display_unit="deg",
            min=0.0,
        ),
    ]
    return rows


@cache
def propshaft_table(joints: int = 2, life: bool = True) -> VariableTable:
    """The table for `joints` joints; `life` off leaves out the bearing and life
    rows (the compliant propshaft's rigid part: its load is the spring's)."""
    if joints not in JOINTS:
        raise ValueError(f"joints = {joints!r}: the Propshaft is built for {JOINTS} joints")
    inputs = [
        replace(joint.BY_NAME["input_speed"], description="Input shaft speed omega_0"),
        replace(
            joint.BY_NAME["input_acceleration"],
            description="Input shaft acceleration alpha_0 = d(omega_0)/dt",
        ),
        joint.BY_NAME["load_torque"],
    ]
    parameters = _geometry(joints) + [
        *(
            replace(
                joint.BY_NAME[f"crosspiece_inertia_{i}"],
                description=f"Every joint's crosspiece: principal moment of inertia about {axis}",
            )
            for i, axis in (
                (1, "the pin its input-side yoke holds"),
                (2, "the other pin"),
                (3, "the normal of the cross"),
            )
        ),
        replace(
            joint.BY_NAME["input_angle_start"],
            description="Input shaft angle gamma_0 at the start time",
        ),
        Variable(
            "max_working_angle",
            _PAR,
            "rad",
            "Largest working angle accepted; a layout reaching it is refused",
            30.0 * DEG_TO_RAD,
            "deg",
            0.0,
            HALF_PI,
        ),
    ]
    parameters += _tubes(joints) + (_life_parameters() if life else [])
    outputs = _outputs(joints) + [
        Variable(
            f"shaft_{k}_critical_speed_ratio",
            _OUT,
            "1",
            f"Speed of intermediate shaft {k} over its tube's first bending critical speed "
            "(pinned-pinned)",
            min=0.0,
            depends_on=_SPEED,
        )
        for k in range(1, joints)
    ]
    outputs += _life_outputs(joints) if life else []
    units = {**JOINT_UNITS, **TUBE_UNITS, **LIFE_UNITS}
    return VariableTable(inputs + parameters + outputs, units)


def _life_parameters():
    """The joint's bearing and life parameters (docs/life.md), one set for every joint."""
    return [
        replace(row, description=f"Every joint: {row.description}")
        for row in joint.LIFE_VARIABLES
        if row.causality == _PAR
    ]


def _life_outputs(joints):
    """The joint's four life outputs for each joint k, `joint_k_` before the name,
    its input shaft the one upstream (shaft k - 1)."""
    rows = [row for row in joint.LIFE_VARIABLES if row.causality == _OUT]
    return [
        replace(row, name=f"joint_{k}_{row.name}", depends_on=_TORQUE if row.depends_on else (),
                description=f"Joint {k}: {row.description}")
        for k in range(1, joints + 1)
        for row in rows
    ]  # fmt: skip


# (name, unit, description, default, min, max) of each intermediate shaft's tube:
# a steel tube 76.2 x 2.1 mm, 1.4 m long.
_TUBE = (
    ("outer_diameter", "m", "tube outer diameter D", 0.0762, 1e-4, 10.0),
    ("inner_diameter", "m", "tube inner diameter d (0: solid)", 0.072, 0.0, 10.0),
    ("length", "m", "tube length L between the joints' centres", 1.4, 1e-3, 100.0),
    ("youngs_modulus", "Pa", "tube Young's modulus E", 2.1e11, 1e6, 1e13),
    ("density", "kg/m3", "tube density rho", 7850.0, 1.0, 1e5),
)


def _tubes(joints):
    rows = [
        Variable(
            f"shaft_{k}_{name}",
            _PAR,
            unit,
            f"Intermediate shaft {k}: {text}",
            start,
            None,
            low,
            high,
        )  # fmt: skip
        for k in range(1, joints)
        for name, unit, text, start, low, high in _TUBE
    ]
    rows.append(
        Variable("critical_speed_margin", _PAR, "1", "Largest shaft speed over critical speed "
                 "without a warning (the shop rule's margin)", 0.75, None, 0.0, 1.0)
    )  # fmt: skip
    return rows
