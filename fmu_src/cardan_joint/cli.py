"""The `cardan-joint` command: build, sweep, simulate any FMU of this project, and
report a duty cycle's life.

    cardan-joint build [--dest DIR] [--name MODEL] [--set NAME=VALUE ...]
    cardan-joint simulate [--set NAME=VALUE[UNIT] ...] [--input inputs.csv] [--stop-time S]
                          [--step S] [--output run.csv] [--plot run.png] [--plot-variables ...]
    cardan-joint sweep [--serial | --scheduler tcp://host:8786 | --compare] [...]
    cardan-joint life CYCLE [--fmu F] [--set NAME=VALUE ...] [--output results/life.csv]
    cardan-joint --version

`simulate` reads names, causalities and units from the FMU's modelDescription,
so it runs every model the build offers; it plots the FMU's outputs unless
told otherwise. Every failure a user can cause (an unknown variable, a
malformed CSV, a step the FMU refuses, a missing FMU) ends in a one-paragraph
message on stderr and a non-zero exit status, never a traceback: 2 for a
mistake found before the first step (the same for `build` and `simulate`), 1
for a run that failed, 128 + the signal for an interrupt. A refused run still
writes what it computed up to the refusal (nothing if refused at the start);
Ctrl-C, SIGTERM and SIGHUP end the run at a step boundary saying where it
was, and every file is written whole or not at all. The command leaves
process-wide state as it found it (no stderr redirection, sys.argv untouched;
the signal handlers it sets for its length are restored after): main() can
run inside a host.

Each subcommand is one entry of COMMANDS: its help line, whether it parses its
own options (then it gets the rest of the command line), and the function that
runs it.
"""

import argparse
import sys
from collections.abc import Callable
from typing import NamedTuple

from . import __version__, results
from .host.fmu_info import MissingFMUError
from .host.interrupts import exit_status, stop_signals_raise
from .life_command import DESCRIPTION as LIFE_DESCRIPTION
from .life_command import HELP as LIFE_HELP
from .life_command import add_arguments as add_life_arguments
from .life_command import life_command
from .names import UsageError
from .simulate_command import PROG, add_simulate_arguments, simulate_command

# Each command writes under its own name: a command never overwrites the files
# of another command or of an example (results/demo.csv, results/design_sweep.*).
SWEEP_NAME = "sweep"


def _build(args, rest) -> int:
    from .build import main as build_main

    return build_main(rest, prog=f"{PROG} build")


def _sweep(args, rest) -> int:
    from .sweep import main as sweep_main

    return sweep_main(rest, prog=f"{PROG} sweep", default_name=SWEEP_NAME)


class Command(NamedTuple):
    help: str
    run: Callable[[argparse.Namespace, list[str]], int]
    # Adds the command's options to its parser; None: the command parses its own (`rest`).
    arguments: Callable[[argparse.ArgumentParser], None] | None = None
    description: str | None = None


COMMANDS = {
    "build": Command("build and validate the FMU", _build),
    "sweep": Command("design sweep on Dask or serially, in deg and rpm", _sweep),
    "simulate": Command(
        "co-simulate any FMU of this project with FMPy",
        lambda args, rest: simulate_command(args),
        add_simulate_arguments,
        "Co-simulate an FMU from constant inputs (--set) and/or an input CSV; write an "
        "output CSV (SI units, each column titled with its unit: 'output_speed [rad/s]') "
        "and a PNG plot (display units). Values are in SI unless a unit follows them: "
        "--set bend_angle=20deg, input_speed=1500rpm, or a CSV column titled "
        "'bend_angle [deg]'. Names, units and start values come from the FMU. An input "
        "left unset does what the FMU does with it: holds its start value, or follows "
        "its rate (a speed its acceleration, a bend angle its rate).",
    ),
    "life": Command(
        LIFE_HELP, lambda args, rest: life_command(args), add_life_arguments, LIFE_DESCRIPTION
    ),
}


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog=PROG,
        description="Build the FMUs of this project, simulate any of them, sweep the "
        "UniversalJoint's design and run duty cycles for the joints' life. Units: "
        "simulate's values and CSVs are SI (rad, rad/s, N.m) unless a unit follows a value "
        "(20deg, 1500rpm); sweep's options are in the units their help names (deg, rpm); "
        "figures use display units.",
        epilog=f"Each command's options: {PROG} COMMAND --help.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, command in COMMANDS.items():
        if command.arguments is None:
            commands.add_parser(name, add_help=False, help=command.help)
        else:
            command.arguments(
                commands.add_parser(name, help=command.help, description=command.description)
            )
    return parser


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = _parser()
    args, rest = parser.parse_known_args(argv)
    command = COMMANDS[args.command]
    if rest and command.arguments is not None:
        parser.error(f"unrecognized arguments: {' '.join(rest)}")
    try:
        with stop_signals_raise():
            return command.run(args, rest)
    except (UsageError, MissingFMUError, results.ResultFileError) as error:
        print(f"{PROG} {args.command}: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as interrupt:  # outside a run (reading the FMU, building, Dask)
        print(f"{PROG} {args.command}: interrupted", file=sys.stderr)
        return exit_status(interrupt)
    except OSError as error:  # a path that cannot be read or written: named
        where = error.filename or ""
        print(f"{PROG} {args.command}: {where}: {error.strerror or error}", file=sys.stderr)
        return 1
    except Exception as error:  # noqa: BLE001 - the user gets a message, not a traceback
        print(f"{PROG} {args.command}: {type(error).__name__}: {error}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
