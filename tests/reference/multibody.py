"""Forward-dynamics rigid multibody reference of a Cardan joint (constant bend).

Independent of models/universal_joint/README.md's torque-path formulas and of the production code.
Three rigid bodies, Newton-Euler equations about the (fixed) joint centre O,
constraint reactions as unknowns.

Bodies and loads (fixed frame F, z = input shaft axis, bend angle b const)
--------------------------------------------------------------------------
* input shaft: rotation gamma1 about z, axial inertia J1 (axisymmetric, so its
  angular momentum is J1 omega1 z), motor torque T_motor(t) z, torque -tau1
  from the cross, bearing couple B1 (B1 . z = 0).
* output shaft: rotation gamma2 about z2 = (sin b, 0, cos b), axial inertia J2,
  external torque -T_ext(t) z2, torque -tau2 from the cross, bearing couple
  B2 (B2 . z2 = 0).
* cross: centre fixed at O, principal inertias (I1, I2, I3) along (p1, p2,
  p3), R = [p1 p2 p3]; torque tau1 from the input yoke (tau1 . p1 = 0, ideal
  frictionless trunnion) and tau2 from the output yoke (tau2 . p2 = 0).

Kinematics (one degree of freedom, the input angle gamma1)
----------------------------------------------------------
The geometric construction (``geometry.construct``) gives R(gamma1) and
gamma2 = G(gamma1).  Its derivatives with respect to gamma1,
R', R'', G', G'', are obtained numerically by mpmath central differences
(the ``mpmath.diff`` scheme, shared stencil) at ``GEO_DPS`` = 20 digits
(results exact to double precision), never from closed forms.  With
omega1 = d gamma1/dt and a1 = d omega1/dt::

    omega2 = G' omega1,           a2 = G' a1 + G'' omega1^2
    Omega  = omega1 W,            W  = vee(R^T R')          (body components)
    dOmega/dt = a1 W + omega1^2 W',  W' = vee(R'^T R' + R^T R'')
    H_cross = R I Omega  (in F)
    dH_cross/dt = a1 (R I W) + omega1^2 (R' I W + R I W')

Newton-Euler system at a state (gamma1, omega1, t): 13 linear equations for
x = (a1, tau1[3], tau2[3], B1[3], B2[3])::

    J1 a1 z        = T_motor z - tau1 + B1          (3)   input shaft
    B1 . z         = 0                              (1)
    J2 a2 z2       = -T_ext z2 - tau2 + B2          (3)   output shaft
    B2 . z2        = 0                              (1)
    tau1 + tau2    = dH_cross/dt                    (3)   cross
    tau1 . p1 = 0,  tau2 . p2 = 0                   (2)   trunnions

solved with ``numpy.linalg.solve``.  The ODE  d(gamma1, omega1)/dt =
(omega1, a1)  is integrated with ``solve_ivp`` (DOP853, rtol = atol = 1e-12),
together with the quadrature  dW/dt = T_motor omega1 - T_ext omega2  (the
work of the external torques, used for the energy check).

Outputs: input_torque = tau1 . z = T_motor - J1 a1 (torque the input shaft
delivers to the joint), load_torque = -tau2 . z2 = J2 a2 + T_ext (torque the
joint delivers to the output shaft), input_yoke_moment = |B1| =
|tau1 - (tau1.z) z|, output_yoke_moment = |B2| = |tau2 - (tau2.z2) z2|.

Accuracy (measured with check_references.py): the reactions and
accelerations are computed algebraically from the state (gamma1, omega1, t).
The geometric derivatives agree with mpmath.diff to < 1e-16 relative and the
13x13 system is well conditioned (condition number < 35 up to b = 85 deg for
J1 = 0.1, J2 = 0.2, cross inertias ~0.01), so at a given state the
outputs are accurate to a few ulps: they agree with geometry.py's
geometric_reference (nested dH/dt route, 6x6 torque path) at the same state
(gamma1, omega1, a1, load torque) to <= 5e-16 relative, and the residuals
input_torque - (T_motor - J1 a1), load_torque - (J2 a2 + T_ext) are ~1e-15
relative.  The trajectory carries the integration error of DOP853 at
rtol=atol=1e-12 plus its 7th-order dense output at t_eval: over 1 s at
omega1 = 10..20 rad/s the state differs from an rtol=1e-14 run by ~6e-13
(angle) and ~5e-12 (speed) relative, the accelerations/torques by ~3e-11
relative, and the energy balance E(t) - E(0) = W(t) closes to ~1e-11 of the
energy scale.  To compare a production model with this reference at 1e-13
level, drive it with the *reference* state and compare the algebraic
outputs.

Cost: ~1 ms per right-hand-side evaluation (three mpmath constructions at
~270 bits); a 1 s simulation takes ~1-3 s (1000-2900 RHS calls depending on
speed and torque variation).  Precondition: |b| < 90 deg, J1 + J2 G'^2 +
(cross inertia term) > 0 (the system matrix is singular if every inertia is
zero).
"""

import numpy as np
from mpmath import mp, mpf
from scipy.integrate import solve_ivp

try:
    from .geometry import construct
except ImportError:  # imported as a top-level module (script use)
    from geometry import construct

__all__ = ["simulate_multibody", "state_quantities", "geometry_derivatives"]

GEO_DPS = 20


def geometry_derivatives(gamma1, bend_angle, yoke_phase=0.0, dps=GEO_DPS):
    """R, R', R'' (3x3 float arrays) and (G, G', G'') at input angle gamma1.

    Primes are derivatives with respect to gamma1 at constant bend angle of
    the geometric construction, by central differences in mpmath with the
    step and working precision of ``mpmath.diff`` (h = 2**-(prec+10),
    evaluation at 3*(prec+20) bits), applied to all ten quantities at once
    so that the three constructions (gamma1 - h, gamma1, gamma1 + h) are
    shared:  f' = (f(+h) - f(-h)) / 2h,  f'' = (f(+h) - 2 f(0) + f(-h)) / h^2.
    Truncation error ~2**-(2 prec), cancellation error ~2**-(prec+40):
    exact to double precision for dps >= 17 (checked against mpmath.diff in
    check_references.py).
    """
    with mp.workdps(dps):
        prec = mp.prec
        g = mpf(gamma1)
        b = mpf(bend_angle)
        phi = mpf(yoke_phase)
        h = mp.ldexp(1, -prec - 10)
        with mp.workprec(3 * (prec + 20)):
            v = {}
            for k in (-1, 0, 1):
                R, psi2 = construct(g + k * h + phi, b)
                v[k] = [R[i][j] for i in range(3) for j in range(3)]
                v[k].append(psi2 - phi)
            d1 = [(v[1][m] - v[-1][m]) / (2 * h) for m in range(10)]
            d2 = [(v[1][m] - 2 * v[0][m] + v[-1][m]) / (h * h) for m in range(10)]
        f0 = [float(x) for x in v[0]]
        f1 = [float(x) for x in d1]
        f2 = [float(x) for x in d2]
    R = np.array(f0[:9]).reshape(3, 3)
    R1 = np.array(f1[:9]).reshape(3, 3)
    R2 = np.array(f2[:9]).reshape(3, 3)
    return R, R1, R2, (f0[9], f1[9], f2[9])


def _vee(S):
    return 0.5 * np.array([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]])


def state_quantities(
    t, gamma1, omega1, bend_angle, inertia, J1, J2, motor_torque, external_torque, yoke_phase=0.0
):
    """Solve the Newton-Euler system at one state; returns a dict of floats."""
    R, R1, R2, (G0, G1, G2) = geometry_derivatives(gamma1, bend_angle, yoke_phase)
    I = np.asarray(inertia, dtype=float)
    sb, cb = np.sin(bend_angle), np.cos(bend_angle)
    z = np.array([0.0, 0.0, 1.0])
    z2 = np.array([sb, 0.0, cb])
    p1, p2 = R[:, 0], R[:, 1]
    W = _vee(R.T @ R1)
    W1 = _vee(R1.T @ R1 + R.T @ R2)
    hA = R @ (I * W)
    hB = R1 @ (I * W) + R @ (I * W1)
    Tm = float(motor_torque(t))
    Te = float(external_torque(t))
    w2 = omega1**2

    # unknowns: a1 | tau1 (1..3) | tau2 (4..6) | B1 (7..9) | B2 (10..12)
    A = np.zeros((13, 13))
    rhs = np.zeros(13)
    E3 = np.eye(3)
    # input shaft: J1 a1 z + tau1 - B1 = T_motor z
    A[0:3, 0] = J1 * z
    A[0:3, 1:4] = E3
    A[0:3, 7:10] = -E3
    rhs[0:3] = Tm * z
    A[3, 7:10] = z
    # output shaft: J2 (G1 a1 + G2 w1^2) z2 + tau2 - B2 = -T_ext z2
    A[4:7, 0] = J2 * G1 * z2
    A[4:7, 4:7] = E3
    A[4:7, 10:13] = -E3
    rhs[4:7] = -Te * z2 - J2 * G2 * w2 * z2
    A[7, 10:13] = z2
    # cross: tau1 + tau2 - a1 hA = w1^2 hB
    A[8:11, 0] = -hA
    A[8:11, 1:4] = E3
    A[8:11, 4:7] = E3
    rhs[8:11] = w2 * hB
    # trunnions
    A[11, 1:4] = p1
    A[12, 4:7] = p2
    x = np.linalg.solve(A, rhs)
    a1 = x[0]
    tau1, tau2, B1, B2 = x[1:4], x[4:7], x[7:10], x[10:13]
    Om = omega1 * W
    return dict(
        input_acceleration=a1,
        output_angle=G0,
        output_speed=G1 * omega1,
        output_acceleration=G1 * a1 + G2 * w2,
        motor_torque=Tm,
        external_torque=Te,
        input_torque=float(tau1 @ z),
        load_torque=float(-(tau2 @ z2)),
        input_yoke_moment=float(np.linalg.norm(B1)),
        output_yoke_moment=float(np.linalg.norm(B2)),
        tau1=tau1,
        tau2=tau2,
        B1=B1,
        B2=B2,
        crosspiece_angular_velocity=Om,
        crosspiece_kinetic_energy=float(0.5 * Om @ (I * Om)),
        residual=float(np.max(np.abs(A @ x - rhs))),
    )


def simulate_multibody(
    t_eval,
    bend_angle,
    inertia,
    J1,
    J2,
    motor_torque,
    external_torque,
    gamma1_0=0.0,
    omega1_0=10.0,
    yoke_phase=0.0,
    diagnostics=False,
):
    """Integrate the joint from t_eval[0] and return outputs at t_eval.

    bend_angle: constant (rad); inertia: (I1, I2, I3) of the cross;
    J1, J2: axial inertias of the shafts; motor_torque(t), external_torque(t):
    callables of float t.  Returns a dict of numpy arrays with keys time,
    input_angle, input_speed, input_acceleration, output_angle, output_speed,
    output_acceleration, motor_torque, input_torque, load_torque,
    input_yoke_moment, output_yoke_moment.  With diagnostics=True also
    external_torque, crosspiece_kinetic_energy, total_kinetic_energy,
    external_work (integral of T_motor omega1 - T_ext omega2) and residual.
    """
    t_eval = np.asarray(t_eval, dtype=float)
    args = (bend_angle, inertia, J1, J2, motor_torque, external_torque, yoke_phase)

    def rhs(t, y):
        q = state_quantities(t, y[0], y[1], *args)
        return [
            y[1],
            q["input_acceleration"],
            q["motor_torque"] * y[1] - q["external_torque"] * q["output_speed"],
        ]

    sol = solve_ivp(
        rhs,
        (t_eval[0], t_eval[-1]),
        [float(gamma1_0), float(omega1_0), 0.0],
        method="DOP853",
        rtol=1e-12,
        atol=1e-12,
        t_eval=t_eval,
    )
    if not sol.success:
        raise RuntimeError(sol.message)

    keys = (
        "input_acceleration",
        "output_angle",
        "output_speed",
        "output_acceleration",
        "motor_torque",
        "input_torque",
        "load_torque",
        "input_yoke_moment",
        "output_yoke_moment",
    )
    extra = ("external_torque", "crosspiece_kinetic_energy", "residual")
    out = {k: np.empty(len(t_eval)) for k in keys + extra}
    for n, t in enumerate(sol.t):
        q = state_quantities(t, sol.y[0, n], sol.y[1, n], *args)
        for k in keys + extra:
            out[k][n] = q[k]
    res = dict(time=sol.t.copy(), input_angle=sol.y[0].copy(), input_speed=sol.y[1].copy())
    for k in keys:
        res[k] = out[k]
    if diagnostics:
        for k in extra:
            res[k] = out[k]
        res["total_kinetic_energy"] = (
            0.5 * J1 * res["input_speed"] ** 2
            + 0.5 * J2 * res["output_speed"] ** 2
            + out["crosspiece_kinetic_energy"]
        )
        res["external_work"] = sol.y[2].copy()
        res["nfev"] = sol.nfev
    return res
