"""Checks of variable values, the input shaft's exact advance and the saved
state, shared by every stepped model (the joint, the propshaft): one wording
for every refusal, one state format."""

import math

from .revolutions import RevolutionAngle, advance

# Beyond 1e15 rad a float has no fractional digits left: the pin's position
# after such a step is undefined, and the exact turn arithmetic would overflow.
MAX_INCREMENT = 1e15


def value_ranges(by_name, names, *excluded):
    """(name, min, max, unit) of each of `names` that has a range in the table."""
    return tuple((n, by_name[n].min, by_name[n].max, by_name[n].unit)
                 for n in names if by_name[n].min is not None and n not in excluded)


class ValueChecks:
    """Explains bad attribute values of a model object, naming value and limit."""

    def _bad_values(self, kind, names, ranges):
        """(name, explanation) of each of `names` not finite or outside its range."""
        for name in names:
            value = getattr(self, name)
            if not math.isfinite(value):
                yield name, f"{kind} {name} = {value!r} is not a finite number"
        for name, low, high, unit in ranges:
            value = getattr(self, name)
            if math.isfinite(value) and not low <= value <= high:
                yield name, (f"{kind} {name} = {value!r} {unit} is outside its range "
                             f"[{low!r}, {high!r}] {unit}")

    def _value_problem(self, kind, names, ranges):
        """The first bad value, explained, or None."""
        return next((text for _, text in self._bad_values(kind, names, ranges)), None)


def advance_input(angle, speed, acceleration, h, speed_limit):
    """(new angle, new speed) after `h` s at constant acceleration, or the
    reason this step would overflow (a string)."""
    increment = h * (speed + 0.5 * acceleration * h)
    if not (abs(increment) <= MAX_INCREMENT and abs(speed + acceleration * h) <= speed_limit):
        return (f"input_speed = {speed!r} rad/s with input_acceleration = {acceleration!r} "
                f"rad/s2 over a step of {h!r} s overflows: the input angle would advance by "
                f"{increment!r} rad (limit {MAX_INCREMENT!r} rad per step) and the speed "
                f"reach {speed + acceleration * h!r} rad/s (limit {speed_limit!r} rad/s)")
    return advance(angle, increment), speed + acceleration * h


class SavedState:
    """state()/restore() of a model with a variable `table`, a clock and an input
    angle kept as exact revolutions; `start(time)` re-derives everything else."""

    def state(self) -> dict:
        """Everything that defines the model, as JSON-serialisable values."""
        values = {name: getattr(self, name) for name in self.table.INPUTS + self.table.PARAMETERS}
        a = self._angle
        values.update(time=self.time, turns=a.turns, fraction=a.fraction,
                      fraction_error=a.fraction_error)
        return values

    def restore(self, state: dict) -> None:
        """Take a `state()`; all or nothing (a malformed state raises and changes nothing)."""
        values = {name: float(state[name])
                  for name in self.table.INPUTS + self.table.PARAMETERS}
        time = float(state["time"])
        angle = RevolutionAngle(int(state["turns"]), float(state["fraction"]),
                                float(state["fraction_error"]))
        for name, value in values.items():
            setattr(self, name, value)
        self.start(time)
        self._angle = angle
