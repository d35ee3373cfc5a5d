"""Instructions per step of the generated step (docs/codegen.md), counted by
callgrind in the C host (tests/c_host `bench`: set 6, doStep, get 20) on
CPython 3.11, as section 7 counts them: the default build (UniversalJoint,
life on) with its step in C, the same FMU with every step in Python
($CARDAN_JOINT_FMU_PYTHON_STEP=1), and its own empty FMU as pythonfmu builds
it (the plain floor: the same Real variables, its own binary, libpython
preloaded), at the benchmarks' operating point (100 rad/s) and at 1000 rad/s;
and the generated step alone (the physical limit): the same step called in a
loop of plain C, its state fed back, without the FMU around it.

    .venv/bin/python -m benchmarks.generated_step

writes its rows, 8a and 8b, into benchmarks/results.md after section 7's
(replacing earlier rows 8).
"""

import subprocess
import tempfile
from pathlib import Path

from cardan_joint.build.step_source import generated_step
from cardan_joint.fmi.native import C_FLAGS, compiler
from cardan_joint.models import discover

from .c_host import compile_c_host
from .floor import build_floor_fmu, build_joint_fmu, unzip
from .instructions import GOAL_MINOR, cpython, per_step
from .timing import ROOT

RESULTS = ROOT / "benchmarks" / "results.md"
ROW = "| 8"
OWN_ROWS = ("| 8. ", "| 8a. ", "| 8b. ")  # this module's (8.: before the life step)

LENGTHS = (100, 600)  # steps of the two counted runs: start-up cancels
SPEEDS = (100.0, 1000.0)  # rad/s: the benchmarks' operating point, the fast one
STEP = 1e-3  # s, as the C host's bench
# The C host's bench inputs besides the speed (tests/c_host/host.c).
INPUTS = {"input_acceleration": 5.0, "bend_angle": 0.3, "bend_angle_rate": 0.01,
          "bend_angle_acceleration": 0.0, "load_torque": 50.0}  # fmt: skip
GOALS = {100.0: 0.1, 1000.0: 0.5}  # issue 32: the default build / its own empty FMU

LOOP = """
#include <stdio.h>
#include <stdlib.h>
int generated_step(const double *arguments, double *results);
static double arguments[] = {%(arguments)s};
static double results[%(results)d];
int main(int argc, char **argv)
{
    int steps = argc > 1 ? atoi(argv[1]) : 0;
    for (int k = 0; k < steps; k++) {
        arguments[0] = k * %(step)r;
        if (generated_step(arguments, results) != 1)
            return 1;
        for (int i = 0; i < %(state)d; i++) /* the inputs are set again, as the host does */
            arguments[2 + i] = results[i];
    }
    printf("%%.17g\\n", results[%(state)d + %(inputs)d]);
    return 0;
}
"""


def step_alone(work: Path, speed: float) -> Path:
    """A program that takes the default build's generated step `steps` times
    (its first argument) from the host's operating point at `speed`."""
    spec = discover()["UniversalJoint"]
    settings = dict(spec.default_settings)
    generated = generated_step(spec, settings, "UniversalJoint")
    assert generated is not None, "the default build's step is not generated"
    model = spec.make(settings)
    for name, value in {"input_speed": speed, **INPUTS}.items():
        setattr(model, name, value)
    table = spec.table(settings)
    state = tuple(model.step_state())
    known = [getattr(model, name) for name in table.INPUTS + table.PARAMETERS]
    values = [0.0, STEP, *map(float, state), *map(float, known)][: len(generated.arguments)]
    folder = work / f"alone_{int(speed)}"
    folder.mkdir()
    return loop_program(folder, generated, values, len(state), len(table.INPUTS))


def loop_program(folder: Path, generated, values: list, state: int, inputs: int) -> Path:
    """`LOOP` around the generated step, from the arguments `values`, compiled
    with the runtime's flags into `folder`."""
    (folder / "step.c").write_text(generated.source)
    (folder / "loop.c").write_text(LOOP % dict(
        arguments=", ".join(map(repr, values)), results=generated.results, step=STEP,
        state=state, inputs=inputs,
    ))  # fmt: skip
    program = folder / "loop"
    flags = [flag for flag in C_FLAGS if flag != "-shared"]  # the runtime's, for a program
    subprocess.run([*compiler(), *flags, str(folder / "step.c"), str(folder / "loop.c"),
                    "-o", str(program), "-lm"], check=True)  # fmt: skip
    return program


def counts(work: Path) -> dict:
    prefix = cpython(GOAL_MINOR)
    if prefix is None:
        raise SystemExit(f"needs pyenv's shared CPython 3.{GOAL_MINOR}")
    library = prefix / "lib" / f"libpython3.{GOAL_MINOR}.so.1.0"
    host = compile_c_host(work)
    joint = unzip(build_joint_fmu(work, life=True), work)
    floor = unzip(build_floor_fmu(work, "plain", loader=False), work)
    seeded = {"PYTHONHASHSEED": "0"}
    joint_host = {**seeded, "CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(library)}
    in_python = {**joint_host, "CARDAN_JOINT_FMU_PYTHON_STEP": "1"}
    floor_host = {**seeded, "LD_PRELOAD": str(library), "PYTHONHOME": str(prefix)}

    def in_host(fmu, speed):
        return lambda steps: [host, "bench", fmu, steps, speed]

    found: dict = {"version": prefix.name, "floor": per_step(in_host(floor, 100.0), floor_host,
                                                             LENGTHS)}  # fmt: skip
    for speed in SPEEDS:
        alone = step_alone(work, speed)
        found[speed] = {
            "generated": per_step(in_host(joint, speed), joint_host, LENGTHS),
            "python": per_step(in_host(joint, speed), in_python, LENGTHS),
            "alone": per_step(lambda steps, alone=alone: [alone, steps], {}, LENGTHS),
        }
    return found


def rows(found: dict) -> list[str]:
    floor, lead = found["floor"], f"instructions per step (callgrind, runs of {LENGTHS[1]} − "
    lead += f"{LENGTHS[0]} steps, {found['version']}), C host (set 6, doStep, get 20), h = 1 ms:"
    cells, alone = [], []
    for speed in SPEEDS:
        at = found[speed]
        ratio = at["generated"] / floor
        cells.append(
            f"{speed:g} rad/s: generated {at['generated'] / 1e3:.1f} k, Python "
            f"{at['python'] / 1e3:.1f} k, floor {floor / 1e3:.1f} k: **×{ratio:.3f}** "
            f"(≤ ×{GOALS[speed]:g}: {'yes' if ratio <= GOALS[speed] else 'NO'})"
        )
        alone.append(f"{speed:g} rad/s: {at['alone'] / 1e3:.2f} k (×{at['alone'] / floor:.4f})")
    met = all(found[s]["generated"] / floor <= GOALS[s] for s in SPEEDS)
    return [
        f"{ROW}a. {lead} the default build (UniversalJoint, life on) with its generated step "
        f"(docs/codegen.md) / the same FMU stepping in Python / its own empty FMU (pythonfmu's "
        f"binary) | {'; '.join(cells)} | ≤ ×0.1; ≤ ×0.5 at 1000 rad/s | "
        f"**{'yes' if met else 'NO'}** |",
        f"{ROW}b. instructions per step (callgrind, {found['version']} not involved): the "
        f"default build's generated step alone, called in a plain C loop (the physical limit), "
        f"against the same floor | {'; '.join(alone)} | (context) | |",
    ]


def with_rows(text: str, new: list[str], own: tuple[str, ...] = OWN_ROWS) -> str:
    """`text` with the rows starting with `own` replaced by `new`, put after the
    last row 7 or 8."""
    lines = [line for line in text.splitlines() if not line.startswith(own)]
    last = max(i for i, line in enumerate(lines) if line.startswith(("| 7", ROW)))
    return "\n".join([*lines[: last + 1], *new, *lines[last + 1 :]]) + "\n"


def main() -> None:
    with tempfile.TemporaryDirectory(prefix="cardan_joint_generated_") as work:
        found = counts(Path(work))
    new = rows(found)
    RESULTS.write_text(with_rows(RESULTS.read_text(), new))
    print("\n".join(new))


if __name__ == "__main__":
    main()
