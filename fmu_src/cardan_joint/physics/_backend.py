"""Pick the math backend for a call: `math` on plain scalars, numpy otherwise.

The FMU evaluates the joint once per communication step on Python floats, where
`math` is about ten times cheaper than numpy's scalar path; design sweeps pass
arrays. numpy >= 2 spells the inverse trigonometric functions like `math`
(`atan`, `atan2`), so one formula text serves both.
"""

import math

import numpy as np

_SCALARS = (float, int)


def namespace(*values):
    for value in values:
        if not isinstance(value, _SCALARS):
            return np
    return math
