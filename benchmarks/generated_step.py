"""7. The generated step alone (docs/codegen.md), the physical limit: each model
whose spec names a step, its C called in a loop of plain C with its state fed
back and its inputs set again at every step, as the C host sets them, without
the FMU around it. Instructions per step, counted by callgrind as section 6
counts them, against the model's own empty pythonfmu FMU in the C host on
CPython 3.11 (section 6's count when it ran, else counted here).
"""

import subprocess
from pathlib import Path

from cardan_joint.build.step_source import generated_step
from cardan_joint.fmi.native import C_FLAGS, compiler
from cardan_joint.models import discover

from .cases import STEP, Case
from .instructions import GOAL_MINOR, in_host, lead, per_step
from .interpreters import Here, interpreter

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


def step_alone(work: Path, case: Case) -> Path | None:
    """A program that takes the default build's generated step `steps` times
    (its first argument) from the case's operating point; None when the
    model's step runs in Python (the build says why)."""
    spec = discover()[case.model]
    settings = dict(spec.default_settings)
    generated = generated_step(spec, settings, case.model)
    if generated is None:
        return None
    model = spec.make(settings, **case.inputs())
    model.start(0.0)
    table = spec.table(settings)
    state = tuple(model.step_state())
    known = [getattr(model, name) for name in table.INPUTS + table.PARAMETERS]
    values = [0.0, STEP, *map(float, state), *map(float, known)][: len(generated.arguments)]
    folder = work / f"alone_{case.label.replace(' ', '_').replace('/', '_')}"
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "step.c").write_text(generated.source)
    (folder / "loop.c").write_text(LOOP % dict(
        arguments=", ".join(map(repr, values)), results=generated.results, step=STEP,
        state=len(state), inputs=len(table.INPUTS),
    ))  # fmt: skip
    program = folder / "loop"
    flags = [flag for flag in C_FLAGS if flag != "-shared"]  # the runtime's, for a program
    subprocess.run([*compiler(), *flags, str(folder / "step.c"), str(folder / "loop.c"),
                    "-o", str(program), "-lm"], check=True)  # fmt: skip
    return program


def alone(work: Path, host, cases, floor_of, sizes, counted=None) -> dict:
    """{case label: (the step alone or None, the floor on 3.11)} per step;
    `floor_of(model)`: its unzipped pythonfmu floor; `counted`: section 6's
    results, whose 3.11 floors are reused."""
    where = interpreter(GOAL_MINOR)
    if not isinstance(where, Here):
        raise SystemExit(f"section 7 needs pyenv's shared CPython 3.{GOAL_MINOR}")
    lengths = sizes.instruction_steps
    earlier = ((counted or {}).get(GOAL_MINOR) or {}).get("cases", {})
    found: dict = {"version": where.version, "cases": {}}
    for case in cases:
        program = step_alone(work, case)
        step = None
        if program is not None:
            step = per_step(where, lambda steps, program=program: [program, steps], {}, lengths)
        floor = earlier[case.label][1] if case.label in earlier else None
        if floor is None:
            floor_in_host = in_host(host, floor_of(case.model), case)
            floor = per_step(where, floor_in_host, where.floor_env, lengths)
        found["cases"][case.label] = (step, floor)
    return found


def alone_rows(found: dict, sizes) -> list[str]:
    rows = []
    for label, (step, floor) in found["cases"].items():
        cell = (
            "no generated step: the model steps in Python"
            if step is None
            else f"{step / 1e3:.2f} k / {floor / 1e3:.1f} k = **×{step / floor:.4f}**"
        )
        rows.append(
            f"| 7. {lead(sizes)}: {label}, the generated step alone in a plain C loop (the "
            f"physical limit) / its own empty pythonfmu FMU in the C host on {found['version']} "
            f"| {cell} | (context) | |"
        )
    return rows
