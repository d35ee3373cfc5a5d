"""The driveline industry's angle checks: warnings, never refusals.

Sources (models/propshaft/README.md, "Angle checks", quotes them):
- Dana Spicer, "Driveline Operating Angle Calculator", Basic rules 1-3 and the
  table "Driveshaft RPM / Max. Operating Angle"
  (https://spicerparts.com/calculators/driveline-operating-angle-calculator):
  operating angles at least 1/2 deg; the two ends of a driveshaft equal within
  1 deg; maxima 5.0 deg at 3500 rpm, 4.2 at 4000, 3.7 at 4500, 3.2 at 5000.
- ELBE Gelenkwellen, technical information, sections 3.2 and 3.3
  (http://www.elbe-group.de/technik/elbe_techan3_u.htm): the fluctuation rate
  U = tan(beta) sin(beta) of a two-joint or multi-joint driveline should stay
  U <= 0.0027; beta_res is the single joint with the same U. (Engineers Edge's
  driveline design guide refers residual angles to SAE AE-7, "Universal Joint
  and Driveshaft Design Manual", section 3.1.1; we have not read AE-7 itself.)
Only the table's four rows are used: between them the limit is interpolated
linearly (our choice, the maker publishes points); outside them the report says
so instead of inventing a limit.
"""

from typing import NamedTuple

from ...units import DEG_TO_RAD, RAD_PER_S_TO_RPM, RAD_TO_DEG
from .fluctuation import equivalent_angle, speed_ratio_fluctuation

MIN_WORKING_ANGLE = 0.5 * DEG_TO_RAD
EQUAL_WITHIN = 1.0 * DEG_TO_RAD
FLUCTUATION_LIMIT = 0.0027
# (driveshaft rpm, maximum operating angle in deg), Spicer's table.
MAX_ANGLE_TABLE = ((3500.0, 5.0), (4000.0, 4.2), (4500.0, 3.7), (5000.0, 3.2))


class AngleReport(NamedTuple):
    working_angles: tuple[float, ...]  # rad
    speed_ratio_fluctuation: float
    equivalent_angle: float  # rad
    operating_speed: float  # rad/s, the speed the table check used
    max_operating_angle: float | None  # rad, None where the table says nothing
    warnings: tuple[str, ...]


def max_operating_angle(speed: float):
    """(limit in rad or None, how it was found) for a driveshaft speed in rad/s."""
    rpm = abs(speed) * RAD_PER_S_TO_RPM
    (low_rpm, low_deg), (high_rpm, high_deg) = MAX_ANGLE_TABLE[0], MAX_ANGLE_TABLE[-1]
    if rpm > high_rpm:
        # The limit falls with speed: above the table it is below the last entry.
        return None, (
            f"{rpm:.0f} rpm is above the table's last row ({high_rpm:.0f} rpm, "
            f"{high_deg} deg): no published limit, it is below {high_deg} deg"
        )
    if rpm < low_rpm:
        return None, (
            f"{rpm:.0f} rpm is below the table's first row ({low_rpm:.0f} rpm, "
            f"{low_deg} deg): no limit checked (it is at least {low_deg} deg)"
        )
    for (r0, a0), (r1, a1) in zip(MAX_ANGLE_TABLE, MAX_ANGLE_TABLE[1:]):
        if r0 <= rpm <= r1:
            limit = a0 + (a1 - a0) * (rpm - r0) / (r1 - r0)
            return (
                limit * DEG_TO_RAD,
                f"{limit:.3g} deg at {rpm:.0f} rpm (linear between table rows)",
            )
    raise AssertionError("unreachable: the table covers [first, last]")


def angle_warnings(working_angles, fluctuation, speed):
    """(warnings, max operating angle or None) for working angles (rad), the
    residual fluctuation and the driveshaft speed (rad/s)."""
    warnings = []
    for k, beta in enumerate(working_angles, start=1):
        if beta < MIN_WORKING_ANGLE:
            warnings.append(
                f"joint {k} working angle {beta * RAD_TO_DEG:.3f} deg is below 0.5 deg: "
                f"its needle bearings do not rotate (Spicer rule 1)"
            )
    for k in range(1, len(working_angles)):
        first, second = working_angles[k - 1], working_angles[k]
        if abs(first - second) > EQUAL_WITHIN:
            warnings.append(
                f"shaft {k}: working angles {first * RAD_TO_DEG:.3f} deg (joint {k}) and "
                f"{second * RAD_TO_DEG:.3f} deg (joint {k + 1}) differ by more than "
                f"1 deg (Spicer rule 2)"
            )
    limit, how = max_operating_angle(speed)
    largest = max(working_angles)
    if limit is None and abs(speed) * RAD_PER_S_TO_RPM > MAX_ANGLE_TABLE[-1][0]:
        warnings.append(
            f"operating speed {how}; largest working angle {largest * RAD_TO_DEG:.3f} deg"
        )
    elif limit is not None and largest > limit:
        warnings.append(
            f"working angle {largest * RAD_TO_DEG:.3f} deg exceeds the maximum operating "
            f"angle {how} (Spicer's table)"
        )
    if fluctuation > FLUCTUATION_LIMIT:
        warnings.append(
            f"residual speed-ratio fluctuation {fluctuation:.3g} exceeds 0.0027 "
            f"(ELBE: U = tan b sin b <= 0.0027, about a 3 deg single joint)"
        )
    return tuple(warnings), limit


def angle_report(geometry, speed: float) -> AngleReport:
    """The checks for a `geometry.Layout` at driveshaft speed `speed` (rad/s)."""
    fluctuation = speed_ratio_fluctuation(geometry)
    warnings, limit = angle_warnings(geometry.working_angles, fluctuation, speed)
    return AngleReport(
        geometry.working_angles,
        fluctuation,
        equivalent_angle(fluctuation),
        float(speed),
        limit,
        warnings,
    )
