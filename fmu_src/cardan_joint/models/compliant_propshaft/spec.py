"""The CompliantPropshaft FMU: the Propshaft (N joints) with the compliant layer."""

from .. import Model
from ..compliant_joint.spec import TWIST_WATCH
from ..propshaft.spec import PROPSHAFT_WATCHES, check_joints, joints_namer
from ..propshaft.variables import JOINTS
from .entries import STEPS
from .model import CompliantPropshaft
from .variables import compliant_propshaft_table

MODEL = Model(
    key="CompliantPropshaft",
    description=(
        "Propshaft of several exact Cardan joints in 3-D with a torsional "
        "spring-damper at its output: takes both shaft speeds, returns both torques"
    ),
    table_for=lambda settings: compliant_propshaft_table(settings.get("joints", 2)),
    make=lambda settings, **values: CompliantPropshaft(settings.get("joints", 2), **values),
    live_outputs=("input_angle", "output_angle"),
    owner="joint",
    watches=(*PROPSHAFT_WATCHES, TWIST_WATCH),
    default_settings={"joints": 2},
    setting_choices={"joints": JOINTS},
    setting_help={"joints": "number of joints"},
    check_settings=check_joints("CompliantPropshaft"),
    name_for=joints_namer("CompliantPropshaft"),
    warns=True,
    # The step in C, one entry per number of joints (docs/codegen.md).
    step=lambda settings: STEPS[settings.get("joints", 2)],
)
