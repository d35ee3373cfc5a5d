"""Design sweeps of the UniversalJoint FMU, serially or on Dask.

A sweep crosses bend angles, input speeds and crosspiece inertia distributions
(the paper's T1..T4 of a total I0 = (I1 + I2 + I3) / 2) and co-simulates each
case at constant inputs over whole input revolutions, sampled at a fixed
angle step so that fast and slow shafts are resolved alike. Each row of the
tidy result table holds one case's peaks, or its status "failed" and the
FMU's message: a refused run is reported, never dropped.

A task is one (bend angle, input speed) point with all its inertia
distributions: a few co-simulations, enough that Dask's per-task overhead is
small, and the FMU is unzipped once per task. Tasks are pure functions of
their inputs, so a Dask run and a serial run give identical tables.

Workers must reach the FMU at the same path (same machine, or a shared file
system) and import this package (installed in their Python).
"""

import argparse
import contextlib
import io
import math
import os
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from typing import Optional
from pathlib import Path

RPM = math.pi / 30
DEG = math.pi / 180
# Inertia distributions of Mityushov & Misyura (PHYSICS.md), as (I1, I2, I3) / I0.
INERTIA_DISTRIBUTIONS = {
    "T1": (2 / 3, 2 / 3, 2 / 3),
    "T2": (1 / 3, 4 / 3, 1 / 3),
    "T3": (5 / 6, 1 / 3, 5 / 6),
    "T4": (7 / 9, 1 / 9, 10 / 9),
}
# Driveline makers keep the driven inertia's excitation (the output shaft's
# angular acceleration) below 1000 rad/s2 for smooth running.
ACCELERATION_LIMIT = 1000.0
OK, FAILED = "ok", "failed"
PEAKS = ("peak_output_acceleration", "peak_crosspiece_torque", "speed_fluctuation",
         "peak_input_torque", "peak_input_yoke_moment", "peak_output_yoke_moment")
_RECORDED = ("output_speed", "output_acceleration", "crosspiece_torque_1",
             "crosspiece_torque_2", "crosspiece_torque_3", "input_torque",
             "input_yoke_moment", "output_yoke_moment")


@dataclass(frozen=True)
class SweepSpec:
    bend_angles_deg: tuple = (1, 2, 3, 4, 6, 8, 10, 12, 15, 20, 25, 30)
    input_speeds_rpm: tuple = (500, 1000, 1500, 2000, 2500, 3000, 4000)
    distributions: tuple = ("T1", "T2", "T3", "T4")
    total_inertia: float = 0.039          # I0 [kg.m2], the paper's
    load_torque: float = 0.0              # [N.m]
    revolutions: int = 2
    steps_per_revolution: int = 720       # 0.5 deg per communication step
    max_bend_angle_deg: Optional[float] = None   # None: the FMU's own guard

    def tasks(self):
        """One task per (bend angle, speed): its cases, one per distribution."""
        return [[Case(bend, speed, name) for name in self.distributions]
                for bend in self.bend_angles_deg for speed in self.input_speeds_rpm]


@dataclass(frozen=True)
class Case:
    bend_angle_deg: float
    input_speed_rpm: float
    inertia_distribution: str


# --- one case -------------------------------------------------------------

def _inertias(spec, name):
    return tuple(fraction * spec.total_inertia for fraction in INERTIA_DISTRIBUTIONS[name])


def _failure_message(error):
    from .simulate import SimulationError

    if isinstance(error, SimulationError):
        return " ".join(str(error).split())
    return f"{type(error).__name__}: {' '.join(str(error).split())}"


def run_case(fmu_dir, spec: SweepSpec, case: Case) -> dict:
    """Co-simulate one case; return its table row (never raises for a bad case)."""
    import numpy as np

    from .simulate import simulate

    inertias = _inertias(spec, case.inertia_distribution)
    row = {**asdict(case),
           **{f"crosspiece_inertia_{k}": value for k, value in enumerate(inertias, 1)},
           "load_torque": spec.load_torque, "status": OK, "message": ""}
    speed = case.input_speed_rpm * RPM
    try:
        if speed <= 0.0:
            raise ValueError(f"input speed {case.input_speed_rpm!r} rpm must be > 0")
        step = 2 * math.pi / speed / spec.steps_per_revolution
        start_values = {f"crosspiece_inertia_{k}": value for k, value in enumerate(inertias, 1)}
        if spec.max_bend_angle_deg is not None:
            start_values["max_bend_angle"] = spec.max_bend_angle_deg * DEG
        inputs = {"input_speed": speed, "input_acceleration": 0.0,
                  "bend_angle": case.bend_angle_deg * DEG, "bend_angle_rate": 0.0,
                  "bend_angle_acceleration": 0.0, "load_torque": spec.load_torque}
        # The FMU also writes refusals to stderr; the row's message carries them.
        with contextlib.redirect_stderr(io.StringIO()):
            result = simulate(fmu_dir, output_interval=step, inputs=inputs,
                              stop_time=spec.revolutions * spec.steps_per_revolution * step,
                              start_values=start_values, output=list(_RECORDED))
        torque = np.sqrt(result["crosspiece_torque_1"] ** 2 + result["crosspiece_torque_2"] ** 2
                         + result["crosspiece_torque_3"] ** 2)
        row.update({
            "peak_output_acceleration": float(np.abs(result["output_acceleration"]).max()),
            "peak_crosspiece_torque": float(torque.max()),
            "speed_fluctuation": float(np.ptp(result["output_speed"]) / speed),
            "peak_input_torque": float(np.abs(result["input_torque"]).max()),
            "peak_input_yoke_moment": float(result["input_yoke_moment"].max()),
            "peak_output_yoke_moment": float(result["output_yoke_moment"].max()),
        })
    except Exception as error:         # a failed case is a result, not a crash
        row.update({"status": FAILED, "message": _failure_message(error),
                    **{name: math.nan for name in PEAKS}})
    return row


def run_task(fmu, spec: SweepSpec, cases) -> list:
    """Run a task's cases on one unzipped copy of the FMU (runs on a worker)."""
    from fmpy import extract

    if not Path(fmu).is_file():
        message = f"FMU {fmu} not found on this worker: it must be reachable at the same path"
        return [{**asdict(case), "status": FAILED, "message": message} for case in cases]
    with tempfile.TemporaryDirectory(prefix="cardan_sweep_") as directory:
        extract(str(fmu), unzipdir=directory)
        return [run_case(directory, spec, case) for case in cases]


# --- the sweep --------------------------------------------------------------

class TextProgress:
    """A progress bar on stderr (no dependency): redrawn in place on a terminal,
    a line every 10 % in a log."""

    def __init__(self, total, label="", width=30, stream=None):
        self.total, self.label, self.width = max(total, 1), label, width
        self.stream = stream or sys.stderr
        self.interactive = getattr(self.stream, "isatty", lambda: False)()
        self.granularity = 1 if self.interactive else 10
        self.done = 0
        self._shown = -1
        self.update(0)

    def update(self, advance=1):
        self.done = min(self.done + advance, self.total)
        percent = 100 * self.done // self.total
        shown = percent - percent % self.granularity
        if shown != self._shown:
            filled = self.width * self.done // self.total
            bar = (f"{self.label}[{'#' * filled}{' ' * (self.width - filled)}] "
                   f"{percent:3d}% ({self.done}/{self.total})")
            self.stream.write(f"\r{bar}" if self.interactive else f"{bar}\n")
            self.stream.flush()
            self._shown = shown

    def close(self):
        if self.interactive:
            self.stream.write("\n")
            self.stream.flush()


def run_serial(fmu, spec: SweepSpec, progress=True):
    """Every task in this process, in order; returns the table (a DataFrame)."""
    fmu = str(Path(fmu).resolve())
    tasks = spec.tasks()
    bar = TextProgress(len(tasks), "serial ") if progress else None
    rows = []
    for cases in tasks:
        rows.extend(run_task(fmu, spec, cases))
        if bar:
            bar.update()
    if bar:
        bar.close()
    return to_table(rows, spec)


def local_cluster(n_workers=2):
    """Worker processes, one thread each: each runs FMUs in its own Python."""
    import dask
    from dask.distributed import LocalCluster

    # On a machine with as many CPUs as workers every background wake-up is
    # taken from the co-simulations. The workers' statistical profiler samples
    # the task thread every 10 ms and fights it for the GIL, which every FMI call
    # releases and retakes (about 20 % of their CPU time); the 20 ms event-loop
    # tick (only a blocked-loop watchdog) cost the scheduler in this process
    # about 1 CPU-s per sweep.
    quiet = {"distributed.worker.profile.enabled": False,
             "distributed.admin.tick.interval": "1s",
             "distributed.admin.system-monitor.interval": "5s"}
    with dask.config.set(quiet):
        return LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                            dashboard_address=None)


def run_dask(fmu, spec: SweepSpec, client, progress=True):
    """Every task on the client's cluster; returns the table (a DataFrame)."""
    from dask.distributed import as_completed

    fmu = str(Path(fmu).resolve())
    tasks = spec.tasks()
    # pure=False: fresh keys every run, so a repeated sweep is computed again
    # rather than served from the cluster's memory.
    futures = client.map(run_task, [fmu] * len(tasks), [spec] * len(tasks), tasks, pure=False)
    if progress:
        bar = TextProgress(len(futures), "dask   ")
        for _ in as_completed(futures):
            bar.update()
        bar.close()
    rows = [row for result in client.gather(futures) for row in result]
    return to_table(rows, spec)


def connect(scheduler=None, n_workers=2):
    """(client, cluster or None): a new LocalCluster unless a scheduler address is given."""
    from dask.distributed import Client

    if scheduler:
        return Client(scheduler), None
    cluster = local_cluster(n_workers)
    return Client(cluster), cluster


def _import_fmu_stack():
    import fmpy.fmi2  # noqa: F401

    from . import simulate  # noqa: F401


def warm_up(client):
    """Import the FMU stack on every worker so that timings compare like with like."""
    client.run(_import_fmu_stack)


def to_table(rows, spec: SweepSpec):
    """The tidy table, in the spec's order whatever order the tasks finished in."""
    import pandas as pd

    columns = (["bend_angle_deg", "input_speed_rpm", "inertia_distribution",
                "crosspiece_inertia_1", "crosspiece_inertia_2", "crosspiece_inertia_3",
                "load_torque", "status", "message"] + list(PEAKS) + ["beyond_acceleration_limit"])
    table = pd.DataFrame(rows).reindex(columns=columns)
    table["beyond_acceleration_limit"] = table["peak_output_acceleration"] > ACCELERATION_LIMIT
    order = {name: k for k, name in enumerate(spec.distributions)}
    table = table.sort_values(["bend_angle_deg", "input_speed_rpm", "inertia_distribution"],
                              key=lambda c: c.map(order) if c.name == "inertia_distribution"
                              else c, kind="stable")
    return table.reset_index(drop=True)


def write_table(table, stem):
    """Write <stem>.csv, and <stem>.parquet when a Parquet engine is installed."""
    stem = Path(stem)
    stem.parent.mkdir(parents=True, exist_ok=True)
    written = [stem.with_suffix(".csv")]
    table.to_csv(written[0], index=False)
    try:
        table.to_parquet(stem.with_suffix(".parquet"), index=False)
        written.append(stem.with_suffix(".parquet"))
    except ImportError:
        pass                             # pyarrow/fastparquet not installed: CSV only
    return written


# --- the figure -------------------------------------------------------------

def plot_heatmaps(table, spec: SweepSpec, path):
    """Peak output acceleration and peak crosspiece torque over bend x speed,
    hatched where the output acceleration exceeds ACCELERATION_LIMIT."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.colors import LogNorm
    from matplotlib.patches import Patch, Rectangle

    bends, speeds = list(spec.bend_angles_deg), list(spec.input_speeds_rpm)

    def grid(distribution, column):
        values = np.full((len(speeds), len(bends)), np.nan)
        rows = table[table["inertia_distribution"] == distribution]
        for _, row in rows.iterrows():
            values[speeds.index(row["input_speed_rpm"]), bends.index(row["bend_angle_deg"])] = \
                row[column]
        return values

    panels = [("peak output acceleration [rad/s$^2$]\n(any inertia distribution)",
               grid(spec.distributions[0], "peak_output_acceleration"), "viridis")]
    panels += [(f"peak crosspiece torque |M| [N.m], {name}", grid(name, "peak_crosspiece_torque"),
                "magma") for name in spec.distributions]
    beyond = grid(spec.distributions[0], "peak_output_acceleration") > ACCELERATION_LIMIT
    failed = np.isnan(grid(spec.distributions[0], "peak_output_acceleration"))
    torques = np.concatenate([p[1][np.isfinite(p[1])] for p in panels[1:]] or [np.ones(1)])
    positive = torques[torques > 0]
    torque_norm = (LogNorm(positive.min(), positive.max()) if positive.size else None)

    columns = 3 if len(panels) > 4 else len(panels)
    rows_count = math.ceil(len(panels) / columns)
    fig, axes = plt.subplots(rows_count, columns, figsize=(5.2 * columns, 4.2 * rows_count),
                             squeeze=False)
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for k, (ax, (title, values, cmap)) in enumerate(zip(axes.flat, panels)):
        finite = values[np.isfinite(values) & (values > 0)]
        norm = (LogNorm(finite.min(), finite.max()) if k == 0 and finite.size else
                torque_norm)
        image = ax.imshow(np.ma.masked_invalid(values), origin="lower", aspect="auto",
                          cmap=cmap, norm=norm)
        fig.colorbar(image, ax=ax, shrink=0.9)
        for i, j in zip(*np.nonzero(beyond)):
            ax.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, fill=False, hatch="///",
                                   edgecolor="0.55", linewidth=0))   # seen on dark and light
        for i, j in zip(*np.nonzero(failed)):
            ax.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, color="0.75"))
            ax.text(j, i, "failed", ha="center", va="center", fontsize=6, rotation=90)
        ax.set_xticks(range(len(bends)), [f"{b:g}" for b in bends], fontsize=8)
        ax.set_yticks(range(len(speeds)), [f"{s:g}" for s in speeds], fontsize=8)
        ax.set_xlabel("bend angle [deg]")
        ax.set_ylabel("input speed [rpm]")
        ax.set_title(title, fontsize=9)
    handles = [Patch(facecolor="none", edgecolor="0.55", hatch="///",
                     label=f"output acceleration > {ACCELERATION_LIMIT:g} rad/s$^2$\n"
                           "(beyond the usual driveline limit)"),
               Patch(color="0.75", label="failed run (see the table's message)")]
    spare = list(axes.flat[len(panels):])
    if spare:
        spare[0].set_visible(True)
        spare[0].axis("off")
        spare[0].legend(handles=handles, loc="center", fontsize=9, frameon=False)
    else:
        fig.legend(handles=handles, loc="lower center", ncol=2, fontsize=8)
    fig.suptitle(f"Cardan joint design sweep: I0 = {spec.total_inertia:g} kg.m$^2$, "
                 f"load {spec.load_torque:g} N.m, constant speed and bend", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


# --- command line -----------------------------------------------------------

def add_arguments(parser):
    from .simulate import DEFAULT_FMU

    defaults = SweepSpec()
    parser.add_argument("--fmu", default=str(DEFAULT_FMU), help="FMU file (default %(default)s)")
    parser.add_argument("--out", default="results", help="output folder (default %(default)s)")
    parser.add_argument("--name", default="design_sweep",
                        help="file stem of the table and figure (default %(default)s)")
    parser.add_argument("--bend-angles", type=float, nargs="+",
                        default=list(defaults.bend_angles_deg), metavar="DEG")
    parser.add_argument("--speeds", type=float, nargs="+",
                        default=list(defaults.input_speeds_rpm), metavar="RPM")
    parser.add_argument("--distributions", nargs="+", default=list(defaults.distributions),
                        choices=sorted(INERTIA_DISTRIBUTIONS))
    parser.add_argument("--i0", type=float, default=defaults.total_inertia,
                        help="total crosspiece inertia I0 [kg.m2] (default %(default)s)")
    parser.add_argument("--load-torque", type=float, default=defaults.load_torque,
                        help="N.m (default %(default)s)")
    parser.add_argument("--revolutions", type=int, default=defaults.revolutions)
    parser.add_argument("--steps-per-revolution", type=int,
                        default=defaults.steps_per_revolution)
    parser.add_argument("--max-bend-angle", type=float, default=None, metavar="DEG",
                        help="the FMU's bend guard for every run (default: the FMU's own)")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--scheduler", default=None, metavar="ADDRESS",
                      help="Dask scheduler, e.g. tcp://host:8786 (default: a LocalCluster)")
    mode.add_argument("--serial", action="store_true", help="run every task in this process")
    mode.add_argument("--compare", action="store_true",
                      help="run on Dask and serially, check the tables are identical, "
                           "print both wall times and the speed-up")
    parser.add_argument("--workers", type=int, default=2,
                        help="LocalCluster worker processes (default %(default)s)")
    parser.add_argument("--repeat", type=int, default=1,
                        help="with --compare: timing repetitions (default %(default)s)")
    parser.add_argument("--no-progress", action="store_true")


def spec_from_arguments(args) -> SweepSpec:
    return SweepSpec(tuple(args.bend_angles), tuple(args.speeds), tuple(args.distributions),
                     args.i0, args.load_torque, args.revolutions, args.steps_per_revolution,
                     args.max_bend_angle)


def timed(function, *args, **kwargs):
    start = time.perf_counter()
    value = function(*args, **kwargs)
    return value, time.perf_counter() - start


def _machine_busy_seconds():
    """CPU-seconds the whole machine has been busy so far (Linux), or None."""
    try:
        with open("/proc/stat") as stream:
            fields = [int(x) for x in stream.readline().split()[1:9]]
    except (OSError, ValueError):
        return None
    user, nice, system, _idle, _iowait, irq, softirq, steal = fields
    return (user + nice + system + irq + softirq + steal) / os.sysconf("SC_CLK_TCK")


def _measured(function, *args, client=None):
    """(value, wall s, CPUs that other processes kept busy meanwhile or None).

    Other jobs on the machine skew wall times; the machine's busy time minus
    this process's (and the local workers') tells how much."""
    def own():
        workers = sum(client.run(time.process_time).values()) if client else 0.0
        return time.process_time() + workers

    busy, mine = _machine_busy_seconds(), own()
    value, seconds = timed(function, *args)
    if busy is None:
        return value, seconds, None
    others = (_machine_busy_seconds() - busy) - (own() - mine)
    return value, seconds, max(others, 0.0) / seconds


def _dask_run(fmu, spec, scheduler, n_workers, progress):
    """(table, sweep s, start-up s, others' CPUs): a fresh cluster per run,
    closed before the serial run so its scheduler cannot slow that run down."""
    (client, cluster), startup = timed(connect, scheduler, n_workers)
    try:
        warm_up(client)
        table, seconds, others = _measured(run_dask, fmu, spec, client, progress,
                                           client=client if cluster is not None else None)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return table, seconds, startup, others if cluster is not None else None


def compare(fmu, spec, scheduler=None, n_workers=2, repeat=1, progress=True):
    """Run serially and on Dask `repeat` times; return (table, timings), each
    timing a dict of wall times, cluster start-up and the CPUs that other
    processes kept busy. Raises AssertionError if the tables differ.

    The serial run goes first, with no cluster in this process: a LocalCluster's
    scheduler lives in this process, and its event loop, kept busy by the
    workers, took about a quarter more CPU from a serial run beside it."""
    import pandas as pd

    run_task(str(Path(fmu).resolve()), spec, spec.tasks()[0][:1])   # imports, as workers do
    timings = []
    for _ in range(repeat):
        serial, serial_seconds, serial_others = _measured(run_serial, fmu, spec, progress)
        on_dask, dask_seconds, startup, dask_others = _dask_run(fmu, spec, scheduler, n_workers,
                                                                progress)
        pd.testing.assert_frame_equal(on_dask, serial, check_exact=True)
        timings.append({"dask": dask_seconds, "serial": serial_seconds, "startup": startup,
                        "others_dask": dask_others, "others_serial": serial_others})
    return on_dask, timings


def main(argv=None, prog=None) -> int:
    parser = argparse.ArgumentParser(prog=prog, description="Design sweep of the Cardan joint "
                                     "FMU over bend angle x input speed x inertia distribution.")
    add_arguments(parser)
    args = parser.parse_args(argv)
    spec = spec_from_arguments(args)
    fmu = Path(args.fmu)
    if not fmu.is_file():
        print(f"sweep: {fmu} does not exist: build it with `python build_fmu.py`", file=sys.stderr)
        return 1
    progress = not args.no_progress
    cases = sum(len(t) for t in spec.tasks())
    print(f"{cases} co-simulations in {len(spec.tasks())} tasks, "
          f"{spec.revolutions * spec.steps_per_revolution} steps each")
    if args.compare:
        table, timings = compare(fmu, spec, args.scheduler, args.workers, args.repeat, progress)
        where = args.scheduler or f"LocalCluster of {args.workers} worker processes"
        print(f"Dask ({where}) and serial tables identical")
        for k, t in enumerate(timings, 1):
            load = ("" if None in (t["others_dask"], t["others_serial"]) else
                    f"; other processes kept {t['others_serial']:.2f} and {t['others_dask']:.2f}"
                    f" of {os.cpu_count()} CPUs busy")
            print(f"  run {k}: serial {t['serial']:.1f} s, Dask {t['dask']:.1f} s, speed-up "
                  f"{t['serial'] / t['dask']:.2f} ({t['serial'] / (t['dask'] + t['startup']):.2f}"
                  f" counting {t['startup']:.1f} s of cluster start-up){load}")
    elif args.serial:
        table, seconds = timed(run_serial, fmu, spec, progress)
        print(f"serial: {seconds:.1f} s")
    else:
        (client, cluster), startup = timed(connect, args.scheduler, args.workers)
        try:
            table, seconds = timed(run_dask, fmu, spec, client, progress)
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
        print(f"Dask: {seconds:.1f} s (+ {startup:.1f} s to start or reach the cluster)")
    out = Path(args.out)
    written = write_table(table, out / args.name)
    figure = out / f"{args.name}.png"
    plot_heatmaps(table, spec, figure)
    failed = table[table["status"] == FAILED]
    ok = table[table["status"] == OK]
    print(f"{len(ok)} ok, {len(failed)} failed; "
          f"{int(ok['beyond_acceleration_limit'].sum())} beyond {ACCELERATION_LIMIT:g} rad/s2")
    for _, row in failed.drop_duplicates("message").head(5).iterrows():
        print(f"  failed at {row['bend_angle_deg']:g} deg, {row['input_speed_rpm']:g} rpm: "
              f"{row['message']}")
    print("wrote " + ", ".join(str(p) for p in written + [figure]))
    return 0
