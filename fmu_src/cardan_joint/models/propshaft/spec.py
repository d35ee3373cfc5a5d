"""The Propshaft FMU: N exact Cardan joints in 3-D (`--joints N`, 2 by default)."""

from collections.abc import Mapping

from ...framework.watches import Watch
from .. import Model, StartValueError
from ..universal_joint.spec import TORQUE_WATCH
from .entries import STEPS
from .model import Propshaft
from .variables import JOINTS, propshaft_table


def check_joints(key: str):
    """`Model.check_settings` of an N-joint model named `key`."""

    def check(settings: Mapping) -> None:
        if settings.get("joints") not in JOINTS:
            raise StartValueError(
                f"--joints {settings.get('joints')!r}: the {key} is built for "
                f"{', '.join(map(str, JOINTS))} joints"
            )

    return check


def joints_namer(key: str):
    """`Model.name_for` of an N-joint model: `key`, or `key<N>` beyond 2 joints."""

    def name_for(settings: Mapping) -> str:
        joints = settings.get("joints", 2)
        return key if joints == 2 else f"{key}{joints}"

    return name_for


# The input torque is joint 1's; every joint's life; every tube's critical speed.
PROPSHAFT_WATCHES = (
    TORQUE_WATCH,
    Watch("joint_*_life_consumed", 1.0, "this joint's catalogue B10 life is used up"),
    Watch(
        "shaft_*_critical_speed_ratio",
        "critical_speed_margin",
        "the tube runs too near its first bending critical speed (shorten or widen it)",
    ),
)

MODEL = Model(
    key="Propshaft",
    description=(
        "Propshaft of several exact Cardan joints in 3-D: working angles from "
        "side and top views, yoke phasing, intermediate shaft inertia, input "
        "torque, speed-ratio fluctuation and the joint makers' angle checks"
    ),
    table_for=lambda settings: propshaft_table(settings.get("joints", 2)),
    make=lambda settings, **values: Propshaft(settings.get("joints", 2), **values),
    live_outputs=("input_angle",),
    owner="joint",
    watches=PROPSHAFT_WATCHES,
    default_settings={"joints": 2},
    setting_choices={"joints": JOINTS},
    setting_help={"joints": "number of joints"},
    check_settings=check_joints("Propshaft"),
    name_for=joints_namer("Propshaft"),
    warns=True,
    # The step in C, one entry per number of joints (docs/codegen.md).
    step=lambda settings: STEPS[settings.get("joints", 2)],
)
