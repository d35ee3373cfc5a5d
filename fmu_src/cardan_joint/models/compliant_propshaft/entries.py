"""The CompliantPropshaft's step entry, one definition for any number of
joints: the runtime passes the step state (`step.compliant_state_names`) and
the inputs flat, by name (docs/codegen.md), gathered into
`step.compliant_propshaft_advanced`'s tuples as the Propshaft's are, the
spring's state as one more."""

from ...framework.written_step import grouped_step
from ..propshaft.entries import PROPSHAFT_GROUPS
from ..propshaft.variables import JOINTS
from .step import (
    SPRING_STATE,
    compliant_propshaft_advanced,
    compliant_state_names,
    compliant_takes_step,
)
from .variables import compliant_propshaft_table


def compliant_propshaft_step(time, h, angle: tuple[int, float, float], parameters_valid: bool,
                             layout, trig, shifts, critical_speeds, fixed, crosspiece, life,
                             singularity_reach, sums, ahead, spring, input_speed,
                             input_acceleration, output_speed,
                             output_acceleration) -> tuple | None:  # fmt: skip
    """The CompliantPropshaft's step (`compliant_state_names`, then the inputs,
    grouped): `compliant_propshaft_advanced`, or None when the step is not
    taken here (the model's checks then name the refusal)."""
    if not compliant_takes_step(h, parameters_valid, input_speed, input_acceleration,
                                output_speed, output_acceleration):  # fmt: skip
        return None
    return compliant_propshaft_advanced(
        h, angle, parameters_valid, layout, trig, shifts, critical_speeds, fixed, crosspiece, life,
        singularity_reach, sums, ahead, spring, input_speed, input_acceleration, output_speed,
        output_acceleration,
    )  # fmt: skip


# The entry for each number of joints (the spec's `step`).
STEPS = {
    joints: grouped_step(
        f"compliant_propshaft_{joints}_step",
        compliant_propshaft_step,
        compliant_state_names(joints),
        compliant_propshaft_table(joints),
        {**PROPSHAFT_GROUPS, "spring": SPRING_STATE},
    )  # fmt: skip
    for joints in JOINTS
}
