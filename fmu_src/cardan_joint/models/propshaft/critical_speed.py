"""First bending critical speed of a propshaft's tubes: the catalogues' check
beside the life rule (docs/life.md, "Critical speed").

A pinned-pinned uniform tube of outer and inner diameter D, d, length L,
Young's modulus E and density rho whirls first at
omega_c = (pi^2 / L^2) sqrt(E I / (rho A)) with I / A = (D^2 + d^2) / 16.
The shop rule keeps the shaft speed below a margin (0.75) of it. A warning,
never a refusal, like the angle checks.
"""

import math

from ...units import RAD_PER_S_TO_RPM


def critical_speed(outer, inner, length, modulus, density) -> float:
    """omega_c (rad/s) of a pinned-pinned tube."""
    return (math.pi / length) ** 2 * math.sqrt(
        modulus * (outer * outer + inner * inner) / (16.0 * density)
    )


def critical_speed_warnings(critical_speeds, speed, margin) -> tuple[str, ...]:
    """A warning for each shaft whose ratio at `speed` (rad/s) passes `margin`."""
    warnings = []
    for k, omega_c in enumerate(critical_speeds, start=1):
        ratio = abs(speed) / omega_c
        if ratio > margin:
            warnings.append(
                f"shaft {k} runs at {ratio:.3f} of its first bending critical speed "
                f"({omega_c * RAD_PER_S_TO_RPM:.0f} rpm) at {abs(speed) * RAD_PER_S_TO_RPM:.0f} "
                f"rpm: above critical_speed_margin = {margin:g} (shorten the tube or widen it)"
            )
    return tuple(warnings)
