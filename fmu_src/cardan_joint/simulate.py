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


DEFAULT_FMU = Path("dist") / "UniversalJoint.fmu"
_STATUS = {0: "ok", 1: "warning", 2: "discard", 3: "error", 4: "fatal", 5: "pending"}


class SimulationError(RuntimeError):
    """The FMU refused a step or reported an error; `messages` holds its log,
    `result` the run up to there."""

    refusal = None

    def __init__(self, text, messages, result):
        super().__init__(text)
        self.messages = messages
        self.result = result


class RefusalError(SimulationError):
    """A SimulationError whose first problem is a `Refusal`: its `variable`,
    `value`, `limit`, `time`, `code` (a `Reason`) and `unit` are attributes."""

    def __init__(self, text, messages, result, refusal):
        super().__init__(text, messages, result)
        self.refusal = refusal
        self.variable, self.value, self.limit = refusal.variable, refusal.value, refusal.limit
        self.time, self.code, self.unit = refusal.time, refusal.code, refusal.unit


def first_refusal(texts):
    """The first `Refusal` written in `texts` (the FMU's log), or None."""
    from .physics.refusal import Refusal

    for text in texts:
        try:
            return Refusal.from_message(text)
        except ValueError:
            continue
    return None


def simulate(fmu=DEFAULT_FMU, stop_time=None, output_interval=None, inputs=None,
             start_values=None, output=None, **fmpy_options):
    """Co-simulate the FMU; return FMPy's structured result array.

    `inputs`: an FMPy structured array (field "time" plus input names), or a
    dict of constant input values. `output_interval` is the communication step.
    Raises SimulationError if the FMU refused a step or logged an error: a
    RefusalError, with the refusal's fields, when the FMU said why.
    """
    from fmpy import read_model_description, simulate_fmu

    from .inputs import complete_inputs

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
        inputs = complete_inputs(inputs, starts, stop_time, output_interval)   # FMPy warns otherwise

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
        text = f"the FMU stopped at t = {reached!r} s of {stop_time!r} s:\n  {detail}"
        refusal = first_refusal(text for _, _, text in problems)
        if refusal is None:
            raise SimulationError(text, messages, result)
        raise RefusalError(text, messages, result, refusal)
    # One warning per distinct message, however often and in whatever order it came.
    repeats = Counter(text for status, _, text in messages if status == "warning")
    for text, count in repeats.items():
        suffix = f" ({count} times)" if count > 1 else ""
        warnings.warn(f"UniversalJoint: {text}{suffix}", RuntimeWarning, stacklevel=2)
    return result
