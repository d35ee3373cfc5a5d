"""Monolithic reference of the compliant driveline: Motor -> CompliantJoint -> InertiaLoad
as ONE ordinary differential equation, integrated by DOP853 at tight tolerance.

State y = (gamma1, omega1, theta_L, omega_L): motor and input shaft angle and
speed, load angle and speed. The joint's kinematics come from the geometric
construction (`multibody.geometry_derivatives`: output angle G0 and dG/dgamma1),
the motor's acceleration from the Newton-Euler equations of shaft, cross and
yokes (`multibody.state_quantities`, motor inertia on the input shaft, the
spring's torque taken by the output shaft); nothing from the FMUs' closed forms:

    torque = k (G0(gamma1) - theta_L) + c (G1(gamma1) omega1 - omega_L)
    motor torque = T_s (1 - omega1 / omega_0)
    J_L omega_L' = torque - drag omega_L - T0
"""

import numpy as np
from scipy.integrate import solve_ivp

from .multibody import geometry_derivatives, state_quantities


def simulate_compliant_driveline(t_eval, motor, drive, load, rtol=1e-10):
    """The recorded quantities at `t_eval` (from t = 0, at rest, twist 0).

    motor: stall_torque, no_load_speed, rotor_inertia; drive: bend_angle,
    torsional_stiffness, torsional_damping, crosspiece_inertia_1..3 (yoke phase 0);
    load: inertia, drag, constant_torque. Returns a dict of arrays keyed like
    `driveline_system.COMPLIANT_RECORDED`."""
    bend = drive["bend_angle"]
    inertia = tuple(drive[f"crosspiece_inertia_{i}"] for i in (1, 2, 3))
    k, c = drive["torsional_stiffness"], drive["torsional_damping"]

    def spring(gamma1, omega1, theta, omega):
        _, _, _, (g0, g1, _) = geometry_derivatives(gamma1, bend)
        return k * (g0 - theta) + c * (g1 * omega1 - omega), g0 - theta

    def motor_torque(omega1):
        return motor["stall_torque"] * (1.0 - omega1 / motor["no_load_speed"])

    def quantities(t, y):
        gamma1, omega1, theta, omega = y
        torque, twist = spring(*y)
        q = state_quantities(
            t,
            gamma1,
            omega1,
            bend,
            inertia,
            motor["rotor_inertia"],
            0.0,
            lambda _: motor_torque(omega1),
            lambda _: torque,
        )
        load_acceleration = (torque - load["drag"] * omega - load["constant_torque"]) / load[
            "inertia"
        ]
        return q, torque, twist, load_acceleration

    def rhs(t, y):
        q, _, _, load_acceleration = quantities(t, y)
        return [y[1], q["input_acceleration"], y[3], load_acceleration]

    t_eval = np.asarray(t_eval, dtype=float)
    solution = solve_ivp(
        rhs,
        (0.0, t_eval[-1]),
        [0.0, 0.0, 0.0, 0.0],
        method="DOP853",
        rtol=rtol,
        atol=rtol,
        t_eval=t_eval,
    )
    assert solution.success, solution.message
    rows: dict = {key: [] for key in _KEYS}
    for t, y in zip(solution.t, solution.y.T):
        q, torque, twist, load_acceleration = quantities(t, y)
        values = (y[1], q["input_acceleration"], y[0], twist, torque, q["input_torque"], y[3])
        for key, value in zip(_KEYS, values + (load_acceleration, y[2])):
            rows[key].append(value)
    return {key: np.array(v) for key, v in rows.items()}


_KEYS = (
    "Motor.speed",
    "Motor.acceleration",
    "Motor.angle",
    "Drive.twist_angle",
    "Drive.output_torque",
    "Drive.input_torque",
    "Load.speed",
    "Load.acceleration",
    "Load.angle",
)
