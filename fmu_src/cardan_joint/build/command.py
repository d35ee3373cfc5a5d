"""The build's command line (`python build_fmu.py`, `cardan-joint build`): parse
the arguments, then call `builder.build`."""

import argparse
import sys
from pathlib import Path

from ..models import discover
from ..names import UsageError, parse_assignments
from .builder import DEFAULT_MODEL, FMI_VERSIONS, BuildError, build


def main(argv=None, prog=None) -> int:
    parser = argparse.ArgumentParser(
        prog=prog,
        description="Build and validate an FMU of this project (default: the UniversalJoint FMU).",
    )
    parser.add_argument(
        "--model",
        default=DEFAULT_MODEL,
        choices=sorted(discover()),
        help="which model to build (default: %(default)s)",
    )
    parser.add_argument(
        "--fmi-version",
        type=int,
        default=2,
        choices=FMI_VERSIONS,
        help="FMI version (default: 2; FMI 3 goes to DEST/fmi3/)",
    )
    parser.add_argument("--dest", default="dist", help="output folder (default: dist)")
    parser.add_argument(
        "--name", default=None, help="model name and FMU file name (default: the model's own name)"
    )
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="start value of an input or parameter in SI units (rad, rad/s, N.m, kg.m2), "
        "e.g. --set bend_angle=0.2",
    )
    parser.add_argument(
        "--joints",
        type=int,
        default=None,
        metavar="N",
        help="Propshaft only: number of joints, 2 (Propshaft, the default), "
        "3 or 4 (Propshaft3, Propshaft4)",
    )
    parser.add_argument(
        "--without-life",
        action="store_true",
        help="UniversalJoint only: build without the bearing loads and catalogue life "
        "(UniversalJointNoLife; docs/life.md), e.g. to measure the joint's step without them",
    )
    parser.add_argument(
        "--cross-check",
        action="store_true",
        help="also write DEST/cross-check/fmus/2.0/cs/linux64/... with the "
        "reference run (fmi-cross-check layout; default model only)",
    )
    args = parser.parse_args(argv)
    settings = {}
    if args.joints is not None:
        if "joints" not in discover()[args.model].default_settings:
            parser.error(f"--joints does not apply to {args.model}")
        settings["joints"] = args.joints
    if args.without_life:
        if "life" not in discover()[args.model].default_settings:
            parser.error(f"--without-life does not apply to {args.model}")
        settings["life"] = False
    if args.cross_check and (
        args.model != DEFAULT_MODEL
        or args.fmi_version != 2
        or args.name not in (None, DEFAULT_MODEL)
        or args.set
    ):
        parser.error(
            "--cross-check takes the default model: its reference run assumes the "
            "default FMI 2 UniversalJoint with its start values (no --model, "
            "--fmi-version, --name or --set)"
        )
    try:
        start_values = parse_assignments(args.set)
    except UsageError as error:
        parser.error(str(error))
    try:
        fmu = build(
            args.dest,
            args.name,
            start_values,
            model=args.model,
            settings=settings,
            fmi_version=args.fmi_version,
        )
    except BuildError as error:
        print(f"build_fmu: {error}", file=sys.stderr)
        return 1
    print(f"built and validated {fmu}")
    if args.cross_check:
        from .cross_check import write_cross_check

        print(f"wrote {write_cross_check(Path(args.dest) / 'cross-check', fmu)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
