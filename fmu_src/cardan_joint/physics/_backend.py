"""Pick the math backend for a call: `math` on plain scalars, numpy otherwise.

The FMU evaluates the joint once per communication step on Python floats, where
`math` is about ten times cheaper than numpy's scalar path; design sweeps pass
arrays. numpy >= 2 spells the inverse trigonometric functions like `math`
(`atan`, `atan2`), so one formula text serves both.

numpy is imported only when an array is passed: the FMU runs on the standard
library alone (a host's Python need not have numpy).
"""

import math
from typing import TYPE_CHECKING, Any, TypeAlias

if TYPE_CHECKING:
    import numpy as np

_SCALARS = (float, int)

# What the closed forms take and give: a plain number or a numpy array (broadcast).
# A string, so that the alias does not import numpy at run time.
Real: TypeAlias = "float | np.ndarray"


def namespace(*values: object) -> Any:
    for value in values:
        if not isinstance(value, _SCALARS):
            import numpy

            return numpy
    return math
