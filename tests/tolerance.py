"""Relative comparison with a stated scale, for quantities that cross zero."""

import math


def close(actual, expected, rel=1e-9, scale=None):
    """|actual - expected| <= rel * max(|expected|, scale)."""
    reference = abs(float(expected)) if scale is None else max(abs(float(expected)), scale)
    return abs(float(actual) - float(expected)) <= rel * reference or (
        reference == 0.0 and actual == 0.0
    )


def assert_close(actual, expected, rel=1e-9, scale=None, what=""):
    assert math.isfinite(float(actual)), f"{what}: {actual!r} is not finite"
    assert close(actual, expected, rel, scale), (
        f"{what}: {float(actual)!r} vs {float(expected)!r} "
        f"(difference {float(actual) - float(expected):.3e}, scale {scale})"
    )
