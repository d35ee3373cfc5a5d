"""7. Instructions per step (issue 24, item 6), counted by callgrind where wall time
is noise: on CPython 3.10-3.13 (pyenv's shared builds), side by side in one run.

Per step = (instructions of a run of LONG steps - those of SHORT steps) / (LONG -
SHORT): start-up (interpreter, imports, instantiate) cancels. The floor is the plain
floor FMU (`floor`) as pythonfmu builds it, its own C++ binary and no project code,
at its best: libpython preloaded into the host (that binary starts Python from the
global symbols; PYTHONHOME, as its prefix cannot be found from the host's path).
Three ratios:

(a) C host (tests/c_host `bench`: set 6, doStep, get 20): the joint / the floor;
(b) the joint in the C host / the same model's step and outputs called from Python
    (`one_call`'s physics loop), i.e. what the runtime adds;
(c) FMPy's low-level loop (`step_cost.step_loop`): the joint / the floor.

Each CPython gets a venv with FMPy and pythonfmu, kept in VENVS between runs.
"""

import os
import re
import subprocess
from pathlib import Path

from .c_host import compile_c_host
from .timing import ROOT, met

MINORS = (10, 11, 12, 13)
PYENV = Path(os.environ.get("PYENV_ROOT", "/root/.pyenv"))
VENVS = Path(os.environ.get("CARDAN_JOINT_BENCH_VENVS", Path.home() / ".cache/cardan-joint"))
REQUIREMENTS = ("fmpy", "pythonfmu==0.7.0")
GOALS = {"c_host": 0.6, "runtime": 1.10, "fmpy": 0.8}
GOAL_MINOR = 11  # the CPython the issue measured and states its goals for


def cpython(minor: int) -> Path | None:
    """pyenv's newest shared CPython 3.<minor>: its prefix, or None."""
    found = sorted((PYENV / "versions").glob(f"3.{minor}.*"))
    ok = [p for p in found if (p / "lib" / f"libpython3.{minor}.so.1.0").exists()]
    return ok[-1] if ok else None


def venv(prefix: Path) -> Path:
    """A venv of that CPython with REQUIREMENTS: its python."""
    folder = VENVS / f"benchmark-venv-{prefix.name}"
    python = folder / "bin" / "python"
    if not (folder / ".complete").exists():
        for command in (
            [prefix / "bin" / "python3", "-m", "venv", "--clear", folder],
            [python, "-m", "pip", "install", "-q", *REQUIREMENTS],
        ):
            subprocess.run(list(map(str, command)), check=True, capture_output=True)
        (folder / ".complete").write_text(" ".join(REQUIREMENTS))
    return python


def callgrind(command: list, environment: dict) -> int:
    """Instructions executed by `command` (callgrind's total), niced."""
    run = subprocess.run(
        ["nice", "-n", "10", "valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
         *map(str, command)],
        capture_output=True, text=True, env={"PATH": "/usr/bin:/bin", **environment},
    )  # fmt: skip
    found = re.search(r"Collected : (\d+)", run.stderr)
    if run.returncode != 0 or not found:
        raise RuntimeError(f"{command} under callgrind failed:\n{run.stdout}{run.stderr[-3000:]}")
    return int(found.group(1))


def per_step(command, environment, lengths) -> float:
    """Instructions per step: `command(steps)` at two lengths, start-up cancelled.
    A first run, not counted, writes the bytecode caches both counted runs then read."""
    short, long = lengths
    warm_up = subprocess.run(
        list(map(str, command(short))),
        capture_output=True,
        env={"PATH": "/usr/bin:/bin", **environment},
    )
    if warm_up.returncode != 0:
        raise RuntimeError(f"{command(short)} failed:\n{warm_up.stdout}{warm_up.stderr}")
    counts = [callgrind(command(steps), environment) for steps in (short, long)]
    return (counts[1] - counts[0]) / (long - short)


def python_worker(python: Path, what: str, fmu=None):
    def command(steps):
        request = f'{{"kind": "instructions", "what": "{what}", "steps": {steps}, "fmu": "{fmu}"}}'
        return [python, "-m", "benchmarks", "--worker", request]

    return command


def worker_instructions(what, steps, fmu):
    """The loop counted in a Python process: `physics` or FMPy's low-level `loop`."""
    from .one_call import _physics_stepper
    from .step_cost import instantiate, step_loop

    if what == "physics":
        _physics_stepper()(0, steps)
    else:
        joint = instantiate(fmu)
        step_loop(joint, steps)
        joint.close()
    return {}


def count_minor(minor, host, joint, floor, lengths, life=None) -> dict | None:
    prefix = cpython(minor)
    if prefix is None:
        return None
    python, library = venv(prefix), prefix / "lib" / f"libpython3.{minor}.so.1.0"
    # One BLAS thread: numpy's OpenBLAS workers spin after a call, and their
    # instructions (10 k a step in some runs, none in others) are not the loop's.
    # One hash seed in every counted process: str hashes set dict probe chains,
    # and a random seed moved a C host's count by up to 1 k a step between runs.
    seeded = {"PYTHONHASHSEED": "0"}
    path = {
        **seeded,
        "PYTHONPATH": f"{ROOT}:{ROOT / 'fmu_src'}",
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
    }

    def in_host(fmu):
        return lambda steps: [host, "bench", fmu, steps]

    joint_host = {**seeded, "CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(library)}
    floor_host = {**seeded, "LD_PRELOAD": str(library), "PYTHONHOME": str(prefix)}
    counts = {
        "c_host joint": per_step(in_host(joint), joint_host, lengths),
        "c_host floor": per_step(in_host(floor), floor_host, lengths),
        "physics": per_step(python_worker(python, "physics"), path, lengths),
        "fmpy joint": per_step(python_worker(python, "loop", joint), path, lengths),
        "fmpy floor": per_step(python_worker(python, "loop", floor), path, lengths),
    }
    if life:
        counts["c_host life"] = per_step(in_host(life), joint_host, lengths)
    counts["version"] = prefix.name
    return counts


def instructions(joint, floor, workdir, sizes, life=None) -> dict:
    """{minor: counts per step} for each CPython found (None where it is missing);
    `life`: the joint built with life (the default build), counted beside `joint`."""
    host = compile_c_host(workdir)
    lengths = sizes.instruction_steps
    return {
        minor: count_minor(minor, host, joint, floor, lengths, life)
        for minor in sizes.instruction_minors
    }


def ratios(counts) -> dict:
    return {
        "c_host": counts["c_host joint"] / counts["c_host floor"],
        "runtime": counts["c_host joint"] / counts["physics"],
        "fmpy": counts["fmpy joint"] / counts["fmpy floor"],
    }


ROWS = {
    "c_host": ("C host: the joint's step / the floor's (pythonfmu's binary)", "joint", "floor"),
    "runtime": ("the joint in the C host / its physics step and outputs called from Python",
                "C host", "Python"),
    "fmpy": ("FMPy's low-level loop (set 6, doStep, get 20): the joint / the floor",
             "joint", "floor"),
}  # fmt: skip
PARTS = {
    "c_host": ("c_host joint", "c_host floor"),
    "runtime": ("c_host joint", "physics"),
    "fmpy": ("fmpy joint", "fmpy floor"),
}


def instruction_rows(results, sizes) -> list:
    lengths = sizes.instruction_steps
    measured = {minor: counts for minor, counts in results.items() if counts}
    missing = [f"3.{minor}" for minor, counts in results.items() if not counts]
    note = f"; not measured (no pyenv CPython): {', '.join(missing)}" if missing else ""
    rows, life_rows = [], []
    with_life = {m: c for m, c in measured.items() if "c_host life" in c}
    if with_life:
        cells = [
            f"{c['version']}: with life {c['c_host life'] / 1e3:.1f} k, without "
            f"{c['c_host joint'] / 1e3:.1f} k: **×{c['c_host life'] / c['c_host joint']:.2f}**"
            for c in with_life.values()
        ]
        life_rows.append(
            f"| 7d. instructions per step (callgrind, runs of {lengths[1]:,} − "
            f"{lengths[0]:,} steps): C host: the joint with life (the default build, "
            f"docs/life.md) / without (`--no-life`) | {'; '.join(cells)}{note} | (context) | |"
        )
    for key, (title, first, second) in ROWS.items():
        cells, meeting = [], {}
        for minor, counts in measured.items():
            ratio = ratios(counts)[key]
            meeting[minor] = ratio <= GOALS[key]
            a, b = (counts[part] / 1e3 for part in PARTS[key])
            cells.append(
                f"{counts['version']}: {first} {a:.1f} k, {second} {b:.1f} k: **×{ratio:.2f}**"
            )
        rows.append(
            f"| 7{'abc'[list(ROWS).index(key)]}. instructions per step (callgrind, runs of "
            f"{lengths[1]:,} − {lengths[0]:,} steps): {title} | {'; '.join(cells)}{note} | "
            f"≤ ×{GOALS[key]} | {verdict(meeting)} |"
        )
    return rows + life_rows


def verdict(meeting: dict) -> str:
    """Met on the goal's own interpreter (issue 24 states its figures for CPython
    3.11), then where else it is met and where not."""
    others = {minor: ok for minor, ok in meeting.items() if minor != GOAL_MINOR}
    said = [f"{met(meeting.get(GOAL_MINOR, False))} on 3.{GOAL_MINOR}"]
    for ok, how in ((True, "met"), (False, "not met")):
        where = [f"3.{minor}" for minor, good in others.items() if good == ok]
        said += [f"{how} on {', '.join(where)}"] if where else []
    return "; ".join(said)
