"""The propshaft as a chain of single Cardan joints, evaluated in closed form.

Shaft angles gamma_k = gamma_0 + o_k (models/propshaft/README.md): with the pin
of joint k at psi_k = gamma_0 + o_{k-1} + (k-1) pi/2 + phi_{k-1} - b_k (o_0 = 0,
phi_0 = 0), o_k = o_{k-1} + phi_{k-1} + c_k + Delta(psi_k, beta_k), Delta the
single joint's cardan error. Each joint's output speed and acceleration are the
single joint's closed forms with the upstream shaft's speed and acceleration
as input (constant geometry: no bend rate).

Torque. The single joint's input torque is affine in its load with slope
cos(beta)/D = its speed ratio (response.py: T1 = (M2 sin b sin psi + M3 cos b)
/ sqrt(D) + cos b (T_L + M1 sin b cos psi) / D), so one forward pass at zero
load gives every joint's T0_k and s_k, and the backward pass
T_k = T0_k + s_k L_k, L_{k-1} = T_k + J_{k-1} alpha_{k-1} (L_N = load torque)
is exact: the power balance T_1 omega_0 = T_L omega_N + dE/dt holds term by term.

Scalars (the FMU, once per step) or numpy arrays (the fluctuation search).
"""

import math
from typing import Any, NamedTuple

from ...physics._backend import namespace
from ...physics.response import JointResponse, kernel
from .geometry import HALF_PI, Layout

_CARDAN_ERROR = JointResponse._fields.index("cardan_error")
_SPEED_RATIO = JointResponse._fields.index("speed_ratio")
_SPEED = JointResponse._fields.index("output_speed")
_ACCELERATION = JointResponse._fields.index("output_acceleration")
_ENERGY = JointResponse._fields.index("crosspiece_kinetic_energy")
_TORQUE = JointResponse._fields.index("input_torque")


class ChainState(NamedTuple):
    offsets: tuple[Any, ...]  # o_1 .. o_N (gamma_k - gamma_0, before the branch shift)
    speeds: tuple[Any, ...]  # omega_1 .. omega_N
    accelerations: tuple[Any, ...]  # alpha_1 .. alpha_N
    input_torque: Any
    kinetic_energy: Any  # crosspieces and intermediate shafts
    # Each joint's pin angle psi_k, input torque T_k and load L_k (its output
    # shaft's torque): what its bearing loads and life are evaluated from.
    pins: tuple[Any, ...] = ()
    torques: tuple[Any, ...] = ()
    loads: tuple[Any, ...] = ()


def chain(
    geometry: Layout,
    angle,
    speed,
    acceleration,
    crosspiece_inertia=(0.0, 0.0, 0.0),
    shaft_inertias=None,
    load_torque=0.0,
    angle_error=0.0,
) -> ChainState:
    """Every shaft's motion and the input torque at input angle `angle` (+ `angle_error`,
    the low part of a double-double angle), input speed and acceleration."""
    I1, I2, I3 = crosspiece_inertia
    offset = 0.0
    phases = (0.0,) + geometry.phases
    offsets, speeds, accelerations, free_torques, ratios, pins = [], [], [], [], [], []
    energy = 0.0
    w, a = speed, acceleration
    for k, joint in enumerate(geometry.joints):
        base = offset + k * HALF_PI + phases[k] - joint.pin_offset
        psi, beta = angle + (angle_error + base), joint.working_angle
        pins.append(psi)
        xp = math if psi.__class__ is float and beta.__class__ is float else namespace(psi, beta)
        r = kernel(xp, psi, beta, w, a, 0.0, 0.0, I1, I2, I3, 0.0, 1.0)
        offset = offset + phases[k] + joint.twist + r[_CARDAN_ERROR]
        w, a = r[_SPEED], r[_ACCELERATION]
        offsets.append(offset)
        speeds.append(w)
        accelerations.append(a)
        free_torques.append(r[_TORQUE])
        ratios.append(r[_SPEED_RATIO])
        energy = energy + r[_ENERGY]
    inertias = shaft_inertias or (0.0,) * (len(geometry.joints) - 1)
    load = load_torque
    torque = load
    torques, loads = [], []
    for k in range(len(geometry.joints) - 1, -1, -1):
        torque = free_torques[k] + ratios[k] * load
        torques.append(torque)
        loads.append(load)
        if k:
            load = torque + inertias[k - 1] * accelerations[k - 1]
    for J, w_k in zip(inertias, speeds):
        energy = energy + 0.5 * J * w_k * w_k
    return ChainState(
        tuple(offsets),
        tuple(speeds),
        tuple(accelerations),
        torque,
        energy,
        tuple(pins),
        tuple(reversed(torques)),
        tuple(reversed(loads)),
    )
