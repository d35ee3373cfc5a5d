"""The UniversalJoint FMU: one exact Cardan joint."""

from ...framework.watches import Watch
from .. import Model, ReferenceRun
from . import variables
from .model import CardanJoint
from .step import joint_life_step, joint_step

# What a joint's engineer wants to hear of, once (a build without life has none).
TORQUE_WATCH = Watch(
    "input_torque",
    "rated_torque",
    "the joint is loaded past its rating, where the catalogue life rule no longer holds",
)
LIFE_WATCH = Watch(
    "life_consumed", 1.0, "the catalogue B10 life is used up (90 % of bearings reach it)"
)

MODEL = Model(
    key="UniversalJoint",
    description=(
        "Exact Cardan (Hooke) universal joint: output shaft motion, crosspiece "
        "orientation and dynamics, input torque and secondary couples"
    ),
    table_for=lambda settings: variables.table_for(settings.get("life", True)),
    make=lambda settings, **values: CardanJoint(settings.get("life", True), **values),
    live_outputs=("input_angle",),
    owner="joint",
    watches=(TORQUE_WATCH, LIFE_WATCH),
    # `life`: the bearing loads and catalogue life (docs/life.md); off measures
    # the joint's step without them.
    default_settings={"life": True},
    setting_choices={"life": (True, False)},
    setting_help={"life": "bearing loads and catalogue life (--no-life: UniversalJointNoLife)"},
    # The step in C, with life or without (docs/codegen.md).
    step=lambda settings: joint_life_step if settings.get("life", True) else joint_step,
    name_for=lambda settings: (
        "UniversalJoint" if settings.get("life", True) else "UniversalJointNoLife"
    ),
    # Inputs linear in time, their rates given beside them, so that every step is
    # exact: the shaft runs up 20 -> 40 rad/s while the joint bends 0.2 -> 0.6 rad
    # against a constant load. Two rows: FMI tools interpolate linearly between them.
    reference=ReferenceRun(
        input_rows=(
            # time, input_speed, input_acceleration, bend_angle, bend_angle_rate,
            # bend_angle_acceleration, load_torque
            (0.0, 20.0, 20.0, 0.2, 0.4, 0.0, 100.0),
            (1.0, 40.0, 20.0, 0.6, 0.4, 0.0, 100.0),
        ),
        # At most 10 columns with the time (the cross-check rules' recommendation).
        outputs=(
            "output_angle",
            "output_speed",
            "output_acceleration",
            "cardan_error",
            "input_torque",
            "input_yoke_moment",
            "output_yoke_moment",
            "input_bearing_force",
            "life_consumed",
        ),
    ),
)
