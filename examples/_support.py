"""Plumbing shared by the examples: the command line (figures: cardan_joint.plotting)."""

import argparse
from pathlib import Path

from cardan_joint.simulate import DEFAULT_FMU


def example_parser(doc: str, default_out: str = "results") -> argparse.ArgumentParser:
    """A parser with the options every example takes: --fmu and --out."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--fmu", default=str(DEFAULT_FMU), help="the FMU to co-simulate")
    parser.add_argument("--out", default=default_out, help="folder for the results")
    return parser


def output_folder(args) -> Path:
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    return out
