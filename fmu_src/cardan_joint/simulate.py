"""Run the UniversalJoint FMU with FMPy, and fail loudly.

Plain `fmpy.simulate_fmu` stops silently when the FMU refuses a step (it
returns the result up to there), and pythonfmu drops the FMU's messages unless
debug logging is on. `simulate` turns debug logging on, collects the messages,
and raises `SimulationError` naming the variable, value, limit and time when
the run did not reach its stop time.
"""

import warnings
from collections import Counter
from pathlib import Path

import numpy as np

DEFAULT_FMU = Path("dist") / "UniversalJoint.fmu"
_STATUS = {0: "ok", 1: "warning", 2: "discard", 3: "error", 4: "fatal", 5: "pending"}


class SimulationError(RuntimeError):
    """The FMU refused a step or reported an error; `messages` holds its log."""

    def __init__(self, text, messages, result):
        super().__init__(text)
        self.messages = messages
        self.result = result


def inputs_from_constants(constants: dict, stop_time: float) -> np.ndarray:
    """A structured input signal holding each value constant over [0, stop_time]."""
    signal = np.zeros(2, dtype=[("time", float)] + [(name, float) for name in constants])
    signal["time"] = (0.0, stop_time)
    for name, value in constants.items():
        signal[name] = value
    return signal


# Inputs the FMU carries along a rate when no one sets them (see "Step semantics").
_RATES = {"input_speed": ("input_acceleration",), "bend_angle_rate": ("bend_angle_acceleration",),
          "bend_angle": ("bend_angle_rate", "bend_angle_acceleration")}


def complete_inputs(inputs, starts: dict, stop_time: float, step: float) -> np.ndarray:
    """`inputs` (dict of constants or structured array) with a signal for every
    input of the FMU, each missing one following what the FMU would do with it
    left unset: held at its start value, or carried along its rate. FMPy warns
    ("missing input") for every input without a signal."""
    names = tuple(name for name in starts if name not in _RATES) + tuple(_RATES)
    if not isinstance(inputs, dict):
        given = set(inputs.dtype.names)
        moving = {n for n in names if n not in given and any(
            r in given or starts[r] != 0.0 for r in _RATES.get(n, ()))}
        if moving:
            return inputs        # the FMU carries these along given rates: leave them unset
        signal = np.zeros(len(inputs), dtype=inputs.dtype.descr +
                          [(n, float) for n in names if n not in given])
        for name in signal.dtype.names:
            signal[name] = inputs[name] if name in given else starts[name]
        return signal
    value = {name: float(inputs.get(name, starts[name])) for name in names}
    # Linear pieces are exact between two points; a bend angle carried by its
    # acceleration is a parabola, given at every communication point.
    curved = "bend_angle" not in inputs and value["bend_angle_acceleration"] != 0.0
    t = (np.linspace(0.0, stop_time, max(1, round(stop_time / step)) + 1) if curved
         else np.array([0.0, stop_time]))
    signal = np.zeros(len(t), dtype=[("time", float)] + [(n, float) for n in names])
    signal["time"] = t
    for name in names:
        signal[name] = value[name]
    if "input_speed" not in inputs:
        signal["input_speed"] = value["input_speed"] + value["input_acceleration"] * t
    if "bend_angle_rate" not in inputs:
        signal["bend_angle_rate"] = value["bend_angle_rate"] + value["bend_angle_acceleration"] * t
    if "bend_angle" not in inputs:
        signal["bend_angle"] = (value["bend_angle"] + value["bend_angle_rate"] * t
                                + 0.5 * value["bend_angle_acceleration"] * t * t)
    return signal


def simulate(fmu=DEFAULT_FMU, stop_time=None, output_interval=None, inputs=None,
             start_values=None, output=None, **fmpy_options):
    """Co-simulate the FMU; return FMPy's structured result array.

    `inputs`: an FMPy structured array (field "time" plus input names), or a
    dict of constant input values. `output_interval` is the communication step.
    Raises SimulationError if the FMU refused a step or logged an error.
    """
    from fmpy import read_model_description, simulate_fmu

    fmu = str(fmu)
    if not Path(fmu).exists():
        raise FileNotFoundError(f"{fmu} does not exist: build it with `python build_fmu.py`")
    description = read_model_description(fmu)
    experiment = description.defaultExperiment
    stop_time = float(experiment.stopTime) if stop_time is None else stop_time
    output_interval = (float(experiment.stepSize) if output_interval is None else output_interval)
    if inputs is not None:
        starts = {v.name: float((start_values or {}).get(v.name, v.start))
                  for v in description.modelVariables if v.causality == "input"}
        inputs = complete_inputs(inputs, starts, stop_time, output_interval)

    messages = []

    def collect(component, instance, status, category, message):
        messages.append((_STATUS.get(status, str(status)), category.decode(errors="replace"),
                         message.decode(errors="replace")))

    result = simulate_fmu(fmu, stop_time=stop_time, output_interval=output_interval, input=inputs,
                          start_values=start_values or {}, output=output, debug_logging=True,
                          logger=collect, **fmpy_options)
    problems = [m for m in messages if m[0] in ("discard", "error", "fatal")]
    reached = float(result["time"][-1]) if len(result) else float("nan")
    if problems or not reached >= stop_time - 1e-9 * max(1.0, abs(stop_time)):
        detail = "\n  ".join(f"{status}: {text}" for status, _, text in problems) or \
            "(the FMU gave no reason)"
        raise SimulationError(f"the FMU stopped at t = {reached!r} s of {stop_time!r} s:\n  {detail}",
                              messages, result)
    # One warning per distinct message, however often and in whatever order it came.
    repeats = Counter(text for status, _, text in messages if status == "warning")
    for text, count in repeats.items():
        suffix = f" ({count} times)" if count > 1 else ""
        warnings.warn(f"UniversalJoint: {text}{suffix}", RuntimeWarning, stacklevel=2)
    return result
