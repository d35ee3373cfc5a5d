"""The driveline system: Motor -> drive element -> Load, as SSP, run in two hosts.

The drive element is any FMU with the single joint's drive-path interface
(inputs input_speed, input_acceleration, load_torque; outputs output_speed,
output_acceleration, input_torque): `UniversalJoint` or `Propshaft`, named by
`drive`. Speed and acceleration flow downstream, torque flows back:

    Motor.speed, .acceleration -> Drive.input_speed, .input_acceleration
    Drive.output_speed, .output_acceleration -> Load.speed, .acceleration
    Load.torque -> Drive.load_torque;  Drive.input_torque -> Motor.load_torque

Both hosts couple explicitly (Jacobi): every FMU steps with the inputs of the
last communication point, then outputs are passed on. See the README for what
that does to the torque loop.
"""

import math
from pathlib import Path

import numpy as np

from .ssp import Component, fmpy_parameter_set, write_ssp

DRIVE = "Propshaft"
DRIVE_INSTANCE = "Drive"
# Drive-element parameters per drive model (anything the drive does not name keeps
# its FMU's start value).
DRIVE_PARAMETERS = {
    "UniversalJoint": {"bend_angle": math.radians(20.0)},
    # A Z-arrangement of two 12 deg working angles: the intermediate shaft fluctuates,
    # the output follows the input.
    "Propshaft": {"shaft_1_side_angle": math.radians(-10.0)},
}
# A straight drive without inertia of its own: the load's inertia meets the motor's
# unchanged (the example's stability demonstration).
STRAIGHT_DRIVE_PARAMETERS = {
    "UniversalJoint": {
        "bend_angle": 0.0,
        "crosspiece_inertia_1": 0.0,
        "crosspiece_inertia_2": 0.0,
        "crosspiece_inertia_3": 0.0,
    },
    "Propshaft": {
        **{f"shaft_{i}_{view}_angle": 0.0 for i in range(3) for view in ("side", "top")},
        "shaft_1_inertia": 0.0,
        "crosspiece_inertia_1": 0.0,
        "crosspiece_inertia_2": 0.0,
        "crosspiece_inertia_3": 0.0,
    },
}
MOTOR_PARAMETERS = {
    "stall_torque": 120.0,
    "no_load_speed": 157.07963267948966,
    "rotor_inertia": 0.2,
}
LOAD_PARAMETERS = {"inertia": 0.05, "drag": 0.05, "constant_torque": 20.0}

CONNECTIONS = [
    ("Motor", "speed", DRIVE_INSTANCE, "input_speed"),
    ("Motor", "acceleration", DRIVE_INSTANCE, "input_acceleration"),
    (DRIVE_INSTANCE, "output_speed", "Load", "speed"),
    (DRIVE_INSTANCE, "output_acceleration", "Load", "acceleration"),
    ("Load", "torque", DRIVE_INSTANCE, "load_torque"),
    (DRIVE_INSTANCE, "input_torque", "Motor", "load_torque"),
]
RECORDED = [
    "Motor.speed",
    "Motor.acceleration",
    "Motor.angle",
    "Motor.motor_torque",
    f"{DRIVE_INSTANCE}.output_speed",
    f"{DRIVE_INSTANCE}.output_acceleration",
    f"{DRIVE_INSTANCE}.input_torque",
    "Load.torque",
]


def _connectors(instance):
    kinds = {}
    for start, start_connector, end, end_connector in CONNECTIONS:
        if start == instance:
            kinds[start_connector] = "output"
        if end == instance:
            kinds[end_connector] = "input"
    # Outputs recorded but not connected are declared too, so both hosts can report them.
    for key in RECORDED:
        component, _, variable = key.partition(".")
        if component == instance:
            kinds.setdefault(variable, "output")
    return kinds


def build_fmus(dest, drive: str = DRIVE) -> dict:
    """Build the Motor, Load and drive FMUs into `dest`; return {instance: path}."""
    from .build import build

    return {
        "Motor": build(dest, model="Motor"),
        DRIVE_INSTANCE: build(dest, model=drive),
        "Load": build(dest, model="Load"),
    }


def write_driveline_ssp(
    path,
    fmus: dict,
    drive: str = DRIVE,
    stop_time: float = 2.0,
    motor=None,
    load=None,
    drive_parameters=None,
) -> Path:
    """Write the system as an SSP archive. `fmus`: {instance: FMU path} as from
    `build_fmus`; parameter dicts override the defaults above."""
    parameters = {
        "Motor": {**MOTOR_PARAMETERS, **(motor or {})},
        DRIVE_INSTANCE: {**DRIVE_PARAMETERS.get(drive, {}), **(drive_parameters or {})},
        "Load": {**LOAD_PARAMETERS, **(load or {})},
    }
    components = [
        Component(name, fmus[name], _connectors(name), parameters[name])
        for name in ("Motor", DRIVE_INSTANCE, "Load")
    ]
    return write_ssp(path, "Driveline", components, CONNECTIONS, stop_time)


def run_fmpy(ssp_path, stop_time: float, step_size: float) -> dict:
    """FMPy's `simulate_ssp` with the SSP's own parameter bindings.

    `simulate_ssp` stamps each row with the time at the step's start although it
    holds the outputs at the step's end, and steps while an accumulated time is
    below the stop time (one step too many when the sum rounds down). So it is
    asked for n steps exactly (stop time half a step short) and its rows are
    restamped t_k = (k + 1) h. It has no row at t = 0.
    """
    from fmpy.ssp.simulation import simulate_ssp

    n = round(stop_time / step_size)
    result = simulate_ssp(
        str(ssp_path),
        stop_time=(n - 0.5) * step_size,
        step_size=step_size,
        parameter_set=fmpy_parameter_set(ssp_path),
    )
    if len(result) != n:
        raise RuntimeError(f"simulate_ssp made {len(result)} steps, not {n}")
    rows = {"time": np.arange(1, n + 1) * step_size}
    rows.update({key: np.asarray(result[key]) for key in RECORDED})
    return rows


def run_libcosim(ssp_path, stop_time: float, step_size: float, log_level="warning") -> dict:
    """OSP libcosim on the same SSP; samples from t = 0 (initial outputs) on."""
    from .cosim import run_libcosim_ssp

    return run_libcosim_ssp(ssp_path, stop_time, step_size, RECORDED, log_level)


def host_difference(fmpy_rows: dict, libcosim_rows: dict, keys=RECORDED) -> dict:
    """Largest |FMPy - libcosim| per variable over the common time points."""
    assert np.allclose(fmpy_rows["time"], libcosim_rows["time"][1:], rtol=0, atol=1e-12)
    return {key: float(np.max(np.abs(fmpy_rows[key] - libcosim_rows[key][1:]))) for key in keys}
