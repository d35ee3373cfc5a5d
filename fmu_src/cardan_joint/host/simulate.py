"""Run any FMU of this project with FMPy, and fail loudly.

Plain `fmpy.simulate_fmu` stops silently when the FMU refuses a step (it
returns the result up to there), and pythonfmu drops the FMU's messages unless
debug logging is on. `simulate` turns debug logging on, collects the messages,
and raises `SimulationError` naming the variable, value, limit and time when
the run did not reach its stop time. It takes the FMI 2.0 and the FMI 3.0 FMU
alike: with FMI 3, FMPy raises at a refused step (the messages and the result
up to there still go into the SimulationError), output names may be given in
either form, and the result holds the arrays (`flat_columns` splits them into
the FMI 2 columns). Names are checked against the FMU's own modelDescription:
a misspelt input, start value or output is refused naming the nearest valid ones.
"""

import warnings
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import DEFAULT_MODEL
from .fmu_info import FmuInfo, array_columns

if TYPE_CHECKING:  # imported in first_refusal at run time, where it is needed
    from ..physics.refusal import Refusal

DEFAULT_FMU = Path("dist") / f"{DEFAULT_MODEL}.fmu"
# (status name, category, text) of one FMU log message.
Message = tuple[str, str, str]
_STATUS = {0: "ok", 1: "warning", 2: "discard", 3: "error", 4: "fatal", 5: "pending"}


class SimulationError(RuntimeError):
    """The FMU refused a step or reported an error; `messages` holds its log,
    `result` the run up to there."""

    refusal: "Refusal | None" = None

    def __init__(self, text: str, messages: list[Message], result: np.ndarray) -> None:
        super().__init__(text)
        self.messages = messages
        self.result = result


class RefusalError(SimulationError):
    """A SimulationError whose first problem is a `Refusal`: its `variable`,
    `value`, `limit`, `time`, `code` (a `Reason`) and `unit` are attributes."""

    def __init__(
        self, text: str, messages: list[Message], result: np.ndarray, refusal: "Refusal"
    ) -> None:
        super().__init__(text, messages, result)
        self.refusal = refusal
        self.variable, self.value, self.limit = refusal.variable, refusal.value, refusal.limit
        self.time, self.code, self.unit = refusal.time, refusal.code, refusal.unit


def first_refusal(texts: Iterable[str]) -> "Refusal | None":
    """The first `Refusal` written in `texts` (the FMU's log), or None."""
    from ..models import discover
    from ..physics.refusal import Refusal

    discover()  # every model's own reasons are declared (read back) with its folder

    for text in texts:
        try:
            return Refusal.from_message(text)
        except ValueError:
            continue
    return None


def flat_columns(result: np.ndarray) -> np.ndarray:
    """The result with each FMI 3 array column split into its FMI 2 variables
    (an FMI 2 result comes back unchanged): the same columns for either FMU."""
    names = result.dtype.names
    if names is None:
        raise ValueError("flat_columns takes a structured result array (FMPy's)")
    fields: list[tuple[str, np.dtype | type[float]]] = []
    for name in names:
        shape = result.dtype[name].shape
        rows = array_columns(name, shape[0]) if shape else ()
        fields += [(row, float) for row in rows] or [(name, result.dtype[name])]
    flat = np.zeros(len(result), dtype=fields)
    for name in names:
        shape = result.dtype[name].shape
        if shape:
            for i, row in enumerate(array_columns(name, shape[0])):
                flat[row] = result[name][:, i]
        else:
            flat[name] = result[name]
    return flat


def _without_repeated_end(result: np.ndarray) -> np.ndarray:
    """A refused FMI 2.0 run's result without the row FMPy adds at the refusal's
    time: it pairs the refused inputs with the held outputs of the row before."""
    end = len(result)
    while end > 1 and result["time"][end - 1] <= result["time"][end - 2]:
        end -= 1
    return result[:end]


def simulate(
    fmu: str | Path | FmuInfo = DEFAULT_FMU,
    stop_time: float | None = None,
    output_interval: float | None = None,
    inputs: np.ndarray | Mapping[str, float] | None = None,
    start_values: Mapping[str, float] | None = None,
    output: Sequence[str] | None = None,
    **fmpy_options: Any,
) -> np.ndarray:
    """Co-simulate the FMU; return FMPy's structured result array.

    `inputs`: an FMPy structured array (field "time" plus input names), or a
    dict of constant input values. `output_interval` is the communication step.
    Raises SimulationError if the FMU refused a step or logged an error: a
    RefusalError, with the refusal's fields, when the FMU said why. A name
    the FMU does not have raises UnknownNameError (a KeyError) naming the
    nearest valid ones; a missing FMU, MissingFMUError naming its build command.
    `fmu` may be an `FmuInfo` already read (its description is not read again).
    """
    from fmpy import simulate_fmu
    from fmpy.fmi1 import FMICallException

    from .run_inputs import complete_inputs

    info = fmu if isinstance(fmu, FmuInfo) else FmuInfo.read(fmu)
    description = info.model_description
    fmu = str(info.path)
    start_values = dict(start_values or {})
    info.check(start_values, ("input", "parameter"), "start value (an input or parameter)")
    if output is not None:
        info.check(output, ("input", "output", "parameter", "local"), "output")
    experiment = description.defaultExperiment
    stop_time = float(experiment.stopTime) if stop_time is None else stop_time
    output_interval = float(experiment.stepSize) if output_interval is None else output_interval
    if inputs is not None:
        inputs = dict(inputs) if isinstance(inputs, Mapping) else inputs
        given = list(inputs) if isinstance(inputs, dict) else list(inputs.dtype.names or ())
        info.check([n for n in given if n != "time"], ("input",), "input")
        starts = info.starts("input")
        starts.update((k, v) for k, v in start_values.items() if k in starts)
        # Every input gets a signal: FMPy warns otherwise.
        inputs = complete_inputs(inputs, starts, stop_time, output_interval)

    messages: list[Message] = []

    def collect(*arguments):  # FMI 2 passes (component, instance, ...), FMI 3 (environment, ...)
        status, category, message = arguments[-3:]
        messages.append(
            (
                _STATUS.get(status, str(status)),
                category.decode(errors="replace"),
                message.decode(errors="replace"),
            )
        )

    fmi3 = info.fmi3
    if output is not None:
        output = info.fmu_names(output)
    # FMPy raises on an FMI 3 refusal and on a refused initialization (either version),
    # losing its recorder: keep it for the partial result.
    recorders: list[Any] = []  # FMPy's Recorder (its class is private)
    step_finished = fmpy_options.pop("step_finished", None)

    def keep_recorder(time, recorder):
        recorders[:1] = [recorder]
        return step_finished is None or step_finished(time, recorder)

    try:
        result = simulate_fmu(
            fmu,
            stop_time=stop_time,
            output_interval=output_interval,
            input=inputs,
            start_values=start_values,
            output=output,
            model_description=description,
            debug_logging=True,
            logger=collect,
            step_finished=keep_recorder,
            **fmpy_options,
        )
    except FMICallException:
        if not messages:  # no reason to report: FMPy's own error is all there is
            raise
        result = recorders[0].result() if recorders else np.zeros(0, dtype=[("time", float)])
    problems = [m for m in messages if m[0] in ("discard", "error", "fatal")]
    reached = float(result["time"][-1]) if len(result) else float("nan")
    if problems or not reached >= stop_time - 1e-9 * max(1.0, abs(stop_time)):
        detail = (
            "\n  ".join(f"{status}: {text}" for status, _, text in problems)
            or "(the FMU gave no reason)"
        )
        text = f"the FMU stopped at t = {reached!r} s of {stop_time!r} s:\n  {detail}"
        if not fmi3:  # FMI 3.0 in event mode records two rows at an event
            result = _without_repeated_end(result)
        refusal = first_refusal(text for _, _, text in problems)
        if refusal is None:
            raise SimulationError(text, messages, result)
        raise RefusalError(text, messages, result, refusal)
    # One warning per distinct message, however often and in whatever order it came.
    repeats = Counter(text for status, _, text in messages if status == "warning")
    for text, count in repeats.items():
        suffix = f" ({count} times)" if count > 1 else ""
        warnings.warn(f"{info.model_name}: {text}{suffix}", RuntimeWarning, stacklevel=2)
    return result
