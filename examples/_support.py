"""Plumbing shared by the examples: the command line, the FMU they need, legends.

Figures otherwise come from cardan_joint.host.plotting.
"""

import argparse
import sys
from pathlib import Path

from cardan_joint.host.fmu_info import build_command as fmu_build_command
from cardan_joint.host.simulate import DEFAULT_FMU

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
    (a message, not a traceback: the user's next step is a build, not a bug report)."""
    fmu = Path(args.fmu)
    if not fmu.is_file():
        sys.exit(
            f"{fmu} does not exist: build the {args.model} FMU first with "
            f"`{build_command(args.model)}` (it writes "
            f"{DEFAULT_FMU.with_name(args.model + '.fmu')}), or pass --fmu"
        )
    return fmu


def output_folder(args) -> Path:
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    return out


def legend_outside(ax, **options) -> None:
    """The legend to the right of the axes, where it cannot cover the data."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **options)
