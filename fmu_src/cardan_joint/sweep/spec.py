"""What a design sweep computes: the grid of cases and the settings they share."""

import math
import numbers
from dataclasses import asdict, dataclass

from ..names import UsageError

# Mityushov & Misyura's inertia distributions (UniversalJoint model page), as (I1, I2, I3) / I0.
INERTIA_DISTRIBUTIONS = {
    "T1": (2 / 3, 2 / 3, 2 / 3),
    "T2": (1 / 3, 4 / 3, 1 / 3),
    "T3": (5 / 6, 1 / 3, 5 / 6),
    "T4": (7 / 9, 1 / 9, 10 / 9),
}
# Driveline makers keep the driven inertia's excitation (the output shaft's
# angular acceleration) below 1000 rad/s2 for smooth running.
ACCELERATION_LIMIT = 1000.0
OK, FAILED = "ok", "failed"
PEAKS = (
    "peak_output_acceleration",
    "peak_crosspiece_torque",
    "speed_fluctuation",
    "peak_input_torque",
    "peak_input_yoke_moment",
    "peak_output_yoke_moment",
)
GRID = ("bend_angles_deg", "input_speeds_rpm", "distributions")


@dataclass(frozen=True)
class Case:
    bend_angle_deg: float
    input_speed_rpm: float
    inertia_distribution: str

    @property
    def key(self) -> str:
        """A name that identifies the case (the same for 10 and 10.0)."""
        return (
            f"{float(self.bend_angle_deg)!r}deg_{float(self.input_speed_rpm)!r}rpm_"
            f"{self.inertia_distribution}"
        )


@dataclass(frozen=True)
class SweepSpec:
    bend_angles_deg: tuple = (1, 2, 3, 4, 6, 8, 10, 12, 15, 20, 25, 30)
    input_speeds_rpm: tuple = (500, 1000, 1500, 2000, 2500, 3000, 4000)
    distributions: tuple = ("T1", "T2", "T3", "T4")
    total_inertia: float = 0.039  # I0 [kg.m2], the paper's
    load_torque: float = 0.0  # [N.m]
    revolutions: int = 2
    steps_per_revolution: int = 720  # 0.5 deg per communication step
    max_bend_angle_deg: float | None = None  # None: the FMU's own guard

    def __post_init__(self) -> None:
        """UsageError naming the first argument no case could run with (and its
        command-line option): checked once, before any case."""
        problems = self.problems()
        if problems:
            raise UsageError("; ".join(problems))

    def problems(self) -> list[str]:
        """What is wrong with the settings, one sentence each (none: every case can run)."""
        found = []

        def finite(values) -> bool:
            return all(isinstance(v, numbers.Real) and math.isfinite(v) for v in values)

        if not self.bend_angles_deg or not finite(self.bend_angles_deg):
            found.append(
                f"bend angles {list(self.bend_angles_deg)} (--bend-angles): "
                "give one or more finite numbers [deg]"
            )
        if (
            not self.input_speeds_rpm
            or not finite(self.input_speeds_rpm)
            or min(self.input_speeds_rpm) <= 0
        ):
            found.append(
                f"input speeds {list(self.input_speeds_rpm)} (--speeds) must each be "
                "a finite number > 0 rpm (each case spans whole input revolutions)"
            )
        unknown = [d for d in self.distributions if d not in INERTIA_DISTRIBUTIONS]
        if not self.distributions or unknown:
            found.append(
                f"inertia distributions {list(self.distributions)} (--distributions): "
                f"give one or more of {', '.join(INERTIA_DISTRIBUTIONS)}"
            )
        if not (finite([self.total_inertia]) and self.total_inertia > 0):
            found.append(
                f"total crosspiece inertia I0 = {self.total_inertia!r} kg.m2 (--i0) "
                "must be a finite number > 0"
            )
        if not finite([self.load_torque]):
            found.append(f"load torque {self.load_torque!r} N.m (--load-torque) must be finite")
        if not (isinstance(self.revolutions, numbers.Integral) and self.revolutions >= 1):
            found.append(
                f"revolutions {self.revolutions!r} (--revolutions) must be a whole number >= 1"
            )
        if not (
            isinstance(self.steps_per_revolution, numbers.Integral)
            and self.steps_per_revolution >= 1
        ):
            found.append(
                f"steps per revolution {self.steps_per_revolution!r} "
                "(--steps-per-revolution) must be a whole number >= 1"
            )
        limit = self.max_bend_angle_deg
        if limit is not None and not (finite([limit]) and limit > 0):
            found.append(
                f"max bend angle {limit!r} deg (--max-bend-angle) must be a finite number > 0"
            )
        return found

    def tasks(self) -> list:
        """One task per (bend angle, speed): its cases, one per distribution.

        A few co-simulations per task keep Dask's per-task overhead small, and
        the FMU is unzipped once per task."""
        return [
            [Case(bend, speed, name) for name in self.distributions]
            for bend in self.bend_angles_deg
            for speed in self.input_speeds_rpm
        ]

    def cases(self) -> list:
        return [case for task in self.tasks() for case in task]

    def settings(self) -> dict:
        """Everything but the grid: what every case's result depends on."""
        return {name: value for name, value in asdict(self).items() if name not in GRID}

    def inertias(self, distribution: str) -> tuple:
        return tuple(
            fraction * self.total_inertia for fraction in INERTIA_DISTRIBUTIONS[distribution]
        )
