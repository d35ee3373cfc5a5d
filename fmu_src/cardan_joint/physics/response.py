"""Every closed form of the joint (models/universal_joint/README.md), evaluated in one pass.

This one function is the single home of the equations: the FMU calls it once
per step on floats (through `math`), design sweeps call it on numpy arrays, and
the single-quantity functions of `quantities` pick from it. Its parts the
input torque alone needs (`pose_of`, `crosspiece_motion`, `euler_moments`,
`yoke_reactions`) are functions of their own, which the life integral's
torque (`life_torque`) calls too.

Notation: psi = input angle + yoke phase (input-pin angle), b = bend angle,
D = 1 - sin^2 b cos^2 psi (>= cos^2 b, so nothing is singular below 90 deg).

Frames. Input pin p1 = (cos psi, sin psi, 0); output pin p2 = unit(z2 x p1)
= (-cos b sin psi, cos b cos psi, sin b sin psi) / sqrt(D); p3 = p1 x p2
= (sin b sin^2 psi, -sin b sin psi cos psi, cos b) / sqrt(D). So the crosspiece
matrix R = [p1 p2 p3] = Rz(psi) Rx(rho), with roll rho = atan(tan b sin psi).

Crosspiece angular velocity. The cross turns with the input yoke about z plus
about p1, and with the output yoke (omega2 about z2, b' about the hinge axis y)
plus about p2. Projected on p2, p3 the first gives Omega2, Omega3; projected on
p1 the second gives Omega1.

Torque path. Yoke k pushes on the cross only normal to its pin:
tau1 = M2 p2 + B p3, tau2 = M1 p1 + Dd p3, with B + Dd = M3; the output shaft
takes -tau2 . z2 = T_L, and p3 . z2 = sqrt(D), p1 . z2 = sin b cos psi. Each
secondary couple lies along one known direction (z x p1, resp. z2 x p2).
"""

import math
from typing import Any, NamedTuple

from ._backend import Real, namespace

_new_tuple = tuple.__new__  # skips NamedTuple's Python-level __new__


class JointResponse(NamedTuple):
    """Field names are the FMU's output names (models/universal_joint/README.md), in its
    order after the two angles, plus four extras."""

    output_speed: Any
    output_acceleration: Any
    cardan_error: Any
    speed_ratio: Any
    crosspiece_angular_velocity_1: Any
    crosspiece_angular_velocity_2: Any
    crosspiece_angular_velocity_3: Any
    crosspiece_torque_1: Any
    crosspiece_torque_2: Any
    crosspiece_torque_3: Any
    crosspiece_kinetic_energy: Any
    crosspiece_quaternion_0: Any
    crosspiece_quaternion_1: Any
    crosspiece_quaternion_2: Any
    crosspiece_quaternion_3: Any
    input_torque: Any
    input_yoke_moment: Any
    output_yoke_moment: Any
    # Extras: the torque tau2 . y the output yoke exerts about the bend hinge
    # (b' times it is the power that enters through the bending), and dOmega/dt.
    hinge_torque: Any
    crosspiece_angular_acceleration_1: Any
    crosspiece_angular_acceleration_2: Any
    crosspiece_angular_acceleration_3: Any


_BLOCK = 8192  # samples per pass on large arrays: the temporaries stay in cache


def joint_response(
    psi: Real,
    bend_angle: Real,
    input_speed: Real,
    input_acceleration: Real = 0.0,
    bend_angle_rate: Real = 0.0,
    bend_angle_acceleration: Real = 0.0,
    inertia: tuple[Real, Real, Real] = (0.0, 0.0, 0.0),
    load_torque: Real = 0.0,
    quaternion_sign: Real = 1.0,
) -> JointResponse:
    """All outputs at input-pin angle `psi`.

    Scalars or numpy arrays (broadcast) for every argument, including the three
    principal inertias. The quaternion has period 4 pi in psi: a caller passing
    psi reduced modulo 2 pi gives `quaternion_sign` = (-1)^(whole revolutions).
    """
    args = (
        psi,
        bend_angle,
        input_speed,
        input_acceleration,
        bend_angle_rate,
        bend_angle_acceleration,
        *inertia,
        load_torque,
        quaternion_sign,
    )
    xp = namespace(*args)
    if xp is not math and xp.broadcast(*args).size > 2 * _BLOCK:
        return _in_blocks(args)
    return _new_tuple(JointResponse, kernel(namespace(psi, bend_angle), *args))


def _in_blocks(args) -> JointResponse:
    """Evaluate a large broadcast in cache-sized blocks (1.5x faster than one
    pass over arrays of a million, and far less memory for the temporaries)."""
    import numpy as np

    arrays = [a.ravel() for a in np.broadcast_arrays(*(np.asarray(a, float) for a in args))]
    shape = np.broadcast_shapes(*(np.shape(a) for a in args))
    n = arrays[0].size
    out = np.empty((len(JointResponse._fields), n))
    for start in range(0, n, _BLOCK):
        block = slice(start, start + _BLOCK)
        out[:, block] = kernel(np, *(a[block] for a in arrays))
    return JointResponse(*(row.reshape(shape) for row in out))


def kernel(
    xp,
    psi,
    bend_angle,
    input_speed,
    input_acceleration,
    bend_angle_rate,
    bend_angle_acceleration,
    I1,
    I2,
    I3,
    load_torque,
    quaternion_sign,
):
    """`joint_response`'s fields, in its order, as a plain tuple; `xp` is `math`
    for floats (the FMU, once per step), numpy for arrays."""
    return kernel_at(
        xp, psi, xp.sin(bend_angle), xp.cos(bend_angle), input_speed, input_acceleration,
        bend_angle_rate, bend_angle_acceleration, I1, I2, I3, load_torque, quaternion_sign,
    )  # fmt: skip


def kernel_at(xp, psi, sb, cb, w1, a1, rb, ab, I1, I2, I3, load_torque, quaternion_sign):
    """`kernel` from the bend's sine `sb` and cosine `cb`: where the bend is
    fixed (a propshaft's), they are computed once, not at every step."""
    sh, ch, s, c, sb, cb, D, rD = pose_of(xp, psi, sb, cb)
    sc = s * c
    sbc = sb * c  # p1 . z2
    sbs = sb * s

    cardan_error = cardan_error_at(xp, s, c, sb, cb)
    speed_ratio = cb / D
    w2, a2, W1, W2, W3, dW1, dW2, dW3 = crosspiece_motion(s, c, sb, cb, D, rD, w1, a1, rb, ab)
    M1, M2, M3 = euler_moments(I1, I2, I3, W1, W2, W3, dW1, dW2, dW3)
    energy = 0.5 * (I1 * W1 * W1 + I2 * W2 * W2 + I3 * W3 * W3)

    # Quaternion of Rz(psi) Rx(rho); |rho| < 90 deg, so the half-angle formulas
    # need no branch.
    cos_half_rho = xp.sqrt(0.5 * (1.0 + cb / rD))
    sin_half_rho = sbs / rD / (2.0 * cos_half_rho)
    qc = quaternion_sign * ch
    qs = quaternion_sign * sh

    # Yoke reactions.
    Dd, B, input_torque = yoke_reactions(M1, M2, M3, s, c, sb, cb, rD, load_torque)
    input_moment = abs(B * sbs - M2 * cb) / rD
    output_moment = abs(Dd * sbc - M1 * rD)
    hinge_torque = M1 * s - Dd * sb * sc / rD

    return (
        w2,
        a2,
        cardan_error,
        speed_ratio,
        W1,
        W2,
        W3,
        M1,
        M2,
        M3,
        energy,
        qc * cos_half_rho,
        qc * sin_half_rho,
        qs * sin_half_rho,
        qs * cos_half_rho,
        input_torque,
        input_moment,
        output_moment,
        hinge_torque,
        dW1,
        dW2,
        dW3,
    )


def pose_of(xp, psi, sb, cb):
    """(sin psi/2, cos psi/2, sin psi, cos psi, sin b, cos b, D, sqrt D) from
    the bend's sine `sb` and cosine `cb`. Half angles first: the quaternion
    needs them, and sin/cos psi follow from them without two more
    trigonometric calls."""
    sh = xp.sin(0.5 * psi)
    ch = xp.cos(0.5 * psi)
    return (sh, ch) + pose_at(xp, 2.0 * sh * ch, (ch - sh) * (ch + sh), sb, cb)


def pose_at(xp, s, c, sb, cb):
    """`pose_of`'s (sin psi, cos psi, sin b, cos b, D, sqrt D) from psi's sine `s`
    and cosine `c`."""
    sbs = sb * s
    # D = 1 - (sin b cos psi)^2, written as a sum of squares: no cancellation
    # near the lock-up, where D -> cos^2 b.
    D = cb * cb + sbs * sbs
    return s, c, sb, cb, D, xp.sqrt(D)


def crosspiece_motion(s, c, sb, cb, D, rD, w1, a1, rb, ab):
    """(omega2, its rate, the crosspiece's angular velocity Omega and its rate
    dOmega/dt, components in C) at the pose `pose_of` gives."""
    sc = s * c
    sbc = sb * c
    sbs = sb * s
    ccb = cb * c
    # Products several terms share, each computed once (the same roundings:
    # IEEE multiplication is commutative, so w1 sbs is sbs w1 to the bit).
    w1cb = w1 * cb
    w1sbs = w1 * sbs
    a1cb = a1 * cb
    w1rbsb = w1 * rb * sb
    w2 = (w1cb + rb * sb * sc) / D
    D_rate = 2.0 * sbc * (w1sbs - ccb * rb)
    a2 = (
        a1cb - w1rbsb + ab * sb * sc + rb * rb * cb * sc + w1rbsb * (c - s) * (c + s) - w2 * D_rate
    ) / D
    W1 = w2 * sbc + rb * s
    W2 = w1sbs / rD
    W3 = w1cb / rD
    half_log_rate = 0.5 * D_rate / D
    dW1 = a2 * sbc + w2 * (cb * rb * c - w1sbs) + ab * s + rb * c * w1
    dW2 = (a1 * sbs + w1cb * rb * s + w1 * w1 * sbc) / rD - W2 * half_log_rate
    dW3 = (a1cb - w1 * sb * rb) / rD - W3 * half_log_rate
    return w2, a2, W1, W2, W3, dW1, dW2, dW3


def steady_crosspiece_motion(s, c, sb, cb, D, rD, w1, a1):
    """`crosspiece_motion` at a constant bend (rb = ab = 0), to the bit: its
    terms in rb and ab are exact zeros there, which IEEE arithmetic cannot
    drop by itself (0 x is not 0 for every x), so they are left out; the
    others keep their order. Only a zero's sign may differ."""
    sbc = sb * c
    sbs = sb * s
    w1cb = w1 * cb
    w1sbs = w1 * sbs
    a1cb = a1 * cb
    w2 = w1cb / D
    D_rate = 2.0 * sbc * w1sbs
    a2 = (a1cb - w2 * D_rate) / D
    W2 = w1sbs / rD
    W3 = w1cb / rD
    half_log_rate = 0.5 * D_rate / D
    dW1 = a2 * sbc - w2 * w1sbs
    dW2 = (a1 * sbs + w1 * w1 * sbc) / rD - W2 * half_log_rate
    dW3 = a1cb / rD - W3 * half_log_rate
    return w2, a2, w2 * sbc, W2, W3, dW1, dW2, dW3


def euler_moments(I1, I2, I3, W1, W2, W3, dW1, dW2, dW3):
    """The moments (M1, M2, M3) the yokes exert on the cross: Euler's equations."""
    return (
        I1 * dW1 + (I3 - I2) * W2 * W3,
        I2 * dW2 + (I1 - I3) * W3 * W1,
        I3 * dW3 + (I2 - I1) * W1 * W2,
    )


def yoke_reactions(M1, M2, M3, s, c, sb, cb, rD, load_torque):
    """(Dd, B, T1): tau2's and tau1's p3 parts and the input torque tau1 . z."""
    Dd = -(load_torque + M1 * (sb * c)) / rD
    B = M3 - Dd
    return Dd, B, (M2 * (sb * s) + B * cb) / rD


def cardan_error_at(xp, s, c, sb, cb):
    """The cardan error (output angle - input angle) at the pose `pose_of` gives:
    the atan of `cardan_tangent`."""
    return xp.atan(cardan_tangent(s, c, sb, cb))


def cardan_tangent(s, c, sb, cb):
    """The cardan error's tangent at the pose `pose_of` gives. 1 - cos b is
    written sin^2 b / (1 + cos b) for full relative precision at small bend;
    the denominator stays positive below 90 deg, so the cardan error never
    jumps branch."""
    return sb * sb / (1.0 + cb) * (s * c) / (cb * c * c + s * s)
