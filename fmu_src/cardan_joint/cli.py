"""The `cardan-joint` command: build, simulate and sweep the UniversalJoint FMU.

    cardan-joint build [--dest DIR] [--name MODEL] [--set NAME=VALUE ...]
    cardan-joint simulate [--set NAME=VALUE ...] [--input inputs.csv] [--stop-time S]
                          [--step S] [--output run.csv] [--plot run.png] [--plot-variables ...]
    cardan-joint sweep [--serial | --scheduler tcp://host:8786 | --compare] [...]

Every failure a user can cause (an unknown variable, a malformed CSV, a step
the FMU refuses, a missing FMU) ends in a one-paragraph message on stderr and
a non-zero exit status, never a traceback; a refused run still writes what it
computed up to the refusal. The command changes no process-wide state (no
stderr redirection, sys.argv as it found it): main() can run inside a host.
"""

import argparse
import math
import sys
from pathlib import Path

from . import results
from . import variables as table
from .run_inputs import UsageError, input_signal, parse_assignments, read_input_csv, start_values

PROG = "cardan-joint"
DEFAULT_PLOT_VARIABLES = ("output_speed", "output_acceleration", "cardan_error", "input_torque")
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


def write_outputs(result, output: Path, plot: Path, names, title) -> str:
    """Write the result CSV and its plot; say which files existed before."""
    existed = {p: p.exists() for p in (output, plot)}
    results.write_csv(result, output)
    if len(result):
        from .plotting import plot_time_series

        plot_time_series(result, names, plot, title)
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


def _refusal(error, stop_time) -> str:
    """Where a refused run stopped, rounded, and the FMU's reasons."""
    reached = float(error.result["time"][-1]) if len(error.result) else 0.0
    reasons = [
        text for status, _, text in error.messages if status in ("discard", "error", "fatal")
    ] or ["(the FMU gave no reason)"]
    return (
        f"the FMU refused a step: stopped at t = {reached:.6g} s of {stop_time:.6g} s\n  "
        + "\n  ".join(reasons)
    )


def simulate_command(args):
    from .simulate import SimulationError, flat_columns, simulate

    fmu = Path(args.fmu)
    if not fmu.is_file():
        raise UsageError(f"{fmu} does not exist: build it with `{PROG} build`")
    constants, parameters = parse_assignments(args.set)
    csv_signal = read_input_csv(args.input) if args.input else None
    starts, experiment = start_values(fmu)
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
    unknown = [n for n in args.plot_variables if n not in table.BY_NAME]
    if unknown:
        raise UsageError(f"--plot-variables: unknown variable(s) {', '.join(unknown)}")
    signal = input_signal(constants, csv_signal, starts, stop_time)
    steps = round(stop_time / step)
    show = not args.no_progress and (args.progress or steps >= PROGRESS_MIN_STEPS)
    step_finished, bar = _progress_callback(stop_time, step, show)
    output = Path(args.output)
    plot = Path(args.plot) if args.plot else output.with_suffix(".png")
    title = f"{fmu.name}: {steps} steps of {step:.6g} s"
    try:
        result = simulate(
            fmu,
            stop_time=stop_time,
            output_interval=step,
            inputs=signal,
            start_values=parameters,
            output=list(table.INPUTS + table.OUTPUTS),
            step_finished=step_finished,
        )
    except SimulationError as error:
        written = write_outputs(
            flat_columns(error.result), output, plot, args.plot_variables, f"{title} (refused)"
        )
        print(
            f"{PROG} simulate: {_refusal(error, stop_time)}\n"
            f"wrote the run up to the refusal: {written}",
            file=sys.stderr,
        )
        return 1
    finally:
        if bar:
            bar.close()
    result = flat_columns(result)  # an FMI 3 FMU's arrays, as FMI 2 columns
    print(f"wrote {write_outputs(result, output, plot, args.plot_variables, title)}")
    return 0


# --- the command ------------------------------------------------------------


def _parser():
    parser = argparse.ArgumentParser(
        prog=PROG,
        description="Build, simulate and sweep the exact Cardan joint FMU (UniversalJoint).",
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
        help="co-simulate the FMU with FMPy",
        description="Co-simulate the FMU from constant inputs (--set) "
        "and/or an input CSV; write an output CSV and a PNG plot. Inputs "
        "hold over each step with their rates: give input_acceleration "
        "and bend_angle_rate columns with speed and bend angle columns "
        "for an exact run.",
    )
    from .simulate import DEFAULT_FMU

    run.add_argument("--fmu", default=str(DEFAULT_FMU), help="FMU file (default %(default)s)")
    run.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="constant input or parameter value, e.g. --set bend_angle=0.3 "
        "(SI units: rad, rad/s, N.m, kg.m2)",
    )
    run.add_argument(
        "--input", metavar="CSV", help="input CSV: a 'time' column and input-name columns"
    )
    run.add_argument(
        "--stop-time",
        type=float,
        default=None,
        help="[s] (default: the CSV's last time, else the FMU's default experiment)",
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
        default=list(DEFAULT_PLOT_VARIABLES),
        metavar="NAME",
        help="variables to plot (default: %(default)s)",
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
    except UsageError as error:
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
