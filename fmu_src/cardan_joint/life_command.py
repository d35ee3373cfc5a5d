"""`cardan-joint life`: a duty cycle in, the life it uses out (docs/life.md).

    cardan-joint life CYCLE [--fmu F] [--set NAME=VALUE ...] [--cycle-time S]
                      [--step S] [--spans N] [--output results/life.csv]

CYCLE is a measured time series (CSV or Parquet) or a block table (CSV); the
report is printed and written as CSV (per block or span), JSON (summary) and
PNG (damage over the cycle and by part), beside `--output`.
"""

from __future__ import annotations

import argparse

DEFAULT_OUTPUT = "results/life.csv"


HELP = "run a duty cycle (time series or block table) and report the joints' life"
DESCRIPTION = (
    "Run a duty cycle through a jointed FMU and report the life it uses: "
    "a measured time series (CSV or Parquet: time, input_speed, a torque, bend_angle, "
    "optional rates; bare names in SI, or units in brackets, e.g. 'input_speed [rpm]') "
    "or a block table (CSV: block, time_share or revolution_share, 'speed [rpm]', "
    "'torque [N.m]', 'angle [deg]'). Writes CSV, JSON and PNG beside --output."
)


def add_arguments(life: argparse.ArgumentParser) -> None:
    """The `life` command's options, on its parser (cli.COMMANDS)."""
    from .host.simulate import DEFAULT_FMU

    life.add_argument("cycle", metavar="CYCLE", help="time series (.csv/.parquet) or block table")
    life.add_argument("--fmu", default=str(DEFAULT_FMU), help="a jointed FMU (default %(default)s)")
    life.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="parameter start value in the FMU's SI unit, e.g. --set rated_torque=1200",
    )
    life.add_argument(
        "--cycle-time",
        type=float,
        default=10.0,
        help="block table: seconds of driving the shares divide (default %(default)s s; "
        "B10 hours do not depend on it)",
    )
    life.add_argument(
        "--step",
        type=float,
        default=1e-3,
        help="block table: longest step [s] (default %(default)s)",
    )
    life.add_argument(
        "--spans",
        type=int,
        default=10,
        help="time series: equal spans reported (default %(default)s)",
    )
    life.add_argument(
        "--output", default=DEFAULT_OUTPUT, help="report CSV; .json and .png beside it "
        "(default %(default)s)"
    )  # fmt: skip


def _positive(args: argparse.Namespace) -> None:
    from .names import UsageError

    for option, value in (("--cycle-time", args.cycle_time), ("--step", args.step)):
        if not value > 0.0 or value == float("inf"):
            raise UsageError(f"{option} {value!r}: give a positive number of seconds")
    if args.spans < 1:
        raise UsageError(f"--spans {args.spans}: give at least 1")


def life_command(args: argparse.Namespace) -> int:
    from .host.life_files import write_report
    from .host.life_report import life_report, report_text
    from .names import parse_assignments

    _positive(args)
    starts = parse_assignments(args.set)
    report = life_report(args.cycle, args.fmu, starts, args.cycle_time, args.step, args.spans)
    print(report_text(report))
    paths = write_report(report, args.output)
    print("wrote " + ", ".join(str(p) for p in paths.values()))
    return 0
