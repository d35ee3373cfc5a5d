"""Instructions per step of every model whose step is generated into its FMU's
runtime (docs/codegen.md), counted by callgrind as section 7 counts them
(runs of 11,000 − 1,000 steps, CPython 3.11): its default build in a plain C host
(tests/c_host's FMI 2.0 calls; per step: set every input, doStep of 1 ms, get
every output) at its start values, with its step in C and with
$CARDAN_JOINT_FMU_PYTHON_STEP=1, against its own empty FMU as pythonfmu builds
it (the same Real variables, pythonfmu's binary, libpython preloaded); and the
generated step alone, called in a loop of plain C with its state fed back.

    .venv/bin/python -m benchmarks.model_steps [MODEL ...]

prints one row per model (default: every model with a generated step).
"""

import subprocess
import sys
import tempfile
from pathlib import Path

from cardan_joint.build.step_source import generated_step
from cardan_joint.fmi.native import compiler
from cardan_joint.models import discover

from .floor import build_floor_fmu, unzip
from .generated_step import STEP, loop_program
from .instructions import GOAL_MINOR, cpython, per_step
from .timing import ROOT, run_checked

# Steps of the two counted runs: start-up cancels, and its own spread between runs
# (a few hundred thousand instructions) is below 0.05 k a step.
LENGTHS = (1_000, 11_000)

# The host: tests/c_host's loading and calls, this loop for a main.
HOST = r"""
#include "host.h"

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 3 + 16)
        fail("usage: steps DIR STEPS name=value...");
    int steps = atoi(argv[2]), n_in = argc - 3;
    fmi2ValueReference in[16], out[64];
    double values[16], y[64];
    load(argv[1]);
    fmi2Component c = start("bench", fmi2False);
    initialize(c);
    for (int i = 0; i < n_in; i++) {
        char name[64];
        if (sscanf(argv[3 + i], "%63[^=]=%lf", name, &values[i]) != 2)
            fail("expected name=value, got %s", argv[3 + i]);
        in[i] = reference(name);
    }
    int n = outputs(out);
    for (int k = 0; k < steps; k++) {
        fmu.SetReal(c, in, n_in, values);
        check(fmu.DoStep(c, k * STEP, STEP, fmi2True), "DoStep");
        fmu.GetReal(c, out, n, y);
    }
    printf("%.17g\n", y[0]);
    fmu.FreeInstance(c);
    return 0;
}
"""


def compile_host(work: Path) -> Path:
    sys.path.insert(0, str(ROOT / "tests"))
    try:
        from c_host.compile import host_files
    finally:
        sys.path.remove(str(ROOT / "tests"))
    include, sources = host_files()
    flags = ["-std=gnu11", "-O2", "-pthread", f"-I{include}", f"-I{ROOT / 'tests' / 'c_host'}"]
    objects = []
    for source in sources:  # their own main renamed: this one's runs
        objects.append(work / f"{source.stem}.o")
        command = [*compiler(), *flags, "-Dmain=host_main", "-c", source, "-o", objects[-1]]
        subprocess.run(list(map(str, command)), check=True)
    (work / "steps.c").write_text(HOST)
    host = work / "steps"
    command = [*compiler(), *flags, f"-DSTEP={STEP!r}", work / "steps.c", *objects, "-ldl",
               "-lm", "-o", host]  # fmt: skip
    subprocess.run(list(map(str, command)), check=True)
    return host


def step_alone(folder: Path, key: str) -> Path:
    """A program that takes the model's generated step `steps` times from its
    start values (`generated_step.loop_program`)."""
    spec = discover()[key]
    settings = dict(spec.default_settings)
    generated = generated_step(spec, settings, key)
    assert generated is not None, f"{key}'s default build has no generated step"
    model, table = spec.make(settings), spec.table(settings)
    state = tuple(model.step_state())
    known = [getattr(model, name) for name in table.INPUTS + table.PARAMETERS]
    values = [0.0, STEP, *map(float, state), *map(float, known)][: len(generated.arguments)]
    return loop_program(folder, generated, values, len(state), len(table.INPUTS))


def count(work: Path, host: Path, key: str) -> dict:
    prefix = cpython(GOAL_MINOR)
    if prefix is None:
        raise SystemExit(f"needs pyenv's shared CPython 3.{GOAL_MINOR}")
    library = prefix / "lib" / f"libpython3.{GOAL_MINOR}.so.1.0"
    spec = discover()[key]
    table = spec.table()
    folder = work / key
    folder.mkdir()
    run_checked([ROOT / "build_fmu.py", "--model", key, "--dest", folder], cwd=ROOT)
    fmu = unzip(folder / f"{spec.default_name(spec.default_settings)}.fmu", folder)
    floor = unzip(build_floor_fmu(folder, "plain", loader=False, table=table), folder)
    inputs = [f"{name}={value!r}" for name, value in table.start_values().items()
              if name in table.INPUTS]  # fmt: skip

    def in_host(unzipped):
        return lambda steps: [host, unzipped, steps, *inputs]

    seeded = {"PYTHONHASHSEED": "0"}
    model_host = {**seeded, "CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(library)}
    floor_host = {**seeded, "LD_PRELOAD": str(library), "PYTHONHOME": str(prefix)}
    alone = step_alone(folder, key)
    return {
        "version": prefix.name,
        "floor": per_step(in_host(floor), floor_host, LENGTHS),
        "generated": per_step(in_host(fmu), model_host, LENGTHS),
        "python": per_step(
            in_host(fmu), {**model_host, "CARDAN_JOINT_FMU_PYTHON_STEP": "1"}, LENGTHS
        ),  # fmt: skip
        "alone": per_step(lambda steps: [alone, steps], {}, LENGTHS),
    }


def row(key: str, found: dict) -> str:
    floor, generated, python, alone = (found[k] for k in ("floor", "generated", "python", "alone"))
    what = (
        f"{key}, default build at its start values: instructions per step (callgrind, runs "
        f"of {LENGTHS[1]} − {LENGTHS[0]} steps, {found['version']}), C host (set every input, "
        f"doStep of {STEP:g} s, get every output)"
    )
    figures = (
        f"generated {generated / 1e3:.2f} k / its own empty FMU {floor / 1e3:.1f} k: "
        f"**×{generated / floor:.3f}**; every step in Python {python / 1e3:.1f} k "
        f"(×{python / floor:.2f}); the generated step alone {alone / 1e3:.3f} k "
        f"(×{alone / floor:.4f})"
    )
    return f"| {what} | {figures} |"


def main() -> None:
    keys = sys.argv[1:] or [key for key, spec in discover().items() if spec.step]
    with tempfile.TemporaryDirectory(prefix="cardan_joint_model_steps_") as work:
        host = compile_host(Path(work))
        for key in keys:
            print(row(key, count(Path(work), host, key)), flush=True)


if __name__ == "__main__":
    main()
