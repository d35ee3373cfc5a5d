"""`cardan-joint simulate`: one run of any FMU, streamed to its CSV, and its figure.

The run's arguments are checked before the first step (`host.run_arguments`);
the rows go to the CSV as they come, which becomes the file only when the run
is over (`host.csv_run`). Ctrl-C ends the run between two steps and exits 130
writing nothing; a refused run writes what it computed up to the refusal; the
FMU's warnings print one line each.
"""

import sys
import textwrap
from pathlib import Path

from . import results
from .host.fmu_info import FmuInfo
from .host.run_inputs import read_input_csv, split_assignments, with_constants

PROG = "cardan-joint"
# Runs with fewer steps finish before a progress bar would help.
PROGRESS_MIN_STEPS = 20_000


def _written(path: Path, existed: bool, detail: str = "") -> str:
    notes = ", ".join(note for note in (detail, "replaced" if existed else "") if note)
    return f"{path} ({notes})" if notes else str(path)


def _progress_callback(length, show):
    """(step_finished, bars): a progress bar made at the first step (none for a
    run refused before it starts)."""
    bars = []
    if not show:
        return None, bars

    def step_finished(time, recorder):
        if not bars:
            from tqdm import tqdm

            bars.append(tqdm(total=length.steps, desc="simulate", unit="step"))
        bars[0].update(round(time / length.step) - bars[0].n)
        return True

    return step_finished, bars


def _reasons(error) -> list[str]:
    return [
        text for status, _, text in error.messages if status in ("discard", "error", "fatal")
    ] or ["(the FMU gave no reason)"]


def _warned(caught) -> str:
    """The run's warnings, one line each (not Python's two-line format with a source line)."""
    return "".join(f"{PROG} simulate: warning: {w.message}\n" for w in caught)


def _title(info, length, args, csv_signal, given, refusal=None, rows=0, stride=1) -> str:
    """The figure's title: model, FMI version, length, how each input was set, a refusal."""
    from .host.run_plot import run_title

    unit = {name: info.variables[name].unit for name in given}
    inputs = {name: f"= {value:g} {unit[name]}".rstrip() for name, value in given.items()}
    if csv_signal is not None and len(csv_signal.dtype.names) > 1:
        inputs[", ".join(n for n in csv_signal.dtype.names if n != "time")] = f"from {args.input}"
    steps = f"{length.steps} steps of {length.step:g} s"
    if refusal is None:
        length_text = f"{steps} to {length.stop_time:g} s"
    else:
        length_text = f"refused after {rows - 1} of {steps} (t = {refusal[0]:.6g} s)"
    if stride > 1:
        length_text += f", 1 row in {stride} drawn"
    reason = None if refusal is None else f"Refused: {textwrap.shorten(refusal[1], 320)}"
    return run_title(
        info.model_name, info.model_description.fmiVersion, inputs, length_text, reason
    )


def simulate_command(args):
    import warnings

    from .host.csv_run import PLOT_ROWS, StreamedRun, simulate_to_csv
    from .host.interrupts import SimulationInterrupted
    from .host.run_plot import plot_run
    from .host.simulate import SimulationError, run_times

    info = FmuInfo.read(args.fmu)  # read once: names, units, start values
    constants, parameters = split_assignments(args.set, info)
    csv_signal = read_input_csv(args.input, info) if args.input else None
    stop_time = (
        args.stop_time
        if args.stop_time is not None
        else float(csv_signal["time"][-1])
        if csv_signal is not None
        else None  # the FMU's default experiment
    )
    length = run_times(info, stop_time, args.step)
    recorded = info.names("input", "output")
    plot_variables = args.plot_variables or info.columns("output")
    info.check(plot_variables, ("input", "output"), "--plot-variables variable")
    inputs = with_constants(csv_signal, constants) if csv_signal is not None else constants
    show = not args.no_progress and (args.progress or length.steps >= PROGRESS_MIN_STEPS)
    output = Path(args.output)
    plot = Path(args.plot) if args.plot else output.with_suffix(".png")
    existed = {results.check_writable(p): p.exists() for p in (output, plot)}
    run = StreamedRun(output, stride=max(1, -(-length.rows // PLOT_ROWS)))
    step_finished, bars = _progress_callback(length, show)
    refused = None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            simulate_to_csv(
                info,
                output,
                length.stop_time,
                length.step,
                inputs,
                parameters,
                recorded,
                run=run,
                step_finished=step_finished,
            )
        except SimulationInterrupted as interrupt:
            print(
                f"{PROG} simulate: interrupted at t = {interrupt.time:.6g} s of "
                f"{length.stop_time:.6g} s: no file written",
                file=sys.stderr,
            )
            return 130
        except KeyboardInterrupt:  # after the run: while its last rows were written
            print(
                f"{PROG} simulate: interrupted while writing {output}: no file written",
                file=sys.stderr,
            )
            return 130
        except SimulationError as error:
            refused = error
        finally:
            for bar in bars:
                bar.close()
    sys.stderr.write(_warned(caught))
    if refused is not None and run.rows <= 1:  # at most the initial row: no step was taken
        print(
            f"{PROG} simulate: the FMU refused the run at its start (t = 0 s): nothing "
            "computed, no CSV or plot written\n  " + "\n  ".join(_reasons(refused)),
            file=sys.stderr,
        )
        return 1
    sample = run.sample()
    reached = float(sample["time"][-1])
    reason = None if refused is None else (reached, _reasons(refused)[0])
    title = _title(
        info, length, args, csv_signal, {**constants, **parameters}, reason, run.rows, run.stride
    )
    try:
        plot_run(sample, plot_variables, plot, title, info.display)
    except KeyboardInterrupt:
        print(
            f"{PROG} simulate: interrupted while drawing {plot}: wrote {output} "
            f"({run.rows} rows), no plot",
            file=sys.stderr,
        )
        return 130
    written = (
        f"{_written(output, existed[output], f'{run.rows} rows')} and "
        f"{_written(plot, existed[plot])}"
    )
    if refused is None:
        print(f"wrote {written}")
        return 0
    print(
        f"{PROG} simulate: the FMU refused a step: stopped at t = {reached:.6g} s of "
        f"{length.stop_time:.6g} s\n  "
        + "\n  ".join(_reasons(refused))
        + f"\nwrote the run up to the refusal: {written}",
        file=sys.stderr,
    )
    return 1
