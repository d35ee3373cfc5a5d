"""A signal for every input of the FMU, so that FMPy runs it without warnings.

FMPy prints `Warning: missing input for variable ...` for every input without
a signal. An input nobody sets is not undefined for this FMU: it holds its
start value, or (speed, bend angle, bend angle rate) is carried along its rate
over each step. `complete_inputs` gives each missing input exactly that
signal, so completing the inputs changes nothing but the noise.
"""

import numpy as np

# Inputs the FMU carries along a rate when no one sets them (see "Step semantics").
_RATES = {
    "input_speed": ("input_acceleration",),
    "bend_angle_rate": ("bend_angle_acceleration",),
    "bend_angle": ("bend_angle_rate", "bend_angle_acceleration"),
}


def complete_inputs(inputs, starts: dict, stop_time: float, step: float) -> np.ndarray:
    """`inputs` (dict of constants or structured array) with a signal for every
    input of the FMU, each missing one following what the FMU would do with it
    left unset: held at its start value, or carried along its rate. FMPy warns
    ("missing input") for every input without a signal."""
    # Only the carried inputs this FMU has (the propshaft has no bend angle).
    rates = {name: r for name, r in _RATES.items() if name in starts}
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
