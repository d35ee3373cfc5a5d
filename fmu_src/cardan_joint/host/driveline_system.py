"""The driveline system: Motor -> drive element -> Load, as SSP, run in three hosts.

The drive element is any FMU with the single joint's drive-path interface
(inputs input_speed, input_acceleration, load_torque; outputs output_speed,
output_acceleration, input_torque): `UniversalJoint` or `Propshaft`, named by
`drive`. Speed and acceleration flow downstream, torque flows back:

    Motor.speed, .acceleration -> Drive.input_speed, .input_acceleration
    Drive.output_speed, .output_acceleration -> Load.speed, .acceleration
    Load.torque -> Drive.load_torque;  Drive.input_torque -> Motor.load_torque

FMPy, libcosim and Ecos couple explicitly (Jacobi): every FMU steps with the
inputs of the last communication point, then outputs are passed on. See the
README for what that does to the torque loop.

The compliant system (`COMPLIANT_CONNECTIONS`) couples Motor -> CompliantJoint
(or CompliantPropshaft) -> InertiaLoad: each inertia is a state of its own FMU,
the drive takes both shaft motions and returns both torques, so the load's
inertia may exceed the motor's by any factor. Its step follows
`torsional_step` (models/compliant_joint/README.md derives the rule).
"""

import math
from pathlib import Path

import numpy as np

from .ssp import Component, check_ssp, fmpy_parameter_set, write_ssp

DRIVE = "Propshaft"
DRIVE_INSTANCE = "Drive"
SYSTEM = "Driveline"  # also the name of the parameter set every component binds
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


COMPLIANT_CONNECTIONS = [
    ("Motor", "speed", DRIVE_INSTANCE, "input_speed"),
    ("Motor", "acceleration", DRIVE_INSTANCE, "input_acceleration"),
    ("Load", "speed", DRIVE_INSTANCE, "output_speed"),
    ("Load", "acceleration", DRIVE_INSTANCE, "output_acceleration"),
    (DRIVE_INSTANCE, "output_torque", "Load", "drive_torque"),
    (DRIVE_INSTANCE, "input_torque", "Motor", "load_torque"),
]
COMPLIANT_RECORDED = [
    "Motor.speed",
    "Motor.acceleration",
    "Motor.angle",
    f"{DRIVE_INSTANCE}.twist_angle",
    f"{DRIVE_INSTANCE}.output_torque",
    f"{DRIVE_INSTANCE}.input_torque",
    "Load.speed",
    "Load.acceleration",
    "Load.angle",
]
COMPLIANT_DRIVE_PARAMETERS = {
    "bend_angle": math.radians(20.0),
    "torsional_stiffness": 1e4,
}
COMPLIANT_LOAD_PARAMETERS = {"drag": 0.05, "constant_torque": 20.0}
# Largest omega_n h of the compliant system's step (radians of its torsional mode).
STEP_PER_RADIAN = 0.1


def torsional_step(stiffness: float, inertia_in: float, inertia_out: float, damping_ratio: float):
    """(natural frequency omega_n [rad/s], damping [N.m.s/rad], step [s]) of a spring
    `stiffness` between two inertias, for the damping ratio `damping_ratio`:

        omega_n = sqrt(k (1/J_in + 1/J_out)),  c = 2 zeta sqrt(k J_eff),
        J_eff = J_in J_out / (J_in + J_out),  h = min(0.1, zeta) / omega_n.

    Explicit (Jacobi) coupling holds each torque and speed over a step; that delay
    feeds energy into the torsional mode at a rate equal to a negative damping
    ratio of about omega_n h / 4 (J_eff / J_out) + 2 (omega_n h)^2, measured on
    this driveline. The rule keeps it below about half the physical damping ratio.
    """
    # 1/(1/J_in + 1/J_out): a prescribed input motion is J_in = inf.
    effective = 1.0 / (1.0 / inertia_in + 1.0 / inertia_out)
    omega_n = math.sqrt(stiffness / effective)
    damping = 2.0 * damping_ratio * math.sqrt(stiffness * effective)
    return omega_n, damping, min(STEP_PER_RADIAN, damping_ratio) / omega_n


def compliant_parameters(inertia_ratio: float, damping_ratio: float = 0.1):
    """(motor, drive, load parameters, step size) of the compliant system with a load
    `inertia_ratio` times the motor's rotor inertia, its step by `torsional_step`."""
    motor_inertia = MOTOR_PARAMETERS["rotor_inertia"]
    load_inertia = inertia_ratio * motor_inertia
    drive = dict(COMPLIANT_DRIVE_PARAMETERS)
    _, damping, step = torsional_step(
        drive["torsional_stiffness"], motor_inertia, load_inertia, damping_ratio
    )
    drive["torsional_damping"] = damping
    load = {**COMPLIANT_LOAD_PARAMETERS, "inertia": load_inertia}
    # Down to whole microseconds: libcosim counts time in nanoseconds, and a stop
    # time of n such steps is then exact in both hosts.
    return dict(MOTOR_PARAMETERS), drive, load, math.floor(step * 1e6) / 1e6


def _connectors(instance, connections=CONNECTIONS, recorded=RECORDED):
    kinds = {}
    for start, start_connector, end, end_connector in connections:
        if start == instance:
            kinds[start_connector] = "output"
        if end == instance:
            kinds[end_connector] = "input"
    # Outputs recorded but not connected are declared too, so both hosts can report them.
    for key in recorded:
        component, _, variable = key.partition(".")
        if component == instance:
            kinds.setdefault(variable, "output")
    return kinds


def system_parameters(drive: str = DRIVE, motor=None, load=None, drive_parameters=None) -> dict:
    """{instance: {parameter: value}}: the defaults above, overridden by the dicts given."""
    return {
        "Motor": {**MOTOR_PARAMETERS, **(motor or {})},
        DRIVE_INSTANCE: {**DRIVE_PARAMETERS.get(drive, {}), **(drive_parameters or {})},
        "Load": {**LOAD_PARAMETERS, **(load or {})},
    }


def build_fmus(dest, drive: str = DRIVE, load: str = "Load", parameters=None) -> dict:
    """Build the Motor, load (`Load` or `InertiaLoad`) and drive FMUs into `dest`;
    return {instance: path}. `parameters` ({instance: {parameter: value}}, as
    `system_parameters` gives) become the FMUs' own start values: a host that
    applies no SSP binding (Ecos when no parameter set is named) then runs the
    system as the SSP binds it."""
    from ..build import build

    parameters = parameters or {}
    models = {"Motor": "Motor", DRIVE_INSTANCE: drive, "Load": load}
    return {
        instance: build(dest, model=model, start_values=parameters.get(instance))
        for instance, model in models.items()
    }


def write_driveline_ssp(
    path,
    fmus: dict,
    drive: str = DRIVE,
    stop_time: float = 2.0,
    motor=None,
    load=None,
    drive_parameters=None,
    connections=CONNECTIONS,
    recorded=RECORDED,
    step_size: float = 1e-3,
) -> Path:
    """Write the system as an SSP archive. `fmus`: {instance: FMU path} as from
    `build_fmus` (given the same parameters, every host runs the system as bound);
    `step_size` is the fixed step the SSP names for OMSimulator; parameter dicts
    override the defaults above (the compliant system: `COMPLIANT_CONNECTIONS`,
    `COMPLIANT_RECORDED` and its parameters from `compliant_parameters`)."""
    parameters = system_parameters(drive, motor, load, drive_parameters)
    components = [
        Component(name, fmus[name], _connectors(name, connections, recorded), parameters[name])
        for name in ("Motor", DRIVE_INSTANCE, "Load")
    ]
    return write_ssp(path, SYSTEM, components, connections, stop_time, step_size)


def run_fmpy(ssp_path, stop_time: float, step_size: float, recorded=RECORDED) -> dict:
    """FMPy's `simulate_ssp` with the SSP's own parameter bindings.

    `simulate_ssp` stamps each row with the time at the step's start although it
    holds the outputs at the step's end, and steps while an accumulated time is
    below the stop time (one step too many when the sum rounds down). So it is
    asked for n steps exactly (stop time half a step short) and its rows are
    restamped t_k = (k + 1) h. It has no row at t = 0.
    """
    from fmpy.ssp.simulation import simulate_ssp

    check_ssp(ssp_path)
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
    rows.update({key: np.asarray(result[key]) for key in recorded})
    return rows


def run_libcosim(
    ssp_path, stop_time: float, step_size: float, log_level="warning", recorded=RECORDED
) -> dict:
    """OSP libcosim on the same SSP; samples from t = 0 (initial outputs) on."""
    from .cosim import run_libcosim_ssp

    check_ssp(ssp_path)
    return run_libcosim_ssp(ssp_path, stop_time, step_size, recorded, log_level)


def run_ecos(ssp_path, stop_time: float, step_size: float, recorded=RECORDED) -> dict:
    """Ecos on the same SSP with its one parameter set (`SYSTEM`, every component's
    binding); samples from t = 0 (initial outputs) on, as `run_libcosim`."""
    from .ecos import run_ecos_ssp

    check_ssp(ssp_path)
    return run_ecos_ssp(ssp_path, stop_time, step_size, recorded, parameter_set=SYSTEM)


def host_difference(fmpy_rows: dict, libcosim_rows: dict, keys=RECORDED) -> dict:
    """Largest |FMPy - libcosim| per variable over the common time points."""
    assert np.allclose(fmpy_rows["time"], libcosim_rows["time"][1:], rtol=0, atol=1e-12)
    return {key: float(np.max(np.abs(fmpy_rows[key] - libcosim_rows[key][1:]))) for key in keys}
