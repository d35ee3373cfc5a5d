"""Plumbing shared by the examples: the command line, the FMU they need, legends.

Figures otherwise come from cardan_joint.host.plotting.
"""

import argparse
import math
import sys
from collections.abc import Callable
from pathlib import Path

from cardan_joint.host.fmu_info import FmuInfo, MissingFMUError
from cardan_joint.host.fmu_info import build_command as fmu_build_command
from cardan_joint.host.instance import StepRefusedError
from cardan_joint.host.interrupts import exit_status, stop_signals_raise
from cardan_joint.host.simulate import DEFAULT_FMU, SimulationError
from cardan_joint.names import UsageError
from cardan_joint.results import ResultFileError

DEFAULT_MODEL = "UniversalJoint"


def build_command(model: str = DEFAULT_MODEL) -> str:
    """The command that writes dist/<model>.fmu."""
    return fmu_build_command(DEFAULT_FMU.with_name(f"{model}.fmu"))


def example_parser(
    doc: str, default_out: str = "results", model: str = DEFAULT_MODEL
) -> argparse.ArgumentParser:
    """A parser with the options every example takes: --fmu (of `model`) and --out."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument(
        "--fmu",
        default=str(DEFAULT_FMU.with_name(f"{model}.fmu")),
        help=f"the {model} FMU to co-simulate (default: %(default)s, built by "
        f"`{build_command(model)}`)",
    )
    parser.add_argument("--out", default=default_out, help="folder for the results")
    parser.set_defaults(model=model)
    return parser


def example_fmu(args) -> Path:
    """The FMU the example runs; exits with the command that builds it when it is missing
    (a message, not a traceback: the user's next step is a build, not a bug report),
    and refuses a file that is not an FMU."""
    fmu = Path(args.fmu)
    if not fmu.is_file():
        sys.exit(
            f"{fmu} does not exist: build the {args.model} FMU first with "
            f"`{build_command(args.model)}` (it writes "
            f"{DEFAULT_FMU.with_name(args.model + '.fmu')}), or pass --fmu"
        )
    FmuInfo.read(fmu)  # BadFMUError (one line from run_example) for a file that is not an FMU
    return fmu


def positive(text: str) -> float:
    """An argparse type: a finite number > 0 (a stop time, a step, a speed)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"{text} must be a finite number > 0")
    return value


def run_example(main: Callable[[], int | None]) -> int:
    """Run an example's `main` as a command: a mistake (an argument, a missing or
    damaged FMU, a path) exits 2 with one line, a run the FMU refused 1, Ctrl-C
    (SIGTERM, SIGHUP) 128 + the signal, saying so in one line; a bug keeps its
    traceback."""
    prog = Path(sys.argv[0]).name
    try:
        with stop_signals_raise():
            status = main()
    except (UsageError, MissingFMUError, ResultFileError) as error:
        print(f"{prog}: {error}", file=sys.stderr)
        return 2
    except (SimulationError, StepRefusedError) as error:
        print(f"{prog}: {' '.join(str(error).split())}", file=sys.stderr)
        return 1
    except KeyboardInterrupt as interrupt:
        print(f"{prog}: interrupted", file=sys.stderr)
        return exit_status(interrupt)
    return status or 0


def output_folder(args) -> Path:
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    return out


def legend_outside(ax, **options) -> None:
    """The legend to the right of the axes, where it cannot cover the data."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **options)
