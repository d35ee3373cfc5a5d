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
The stop time and output interval are checked (`run_arguments`) before the
first step, the recorded rows against the memory available, or, given
`rows_to`, handed over in chunks as the run goes (`simulate_to_csv` streams a
long run to a file). Ctrl-C (SIGTERM, SIGHUP alike) ends the run between two
steps and raises `SimulationInterrupted` (a KeyboardInterrupt) naming the time
reached; the FMU unzipped for the run is removed however it ends.
"""

import warnings
from collections import Counter
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import DEFAULT_MODEL
from .fmu_info import FmuInfo, array_columns
from .interrupts import SimulationInterrupted, interrupt_between_steps
from .progress import StepProgress
from .run_arguments import RunLength, check_memory, run_length
from .unpacked import ExtractedFMU

if TYPE_CHECKING:  # imported in first_refusal at run time, where it is needed
    from ..framework.refusal import Refusal

DEFAULT_FMU = Path("dist") / f"{DEFAULT_MODEL}.fmu"
# (status name, category, text) of one FMU log message.
Message = tuple[str, str, str]
_STATUS = {0: "ok", 1: "warning", 2: "discard", 3: "error", 4: "fatal", 5: "pending"}
# With `rows_to`, rows are handed over in chunks of this many; the last rows stay
# with the recorder (a refused FMI 2.0 run's repeated end row is dropped from them).
CHUNK_ROWS, KEPT_ROWS = 4096, 2


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
    from ..framework.refusal import Refusal
    from ..models import discover

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


def run_times(info: FmuInfo, stop_time: float | None, output_interval: float | None) -> RunLength:
    """The run's stop time and output interval (defaults: the FMU's default
    experiment), checked: UsageError unless finite, > 0, the interval at most
    the stop time."""
    experiment = info.model_description.defaultExperiment
    return run_length(
        float(experiment.stopTime) if stop_time is None else stop_time,
        float(experiment.stepSize) if output_interval is None else output_interval,
    )


def recorded_variables(info: FmuInfo, output: Sequence[str] | None) -> list[str]:
    """The FMU variables a run records: those holding `output` (default: the outputs)."""
    return info.fmu_names(output) if output is not None else info.outputs


def recorded_values(info: FmuInfo, recorded: Sequence[str]) -> int:
    """Values in a recorded row: the time and every element of each variable."""
    return 1 + sum(info.variables[name].size for name in recorded)


def simulate(
    fmu: str | Path | FmuInfo = DEFAULT_FMU,
    stop_time: float | None = None,
    output_interval: float | None = None,
    inputs: np.ndarray | Mapping[str, float] | None = None,
    start_values: Mapping[str, float] | None = None,
    output: Sequence[str] | None = None,
    rows_to: Callable[[np.ndarray], None] | None = None,
    progress: bool | None = None,
    **fmpy_options: Any,
) -> np.ndarray:
    """Co-simulate the FMU; return FMPy's structured result array.

    `inputs`: an FMPy structured array (field "time" plus input names), or a
    dict of constant input values. `output_interval` is the communication step.
    Raises SimulationError if the FMU refused a step or logged an error: a
    RefusalError, with the refusal's fields, when the FMU said why. A name
    the FMU does not have raises UnknownNameError (a KeyError) naming the
    nearest valid ones; a missing FMU, MissingFMUError naming its build command;
    a damaged one (not a zip, no binary for this platform), BadFMUError naming it.
    `fmu` may be an `FmuInfo` already read (its description is not read again).
    A stop time or output interval that is not a finite number > 0 (the interval
    at most the stop time) raises UsageError, a result that would not fit in the
    memory available RunTooLargeError naming its size, before the first step.
    `rows_to(rows)`: every recorded row is handed to it in order, in chunks
    (FMPy's structured rows), the last ones when the run ends (refused too); the
    result returned, or the error's `result`, then holds no rows. Ctrl-C (main
    thread) ends the run after the step in progress: SimulationInterrupted.
    `progress`: a progress bar (`host.progress`; None: a long run's, on a terminal).
    """
    from fmpy import simulate_fmu
    from fmpy.fmi1 import FMICallException

    from .run_inputs import complete_inputs

    info = fmu if isinstance(fmu, FmuInfo) else FmuInfo.read(fmu)
    description = info.model_description
    start_values = dict(start_values or {})
    info.check(start_values, ("input", "parameter"), "start value (an input or parameter)")
    if output is not None:
        info.check(output, ("input", "output", "parameter", "local"), "output")
    length = run_times(info, stop_time, output_interval)
    stop_time, output_interval = length.stop_time, length.step
    recorded = recorded_variables(info, output)
    if rows_to is None:
        check_memory(length, recorded_values(info, recorded))
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

    # FMPy raises on an FMI 3 refusal and on a refused initialization (either version),
    # losing its recorder: keep it for the partial result.
    recorders: list[Any] = []  # FMPy's Recorder (its class is private)
    step_finished = fmpy_options.pop("step_finished", None)

    bar = StepProgress(length.steps, length.step, progress)

    def keep_recorder(time, recorder):
        recorders[:1] = [recorder]
        bar.update(time)
        if rows_to is not None and len(recorder.rows) >= CHUNK_ROWS + KEPT_ROWS:
            _hand_over(recorder, rows_to, KEPT_ROWS)
        if step_finished is not None and not step_finished(time, recorder):
            return False
        return not interrupt.requested  # False: FMPy ends the run and terminates the FMU

    # Unzipped into a folder of ours: FMPy removes its own only after a run that ended well.
    with (
        interrupt_between_steps() as interrupt,
        ExtractedFMU(info.path, description) as unzipped,
    ):
        try:
            result = simulate_fmu(
                unzipped.directory,
                stop_time=stop_time,
                output_interval=output_interval,
                input=inputs,
                start_values=start_values,
                output=recorded if output is not None else None,
                model_description=description,
                debug_logging=True,
                logger=collect,
                step_finished=keep_recorder,
                **fmpy_options,
            )
        except FMICallException:
            # A second Ctrl-C inside the FMU's step surfaces as a failed call.
            if not (messages or interrupt.requested):  # no reason: FMPy's error is all there is
                raise
            result = recorders[0].result() if recorders else np.zeros(0, dtype=[("time", float)])
        finally:
            bar.close()
    reached = float(result["time"][-1]) if len(result) else float("nan")
    if interrupt.requested:
        raise SimulationInterrupted(
            reached if len(result) else 0.0, _rest(result, rows_to), interrupt.signum
        )
    problems = [m for m in messages if m[0] in ("discard", "error", "fatal")]
    if problems or not reached >= stop_time - 1e-9 * max(1.0, abs(stop_time)):
        detail = (
            "\n  ".join(f"{status}: {text}" for status, _, text in problems)
            or "(the FMU gave no reason)"
        )
        where = f"t = {reached!r} s of {stop_time!r} s" if len(result) else "its start (t = 0 s)"
        text = f"the FMU stopped at {where}:\n  {detail}"
        if not info.fmi3:  # FMI 3.0 in event mode records two rows at an event
            result = _without_repeated_end(result)
        refusal = first_refusal(text for _, _, text in problems)
        if refusal is None:
            raise SimulationError(text, messages, _rest(result, rows_to))
        raise RefusalError(text, messages, _rest(result, rows_to), refusal)
    # One warning per distinct message, however often and in whatever order it came.
    repeats = Counter(text for status, _, text in messages if status == "warning")
    for text, count in repeats.items():
        suffix = f" ({count} times)" if count > 1 else ""
        warnings.warn(f"{info.model_name}: {text}{suffix}", RuntimeWarning, stacklevel=2)
    return _rest(result, rows_to)


def _hand_over(recorder: Any, rows_to: Callable[[np.ndarray], None], keep: int) -> None:
    """Hand FMPy's recorded rows but the last `keep` to `rows_to`, and drop them."""
    count = len(recorder.rows) - keep
    rows = recorder.rows[:count]
    del recorder.rows[:count]
    rows_to(np.array(rows, dtype=np.dtype(recorder.cols)))


def _rest(result: np.ndarray, rows_to: Callable[[np.ndarray], None] | None) -> np.ndarray:
    """The result, or with `rows_to` its rows handed over and none kept."""
    if rows_to is None:
        return result
    if len(result):
        rows_to(result)
    return result[:0]
