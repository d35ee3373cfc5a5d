"""Instructions per step of the generated step (docs/codegen.md), counted by
callgrind in the C host (tests/c_host `bench`: set 6, doStep, get 20) on
CPython 3.11, as section 7 counts them: the joint built without life with its
step in C, the same FMU with every step in Python
($CARDAN_JOINT_FMU_PYTHON_STEP=1), and the plain floor FMU as pythonfmu builds
it (its own binary, libpython preloaded).

    .venv/bin/python -m benchmarks.generated_step

writes its row, 8, into benchmarks/results.md after section 7's (replacing an
earlier row 8).
"""

import tempfile
from pathlib import Path

from .c_host import compile_c_host
from .floor import build_floor_fmu, build_joint_fmu, unzip
from .instructions import GOAL_MINOR, cpython, per_step
from .timing import ROOT

RESULTS = ROOT / "benchmarks" / "results.md"
ROW = "| 8."

LENGTHS = (100, 600)  # steps of the two counted runs: start-up cancels


def counts(work: Path) -> dict:
    prefix = cpython(GOAL_MINOR)
    if prefix is None:
        raise SystemExit(f"needs pyenv's shared CPython 3.{GOAL_MINOR}")
    library = prefix / "lib" / f"libpython3.{GOAL_MINOR}.so.1.0"
    host = compile_c_host(work)
    joint = unzip(build_joint_fmu(work, life=False), work)
    floor = unzip(build_floor_fmu(work, "plain", loader=False), work)
    seeded = {"PYTHONHASHSEED": "0"}
    joint_host = {**seeded, "CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(library)}
    in_python = {**joint_host, "CARDAN_JOINT_FMU_PYTHON_STEP": "1"}
    floor_host = {**seeded, "LD_PRELOAD": str(library), "PYTHONHOME": str(prefix)}

    def in_host(fmu):
        return lambda steps: [host, "bench", fmu, steps]

    return {
        "generated": per_step(in_host(joint), joint_host, LENGTHS),
        "python": per_step(in_host(joint), in_python, LENGTHS),
        "floor": per_step(in_host(floor), floor_host, LENGTHS),
        "version": prefix.name,
    }


def row(found: dict) -> str:
    generated, python, floor = found["generated"], found["python"], found["floor"]
    return (
        f"{ROW} instructions per step (callgrind, runs of {LENGTHS[1]} − {LENGTHS[0]} steps, "
        f"{found['version']}): C host, the joint without life: its generated step "
        f"(docs/codegen.md) / the same FMU stepping in Python / the floor (pythonfmu's binary) "
        f"| generated {generated / 1e3:.1f} k, Python {python / 1e3:.1f} k, floor "
        f"{floor / 1e3:.1f} k: **×{generated / floor:.3f}** of the floor, ×{generated / python:.3f}"
        f" of the step in Python | (context) | |"
    )


def with_row(text: str, new: str) -> str:
    """`text` with row 8 replaced, or put after the last row 7."""
    lines = [line for line in text.splitlines() if not line.startswith(ROW)]
    last = max(i for i, line in enumerate(lines) if line.startswith("| 7"))
    return "\n".join([*lines[: last + 1], new, *lines[last + 1 :]]) + "\n"


def main() -> None:
    with tempfile.TemporaryDirectory(prefix="cardan_joint_generated_") as work:
        found = counts(Path(work))
    new = row(found)
    RESULTS.write_text(with_row(RESULTS.read_text(), new))
    print(new)


if __name__ == "__main__":
    main()
