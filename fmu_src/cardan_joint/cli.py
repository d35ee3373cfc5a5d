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
import sys
import textwrap
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
    except (UsageError, MissingFMUError, results.ResultFileError) as error:
        print(f"{PROG} {args.command}: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # outside a run (reading the FMU, building, a Dask start-up)
        print(f"{PROG} {args.command}: interrupted", file=sys.stderr)
        return 130
    except OSError as error:  # a path that cannot be read or written: named
        where = error.filename or ""
        print(f"{PROG} {args.command}: {where}: {error.strerror or error}", file=sys.stderr)
        return 1
    except Exception as error:  # noqa: BLE001 - the user gets a message, not a traceback
        print(f"{PROG} {args.command}: {type(error).__name__}: {error}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
