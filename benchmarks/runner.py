"""The benchmarks' runner: every measurement in one run, one markdown report.

    python -m benchmarks [--quick] [--output FILE] [--fmu FILE]

Measures, each in its module, and writes benchmarks/results.md:

1. `step_cost`: cost per step of the FMU under FMPy's low-level loop and under
   `simulate_fmu`, next to floor FMUs (`floor`) whose do_step does nothing;
2. `accuracy`: against Tătaru's numerical method (the seed's ODE under RK4);
3. `vectorized`: `joint_response` on numpy arrays against a scalar loop;
4. `growth`: per-step cost and memory as the run grows;
5. `c_host`: the same step in a C host against FMPy's loop;
6. `one_call`: the joint against the plain floor in each host (issue 21's
   goals) and the joint's Python alone (physics, slave, one-call step);
7. `instructions`: instructions per step (callgrind) of the joint against
   pythonfmu's own plain floor and against its Python step, on CPython 3.10-3.13.

Not part of the test run: tests/system/test_benchmarks_smoke.py only checks that
`--quick` writes the tables.
"""

import argparse
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from cardan_joint.extras import MissingExtra, require

# The runtime's joint and its floors: the joint built without life (docs/life.md).
from cardan_joint.models.universal_joint.variables import WITHOUT_LIFE as table

from .accuracy import accuracy, accuracy_rows, accuracy_table, worker_accuracy
from .c_host import c_host_cost, c_host_rows
from .floor import FLOORS, build_floor_fmu, build_joint_fmu, unzip
from .growth import growth, growth_rows, growth_table, worker_tracemalloc
from .instructions import MINORS, instruction_rows, instructions, worker_instructions
from .one_call import one_call_rows, python_step, worker_python_step, worker_python_steps
from .step_cost import (
    LOOP_CHUNK,
    SIMULATE_CHUNK,
    STEP_SIZE,
    cost_rows,
    step_cost,
    worker_loop,
    worker_simulate,
)
from .timing import ROOT, machine
from .vectorized import vector_rows, vectorized, worker_scalar, worker_trigonometry, worker_vector

DEFAULT_OUTPUT = ROOT / "benchmarks" / "results.md"
QUICK_OUTPUT = ROOT / "results" / "benchmarks_quick.md"
COMMAND = "python -m benchmarks"


@dataclass(frozen=True)
class Sizes:
    runs: int  # runs of the low-level loop (median taken)
    simulate_runs: int  # runs of simulate_fmu
    steps: int  # steps per FMU per run
    growth_steps: tuple  # run lengths of the growth benchmark
    memory_steps: tuple  # run lengths traced by tracemalloc
    vector_samples: int
    scalar_samples: int
    instruction_steps: tuple  # the two run lengths whose difference callgrind counts
    instruction_minors: tuple  # CPython 3.<minor> counted


FULL = Sizes(
    runs=7,
    simulate_runs=5,
    steps=100_000,
    growth_steps=(1_000, 100_000, 1_000_000),
    memory_steps=(1_000, 100_000),
    vector_samples=1_000_000,
    scalar_samples=100_000,
    instruction_steps=(100, 600),
    instruction_minors=MINORS,
)
QUICK = Sizes(
    runs=1,
    simulate_runs=1,
    steps=300,
    growth_steps=(10, 300, 1_000),
    memory_steps=(10, 100),
    vector_samples=2_000,
    scalar_samples=200,
    instruction_steps=(1, 3),
    instruction_minors=(sys.version_info.minor,),
)

# What `python -m benchmarks --worker REQUEST` runs (timing.in_fresh_process).
WORKERS = {
    "loop": worker_loop,
    "simulate": worker_simulate,
    "tracemalloc": worker_tracemalloc,
    "accuracy": worker_accuracy,
    "vector": worker_vector,
    "scalar": worker_scalar,
    "trigonometry": worker_trigonometry,
    "python_step": worker_python_step,
    "python_steps": worker_python_steps,
    "instructions": worker_instructions,
}


def run_worker(request: str) -> None:
    import json

    arguments = json.loads(request)
    kind = arguments.pop("kind")
    print(json.dumps(WORKERS[kind](**arguments)))


def summary_table(results, sizes):
    return "\n".join(
        [
            "| benchmark | result | goal | met |",
            "|---|---|---|---|",
            *cost_rows(results["cost"], sizes),
            *accuracy_rows(results["accuracy"]),
            *vector_rows(results["vector"], sizes),
            *growth_rows(results["growth"]),
            *c_host_rows(results["c_host"], sizes),
            *one_call_rows(results["python"], results["cost"], results["c_host"], sizes),
            *instruction_rows(results["instructions"], sizes),
        ]
    )


def report(results, sizes, quick, elapsed):
    command = COMMAND + (" --quick" if quick else "")
    return "\n".join(
        [
            "# Benchmarks",
            "",
            f"Measured on {machine()}, by `{command}` in {elapsed / 60:.1f} min: one run on a "
            "shared machine, so absolute times move with other users' load; ratios are measured "
            f"side by side: each run is a fresh process that loads the FMUs, then steps them in "
            f"turns of {LOOP_CHUNK:,} steps ({SIMULATE_CHUNK:,} under `simulate_fmu`).",
            "",
            summary_table(results, sizes),
            "",
            "Floors: pythonfmu FMUs built from `benchmarks/floor_slave.py` with the joint's "
            f"{len(table.VARIABLES)} Real variables (same causality, variability, initial, start) "
            "and a `do_step` that does nothing. *plain*: values through pythonfmu's own "
            "`get_real`/`set_real`; *bare*: through list indexing. "
            f"Communication step {STEP_SIZE} s; times are wall-clock unless marked CPU.",
            "",
            "## Accuracy after 1 s against Tătaru's numerical method (ω1 = 10 rad/s)",
            "",
            "Exact: the closed form atan(tan ψ / cos β) − ψ at 40 digits (mpmath). "
            "RK4: the seed's ODE (ω1' = 0, ω3' = B ω1, φ1' = ω1, φ3' = ω3) at the same step. "
            "FMU: `simulate_fmu` at that communication step.",
            "",
            accuracy_table(results["accuracy"]),
            "",
            "## Growth with the run length (FMU2Slave loop)",
            "",
            "Runs as in section 1, the joint beside the plain floor. Peak RSS: VmHWM of the "
            "worker process (interpreter, numpy, FMPy and both FMUs), from /proc/self/status; "
            "`getrusage().ru_maxrss` is not used because Linux carries it over fork and exec "
            "from the parent. Python heap: tracemalloc over the joint's stepping alone, after 10 "
            "warm-up steps, with garbage collected.",
            "",
            growth_table(results["growth"]),
            "",
        ]
    )


def run_all(sizes, joint_fmu, workdir):
    fmus = {kind: unzip(build_floor_fmu(workdir, kind), workdir) for kind in FLOORS}
    # The runtime's joint is built without life (docs/life.md); the life-on
    # build is timed beside it in section 1's loop.
    fmus["joint"] = unzip(joint_fmu or build_joint_fmu(workdir, life=False), workdir)
    with_life = unzip(build_joint_fmu(workdir / "life"), workdir)
    cost = step_cost(fmus, sizes, with_life)
    return {
        "cost": cost,
        "accuracy": accuracy(fmus["joint"]),
        "vector": vectorized(sizes),
        "growth": growth(fmus, sizes, cost),
        "c_host": c_host_cost(fmus, sizes, workdir),
        "python": python_step(sizes),
        "instructions": instructions(
            fmus["joint"],
            unzip(build_floor_fmu(workdir, "plain", loader=False), workdir),
            workdir,
            sizes,
            with_life,
        ),
    }


INSTRUCTION_ROWS = "| 7"
REMEASURED = "Rows 7a-7d re-measured alone"


def instructions_only(sizes, joint_fmu, workdir, output: Path, elapsed_since: float) -> str:
    """Section 7 alone (callgrind counts, deterministic under load): its rows
    replace those of the results file, which says so under its table."""
    lines = output.read_text().splitlines()
    if not any(line.startswith(INSTRUCTION_ROWS) for line in lines):
        raise SystemExit(f"{output} has no section 7 rows to replace: run the full benchmark")
    joint = unzip(joint_fmu or build_joint_fmu(workdir, life=False), workdir)
    with_life = unzip(build_joint_fmu(workdir / "life"), workdir)
    floor = unzip(build_floor_fmu(workdir, "plain", loader=False), workdir)
    rows = instruction_rows(instructions(joint, floor, workdir, sizes, with_life), sizes)
    # An earlier note goes with the blank line that follows it.
    notes = {i for i, line in enumerate(lines) if line.startswith(REMEASURED)}
    dropped = notes | {i + 1 for i in notes if i + 1 < len(lines) and not lines[i + 1]}
    kept: list[str] = []
    at: int | None = None
    for i, line in enumerate(lines):
        if line.startswith(INSTRUCTION_ROWS) and at is None:
            at = len(kept)  # where the summary table had them
        if i not in dropped and not line.startswith(INSTRUCTION_ROWS):
            kept.append(line)
    minutes = (time.perf_counter() - elapsed_since) / 60
    note = (
        f"{REMEASURED} on {machine()}, by `{COMMAND} --instructions-only` in {minutes:.1f} min "
        "(the other rows are from the full run above)."
    )
    return "\n".join([*kept[:at], *rows, "", note, *kept[at:]]) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python -m benchmarks", description="Benchmarks of the UniversalJoint FMU."
    )
    parser.add_argument(
        "--quick",
        action="store_true",
        help="tiny sizes: checks that everything runs, measures nothing",
    )
    parser.add_argument(
        "--output",
        type=Path,
        default=None,
        help="markdown file to write (default: benchmarks/results.md; with --quick, "
        f"{QUICK_OUTPUT.relative_to(ROOT)}: a smoke run never replaces the measured tables)",
    )
    parser.add_argument(
        "--fmu",
        type=Path,
        help="a built joint FMU without life (default: build the working tree's "
        "UniversalJointNoLife.fmu, `build_fmu.py --no-life`)",
    )
    parser.add_argument(
        "--instructions-only",
        action="store_true",
        help="section 7 alone (callgrind instruction counts): replace its rows in the "
        "results file and keep the others",
    )
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        run_worker(args.worker)
        return 0
    try:
        require("mpmath", "bench", "python -m benchmarks (the accuracy benchmark's exact values)")
    except MissingExtra as error:
        print(f"benchmarks: {error}", file=sys.stderr)
        return 1
    sizes = QUICK if args.quick else FULL
    started = time.perf_counter()
    if args.instructions_only:
        output = args.output or (QUICK_OUTPUT if args.quick else DEFAULT_OUTPUT)
        with tempfile.TemporaryDirectory(prefix="cardan_benchmarks_") as workdir:
            text = instructions_only(sizes, args.fmu, Path(workdir), output, started)
        output.write_text(text)
        print(f"section 7 rows replaced in {output}")
        return 0
    with tempfile.TemporaryDirectory(prefix="cardan_benchmarks_") as workdir:
        results = run_all(sizes, args.fmu, Path(workdir))
    text = report(results, sizes, args.quick, time.perf_counter() - started)
    output = args.output or (QUICK_OUTPUT if args.quick else DEFAULT_OUTPUT)
    if args.quick:
        print(
            f"quick run: every benchmark ran on tiny sizes (its numbers measure nothing); "
            f"tables in {output}"
        )
    else:
        print(text)
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
