"""Reference runs: every model's whose spec declares one (`Model.reference`),
computed by the physics and laid out as the fmi-cross-check repository has them.

    fmus/2.0/cs/linux64/cardan_joint/<version>/<Model>/
        <Model>.fmu
        <Model>_in.csv     inputs, linearly interpolated (all the model's inputs)
        <Model>_ref.opt    StartTime, StopTime, StepSize, RelTol
        <Model>_ref.csv    the reference outputs (time + at most 9 outputs)
        README.md          the model's page (models/<name>/README.md)

The reference is computed by the physics package (the model stepped as a
co-simulation master steps the FMU), not by the FMU: a tool that reproduces it
through the FMU checks the FMI plumbing against the equations. The same three
files are kept in the model's folder (the tests check that they are current and
that the FMU reproduces them); `python -m cardan_joint.build.cross_check --model
<Model>` rewrites them there.
"""

from __future__ import annotations

import argparse
import shutil
import sys
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import numpy as np

from .. import DEFAULT_MODEL
from ..models import Model, ReferenceRun, discover

TOOL_ID = "cardan_joint"


def with_reference() -> dict[str, Model]:
    """The models whose spec declares a reference run, by key."""
    return {key: spec for key, spec in discover().items() if spec.reference}


def _run(model: str) -> tuple[Model, ReferenceRun]:
    spec = discover()[model]
    if spec.reference is None:
        raise ValueError(
            f"{model} declares no reference run (its spec's `reference`): "
            f"models with one: {', '.join(with_reference())}"
        )
    return spec, spec.reference


def reference_files(model: str = DEFAULT_MODEL) -> list[Path]:
    """The model's committed reference files: _in.csv, _ref.opt, _ref.csv."""
    folder = discover()[model].path
    return [folder / f"{model}{suffix}" for suffix in ("_in.csv", "_ref.opt", "_ref.csv")]


def tool_version() -> str:
    try:
        return version("cardan-joint-fmu")
    except PackageNotFoundError:  # a source tree that is not installed
        return "0+unknown"


def inputs(model: str = DEFAULT_MODEL) -> np.ndarray:
    """The input signals as a structured array (FMPy's `input` format)."""
    spec, run = _run(model)
    names = spec.table().INPUTS
    return np.array(list(run.input_rows), dtype=[("time", float)] + [(n, float) for n in names])


def reference(model: str = DEFAULT_MODEL) -> np.ndarray:
    """The reference outputs at every communication point, by the physics package."""
    spec, run = _run(model)
    signals = inputs(model)
    start, stop, step = (run.options[k] for k in ("StartTime", "StopTime", "StepSize"))
    steps = round((stop - start) / step)
    times = start + step * np.arange(steps + 1)
    physics = spec.make(spec.default_settings)
    names, outputs = physics.table.INPUTS, physics.table.OUTPUTS

    def apply_inputs(time):
        for name in names:
            setattr(physics, name, float(np.interp(time, signals["time"], signals[name])))

    # As a master records: a sample at each communication point before the
    # inputs of the next step are set (in between, the FMU carries its inputs along).
    apply_inputs(start)
    physics.start(start)  # after the inputs: a compliant joint starts from the bend angle
    rows = []
    for k, time in enumerate(times):
        values = dict(zip(outputs, physics.outputs()))
        rows.append((time, *(values[n] for n in run.outputs)))
        if k == steps:
            break
        apply_inputs(time)
        problem = physics.step(step)
        if problem:
            raise RuntimeError(f"the reference run was refused at t = {time}: {problem}")
    return np.array(rows, dtype=[("time", float)] + [(n, float) for n in run.outputs])


def write_reference_files(folder: str | Path, model: str = DEFAULT_MODEL) -> list[Path]:
    """Write <model>_in.csv, <model>_ref.opt and <model>_ref.csv into `folder`."""
    from ..results import write_csv

    _, run = _run(model)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    paths = [folder / path.name for path in reference_files(model)]
    write_csv(inputs(model), paths[0])
    paths[1].write_text("".join(f"{key}, {value!r}\n" for key, value in run.options.items()))
    write_csv(reference(model), paths[2])
    return paths


def write_cross_check(dest: str | Path, fmu_path: str | Path, model: str = DEFAULT_MODEL) -> Path:
    """Write the model's cross-check folder under `dest`; return that folder."""
    spec, _ = _run(model)
    folder = Path(dest) / "fmus" / "2.0" / "cs" / "linux64" / TOOL_ID / tool_version() / model
    folder.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(fmu_path, folder / f"{model}.fmu")
    shutil.copyfile(spec.page, folder / "README.md")
    write_reference_files(folder, model)
    return folder


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        description="Rewrite a model's reference files (_in.csv, _ref.opt, _ref.csv)."
    )
    parser.add_argument(
        "--model", default=DEFAULT_MODEL, choices=sorted(with_reference()), help="the model"
    )
    parser.add_argument(
        "folder", nargs="?", help="where to write them (default: the model's folder)"
    )
    args = parser.parse_args(argv)
    folder = args.folder or discover()[args.model].path
    for path in write_reference_files(folder, args.model):
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
