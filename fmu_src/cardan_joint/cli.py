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
start); Ctrl-C exits 130 saying where the run was, and every file is written
whole or not at all. The command leaves process-wide state as it found it (no
stderr redirection, sys.argv untouched; during a run, in the main thread, it
holds Ctrl-C to the step boundary and restores the SIGINT handler after):
main() can run inside a host.
"""

import argparse
import sys

from . import results
from .host.fmu_info import MissingFMUError
from .life_command import add_parser as add_life_parser
from .life_command import life_command
from .names import UsageError
from .simulate_command import PROG, PROGRESS_MIN_STEPS, simulate_command

# Each command writes under its own name: a command never overwrites the files
# of another command or of an example (results/demo.csv, results/design_sweep.*).
DEFAULT_OUTPUT = "results/simulate.csv"
SWEEP_NAME = "sweep"


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
    add_life_parser(commands)
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
        if args.command == "life":
            return life_command(args)
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
