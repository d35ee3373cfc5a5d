"""Pick the math backend for a call: `math` on plain scalars, numpy otherwise.

The FMU evaluates the joint once per communication step on Python floats, where
`math` is about ten times cheaper than numpy's scalar path; design sweeps pass
arrays. numpy >= 2 spells the inverse trigonometric functions like `math`
(`atan`, `atan2`), so one formula text serves both.
"""

import math
from typing import Any

import numpy as np

_SCALARS = (float, int)

# What the closed forms take and give: a plain number or a numpy array (broadcast).
Real = float | np.ndarray


def namespace(*values: object) -> Any:
    for value in values:
        if not isinstance(value, _SCALARS):
            return np
    return math
