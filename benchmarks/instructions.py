"""6. Instructions per step, counted by callgrind where wall time is noise: each
model's default build against its own empty pythonfmu FMU, in the C host, on
every CPython minor that runs here (`interpreters`: pyenv's shared builds of
3.10-3.13, the Debian sid roots of 3.14 and 3.15), side by side in one run; and
FMPy's low-level loop over the UniversalJoint the same way (pyenv's minors).

Per step = (instructions of a run of LONG steps - those of SHORT steps) / (LONG -
SHORT): start-up (interpreter, imports, instantiate) cancels. Callgrind counts
every thread of the process. The C host is tests/c_host `bench`: set every input
at the operating point (`cases`), doStep of 1 ms, get every output. The floor is
the model's plain floor (`floor`) as pythonfmu builds it, its own C++ binary and
no project code, at its best: libpython preloaded into the host (that binary
starts Python from the global symbols; PYTHONHOME, as its prefix cannot be found
from the host's path). The goals are issue 32's, judged on CPython 3.11.

Each pyenv CPython gets a venv with FMPy and pythonfmu (FMPy's loop runs there),
kept in VENVS between runs.
"""

import os
import re
import subprocess
from pathlib import Path

from .cases import Case
from .interpreters import SEEDED, Here, interpreter
from .timing import ROOT, met

MINORS = (10, 11, 12, 13, 14, 15)
VENVS = Path(os.environ.get("CARDAN_JOINT_BENCH_VENVS", Path.home() / ".cache/cardan-joint"))
REQUIREMENTS = ("fmpy", "pythonfmu==0.7.0")
GOAL_MINOR = 11  # the CPython issue 32 measured and states its goals for
FMPY_GOAL = 0.7  # the joint / its floor in FMPy's loop (judged on wall time in section 1)


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


def callgrind(where, command: list, environment: dict) -> int:
    """Instructions executed by `command` (callgrind's total, every thread), niced."""
    run = where.run(command, environment, counted=True)
    found = re.search(r"Collected : (\d+)", run.stderr)
    if run.returncode != 0 or not found:
        raise RuntimeError(f"{command} under callgrind failed:\n{run.stdout}{run.stderr[-3000:]}")
    return int(found.group(1))


def per_step(where, command, environment, lengths) -> float:
    """Instructions per step: `command(steps)` at two lengths, start-up cancelled.
    A first run, not counted, writes the bytecode caches both counted runs then read."""
    short, long = lengths
    warm_up = where.run(command(short), environment, counted=False)
    if warm_up.returncode != 0:
        raise RuntimeError(f"{command(short)} failed:\n{warm_up.stdout}{warm_up.stderr}")
    counts = [callgrind(where, command(steps), environment) for steps in (short, long)]
    return (counts[1] - counts[0]) / (long - short)


def in_host(host, fmu, case: Case):
    return lambda steps: [host, "bench", fmu, steps, *case.host_inputs()]


def worker_instructions(steps, fmu):
    """FMPy's low-level loop over `fmu` in a Python process: what callgrind counts."""
    from .step_cost import instantiate, step_loop

    joint = instantiate(fmu)
    step_loop(joint, steps)
    joint.close()
    return {}


def fmpy_loop(python: Path, fmu):
    def command(steps):
        request = f'{{"kind": "instructions", "steps": {steps}, "fmu": "{fmu}"}}'
        return [python, "-m", "benchmarks", "--worker", request]

    return command


def count_minor(minor, host, cases, fmus, floors, lengths, fmpy) -> dict | None:
    """{case label: (model, floor)} per step on CPython 3.<minor>, and with `fmpy`
    (the joint and its floor) FMPy's loop; None where that CPython is not found."""
    where = interpreter(minor)
    if where is None:
        return None
    host = where.host(host)
    found: dict = {"version": where.version, "cases": {}}
    floor_counts: dict = {}
    for case in cases:
        if case.model not in floor_counts:  # one floor per model
            floor = in_host(host, where.place(floors[case.model]), case)
            floor_counts[case.model] = per_step(where, floor, where.floor_env, lengths)
        model = in_host(host, where.place(fmus[case.model]), case)
        found["cases"][case.label] = (per_step(where, model, where.model_env, lengths),
                                      floor_counts[case.model])  # fmt: skip
    if fmpy and isinstance(where, Here):
        # One BLAS thread: numpy's OpenBLAS workers spin after a call, and their
        # instructions (10 k a step in some runs, none in others) are not the loop's.
        path = {**SEEDED, "PYTHONPATH": f"{ROOT}:{ROOT / 'fmu_src'}",
                "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}  # fmt: skip
        python = venv(where.prefix)
        found["fmpy"] = tuple(
            per_step(where, fmpy_loop(python, fmu), path, lengths) for fmu in fmpy
        )
    return found


def instructions(host, cases, fmus, floors, sizes, fmpy=None) -> dict:
    """{minor: counts} for each CPython asked for (None where it is not found).
    `fmus`, `floors`: unzipped default builds and pythonfmu floors by model;
    `fmpy`: (the joint, its floor) to count in FMPy's loop too."""
    return {
        minor: count_minor(minor, host, cases, fmus, floors, sizes.instruction_steps, fmpy)
        for minor in sizes.instruction_minors
    }


def inputs(case: Case) -> str:
    count = len(case.inputs())
    return f"{count} input{'s' if count != 1 else ''}"


def lead(sizes) -> str:
    short, long = sizes.instruction_steps
    return f"instructions per step (callgrind, all threads, runs of {long:,} − {short:,} steps)"


def instruction_rows(results, cases, sizes) -> list:
    measured = {minor: counts for minor, counts in results.items() if counts}
    missing = [f"3.{minor}" for minor, counts in results.items() if not counts]
    note = f"; not found here: {', '.join(missing)}" if missing else ""
    rows = []
    for case in cases:
        cells, meeting = [], {}
        for minor, counts in measured.items():
            model, floor = counts["cases"][case.label]
            meeting[minor] = case.goal is None or model / floor <= case.goal
            cells.append(
                f"{counts['version']}: {model / 1e3:.1f} k / {floor / 1e3:.1f} k = "
                f"**×{model / floor:.3f}**"
            )
        goal = f"≤ ×{case.goal:g} | {verdict(meeting)}" if case.goal else "(context) |"
        rows.append(
            f"| 6. {lead(sizes)}, C host (set {inputs(case)}, doStep of 1 ms, get "
            f"every output): {case.label}, the default build / its own empty pythonfmu FMU | "
            f"{'; '.join(cells)}{note} | {goal} |"
        )
    fmpy = {minor: counts["fmpy"] for minor, counts in measured.items() if "fmpy" in counts}
    if fmpy:
        cells = [
            f"{measured[minor]['version']}: {joint / 1e3:.1f} k / {floor / 1e3:.1f} k = "
            f"**×{joint / floor:.3f}**"
            for minor, (joint, floor) in fmpy.items()
        ]
        rows.append(
            f"| 6. {lead(sizes)}, FMPy's low-level loop (as section 1): UniversalJoint, the "
            f"default build / its own empty pythonfmu FMU | {'; '.join(cells)}{note} | "
            f"(context: section 1 judges ≤ ×{FMPY_GOAL} on wall time) | |"
        )
    return rows


def verdict(meeting: dict) -> str:
    """Met on the goal's own interpreter (issue 32 states its figures for CPython
    3.11), then where else it is met and where not."""
    others = {minor: ok for minor, ok in meeting.items() if minor != GOAL_MINOR}
    said = [f"{met(meeting[GOAL_MINOR])} on 3.{GOAL_MINOR}" if GOAL_MINOR in meeting
            else f"3.{GOAL_MINOR} not measured"]  # fmt: skip
    for ok, how in ((True, "met"), (False, "not met")):
        where = [f"3.{minor}" for minor, good in others.items() if good == ok]
        said += [f"{how} on {', '.join(where)}"] if where else []
    return "; ".join(said)
