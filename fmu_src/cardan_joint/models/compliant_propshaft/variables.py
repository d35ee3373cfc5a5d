"""Variable table of the CompliantPropshaft: the Propshaft's table for N joints
with the compliant layer of `compliant_joint.variables.compliant_table`."""

from functools import cache

from ...variable_schema import VariableTable
from ..compliant_joint.variables import compliant_table
from ..propshaft.variables import propshaft_table


@cache
def compliant_propshaft_table(joints: int = 2) -> VariableTable:
    """The CompliantPropshaft's table for `joints` joints."""
    # Without life: the rigid part's damage would integrate a load it does not
    # know over the step (the spring's), so the compliant drives leave it out.
    return compliant_table(propshaft_table(joints, life=False))
