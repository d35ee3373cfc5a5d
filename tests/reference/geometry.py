"""Independent high-precision reference for the Cardan (Hooke) joint.

Everything here is derived from the *geometric construction* of the joint
(models/universal_joint/README.md, "Frames and angles"), never from the closed forms for
omega2, a2, Omega or Delta.  Derivatives are taken numerically with
``mpmath.diff`` at high working precision, and the torque path is solved as a
linear system with ``mpmath.lu_solve``.

Construction (fixed frame F, z = input shaft axis), at time t::

    psi  = input_angle(t) + yoke_phase
    b    = bend_angle(t)
    p1   = (cos psi, sin psi, 0)                 input-yoke pin
    z2   = (sin b, 0, cos b)                     output shaft axis
    p2   = unit(z2 x p1)                         output-yoke pin
    p3   = p1 x p2
    R    = [p1 p2 p3]                            cross frame C -> F
    u    = Ry(b)^T p2 = (-sin psi2, cos psi2, 0) output shaft pin, shaft frame
    psi2 = atan2(-u_x, u_y) + 2 pi k,  k chosen so |psi2 - psi| < pi
    gamma2 = psi2 - yoke_phase

Derived quantities (all by ``mpmath.diff`` of functions of t, so rates of the
bend angle are included automatically):

* output_speed / output_acceleration: first / second t-derivative of gamma2.
* speed_ratio: d gamma2 / d gamma1 with the bend angle frozen at b(t).
* crosspiece angular velocity: [Omega]x = R^T dR/dt (dR/dt elementwise);
  angular acceleration: d Omega / dt (nested numerical derivative).
* crosspiece torque: H_F = R diag(I) R^T omega_F (omega_F = R Omega),
  M_F = dH_F/dt numerically (nested), M = R^T M_F.  Euler's equations are
  *not* used.  E = 1/2 Omega . (I Omega).
* yoke reactions: tau1 + tau2 = M_F, tau1 . p1 = 0, tau2 . p2 = 0,
  -tau2 . z2 = load_torque (6x6 system, ``mpmath.lu_solve``).
  input_torque = tau1 . z; input_yoke_moment = |tau1 - (tau1.z) z|;
  output_yoke_moment = |tau2 - (tau2.z2) z2|; hinge_torque = tau2 . y.
* quaternion (scalar first) of R by Shepperd's method; sign such that
  q0 cos(psi/2) + q3 sin(psi/2) > 0 with the unreduced psi.  This is robust:
  Rz(psi)^T R is a rotation about x by the tilt angle theta of p2 out of the
  x-y plane, |theta| <= |b| < 90 deg, and the test quantity equals
  cos(theta/2) > 0.707.  The quaternion therefore has period 4 pi in psi.

Numerical accuracy
------------------
``mpmath.diff`` (default 'step' method) evaluates the function at
``workprec = (prec + 20) * (n + 1)`` bits with a step ``h = 2**-(prec + 10)``,
so both the truncation error (~h^2) and the cancellation error
(~2**-workprec / h**n) are far below 2**-prec; nested derivatives (angular
acceleration, torque) run the inner derivative at the outer working
precision.  The construction is memoised per (t, working precision) so the
nine matrix elements share the same function evaluations.

Measured with check_references.py (section A): dps=40 vs dps=60 on 6 cases
(time-varying bend angle with rate and acceleration, yoke phase 0, 0.2,
-0.7 and 90 deg, input angles up to ~1e3 rad, bend angles 5..80 deg, equal,
unequal and zero inertias, positive/negative/zero load torque): the largest
difference of any output, relative to max(|value|, 1), was 2.4e-39.  The
physical identities (Omega2^2 + Omega3^2 = omega1^2, Euler's equations vs
the dH/dt route, the power balance, quaternion -> R) hold to ~1e-41 at
dps=40.  The dps=40 results are therefore exact to double precision; the
float results carry only the final rounding (<= 0.5 ulp).  Cost: ~7 ms per
call at dps=40 (max ~12 ms; about the same at dps=60).

The callables ``input_angle`` and ``bend_angle`` must accept and return mpmath
numbers (polynomials with float coefficients are fine: floats are exact
binary numbers and are promoted to mpf).
"""

from mpmath import mp, mpf

try:
    from .mp_algebra import _cross, _dot, _matTvec, _matvec, _norm, _quaternion, _vee
except ImportError:  # imported as a top-level module (script use)
    from mp_algebra import _cross, _dot, _matTvec, _matvec, _norm, _quaternion, _vee

__all__ = ["geometric_reference", "geometric_reference_mp", "construct", "KEYS"]

KEYS = (
    "input_angle",
    "output_angle",
    "cardan_error",
    "output_speed",
    "output_acceleration",
    "speed_ratio",
    "crosspiece_angular_velocity_1",
    "crosspiece_angular_velocity_2",
    "crosspiece_angular_velocity_3",
    "crosspiece_angular_acceleration_1",
    "crosspiece_angular_acceleration_2",
    "crosspiece_angular_acceleration_3",
    "crosspiece_torque_1",
    "crosspiece_torque_2",
    "crosspiece_torque_3",
    "crosspiece_kinetic_energy",
    "crosspiece_quaternion_0",
    "crosspiece_quaternion_1",
    "crosspiece_quaternion_2",
    "crosspiece_quaternion_3",
    "input_torque",
    "input_yoke_moment",
    "output_yoke_moment",
    "hinge_torque",
)


# ---------------------------------------------------------- construction
def construct(psi, b):
    """Geometric construction at pin angle psi and bend angle b (mpf).

    Returns (R, psi2): R as a 3x3 nested list, R[i][j] = component i of
    column j (columns p1, p2, p3), and the output pin angle psi2 on the
    branch nearest psi.
    """
    zero = mpf(0)
    c, s = mp.cos_sin(psi)
    p1 = (c, s, zero)
    cb, sb = mp.cos_sin(b)
    z2 = (sb, zero, cb)
    v = _cross(z2, p1)
    n = _norm(v)
    p2 = (v[0] / n, v[1] / n, v[2] / n)
    p3 = _cross(p1, p2)
    R = [[p1[i], p2[i], p3[i]] for i in range(3)]
    # output-shaft frame: Ry(b) Rz(psi2); its pin Ry(b) Rz(psi2) (0,1,0) = p2
    ux = cb * p2[0] - sb * p2[2]  # (Ry(b)^T p2)_x = -sin psi2
    uy = p2[1]  # (Ry(b)^T p2)_y =  cos psi2
    a = mp.atan2(-ux, uy)
    k = mp.nint((psi - a) / (2 * mp.pi))
    psi2 = a + 2 * mp.pi * k
    return R, psi2


def geometric_reference(
    t, input_angle, bend_angle, yoke_phase=0.0, inertia=(0.0, 0.0, 0.0), load_torque=0.0, dps=40
):
    """Reference outputs of the joint at time t (see module docstring).

    input_angle(t), bend_angle(t): callables of an mpf time returning mpf.
    Returns a dict of Python floats (keys: ``KEYS``).
    """
    r = geometric_reference_mp(t, input_angle, bend_angle, yoke_phase, inertia, load_torque, dps)
    return {k: float(v) for k, v in r.items()}


def geometric_reference_mp(
    t, input_angle, bend_angle, yoke_phase=0.0, inertia=(0.0, 0.0, 0.0), load_torque=0.0, dps=40
):
    """As ``geometric_reference`` but returns the mpf values (dps digits)."""
    with mp.workdps(dps):
        t = mpf(t)
        phi = mpf(yoke_phase)
        I = tuple(mpf(x) for x in inertia)
        TL = mpf(load_torque)

        geo_cache = {}

        def geo(s):
            """(R, psi2) at time s, memoised per working precision."""
            key = (s, mp.prec)
            r = geo_cache.get(key)
            if r is None:
                psi = input_angle(s) + phi
                r = construct(psi, bend_angle(s))
                geo_cache[key] = r
            return r

        def R_elem(i, j):
            return lambda s: geo(s)[0][i][j]

        kin_cache = {}

        def kin(s):
            """(R, dR/dt, Omega, H_F) at time s, memoised."""
            key = (s, mp.prec)
            r = kin_cache.get(key)
            if r is None:
                R = geo(s)[0]
                Rd = [[mp.diff(R_elem(i, j), s) for j in range(3)] for i in range(3)]
                # S = R^T dR/dt
                S = [
                    [sum(R[k][i] * Rd[k][j] for k in range(3)) for j in range(3)] for i in range(3)
                ]
                Om = _vee(S)
                IOm = (I[0] * Om[0], I[1] * Om[1], I[2] * Om[2])
                # H_F = R diag(I) R^T omega_F, omega_F = R Omega
                omF = _matvec(R, Om)
                H = _matvec(R, tuple(I[k] * _matTvec(R, omF)[k] for k in range(3)))
                r = (R, Rd, Om, H, IOm)
                kin_cache[key] = r
            return r

        def gamma2(s):
            return geo(s)[1] - phi

        # --- angles and speeds
        g1 = input_angle(t)
        b = bend_angle(t)
        R, psi2 = geo(t)
        g2 = psi2 - phi
        w2 = mp.diff(gamma2, t)
        a2 = mp.diff(gamma2, t, 2)

        def gamma2_of_g1(g):
            return construct(g + phi, b)[1] - phi

        ratio = mp.diff(gamma2_of_g1, g1)

        # --- crosspiece kinematics
        _, _, Om, H, IOm = kin(t)
        Omd = tuple(mp.diff(lambda s, k=k: kin(s)[2][k], t) for k in range(3))
        MF = tuple(mp.diff(lambda s, k=k: kin(s)[3][k], t) for k in range(3))
        M = _matTvec(R, MF)
        E = _dot(Om, IOm) / 2

        # --- yoke reactions
        p1 = (R[0][0], R[1][0], R[2][0])
        p2 = (R[0][1], R[1][1], R[2][1])
        z2 = (mp.sin(b), mpf(0), mp.cos(b))
        A = mp.zeros(6, 6)
        rhs = mp.zeros(6, 1)
        for i in range(3):
            A[i, i] = 1
            A[i, i + 3] = 1
            rhs[i] = MF[i]
            A[3, i] = p1[i]
            A[4, i + 3] = p2[i]
            A[5, i + 3] = -z2[i]
        rhs[5] = TL
        x = mp.lu_solve(A, rhs)
        tau1 = (x[0], x[1], x[2])
        tau2 = (x[3], x[4], x[5])
        T1 = tau1[2]
        perp1 = (tau1[0], tau1[1], mpf(0))
        t2z = _dot(tau2, z2)
        perp2 = tuple(tau2[i] - t2z * z2[i] for i in range(3))

        # --- quaternion
        q = _quaternion(R)
        psi = g1 + phi
        if q[0] * mp.cos(psi / 2) + q[3] * mp.sin(psi / 2) < 0:
            q = tuple(-c for c in q)

        vals = (
            g1,
            g2,
            g2 - g1,
            w2,
            a2,
            ratio,
            Om[0],
            Om[1],
            Om[2],
            Omd[0],
            Omd[1],
            Omd[2],
            M[0],
            M[1],
            M[2],
            E,
            q[0],
            q[1],
            q[2],
            q[3],
            T1,
            _norm(perp1),
            _norm(perp2),
            tau2[1],
        )
        return dict(zip(KEYS, vals))
