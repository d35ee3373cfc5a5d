"""The `cardan-joint` command: build, sweep, and simulate any FMU of this project.

    cardan-joint build [--dest DIR] [--name MODEL] [--set NAME=VALUE ...]
    cardan-joint simulate [--set NAME=VALUE ...] [--input inputs.csv] [--stop-time S]
                          [--step S] [--output run.csv] [--plot run.png] [--plot-variables ...]
    cardan-joint sweep [--serial | --scheduler tcp://host:8786 | --compare] [...]

`simulate` reads names, causalities and units from the FMU's modelDescription,
so it runs every model the build offers; it plots the FMU's outputs unless
told otherwise. Every failure a user can cause (an unknown variable, a
malformed CSV, a step the FMU refuses, a missing FMU) ends in a one-paragraph
message on stderr and a non-zero exit status, never a traceback; a refused run
still writes what it computed up to the refusal (nothing if refused at the
start). The command changes no process-wide state (no stderr redirection,
sys.argv as it found it): main() can run inside a host.
"""

import argparse
import math
import sys
from pathlib import Path

from . import results
from .host.fmu_info import FmuInfo, MissingFMUError
from .host.run_inputs import read_input_csv, split_assignments, with_constants
from .names import UsageError

PROG = "cardan-joint"
# Runs with fewer steps finish before a progress bar would help.
PROGRESS_MIN_STEPS = 20_000
# Each command writes under its own name: a command never overwrites the files
# of another command or of an example (results/demo.csv, results/design_sweep.*).
DEFAULT_OUTPUT = "results/simulate.csv"
SWEEP_NAME = "sweep"


# --- simulate: output -------------------------------------------------------


def _written(path: Path, existed: bool, detail: str = "") -> str:
    notes = ", ".join(note for note in (detail, "replaced" if existed else "") if note)
    return f"{path} ({notes})" if notes else str(path)


def write_outputs(result, output: Path, plot: Path, names, title, display) -> str:
    """Write the result CSV and its plot; say which files existed before."""
    existed = {p: p.exists() for p in (output, plot)}
    results.write_csv(result, output)
    if len(result):
        from .host.plotting import plot_time_series

        plot_time_series(result, names, plot, title, display)
        return (
            f"{_written(output, existed[output], f'{len(result)} rows')} and "
            f"{_written(plot, existed[plot])}"
        )
    return _written(output, existed[output], "no rows: no plot")


def _progress_callback(stop_time, step, show):
    if not show:
        return None, None
    from tqdm import tqdm

    bar = tqdm(total=max(1, round(stop_time / step)), desc="simulate", unit="step")

    def step_finished(time, recorder):
        bar.update(round(time / step) - bar.n)
        return True

    return step_finished, bar


def _refusal(error, start: bool, stop_time) -> str:
    """Where a refused run stopped, rounded, and the FMU's reasons."""
    reached = float(error.result["time"][-1]) if len(error.result) else 0.0
    reasons = [
        text for status, _, text in error.messages if status in ("discard", "error", "fatal")
    ] or ["(the FMU gave no reason)"]
    where = (
        "the FMU refused the run at its start (t = 0 s): nothing computed, no CSV or plot written"
        if start
        else f"the FMU refused a step: stopped at t = {reached:.6g} s of {stop_time:.6g} s"
    )
    return where + "\n  " + "\n  ".join(reasons)


def simulate_command(args):
    from .host.simulate import SimulationError, flat_columns, simulate

    info = FmuInfo.read(args.fmu)  # read once: names, units, start values
    constants, parameters = split_assignments(args.set, info)
    csv_signal = read_input_csv(args.input, info) if args.input else None
    experiment = info.model_description.defaultExperiment
    stop_time = (
        args.stop_time
        if args.stop_time is not None
        else float(csv_signal["time"][-1])
        if csv_signal is not None
        else float(experiment.stopTime)
    )
    step = args.step
    if not (math.isfinite(stop_time) and stop_time > 0):
        raise UsageError(f"--stop-time {stop_time!r} must be a number > 0")
    if not (math.isfinite(step) and 0 < step <= stop_time):
        raise UsageError(f"--step {step!r} must be > 0 and at most the stop time {stop_time!r}")
    recorded = info.names("input", "output")
    plot_variables = args.plot_variables or info.columns("output")
    info.check(plot_variables, ("input", "output"), "--plot-variables variable")
    inputs = with_constants(csv_signal, constants) if csv_signal is not None else constants
    steps = round(stop_time / step)
    show = not args.no_progress and (args.progress or steps >= PROGRESS_MIN_STEPS)
    step_finished, bar = _progress_callback(stop_time, step, show)
    output = Path(args.output)
    plot = Path(args.plot) if args.plot else output.with_suffix(".png")
    title = f"{info.path.name}: {steps} steps of {step:.6g} s"
    try:
        result = simulate(
            info,
            stop_time=stop_time,
            output_interval=step,
            inputs=inputs,
            start_values=parameters,
            output=recorded,
            step_finished=step_finished,
        )
    except SimulationError as error:
        partial = flat_columns(error.result)
        at_start = len(partial) <= 1  # at most the initial row: no step was taken
        message = f"{PROG} simulate: {_refusal(error, at_start, stop_time)}"
        if not at_start:
            written = write_outputs(
                partial, output, plot, plot_variables, f"{title} (refused)", info.display
            )
            message += f"\nwrote the run up to the refusal: {written}"
        print(message, file=sys.stderr)
        return 1
    finally:
        if bar:
            bar.close()
    result = flat_columns(result)  # an FMI 3 FMU's arrays, as FMI 2 columns
    written = write_outputs(result, output, plot, plot_variables, title, info.display)
    print(f"wrote {written}")
    return 0


# --- the command ------------------------------------------------------------


def _parser():
    parser = argparse.ArgumentParser(
        prog=PROG,
        description="Build the FMUs of this project, simulate any of them, and sweep the "
        "UniversalJoint's design. Values: --set and input CSVs in the FMU's SI units "
        "(rad, rad/s, N.m); sweep options and plots in the units their help names (deg, rpm).",
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    commands.add_parser(
        "build",
        add_help=False,
        help="build and validate the FMU (options: cardan-joint build --help)",
    )
    commands.add_parser(
        "sweep",
        add_help=False,
        help="design sweep on Dask or serially (options: cardan-joint sweep --help)",
    )
    run = commands.add_parser(
        "simulate",
        help="co-simulate any FMU of this project with FMPy",
        description="Co-simulate an FMU from constant inputs (--set) "
        "and/or an input CSV; write an output CSV (SI units) and a PNG plot "
        "(display units). Names, units and start values come from the FMU. "
        "An input left unset does what the FMU does with it: holds its start "
        "value, or follows its rate (a speed its acceleration, a bend angle its rate).",
    )
    from .host.simulate import DEFAULT_FMU

    run.add_argument(
        "--fmu", default=str(DEFAULT_FMU), help="FMU file, any model (default %(default)s)"
    )
    run.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="constant input or parameter value in the FMU's SI unit (rad, rad/s, N.m, "
        "kg.m2; not deg or rpm), e.g. --set bend_angle=0.3 (17.2 deg)",
    )
    run.add_argument(
        "--input",
        metavar="CSV",
        help="input CSV: a 'time' column [s] and input-name columns in SI units (rad, rad/s, N.m)",
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
        help="output CSV (default %(default)s; an existing file is replaced, "
        "and the command says so)",
    )
    run.add_argument("--plot", default=None, help="plot PNG (default: the output CSV's name, .png)")
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
        help=f"always show a progress bar (default: from {PROGRESS_MIN_STEPS} steps on)",
    )
    progress.add_argument("--no-progress", action="store_true", help="no progress bar")
    return parser


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = _parser()
    args, rest = parser.parse_known_args(argv)
    try:
        if args.command == "build":
            from .build import main as build_main

            return build_main(rest, prog=f"{PROG} build")
        if args.command == "sweep":
            from .sweep import main as sweep_main

            return sweep_main(rest, prog=f"{PROG} sweep", default_name=SWEEP_NAME)
        if rest:
            parser.error(f"unrecognized arguments: {' '.join(rest)}")
        return simulate_command(args)
    except (UsageError, MissingFMUError) as error:
        print(f"{PROG} {args.command}: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"{PROG} {args.command}: interrupted", file=sys.stderr)
        return 130
    except Exception as error:  # noqa: BLE001 - the user gets a message, not a traceback
        print(f"{PROG} {args.command}: {type(error).__name__}: {error}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
