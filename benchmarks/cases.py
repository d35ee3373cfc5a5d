"""What the per-model benchmarks step: each model's default build at one
operating point, and the goal issue 32 sets it against its own empty FMU.

The operating point is one table of input values by name, so that a model
added under models/ is benchmarked without a line here: each input it has
takes the table's value, or its start value where the table has none.
"""

from dataclasses import dataclass

from cardan_joint.models import discover

# Every term of each model active (speed ramp, bend rate, load), at values a
# driveline sees; the C host sets them again before every step of 1 ms.
OPERATING_POINT = {
    "input_speed": 100.0,
    "input_acceleration": 5.0,
    "bend_angle": 0.3,
    "bend_angle_rate": 0.01,
    "bend_angle_acceleration": 0.0,
    "load_torque": 50.0,
    # A compliant element's far side turns with its near side.
    "output_speed": 100.0,
    "output_acceleration": 5.0,
    # A load driven at the shaft's speed; an inertia driven by a torque.
    "speed": 100.0,
    "acceleration": 5.0,
    "drive_torque": 50.0,
}
STEP = 1e-3  # s: the C host's bench step


@dataclass(frozen=True)
class Case:
    """One model's default build at the operating point (`speed`: another input speed)."""

    model: str
    speed: float | None = None
    goal: float | None = None  # instructions per step / its own empty FMU's, on CPython 3.11

    @property
    def label(self) -> str:
        spec = discover()[self.model]
        joints = spec.default_settings.get("joints")
        label = self.model + (f" ({joints} joints)" if joints else "")
        return label + (f" at {self.speed:g} rad/s" if self.speed is not None else "")

    def inputs(self) -> dict[str, float]:
        """The model's inputs, by name, as the host sets them at every step."""
        table = discover()[self.model].table()
        starts = {v.name: v.start for v in table.VARIABLES}
        chosen = {**OPERATING_POINT, **({"input_speed": self.speed} if self.speed else {})}
        return {name: float(chosen.get(name, starts[name])) for name in table.INPUTS}

    def host_inputs(self) -> list[str]:
        """The inputs as the C host's bench takes them (name=value)."""
        return [f"{name}={value!r}" for name, value in self.inputs().items()]


# Issue 32's goals: the default build ≤ this many times its own empty FMU.
CASES = (
    Case("UniversalJoint", goal=0.1),
    Case("UniversalJoint", speed=1000.0, goal=0.5),
    Case("Propshaft", goal=0.25),
    Case("CompliantJoint", goal=0.25),
    Case("CompliantPropshaft", goal=0.25),
    Case("Motor"),
    Case("Load"),
    Case("InertiaLoad"),
)


def cases_of(models: list[str] | None) -> list[Case]:
    """The cases of `models` (all of CASES when None); a model found under
    models/ with no case here gets one at the operating point."""
    if not models:
        return list(CASES)
    known = discover()
    unknown = [name for name in models if name not in known]
    if unknown:
        raise SystemExit(f"no model {', '.join(unknown)}: the models are {', '.join(known)}")
    return [c for name in models for c in CASES if c.model == name] + [
        Case(name) for name in models if not any(c.model == name for c in CASES)
    ]


def generated(case: Case) -> bool:
    """Whether the model's spec names a step to generate (docs/codegen.md)."""
    spec = discover()[case.model]
    return spec.step is not None and spec.step(spec.default_settings) is not None
