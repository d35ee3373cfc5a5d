"""The CompliantJoint FMU: the exact joint with a torsional spring-damper at its output."""

from ...framework.watches import Watch
from .. import Model, ReferenceRun, stepped
from ..universal_joint.spec import LIFE_WATCH, TORQUE_WATCH
from .model import CompliantJoint
from .step import compliant_joint_step
from .variables import COMPLIANT_JOINT

# Every compliant drive's spring: wound past the twist its maker states.
TWIST_WATCH = Watch(
    "twist_angle", "twist_angle_warning", "the spring is wound past its stated twist"
)

MODEL = Model(
    key="CompliantJoint",
    description=(
        "Exact Cardan (Hooke) universal joint with a torsional spring-damper at its "
        "output: takes both shaft speeds, returns both torques"
    ),
    table_for=lambda settings: COMPLIANT_JOINT,
    make=stepped(CompliantJoint),
    live_outputs=("input_angle", "output_angle"),
    owner="joint",
    watches=(TORQUE_WATCH, LIFE_WATCH, TWIST_WATCH),
    # The step in C (docs/codegen.md).
    step=lambda settings: compliant_joint_step,
    # The input shaft as the UniversalJoint's; the output shaft a little slower
    # and faster in turn, so the spring winds up and back.
    reference=ReferenceRun(
        input_rows=(
            # time, input_speed, input_acceleration, output_speed,
            # output_acceleration, bend_angle, bend_angle_rate, bend_angle_acceleration
            (0.0, 20.0, 20.0, 19.0, 22.0, 0.2, 0.4, 0.0),
            (1.0, 40.0, 20.0, 41.0, 22.0, 0.6, 0.4, 0.0),
        ),
        outputs=(
            "output_angle",
            "twist_angle",
            "output_torque",
            "kinematic_output_speed",
            "input_torque",
            "input_yoke_moment",
            "output_yoke_moment",
            "spring_energy",
            # The joint's life under the spring (the crosspiece's energy is the
            # UniversalJoint reference's; at most 9 outputs here).
            "life_consumed",
        ),
    ),
)
