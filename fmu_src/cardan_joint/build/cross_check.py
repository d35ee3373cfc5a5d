"""The UniversalJoint's reference run, in the fmi-cross-check repository layout.

    fmus/2.0/cs/linux64/cardan_joint/<version>/UniversalJoint/
        UniversalJoint.fmu
        UniversalJoint_in.csv     inputs, linearly interpolated (all six inputs)
        UniversalJoint_ref.opt    StartTime, StopTime, StepSize, RelTol
        UniversalJoint_ref.csv    the reference outputs (time + 9 outputs)
        README.md                 docs/UniversalJoint/README.md

The reference is computed by the physics package (`CardanJoint` stepped as a
co-simulation master steps the FMU), not by the FMU: a tool that reproduces it
through the FMU checks the FMI plumbing against the equations. The same three
files are kept in docs/UniversalJoint/ (tests/test_cross_check.py checks that
they are current; `python -m cardan_joint.build.cross_check docs/UniversalJoint`
rewrites them). The CompliantJoint and the InertiaLoad have reference files of
their own in docs/<model>/ (`CASES`; `python -m cardan_joint.build.cross_check
--model CompliantJoint docs/CompliantJoint`).
"""

from __future__ import annotations

import argparse
import shutil
import sys
from collections.abc import Callable
from dataclasses import dataclass
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

import numpy as np

MODEL = "UniversalJoint"
TOOL_ID = "cardan_joint"
DOCS = Path(__file__).resolve().parents[3] / "docs" / MODEL

OPTIONS = {"StartTime": 0.0, "StopTime": 1.0, "StepSize": 1e-3, "RelTol": 1e-6}
# Inputs linear in time, their rates given beside them, so that every step is
# exact: the shaft runs up 20 -> 40 rad/s while the joint bends 0.2 -> 0.6 rad
# against a constant load. Two rows: FMI tools interpolate linearly between them.
INPUT_ROWS = (
    # time, input_speed, input_acceleration, bend_angle, bend_angle_rate,
    # bend_angle_acceleration, load_torque
    (0.0, 20.0, 20.0, 0.2, 0.4, 0.0, 100.0),
    (1.0, 40.0, 20.0, 0.6, 0.4, 0.0, 100.0),
)
# At most 10 columns with the time (the cross-check rules' recommendation).
REFERENCE_OUTPUTS = (
    "output_angle",
    "output_speed",
    "output_acceleration",
    "cardan_error",
    "input_torque",
    "input_yoke_moment",
    "output_yoke_moment",
    "input_bearing_force",
    "life_consumed",
)


@dataclass(frozen=True)
class Case:
    """One model's reference run: its physics model (made at its table's start
    values), inputs as rows (time first, then the table's inputs) and outputs."""

    model: str
    make: Callable[[], Any]
    input_rows: tuple
    outputs: tuple


def _joint():
    from ..models.universal_joint.model import CardanJoint

    return CardanJoint()


def _compliant_joint():
    from ..models.compliant_joint.model import CompliantJoint

    return CompliantJoint()


def _inertia_load():
    from ..models.inertia_load.model import InertiaLoad

    return InertiaLoad()


CASES = {
    case.model: case
    for case in (
        Case(MODEL, _joint, INPUT_ROWS, REFERENCE_OUTPUTS),
        # The input shaft as the UniversalJoint's; the output shaft a little slower
        # and faster in turn, so the spring winds up and back.
        Case(
            "CompliantJoint",
            _compliant_joint,
            (
                # time, input_speed, input_acceleration, output_speed,
                # output_acceleration, bend_angle, bend_angle_rate, bend_angle_acceleration
                (0.0, 20.0, 20.0, 19.0, 22.0, 0.2, 0.4, 0.0),
                (1.0, 40.0, 20.0, 41.0, 22.0, 0.6, 0.4, 0.0),
            ),
            (
                "output_angle",
                "twist_angle",
                "output_torque",
                "kinematic_output_speed",
                "input_torque",
                "input_yoke_moment",
                "output_yoke_moment",
                "spring_energy",
                "crosspiece_kinetic_energy",
            ),
        ),
        # The drive torque ramps through the constant torque (20 N.m): the load
        # first turns backwards, then runs up.
        Case(
            "InertiaLoad",
            _inertia_load,
            ((0.0, 0.0), (1.0, 60.0)),
            ("speed", "acceleration", "angle"),
        ),
    )
}


def tool_version() -> str:
    try:
        return version("cardan-joint-fmu")
    except PackageNotFoundError:  # a source tree that is not installed
        return "0+unknown"


def inputs(model: str = MODEL) -> np.ndarray:
    """The input signals as a structured array (FMPy's `input` format)."""
    names = CASES[model].make().table.INPUTS
    rows = list(CASES[model].input_rows)
    return np.array(rows, dtype=[("time", float)] + [(n, float) for n in names])


def reference(model: str = MODEL) -> np.ndarray:
    """The reference outputs at every communication point, by the physics package."""
    case = CASES[model]
    signals = inputs(model)
    start, stop, step = (OPTIONS[k] for k in ("StartTime", "StopTime", "StepSize"))
    steps = round((stop - start) / step)
    times = start + step * np.arange(steps + 1)
    joint = case.make()
    names, outputs = joint.table.INPUTS, joint.table.OUTPUTS

    def apply_inputs(time):
        for name in names:
            setattr(joint, name, float(np.interp(time, signals["time"], signals[name])))

    # As a master records: a sample at each communication point before the
    # inputs of the next step are set (in between, the FMU carries its inputs along).
    apply_inputs(start)
    joint.start(start)  # after the inputs: a compliant joint starts from the bend angle
    rows = []
    for k, time in enumerate(times):
        values = dict(zip(outputs, joint.outputs()))
        rows.append((time, *(values[n] for n in case.outputs)))
        if k == steps:
            break
        apply_inputs(time)
        problem = joint.step(step)
        if problem:
            raise RuntimeError(f"the reference run was refused at t = {time}: {problem}")
    return np.array(rows, dtype=[("time", float)] + [(n, float) for n in case.outputs])


def write_reference_files(folder: str | Path, model: str = MODEL) -> list[Path]:
    """Write <model>_in.csv, <model>_ref.opt and <model>_ref.csv into `folder`."""
    from ..results import write_csv

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    paths = [folder / f"{model}_in.csv", folder / f"{model}_ref.opt", folder / f"{model}_ref.csv"]
    write_csv(inputs(model), paths[0])
    paths[1].write_text("".join(f"{key}, {value!r}\n" for key, value in OPTIONS.items()))
    write_csv(reference(model), paths[2])
    return paths


def write_cross_check(dest: str | Path, fmu_path: str | Path) -> Path:
    """Write the model's cross-check folder under `dest`; return that folder."""
    readme = DOCS / "README.md"
    if not readme.is_file():
        raise FileNotFoundError(
            f"{readme} not found: the cross-check folder is written from "
            f"a source checkout of the repository"
        )
    folder = Path(dest) / "fmus" / "2.0" / "cs" / "linux64" / TOOL_ID / tool_version() / MODEL
    folder.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(fmu_path, folder / f"{MODEL}.fmu")
    shutil.copyfile(readme, folder / "README.md")
    write_reference_files(folder)
    return folder


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        description="Rewrite a model's reference files (_in.csv, _ref.opt, _ref.csv)."
    )
    parser.add_argument("--model", default=MODEL, choices=sorted(CASES), help="the model")
    parser.add_argument("folder", nargs="?", help="where to write them (default: docs/<model>/)")
    args = parser.parse_args(argv)
    folder = args.folder or DOCS.parent / args.model
    for path in write_reference_files(folder, args.model):
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
