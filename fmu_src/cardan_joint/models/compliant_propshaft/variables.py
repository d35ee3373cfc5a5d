"""Variable table of the CompliantPropshaft: the Propshaft's table for N joints
with the compliant layer of `compliant_joint.variables.compliant_table`."""

from functools import cache

from ...variable_schema import VariableTable
from ..compliant_joint.variables import compliant_table
from ..propshaft.variables import propshaft_table


@cache
def compliant_propshaft_table(joints: int = 2) -> VariableTable:
    """The CompliantPropshaft's table for `joints` joints."""
    return compliant_table(propshaft_table(joints))
