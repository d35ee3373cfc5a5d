"""The benchmarks' runner: every section in one run, one markdown report, or
some sections (and models) alone, their rows replaced in the report.

    python -m benchmarks [SECTION ...] [--models MODEL ...] [--minors N ...]
                         [--quick] [--output FILE] [--fmu FILE]

Sections, each in its module:

1. `fmpy` (step_cost): the default build (UniversalJoint) under FMPy's low-level
   loop and `simulate_fmu`, next to floor FMUs (`floor`) whose do_step does nothing;
2. `accuracy`: against Tătaru's numerical method (the seed's ODE under RK4);
3. `vectorized`: `joint_response` on numpy arrays against a scalar loop;
4. `growth`: per-step cost and memory as the run grows;
5. `c_host`: the same step in a C host against FMPy's loop;
6. `instructions`: instructions per step (callgrind) of each model's default
   build against its own empty pythonfmu FMU, on CPython 3.10-3.13 (`cases`);
7. `step_alone` (generated_step): the generated step alone, the physical limit;
8. `long_run`: 10^6 revolutions of the default build in the C host.

Not part of the test run: tests/system/test_benchmarks_smoke.py only checks that
`--quick` writes the tables.
"""

import argparse
import sys
import tempfile
import time
from pathlib import Path

from cardan_joint.extras import MissingExtra, require

from .cases import cases_of
from .instructions import MINORS
from .measure import SECTIONS, Bench, measure
from .report import ALONE, full, merged
from .step_cost import LOOP_CHUNK, SIMULATE_CHUNK, STEP_SIZE
from .timing import ROOT, machine
from .workers import run_worker

DEFAULT_OUTPUT = ROOT / "benchmarks" / "results.md"
QUICK_OUTPUT = ROOT / "results" / "benchmarks_quick.md"
COMMAND = "python -m benchmarks"


def header(command: str, minutes: float) -> str:
    return (
        f"# Benchmarks\n\nMeasured on {machine()}, by `{command}` in {minutes:.1f} min: one run "
        "on a shared machine, so absolute times move with other users' load; ratios are "
        "measured side by side: each run is a fresh process that loads the FMUs, then steps "
        f"them in turns of {LOOP_CHUNK:,} steps ({SIMULATE_CHUNK:,} under `simulate_fmu`); "
        "instruction counts (callgrind) do not move with the load."
    )


FOOTNOTE = (
    "Floors: pythonfmu FMUs built from `benchmarks/floor_slave.py` with the model's Real "
    "variables (same names, causality, variability, initial, start) and a `do_step` that does "
    "nothing. Sections 1, 4, 5: the UniversalJoint's, with the project's loader as its binary; "
    "*plain*: values through pythonfmu's own `get_real`/`set_real`; *bare*: through list "
    "indexing. Sections 6 and 7: each model's own plain floor as pythonfmu packs it (its own "
    "binary), libpython preloaded into the host. "
    f"Communication step {STEP_SIZE} s; times are wall-clock unless marked CPU."
)


def command_line(args) -> str:
    words = [COMMAND, *args.sections]
    for option, values in (("--models", args.models), ("--minors", args.minors)):
        if values:
            words += [option, *map(str, values)]
    return " ".join(words + (["--quick"] if args.quick else []))


def parse(argv):
    parser = argparse.ArgumentParser(
        prog="python -m benchmarks",
        description="Benchmarks of the project's FMUs: every section, or the sections named.",
    )
    parser.add_argument("sections", nargs="*", metavar="SECTION",
                        help=f"run these sections alone ({', '.join(SECTIONS)}; default: all) "
                        "and replace their rows in the results file")  # fmt: skip
    parser.add_argument("--models", nargs="+", metavar="MODEL",
                        help="sections 6 and 7: these models only (default: every case of "
                        "benchmarks/cases.py)")  # fmt: skip
    parser.add_argument("--minors", nargs="+", type=int, metavar="N",
                        help=f"section 6: CPython 3.N only (default: {MINORS})")  # fmt: skip
    parser.add_argument("--quick", action="store_true",
                        help="tiny sizes: checks that it runs, measures nothing")  # fmt: skip
    parser.add_argument("--output", type=Path, default=None,
                        help="markdown file to write (default: benchmarks/results.md; with "
                        f"--quick, {QUICK_OUTPUT.relative_to(ROOT)}: a smoke run never replaces "
                        "the measured tables)")  # fmt: skip
    parser.add_argument("--fmu", type=Path,
                        help="a built default UniversalJoint FMU for sections 1-5 and 8 "
                        "(default: build the working tree's)")  # fmt: skip
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    unknown = [name for name in args.sections if name not in SECTIONS]
    if unknown:
        parser.error(f"no section {', '.join(unknown)}: the sections are {', '.join(SECTIONS)}")
    return args


def main(argv=None):
    args = parse(argv)
    if args.worker:
        run_worker(args.worker)
        return 0
    sections = args.sections or list(SECTIONS)
    if "accuracy" in sections:
        try:
            require("mpmath", "bench", "python -m benchmarks (section 2's exact values)")
        except MissingExtra as error:
            print(f"benchmarks: {error}", file=sys.stderr)
            return 1
    cases = cases_of(args.models)
    started = time.perf_counter()
    output = args.output or (QUICK_OUTPUT if args.quick else DEFAULT_OUTPUT)
    with tempfile.TemporaryDirectory(prefix="cardan_benchmarks_") as workdir:
        bench = Bench(Path(workdir), args.quick, args.fmu, cases, args.minors)
        rows, blocks = measure(sections, bench)
    minutes = (time.perf_counter() - started) / 60
    command = command_line(args)
    partial = args.sections or args.models or args.minors
    if partial and output.exists():
        note = f"{ALONE} on {machine()}, by `{command}` in {minutes:.1f} min."
        text = merged(output.read_text(), rows, blocks, note)
    else:
        text = full(header(command, minutes), rows, FOOTNOTE, blocks)
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(text)
    if args.quick:
        print(f"quick run: the sections ran on tiny sizes (their numbers measure nothing); "
              f"tables in {output}")  # fmt: skip
    else:
        print("\n".join(rows))
        print(f"written to {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
