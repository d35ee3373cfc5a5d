"""The sections of a benchmark run, in order, and what they share: the sizes,
the C host, the FMUs (each built once, when a section first needs it).

Each section gives its summary rows and its own tables (`## ` heading: text)."""

import sys
from dataclasses import dataclass, replace
from functools import cached_property
from pathlib import Path

from .accuracy import accuracy, accuracy_rows, accuracy_table
from .c_host import c_host_cost, c_host_rows, compile_c_host
from .floor import JOINT, build_floor_fmu, build_model_fmu, unzip
from .generated_step import alone, alone_rows
from .growth import growth, growth_rows, growth_table
from .instructions import MINORS, instruction_rows, instructions
from .long_run import REVOLUTIONS, long_run, long_run_rows
from .step_cost import cost_rows, step_cost
from .vectorized import vector_rows, vectorized


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
    revolutions: int  # of the long run


FULL = Sizes(
    runs=7,
    simulate_runs=5,
    steps=100_000,
    growth_steps=(1_000, 100_000, 1_000_000),
    memory_steps=(1_000, 100_000),
    vector_samples=1_000_000,
    scalar_samples=100_000,
    instruction_steps=(100, 2_100),
    instruction_minors=MINORS,
    revolutions=REVOLUTIONS,
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
    revolutions=100,
)


class Bench:
    """One run's sizes, cases and work folder; its host and FMUs, made once."""

    def __init__(self, work: Path, quick: bool, joint_fmu, cases, minors=None):
        sizes = QUICK if quick else FULL
        self.sizes = replace(sizes, instruction_minors=tuple(minors)) if minors else sizes
        self.work, self.joint_fmu, self.cases = work, joint_fmu, cases
        self.results: dict = {}
        self._unzipped: dict = {}

    @cached_property
    def host(self) -> Path:
        return compile_c_host(self.work)

    def _once(self, key, build) -> str:
        if key not in self._unzipped:
            self._unzipped[key] = unzip(build(), self.work)
        return self._unzipped[key]

    def model(self, name: str) -> str:
        """The model's default build, unzipped (the joint: `--fmu` when given)."""
        given = self.joint_fmu if name == JOINT else None
        return self._once(("model", name), lambda: given or build_model_fmu(self.work, name))

    def floor(self, name: str, kind: str = "plain", loader: bool = False) -> str:
        """The model's `kind` floor, unzipped: pythonfmu's own binary, or with `loader`
        the project's."""
        return self._once(("floor", name, kind, loader),
                          lambda: build_floor_fmu(self.work, kind, loader, name))  # fmt: skip

    @cached_property
    def fmpy_fmus(self) -> dict:
        """Sections 1, 4, 5: the joint and its floors, each with the project's loader."""
        return {"joint": self.model(JOINT), "plain": self.floor(JOINT, "plain", True),
                "bare": self.floor(JOINT, "bare", True)}  # fmt: skip


ACCURACY = (
    "Accuracy after 1 s against Tătaru's numerical method (ω1 = 10 rad/s)",
    "Exact: the closed form atan(tan ψ / cos β) − ψ at 40 digits (mpmath). RK4: the seed's "
    "ODE (ω1' = 0, ω3' = B ω1, φ1' = ω1, φ3' = ω3) at the same step. FMU: `simulate_fmu` at "
    "that communication step.",
)
GROWTH = (
    "Growth with the run length (FMU2Slave loop)",
    "Runs as in section 1, the joint beside the plain floor. Peak RSS: VmHWM of the worker "
    "process (interpreter, numpy, FMPy and both FMUs), from /proc/self/status; "
    "`getrusage().ru_maxrss` is not used because Linux carries it over fork and exec from the "
    "parent. Python heap: tracemalloc over the joint's stepping alone, after 10 warm-up "
    "steps, with garbage collected.",
)


def fmpy(bench):
    bench.results["cost"] = step_cost(bench.fmpy_fmus, bench.sizes)
    return cost_rows(bench.results["cost"], bench.sizes), {}


def accuracy_section(bench):
    found = accuracy(bench.model(JOINT))
    return accuracy_rows(found), {ACCURACY[0]: f"{ACCURACY[1]}\n\n{accuracy_table(found)}"}


def vectorized_section(bench):
    return vector_rows(vectorized(bench.sizes), bench.sizes), {}


def growth_section(bench):
    found = growth(bench.fmpy_fmus, bench.sizes, bench.results.get("cost"))
    return growth_rows(found), {GROWTH[0]: f"{GROWTH[1]}\n\n{growth_table(found)}"}


def c_host_section(bench):
    return c_host_rows(c_host_cost(bench.host, bench.fmpy_fmus, bench.sizes), bench.sizes), {}


def instructions_section(bench):
    models = dict.fromkeys(case.model for case in bench.cases)
    fmus = {name: bench.model(name) for name in models}
    floors = {name: bench.floor(name) for name in models}
    fmpy = (fmus[JOINT], floors[JOINT]) if JOINT in models else None
    found = instructions(bench.host, bench.cases, fmus, floors, bench.sizes, fmpy)
    bench.results["instructions"] = found
    return instruction_rows(found, bench.cases, bench.sizes), {}


def step_alone_section(bench):
    found = alone(bench.work, bench.host, bench.cases, bench.floor, bench.sizes,
                  bench.results.get("instructions"))  # fmt: skip
    return alone_rows(found, bench.sizes), {}


def long_run_section(bench):
    return long_run_rows(long_run(bench.host, bench.model(JOINT), bench.sizes.revolutions)), {}


SECTIONS = {
    "fmpy": fmpy,
    "accuracy": accuracy_section,
    "vectorized": vectorized_section,
    "growth": growth_section,
    "c_host": c_host_section,
    "instructions": instructions_section,
    "step_alone": step_alone_section,
    "long_run": long_run_section,
}


def measure(names, bench) -> tuple[list[str], dict[str, str]]:
    """The summary rows and own tables of the sections `names`, run in SECTIONS' order."""
    rows: list[str] = []
    blocks: dict[str, str] = {}
    for name, section in SECTIONS.items():
        if name in names:
            print(f"benchmarks: {name}", file=sys.stderr, flush=True)
            more, own = section(bench)
            rows += more
            blocks.update(own)
    return rows, blocks
