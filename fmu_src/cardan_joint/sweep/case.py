"""One case of a sweep: a co-simulation at constant inputs, reduced to its peaks.

Tasks are pure functions of their inputs, so a Dask run and a serial run give
identical rows. Workers must reach the FMU at the same path (same machine, or
a shared file system) and import this package.
"""

import math
from dataclasses import asdict
from pathlib import Path

from .. import DEFAULT_MODEL
from ..units import DEG_TO_RAD, RPM_TO_RAD_PER_S
from .spec import FAILED, OK, PEAKS, Case, SweepSpec

_RECORDED = (
    "output_speed",
    "output_acceleration",
    "crosspiece_torque_1",
    "crosspiece_torque_2",
    "crosspiece_torque_3",
    "input_torque",
    "input_yoke_moment",
    "output_yoke_moment",
)


_DRIVEN = (
    "input_speed",
    "input_acceleration",
    "bend_angle",
    "bend_angle_rate",
    "bend_angle_acceleration",
    "load_torque",
)


def check_fmu(fmu, spec: SweepSpec):
    """The FMU's FmuInfo; UsageError (before any case) unless the FMU has every
    variable the sweep sets and reads; MissingFMUError or BadFMUError for a
    missing or unreadable file."""
    from ..host.fmu_info import FmuInfo
    from ..names import UsageError

    info = FmuInfo.read(fmu)
    wanted = {
        "input": _DRIVEN,
        "parameter": tuple(f"crosspiece_inertia_{k}" for k in (1, 2, 3))
        + (("max_bend_angle",) if spec.max_bend_angle_deg is not None else ()),
        "output": _RECORDED,
    }
    missing = {
        causality: [n for n in names if n not in info.names(causality)]
        for causality, names in wanted.items()
    }
    lacking = "; ".join(f"{kind}s {', '.join(names)}" for kind, names in missing.items() if names)
    if lacking:
        raise UsageError(
            f"{fmu} ({info.model_name}) lacks what the sweep sets and reads: {lacking}; "
            "the sweep takes a UniversalJoint FMU (python build_fmu.py)"
        )
    return info


# What each case setting is called on the command line, for a refusal's message.
_OPTIONS = {
    "bend_angle": "--bend-angles",
    "input_speed": "--speeds",
    "load_torque": "--load-torque",
    "max_bend_angle": "--max-bend-angle",
    **{f"crosspiece_inertia_{k}": "--i0, --distributions" for k in (1, 2, 3)},
}


def check_ranges(parameters: dict, spec: SweepSpec) -> None:
    """UsageError, before any case, naming the first case the joint's own checks
    refuse (the FMU's parameters `parameters`, the case's inputs and inertias):
    the checks the FMU makes at its first step, made once here for every case.
    The command makes them; in Python a case the FMU refuses is a failed row."""
    from ..models import StartValueError, discover
    from ..names import UsageError

    joint = discover()[DEFAULT_MODEL]
    for case in spec.cases():
        values = {**parameters, **_start_values(spec, case), **_inputs(spec, case)}
        try:
            joint.check_start_values(values, joint.default_settings)
        except StartValueError as error:
            named = [o for n, o in _OPTIONS.items() if f" {n} = " in f" {error}"]
            option = f" ({named[0]})" if named else ""
            raise UsageError(
                f"case {case.bend_angle_deg:g} deg, {case.input_speed_rpm:g} rpm, "
                f"{case.inertia_distribution}{option}: {error}; no case was run"
            ) from None


def _start_values(spec: SweepSpec, case: Case) -> dict:
    values = {
        f"crosspiece_inertia_{k}": value
        for k, value in enumerate(spec.inertias(case.inertia_distribution), 1)
    }
    if spec.max_bend_angle_deg is not None:
        values["max_bend_angle"] = spec.max_bend_angle_deg * DEG_TO_RAD
    return values


def _inputs(spec: SweepSpec, case: Case) -> dict:
    return {
        "input_speed": case.input_speed_rpm * RPM_TO_RAD_PER_S,
        "input_acceleration": 0.0,
        "bend_angle": case.bend_angle_deg * DEG_TO_RAD,
        "bend_angle_rate": 0.0,
        "bend_angle_acceleration": 0.0,
        "load_torque": spec.load_torque,
    }


def _failure_message(error):
    from ..host.simulate import SimulationError

    text = " ".join(str(error).split())
    return text if isinstance(error, SimulationError) else f"{type(error).__name__}: {text}"


def cosimulate(fmu_dir, stop_time, step, inputs, start_values, output):
    """The sweep's one call into the FMU stack (the place to switch how FMUs are run)."""
    from ..host.simulate import simulate

    return simulate(
        fmu_dir,
        stop_time=stop_time,
        output_interval=step,
        inputs=inputs,
        start_values=start_values,
        output=output,
    )


def run_case(fmu_dir, spec: SweepSpec, case: Case) -> dict:
    """Co-simulate one case; return its table row (never raises for a bad case)."""
    import numpy as np

    start_values = _start_values(spec, case)
    inertias = {n: v for n, v in start_values.items() if n.startswith("crosspiece_inertia_")}
    row = {**asdict(case), **inertias, "load_torque": spec.load_torque, "status": OK, "message": ""}
    inputs = _inputs(spec, case)
    speed = inputs["input_speed"]
    try:
        step = 2 * math.pi / speed / spec.steps_per_revolution
        result = cosimulate(
            fmu_dir,
            spec.revolutions * spec.steps_per_revolution * step,
            step,
            inputs,
            start_values,
            list(_RECORDED),
        )
        torque = np.sqrt(
            result["crosspiece_torque_1"] ** 2
            + result["crosspiece_torque_2"] ** 2
            + result["crosspiece_torque_3"] ** 2
        )
        row.update(
            {
                "peak_output_acceleration": float(np.abs(result["output_acceleration"]).max()),
                "peak_crosspiece_torque": float(torque.max()),
                "speed_fluctuation": float(np.ptp(result["output_speed"]) / speed),
                "peak_input_torque": float(np.abs(result["input_torque"]).max()),
                "peak_input_yoke_moment": float(result["input_yoke_moment"].max()),
                "peak_output_yoke_moment": float(result["output_yoke_moment"].max()),
            }
        )
    except Exception as error:  # a failed case is a result, not a crash
        row.update(
            {
                "status": FAILED,
                "message": _failure_message(error),
                **{name: math.nan for name in PEAKS},
            }
        )
    return row


def run_task(fmu: str, spec: SweepSpec, cases) -> list:
    """Run a task's cases on one unzipped copy of the FMU (runs on a worker)."""
    from ..host.unpacked import ExtractedFMU

    if not Path(fmu).is_file():
        message = f"FMU {fmu} not found on this worker: it must be reachable at the same path"
        return [{**asdict(case), "status": FAILED, "message": message} for case in cases]
    with ExtractedFMU(fmu) as unzipped:
        return [run_case(unzipped.directory, spec, case) for case in cases]
