"""Value checks shared by every stepped model: finite, within the table's range.

Each problem names the variable, its value, the limit and the unit, so the FMU's
refusal message says exactly what was wrong.
"""

import math


def ranges(table, names, *excluded):
    """(name, min, max, unit) of each of `names` that has a range in `table`."""
    return tuple((n, table.BY_NAME[n].min, table.BY_NAME[n].max, table.BY_NAME[n].unit)
                 for n in names if table.BY_NAME[n].min is not None and n not in excluded)


def bad_values(kind, model, names, value_ranges):
    """(name, explanation) of each of `model`'s `names` not finite or outside its range."""
    for name in names:
        value = getattr(model, name)
        if not math.isfinite(value):
            yield name, f"{kind} {name} = {value!r} is not a finite number"
    for name, low, high, unit in value_ranges:
        value = getattr(model, name)
        if math.isfinite(value) and not low <= value <= high:
            yield name, (f"{kind} {name} = {value!r} {unit} is outside its range "
                         f"[{low!r}, {high!r}] {unit}")


def first_problem(kind, model, names, value_ranges):
    """The first bad value, explained, or None."""
    return next((text for _, text in bad_values(kind, model, names, value_ranges)), None)


def step_size_problem(step_size):
    if not (math.isfinite(step_size) and step_size > 0.0):
        return f"communication step size = {step_size!r} s must be a finite number > 0"
    return None
