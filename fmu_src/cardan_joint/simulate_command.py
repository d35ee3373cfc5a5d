"""`cardan-joint simulate`: one run of any FMU, streamed to its CSV, and its figure.

The run's arguments are checked before the first step (`host.run_arguments`);
the rows go to the CSV as they come, which becomes the file only when the run
is over (`host.csv_run`). Ctrl-C ends the run between two steps and exits 130
writing nothing (SIGTERM and SIGHUP alike, exit 143 and 129); a refused run
writes what it computed up to the refusal; the FMU's warnings print one line
each.
"""

import sys
import textwrap
from pathlib import Path

from . import results
from .host.fmu_info import FmuInfo
from .host.interrupts import exit_status, interrupted
from .host.progress import PROGRESS_MIN_STEPS
from .host.run_inputs import read_input_csv, split_assignments, with_constants
from .names import UsageError

PROG = "cardan-joint"


DEFAULT_OUTPUT = "results/simulate.csv"


def add_simulate_arguments(run) -> None:
    """The options of `cardan-joint simulate`."""
    from .host.simulate import DEFAULT_FMU

    run.add_argument(
        "--fmu", default=str(DEFAULT_FMU), help="FMU file, any model (default %(default)s)"
    )
    run.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE[UNIT]",
        help="constant input or parameter value, in the FMU's SI unit (rad, rad/s, N.m, "
        "kg.m2) or in a unit written after it that the variable's display units offer: "
        "--set bend_angle=0.3 or bend_angle=20deg, input_speed=1500rpm",
    )
    run.add_argument(
        "--input",
        metavar="CSV",
        help="input CSV: a 'time' column [s] and input-name columns in SI units (rad, rad/s, "
        "N.m), or titled with a unit ('bend_angle [deg]', 'input_speed [rpm]')",
    )
    run.add_argument(
        "--stop-time",
        type=float,
        default=None,
        help="stop time [s] (default: the CSV's last time, else the FMU's default experiment)",
    )
    run.add_argument(
        "--step", type=float, default=1e-3, help="communication step [s] (default %(default)s)"
    )
    run.add_argument(
        "--output",
        default=DEFAULT_OUTPUT,
        help="output CSV in SI units, each column titled 'name [unit]' (default %(default)s; "
        "an existing file is replaced, and the command says so)",
    )
    run.add_argument(
        "--plot",
        default=None,
        help="plot file, .png, .pdf, .svg... (default: the output CSV's name, .png)",
    )
    run.add_argument(
        "--plot-variables",
        nargs="+",
        default=None,
        metavar="NAME",
        help="inputs or outputs to plot, each in its display unit (default: the FMU's outputs)",
    )
    progress = run.add_mutually_exclusive_group()
    progress.add_argument(
        "--progress",
        action="store_true",
        help=f"show a progress bar even on a short run (default: from {PROGRESS_MIN_STEPS} "
        "steps on, on a terminal)",
    )
    progress.add_argument("--no-progress", action="store_true", help="no progress bar")


def _written(path: Path, existed: bool, detail: str = "") -> str:
    notes = ", ".join(note for note in (detail, "replaced" if existed else "") if note)
    return f"{path} ({notes})" if notes else str(path)


def check_plot_format(plot: Path) -> None:
    """UsageError, before the run, unless matplotlib writes the plot's format."""
    from matplotlib.backend_bases import FigureCanvasBase

    formats = FigureCanvasBase.get_supported_filetypes()
    if plot.suffix[1:].lower() not in formats:
        raise UsageError(
            f"--plot {plot}: a figure is written as {', '.join('.' + f for f in formats)}; "
            f"not {plot.suffix or 'a name without a suffix'}"
        )


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

    shown = {
        name: (value * info.variables[name].factor, info.variables[name].display_unit)
        for name, value in given.items()
    }  # in display units, as the panels
    inputs = {name: f"= {value:.6g} {unit}".rstrip() for name, (value, unit) in shown.items()}
    if csv_signal is not None and len(csv_signal.dtype.names) > 1:
        inputs[", ".join(n for n in csv_signal.dtype.names if n != "time")] = f"from {args.input}"
    steps = f"{length.steps} steps of {length.step:g} s"
    if refusal is None:
        length_text = f"{steps} to {length.stop_time:g} s"
    else:
        length_text = f"refused after {rows - 1} of {steps} (t = {refusal[0]:.6g} s)"
    if stride > 1:
        length_text += f", drawn from each {stride} rows' least and greatest"
    reason = None if refusal is None else f"Refused: {textwrap.shorten(refusal[1], 320)}"
    return run_title(
        info.model_name, info.model_description.fmiVersion, inputs, length_text, reason
    )


def simulate_command(args):
    import warnings

    from .host.csv_run import StreamedRun, column_units, plot_stride, simulate_to_csv
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
    # --progress: always; by default a long run's bar, on a terminal only (not into a log).
    show = True if args.progress else False if args.no_progress else None
    output = Path(args.output)
    plot = Path(args.plot) if args.plot else output.with_suffix(".png")
    check_plot_format(plot)
    existed = {results.check_output_path(p): p.exists() for p in (output, plot)}
    run = StreamedRun(output, plot_stride(length.rows), column_units(info))
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
                progress=show,
            )
        except SimulationInterrupted as interrupt:
            print(
                f"{PROG} simulate: {interrupted(interrupt)} at t = {interrupt.time:.6g} s of "
                f"{length.stop_time:.6g} s: no file written",
                file=sys.stderr,
            )
            return exit_status(interrupt)
        except KeyboardInterrupt as interrupt:  # after the run: while its last rows were written
            print(
                f"{PROG} simulate: {interrupted(interrupt)} while writing {output}: "
                "no file written",
                file=sys.stderr,
            )
            return exit_status(interrupt)
        except SimulationError as error:
            refused = error
    sys.stderr.write(_warned(caught))
    if refused is not None and run.rows <= 1:  # at most the initial row: no step was taken
        print(
            f"{PROG} simulate: the FMU refused the run at its start (t = 0 s): nothing "
            "computed, no CSV or plot written\n  " + "\n  ".join(_reasons(refused)),
            file=sys.stderr,
        )
        return 2  # a value it cannot start from: the user's mistake, as `build` says it
    sample = run.sample()
    reached = float(sample["time"][-1])
    reason = None if refused is None else (reached, _reasons(refused)[0])
    title = _title(
        info, length, args, csv_signal, {**constants, **parameters}, reason, run.rows, run.stride
    )
    try:
        plot_run(sample, plot_variables, plot, title, info.display)
    except KeyboardInterrupt as interrupt:
        print(
            f"{PROG} simulate: {interrupted(interrupt)} while drawing {plot}: wrote {output} "
            f"({run.rows} rows), no plot",
            file=sys.stderr,
        )
        return exit_status(interrupt)
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
