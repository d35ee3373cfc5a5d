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
from ...physics.response import (
    cardan_tangent,
    euler_moments,
    pose_at,
    pose_of,
    steady_crosspiece_motion,
    yoke_reactions,
)
from .geometry import HALF_PI, Layout

# A layout as plain numbers (`layout_values`), joint after joint: its working
# angle beta_k, pin offset b_k, twist c_k, the yoke phasing phi_{k-1} before it
# (0 at joint 1) and its input shaft's polar inertia (0 for the input shaft).
WORKING_ANGLE, PIN_OFFSET, TWIST, PHASE, INERTIA = range(5)
LAYOUT_FIELDS = 5
# `chain_values`' result, joint after joint: its output shaft's offset o_k,
# speed and acceleration, its pin angle psi_k, input torque T_k and load L_k;
# then the input torque and the kinetic energy.
OFFSET, SPEED, ACCELERATION, PIN, TORQUE, LOAD = range(6)
CHAIN_FIELDS = 6
# The forward pass's record holds T0_k (at no load) and the speed ratio s_k
# where the result holds T_k and L_k.
_FREE_TORQUE, _RATIO = TORQUE, LOAD


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


def layout_values(geometry: Layout, shaft_inertias) -> tuple[float, ...]:
    """The layout's numbers `chain_values` takes (`LAYOUT_FIELDS` per joint)."""
    phases = (0.0, *geometry.phases)
    inertias = (0.0, *shaft_inertias)
    return tuple(
        value
        for k, joint in enumerate(geometry.joints)
        for value in (joint.working_angle, joint.pin_offset, joint.twist, phases[k], inertias[k])
    )


def bend_trig(xp, layout):
    """Each joint's (sin beta_k, cos beta_k), after each other: constant over
    a step, so the life integral's nodes take them from the step's start."""
    trig = ()
    for k in range(len(layout) // LAYOUT_FIELDS):
        beta = layout[LAYOUT_FIELDS * k + WORKING_ANGLE]
        trig = trig + (xp.sin(beta), xp.cos(beta))
    return trig


def node_trig(layout):
    """What the chain takes from the layout alone, computed once when the model
    starts (the step state's `trig`): `bend_trig`'s (sin beta_k, cos beta_k),
    then each joint's (sin Delta_k, cos Delta_k) for a life node's chain
    (`node_forward`), Delta_k = c_k + pi/2 + phi_k + b_k - b_(k+1) the turn
    from its pin angle to the next joint's, psi_(k+1) - psi_k, less its cardan
    error e_k; the last joint turns to no pin: Delta = 0. Its head is
    `bend_trig`'s, so `chain_values` takes it too."""
    turns = ()
    for k in range(1, len(layout) // LAYOUT_FIELDS):
        joint = layout[LAYOUT_FIELDS * (k - 1) : LAYOUT_FIELDS * k]
        following = layout[LAYOUT_FIELDS * k : LAYOUT_FIELDS * (k + 1)]
        pins = joint[PIN_OFFSET] - following[PIN_OFFSET]
        turn = joint[TWIST] + HALF_PI + following[PHASE] + pins
        turns = turns + (math.sin(turn), math.cos(turn))
    return bend_trig(math, layout) + turns + (0.0, 1.0)


def pin_turned(s, c, sine, cosine, tangent):
    """(sin, cos) of psi + Delta + e from psi's `s` and `c`, Delta's `sine` and
    `cosine` and e's `tangent` (|e| < 90 deg): cos e = 1 / sqrt(1 + tan^2 e)
    and sin e = tan e cos e, so no trigonometric call."""
    root = math.sqrt(1.0 + tangent * tangent)
    turn_cosine = (cosine - sine * tangent) / root
    turn_sine = (sine + cosine * tangent) / root
    return s * turn_cosine + c * turn_sine, c * turn_cosine - s * turn_sine


def joint_forward(xp, s, c, sb, cb, w, a, I1, I2, I3):
    """(the cardan error's tangent, output speed and acceleration, the
    cross's kinetic energy, input torque at no load, speed ratio) of one joint
    at pin angle sine `s` and cosine `c`, bend sine `sb` and cosine `cb`,
    input speed `w` and acceleration `a`: the kernel's (response.py) at a
    constant bend, from its own parts, so to the bit; the rest of its outputs
    is not computed."""
    s, c, sb, cb, D, rD = pose_at(xp, s, c, sb, cb)
    w2, a2, W1, W2, W3, dW1, dW2, dW3 = steady_crosspiece_motion(s, c, sb, cb, D, rD, w, a)
    M1, M2, M3 = euler_moments(I1, I2, I3, W1, W2, W3, dW1, dW2, dW3)
    energy = 0.5 * (I1 * W1 * W1 + I2 * W2 * W2 + I3 * W3 * W3)
    torque = yoke_reactions(M1, M2, M3, s, c, sb, cb, rD, 0.0)[2]
    return cardan_tangent(s, c, sb, cb), w2, a2, energy, torque, cb / D


def chain_forward(xp, angle, angle_error, speed, acceleration, layout, trig, I1, I2, I3):
    """The chain's load-free part at input angle `angle` (+ `angle_error`, the
    low part of a double-double angle), input speed and acceleration: per joint
    (`CHAIN_FIELDS`) o_k, omega_k, alpha_k, psi_k, T0_k (at no load) and the
    ratio s_k, then the kinetic energy; `layout` from `layout_values`, `trig`
    from `bend_trig` (or `node_trig`, whose head it is)."""
    offset, w, a, energy = 0.0, speed, acceleration, 0.0
    forward = ()
    for k in range(len(layout) // LAYOUT_FIELDS):
        joint = layout[LAYOUT_FIELDS * k : LAYOUT_FIELDS * (k + 1)]
        psi = pin_angle(angle, angle_error, offset, k, joint)
        sb, cb = trig[2 * k], trig[2 * k + 1]
        s, c = pose_of(xp, psi, sb, cb)[2:4]
        tangent, w, a, crosspiece, torque, ratio = joint_forward(xp, s, c, sb, cb, w, a, I1, I2, I3)
        offset = offset + joint[PHASE] + joint[TWIST] + xp.atan(tangent)
        energy = energy + crosspiece
        forward = forward + (offset, w, a, psi, torque, ratio)
    return forward + (shafts_energy(forward, layout, energy),)


def node_forward(angle, angle_error, speed, acceleration, layout, trig, I1, I2, I3):
    """`chain_forward`'s values at a life node (floats) with one sine and
    cosine for the whole chain: joint 1's pin angle as there, each next one's
    psi_(k+1) = psi_k + Delta_k + e_k by the addition formulas (`pin_turned`)
    from psi_k's, Delta_k's (`node_trig`'s, once a model) and the cardan error
    e_k's tangent. Each offset o_k adds its joint's error e_k = atan(tan e_k)
    as `chain_forward` does (one sum of tangents would leave atan's branch
    once the errors pass 90 deg together, at working angles the model
    accepts); the compiler drops the atans where no one reads an offset
    (`codegen.FLOAT_FLAGS`): a propshaft's torques read none; the spring reads
    the last, which takes every joint's. Equal to `chain_forward`'s to a few ulps."""
    offset, w, a, energy = 0.0, speed, acceleration, 0.0
    s, c = 0.0, 1.0
    forward = ()
    for k in range(len(layout) // LAYOUT_FIELDS):
        joint = layout[LAYOUT_FIELDS * k : LAYOUT_FIELDS * (k + 1)]
        psi = pin_angle(angle, angle_error, offset, k, joint)
        sb, cb = trig[2 * k], trig[2 * k + 1]
        if k == 0:
            s, c = pose_of(math, psi, sb, cb)[2:4]
        error, w, a, crosspiece, torque, ratio = joint_forward(math, s, c, sb, cb, w, a, I1, I2, I3)
        offset = offset + joint[PHASE] + joint[TWIST] + math.atan(error)
        energy = energy + crosspiece
        forward = forward + (offset, w, a, psi, torque, ratio)
        if LAYOUT_FIELDS * (k + 1) < len(layout):
            # `node_trig`'s turns follow its bends.
            turn = trig[len(trig) // 2 + 2 * k : len(trig) // 2 + 2 * k + 2]
            s, c = pin_turned(s, c, turn[0], turn[1], error)
    return forward + (shafts_energy(forward, layout, energy),)


def pin_angle(angle, angle_error, offset, k: int, joint):
    """Joint k's pin angle psi_k (from 0; `joint` its `LAYOUT_FIELDS`) at input
    angle `angle` (+ `angle_error`), the offset before it o_(k-1) = `offset`."""
    return angle + (angle_error + (offset + k * HALF_PI + joint[PHASE] - joint[PIN_OFFSET]))


def shafts_energy(forward, layout, energy):
    """The chain's kinetic energy: the crosspieces' `energy` plus each
    intermediate shaft's at its speed in `forward` (`CHAIN_FIELDS` a joint)."""
    for k in range(1, len(layout) // LAYOUT_FIELDS):
        w = forward[CHAIN_FIELDS * (k - 1) + SPEED]
        energy = energy + 0.5 * layout[LAYOUT_FIELDS * k + INERTIA] * w * w
    return energy


def chain_backward(forward, layout, load_torque):
    """Each joint's input torque T_k and load L_k (after each other), the
    chain's load `load_torque` carried back through `chain_forward`'s values:
    T_k = T0_k + s_k L_k, L_(k-1) = T_k + J_(k-1) alpha_(k-1)."""
    load = load_torque
    backward = ()
    for k in range(len(layout) // LAYOUT_FIELDS - 1, -1, -1):
        torque = (
            forward[CHAIN_FIELDS * k + _FREE_TORQUE] + forward[CHAIN_FIELDS * k + _RATIO] * load
        )
        backward = (torque, load) + backward
        if k > 0:
            inertia = layout[LAYOUT_FIELDS * k + INERTIA]
            load = torque + inertia * forward[CHAIN_FIELDS * (k - 1) + ACCELERATION]
    return backward


def chain_values(xp, angle, angle_error, speed, acceleration, layout, trig, I1, I2, I3,
                 load_torque):  # fmt: skip
    """The chain at input angle `angle` (+ `angle_error`), input speed and
    acceleration under `load_torque`, as one flat tuple (`CHAIN_FIELDS` per
    joint, then the input torque and the energy): `chain_forward`, then
    `chain_backward`; `trig` is `bend_trig`'s (or `node_trig`'s). Written in
    the generator's subset: the propshaft's step (`step.py`) runs it in C; `xp`
    is numpy for arrays."""
    forward = chain_forward(xp, angle, angle_error, speed, acceleration, layout, trig, I1, I2, I3)
    backward = chain_backward(forward, layout, load_torque)
    values = ()
    for k in range(len(layout) // LAYOUT_FIELDS):
        values = values + forward[CHAIN_FIELDS * k : CHAIN_FIELDS * k + 4]
        values = values + backward[2 * k : 2 * k + 2]
    return values + (backward[0], forward[len(forward) - 1])


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
    joints = len(geometry.joints)
    inertias = shaft_inertias or (0.0,) * (joints - 1)
    I1, I2, I3 = crosspiece_inertia
    xp = namespace(angle, angle_error)
    layout = layout_values(geometry, inertias)
    values = chain_values(
        xp, angle, angle_error, speed, acceleration, layout, bend_trig(xp, layout), I1, I2, I3,
        load_torque,
    )  # fmt: skip

    def each(field):
        return tuple(values[CHAIN_FIELDS * k + field] for k in range(joints))

    return ChainState(
        each(OFFSET), each(SPEED), each(ACCELERATION), values[-2], values[-1], each(PIN),
        each(TORQUE), each(LOAD),
    )  # fmt: skip
