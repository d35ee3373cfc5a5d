"""The inputs of a run: input CSVs, `--set` pairs split into inputs and
parameters, and the one input signal for FMPy, every mistake a `UsageError`
naming it. Names come from the FMU (`FmuInfo`), so this serves every model.

FMPy prints `Warning: missing input for variable ...` for every input without
a signal. An input nobody sets is not undefined for these FMUs: it holds its
start value, or (speed, bend angle, bend angle rate) is carried along its rate
over each step. `complete_inputs` gives each missing input exactly that
signal, so completing the inputs changes nothing but the noise.
"""

import numpy as np

from .. import results
from ..names import UsageError, parse_assignments
from .fmu_info import FmuInfo

# Inputs the FMU carries along a rate when no one sets them (see "Step semantics").
RATES = {
    "input_speed": ("input_acceleration",),
    "bend_angle_rate": ("bend_angle_acceleration",),
    "bend_angle": ("bend_angle_rate", "bend_angle_acceleration"),
}


def split_assignments(pairs, info: FmuInfo) -> tuple[dict[str, float], dict[str, float]]:
    """--set NAME=VALUE ... -> (constant inputs, parameter start values)."""
    values = parse_assignments(pairs)
    info.check(values, ("input", "parameter"), "input or parameter")
    inputs = {n: v for n, v in values.items() if info.variables[n].causality == "input"}
    return inputs, {n: v for n, v in values.items() if n not in inputs}


def read_input_csv(path, info: FmuInfo):
    """A CSV with a `time` column and input-name columns -> FMPy's structured array."""
    try:
        signal = results.read_csv(path)
    except results.ResultFileError as error:
        raise UsageError(f"input file {error}") from None
    header = list(signal.dtype.names or ())
    if "time" not in header:
        raise UsageError(f"{path}: no 'time' column (columns: {', '.join(header)})")
    columns = [n for n in header if n != "time"]
    parameters = [n for n in columns if n in info.names("parameter")]
    if parameters:
        raise UsageError(
            f"{path}, column {parameters[0]!r}: a parameter is fixed for the run; "
            f"set it with --set {parameters[0]}=VALUE"
        )
    try:
        info.check(columns, ("input",), "input")
    except UsageError as error:
        raise UsageError(f"{path}: {error}") from None
    for name in header:
        if not np.all(np.isfinite(signal[name])):
            raise UsageError(f"{path}, column {name!r}: every value must be a finite number")
    times = signal["time"]
    if np.any(np.diff(times) < 0):
        raise UsageError(f"{path}: the time column must be non-decreasing")
    return signal


def with_constants(signal: np.ndarray, constants: dict[str, float]) -> np.ndarray:
    """An input CSV's signal with constant columns added (from --set)."""
    names = signal.dtype.names or ()
    clash = sorted(set(names) & set(constants))
    if clash:
        raise UsageError(f"{', '.join(clash)} given both by --set and in the input CSV")
    merged = np.zeros(len(signal), dtype=signal.dtype.descr + [(n, float) for n in constants])
    for name in merged.dtype.names or ():
        merged[name] = signal[name] if name in names else constants[name]
    return merged


def _constant(inputs, name: str, starts: dict) -> float | None:
    """The value of an input held constant over the run (given or left at its start), else None."""
    if isinstance(inputs, dict) or name not in inputs.dtype.names:
        source = inputs if isinstance(inputs, dict) and name in inputs else starts
        return float(source.get(name, 0.0))
    column = inputs[name]
    return float(column[0]) if len(column) and np.all(column == column[0]) else None


def _refuse_contradictions(inputs, rates: dict, starts: dict) -> None:
    """A value given as a constant while its rate is a nonzero constant: the FMU
    would restart it at the constant every step (a saw-tooth), not a run anyone means."""
    given = set(inputs) if isinstance(inputs, dict) else set(inputs.dtype.names)
    for name, (rate, *_) in rates.items():
        value, slope = _constant(inputs, name, starts), _constant(inputs, rate, starts)
        if name in given and value is not None and slope:
            raise UsageError(
                f"{name} = {value:g} is given as a constant while {rate} = {slope:g} "
                f"(nonzero): contradictory; give {name} as a signal that follows "
                f"{rate}, or leave {name} out and the FMU carries it along {rate}"
            )


def _refuse_unrated_ramps(signal: np.ndarray, rates: dict, starts: dict) -> None:
    """A column that ramps while its rate is left at a value the ramp does not
    have (no rate column): the FMU would carry it along that rate within each
    step and jump back at the next, so its outputs (the acceleration) would
    contradict the value. `--set` refuses the same contradiction for constants."""
    given = set(signal.dtype.names or ())
    times = signal["time"]
    for name, (rate, *_) in rates.items():
        if name not in given or rate in given or len(times) < 2:
            continue
        spans = np.diff(times)
        moving = spans > 0
        slopes = np.diff(signal[name])[moving] / spans[moving]
        held = float(starts[rate])
        wrong = np.abs(slopes - held) > 1e-9 * np.maximum(np.abs(slopes), 1.0)
        if np.any(wrong):
            k = int(np.argmax(wrong))
            start, end = times[:-1][moving][k], times[1:][moving][k]
            raise UsageError(
                f"{name} ramps at {slopes[k]:g} per s from t = {start:g} s to {end:g} s "
                f"while {rate} is held at {held:g} (no {rate} column): contradictory; "
                f"give a {rate} column that follows the ramp (or --set {rate}=VALUE "
                f"for a single ramp)"
            )


def complete_inputs(inputs, starts: dict, stop_time: float, step: float) -> np.ndarray:
    """`inputs` (dict of constants or structured array) with a signal for every
    input of the FMU (`starts`: input name -> start value), each missing one
    following what the FMU does with it left unset: held at its start value,
    or carried along its rate."""
    # Only the carried inputs this FMU has (not every model has a bend angle).
    rates = {n: r for n, r in RATES.items() if n in starts and set(r) <= set(starts)}
    _refuse_contradictions(inputs, rates, starts)
    if not isinstance(inputs, dict):
        _refuse_unrated_ramps(inputs, rates, starts)
    names = tuple(name for name in starts if name not in rates) + tuple(rates)
    if not isinstance(inputs, dict):
        given = set(inputs.dtype.names)
        moving = {
            n
            for n in names
            if n not in given and any(r in given or starts[r] != 0.0 for r in rates.get(n, ()))
        }
        if moving:
            return inputs  # the FMU carries these along given rates: leave them unset
        signal = np.zeros(
            len(inputs), dtype=inputs.dtype.descr + [(n, float) for n in names if n not in given]
        )
        for name in signal.dtype.names:
            signal[name] = inputs[name] if name in given else starts[name]
        return signal
    value = {name: float(inputs.get(name, starts[name])) for name in names}
    # Linear pieces are exact between two points; a bend angle carried by its
    # acceleration is a parabola, given at every communication point.
    curved = (
        "bend_angle" in rates
        and "bend_angle" not in inputs
        and value["bend_angle_acceleration"] != 0.0
    )
    t = (
        np.linspace(0.0, stop_time, max(1, round(stop_time / step)) + 1)
        if curved
        else np.array([0.0, stop_time])
    )
    signal = np.zeros(len(t), dtype=[("time", float)] + [(n, float) for n in names])
    signal["time"] = t
    for name in names:
        signal[name] = value[name]
    if "input_speed" in rates and "input_speed" not in inputs:
        signal["input_speed"] = value["input_speed"] + value["input_acceleration"] * t
    if "bend_angle_rate" in rates and "bend_angle_rate" not in inputs:
        signal["bend_angle_rate"] = value["bend_angle_rate"] + value["bend_angle_acceleration"] * t
    if "bend_angle" in rates and "bend_angle" not in inputs:
        signal["bend_angle"] = (
            value["bend_angle"]
            + value["bend_angle_rate"] * t
            + 0.5 * value["bend_angle_acceleration"] * t * t
        )
    return signal
