"""The sweep's command line (`examples/design_sweep.py`, `cardan-joint sweep`)."""

import argparse
import os
import re
import shutil
import sys
from pathlib import Path

from ..extras import MissingExtra, require
from ..host.interrupts import exit_status, interrupted
from ..names import UsageError
from ..results import write_table
from .execution import connect, run_dask, run_serial
from .heatmap import plot_heatmaps
from .spec import ACCELERATION_LIMIT, FAILED, INERTIA_DISTRIBUTIONS, OK, SweepSpec
from .store import SETTINGS_FILE, CaseStore, SettingsMismatch
from .timing import compare, timed


def add_arguments(parser, default_name="design_sweep"):
    from ..host.simulate import DEFAULT_FMU

    defaults = SweepSpec()
    parser.add_argument("--fmu", default=str(DEFAULT_FMU), help="FMU file (default %(default)s)")
    parser.add_argument("--out", default="results", help="output folder (default %(default)s)")
    parser.add_argument(
        "--name",
        default=default_name,
        help="file stem of the table, figure and case folder (default %(default)s)",
    )
    parser.add_argument(
        "--bend-angles",
        type=float,
        nargs="+",
        metavar="DEG",
        default=list(defaults.bend_angles_deg),
        help="bend angles [deg], any spacing (default %(default)s)",
    )
    parser.add_argument(
        "--speeds",
        type=float,
        nargs="+",
        metavar="RPM",
        default=list(defaults.input_speeds_rpm),
        help="input shaft speeds [rpm] (default %(default)s)",
    )
    parser.add_argument(
        "--distributions",
        nargs="+",
        default=list(defaults.distributions),
        choices=sorted(INERTIA_DISTRIBUTIONS),
        help="crosspiece inertia distributions of I0, Mityushov & Misyura's T1..T4 (default: all)",
    )
    parser.add_argument(
        "--i0",
        type=float,
        default=defaults.total_inertia,
        help="total crosspiece inertia I0 [kg.m2] (default %(default)s)",
    )
    parser.add_argument(
        "--load-torque",
        type=float,
        default=defaults.load_torque,
        help="load torque [N.m] (default %(default)s)",
    )
    parser.add_argument(
        "--revolutions",
        type=int,
        default=defaults.revolutions,
        help="input revolutions simulated per case (default %(default)s)",
    )
    parser.add_argument(
        "--steps-per-revolution",
        type=int,
        default=defaults.steps_per_revolution,
        help="communication steps per input revolution (default %(default)s)",
    )
    parser.add_argument(
        "--max-bend-angle",
        type=float,
        default=None,
        metavar="DEG",
        help="the FMU's bend guard [deg] for every run (default: the FMU's own)",
    )
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="Dask scheduler, e.g. tcp://host:8786 (default: a LocalCluster)",
    )
    mode.add_argument("--serial", action="store_true", help="run every task in this process")
    mode.add_argument(
        "--compare",
        action="store_true",
        help="run on Dask and serially, check the tables are identical, "
        "print both wall times and the speed-up (nothing resumed)",
    )
    parser.add_argument(
        "--workers", type=int, default=2, help="LocalCluster worker processes (default %(default)s)"
    )
    parser.add_argument(
        "--repeat",
        type=int,
        default=1,
        help="with --compare: timing repetitions (default %(default)s)",
    )
    parser.add_argument(
        "--fresh",
        action="store_true",
        help="discard the cases of an earlier run of this sweep (default: "
        "resume it, computing only the missing cases)",
    )
    progress = parser.add_mutually_exclusive_group()
    progress.add_argument(
        "--progress", action="store_true", help="a progress bar also into a log or a pipe"
    )
    progress.add_argument("--no-progress", action="store_true", help="no progress bar")


def spec_from_arguments(args) -> SweepSpec:
    return SweepSpec(
        tuple(args.bend_angles),
        tuple(args.speeds),
        tuple(args.distributions),
        args.i0,
        args.load_torque,
        args.revolutions,
        args.steps_per_revolution,
        args.max_bend_angle,
    )


def _print_comparison(timings, where):
    print(f"Dask ({where}) and serial tables identical")
    for k, t in enumerate(timings, 1):
        load = (
            ""
            if None in (t["others_dask"], t["others_serial"])
            else f"; other processes kept {t['others_serial']:.2f} and {t['others_dask']:.2f}"
            f" of {os.cpu_count()} CPUs busy"
        )
        print(
            f"  run {k}: serial {t['serial']:.1f} s, Dask {t['dask']:.1f} s, speed-up "
            f"{t['serial'] / t['dask']:.2f} ({t['serial'] / (t['dask'] + t['startup']):.2f}"
            f" counting {t['startup']:.1f} s of cluster start-up){load}"
        )


def _open_store(folder: Path, spec, fmu, fresh):
    if fresh and (folder / SETTINGS_FILE).is_file():
        shutil.rmtree(folder)
    store = CaseStore(folder, spec, fmu)
    done = len(spec.cases()) - len(store.missing(spec.cases()))
    if done:
        print(
            f"resuming: {done} of {len(spec.cases())} cases already in {folder} "
            f"(--fresh to recompute them)"
        )
    return store


def _run(args, fmu, spec, store, progress):
    if args.serial:
        table, seconds = timed(run_serial, fmu, spec, progress, store)
        print(f"serial: {seconds:.1f} s, {store.written} cases computed")
        return table
    with connect(args.scheduler, args.workers) as (client, _, startup):
        table, seconds = timed(run_dask, fmu, spec, client, progress, store)
    print(
        f"Dask: {seconds:.1f} s (+ {startup:.1f} s to start or reach the cluster), "
        f"{store.written} cases computed"
    )
    return table


def _cause(message: str) -> str:
    """A failure's message with its numbers blanked: the cause shared by cases
    that failed alike at other values."""
    return re.sub(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?|\bnan\b", "#", message)


def _case(row) -> str:
    return (
        f"{row['bend_angle_deg']:g} deg, {row['input_speed_rpm']:g} rpm, "
        f"{row['inertia_distribution']}"
    )


def _summary(table) -> list[str]:
    """Counts, then each cause of failure once: how many cases, which (the first
    few), and the first case's whole message."""
    failed, ok = table[table["status"] == FAILED], table[table["status"] == OK]
    lines = [
        f"{len(ok)} ok, {len(failed)} failed; "
        f"{int(ok['beyond_acceleration_limit'].sum())} beyond {ACCELERATION_LIMIT:g} rad/s2"
    ]
    causes: dict[str, list] = {}
    for _, row in failed.iterrows():
        causes.setdefault(_cause(str(row["message"])), []).append(row)
    for rows in causes.values():
        named = "; ".join(_case(row) for row in rows[:3])
        more = f" and {len(rows) - 3} more" if len(rows) > 3 else ""
        lines.append(
            f"  {len(rows)} failed ({named}{more}), e.g. {_case(rows[0])}: {rows[0]['message']}"
        )
    return lines


def _checked(args):
    """The sweep's settings, every argument checked before the first case."""
    from ..host.fmu_info import MissingFMUError
    from .case import check_fmu, check_ranges

    spec = spec_from_arguments(args)
    local = not (args.serial or args.scheduler)
    if local and args.workers < 1:
        raise UsageError(f"--workers {args.workers}: a LocalCluster needs at least 1 worker")
    if args.compare and args.repeat < 1:
        raise UsageError(f"--repeat {args.repeat}: give at least 1 timing repetition")
    try:
        info = check_fmu(Path(args.fmu), spec)
    except MissingFMUError as error:
        raise UsageError(str(error)) from None
    check_ranges(info.starts("parameter"), spec)  # every case, before the first one runs
    return spec


def main(argv=None, prog=None, default_name="design_sweep") -> int:
    parser = argparse.ArgumentParser(
        prog=prog,
        description="Design sweep of the Cardan joint FMU over bend angle x input speed x "
        "inertia distribution. Units: angles in deg, speeds in rpm, I0 in kg.m2, torque in "
        "N.m, as each option says; the table's columns name theirs (bend_angle_deg, "
        "input_speed_rpm; peaks in SI).",
    )
    add_arguments(parser, default_name)
    args = parser.parse_args(argv)
    name = parser.prog
    try:
        spec = _checked(args)
    except UsageError as error:
        print(f"{name}: {error}", file=sys.stderr)
        return 2
    fmu, out = Path(args.fmu), Path(args.out)
    if not args.serial:
        try:
            require("distributed", "sweep", "a sweep on Dask (--serial runs without it)")
        except MissingExtra as error:
            print(f"{name}: {error}", file=sys.stderr)
            return 1
    # A bar on a terminal only (a log never fills with bars), unless asked.
    progress = True if args.progress else False if args.no_progress else None
    print(
        f"{len(spec.cases())} co-simulations in {len(spec.tasks())} tasks, "
        f"{spec.revolutions * spec.steps_per_revolution} steps each"
    )
    if args.compare:
        table, timings = compare(fmu, spec, args.scheduler, args.workers, args.repeat, progress)
        _print_comparison(
            timings, args.scheduler or f"LocalCluster of {args.workers} worker processes"
        )
    else:
        try:
            store = _open_store(out / f"{args.name}.cases", spec, fmu, args.fresh)
        except SettingsMismatch as error:
            print(f"{name}: {error}", file=sys.stderr)
            return 2
        try:
            table = _run(args, fmu, spec, store, progress)
        except KeyboardInterrupt as interrupt:  # Ctrl-C, SIGTERM, SIGHUP (cli.py)
            print(
                f"{name}: {interrupted(interrupt)}: {store.written} cases computed in this run "
                f"are kept in {store.folder}; run it again (without --fresh) to compute only "
                "the missing ones",
                file=sys.stderr,
            )
            return exit_status(interrupt)
    summary = _summary(table)
    print("\n".join(summary))
    if len(table) and (table["status"] == FAILED).all():  # nothing to show: earlier files stay
        print(
            f"{name}: every case failed, no table or figure written: {summary[1].strip()}",
            file=sys.stderr,
        )
        return 1
    stem, figure = out / args.name, out / f"{args.name}.png"
    existed = {
        p for p in (stem.with_suffix(".csv"), stem.with_suffix(".parquet"), figure) if p.exists()
    }
    drawn = plot_heatmaps(table, spec, figure)  # first: a figure that fails replaces nothing
    written = write_table(table, stem) + [drawn]
    print("wrote " + ", ".join(f"{p}{' (replaced)' if p in existed else ''}" for p in written))
    return 0
