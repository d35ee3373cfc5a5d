"""Internal-consistency checks of the reference implementations.

Checks only the references against themselves, against physical identities
and against the contract's own statements in docs/UniversalJoint/README.md
(section E). It never touches the production code. Collected by pytest through
tests/test_reference_checks.py (section D on a shorter horizon); the full run,
with the worst error of every check, from any directory and interpreter that
has the test dependencies:

    python tests/reference/check_references.py

Exits non-zero on failure.
"""

import math
import sys
import time
from pathlib import Path

import numpy as np
from mpmath import mp, mpf

if __package__ in (None, ""):
    # Run as a script: import `reference` as the package the tests import.
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from reference.geometry import KEYS, construct, geometric_reference, geometric_reference_mp  # noqa: E402
from reference.multibody import geometry_derivatives, simulate_multibody  # noqa: E402


class Checks:
    """Called as check(name, err, tol): err (a non-negative number) must be <= tol.
    Keeps the failures and the worst error per check name."""

    def __init__(self):
        self.failures = []
        self.worst = {}

    def __call__(self, name, err, tol):
        err = float(err)
        self.worst[name] = max(self.worst.get(name, 0.0), err)
        if not (err <= tol):
            self.failures.append("%s: %.3e > %.1e" % (name, err, tol))


def poly(c0, c1=0.0, c2=0.0):
    """c0 + c1 t + c2/2 t^2 and its derivative."""
    f = lambda t: c0 + c1 * t + c2 / 2 * t**2  # noqa: E731
    df = lambda t: c1 + c2 * t  # noqa: E731
    return f, df


def rot_from_quat(q):
    q0, q1, q2, q3 = q
    return [
        [1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
        [2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 - q0 * q1)],
        [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), 1 - 2 * (q1 * q1 + q2 * q2)],
    ]


# (t, input poly (g0, w0, a1), bend poly (b0, bd, bdd), phase, inertia, T_L)
CASES = [
    (0.37, (0.3, 10.0, 2.0), (0.5, 0.2, -0.2), 0.2, (0.01, 0.02, 0.015), 3.0),
    (0.0, (0.0, 0.5, 0.0), (math.pi / 6, 0, 0), 0.0, (0.026,) * 3, 0.0),
    (1.3, (1000.3, 7.0, -0.5), (0.09, 0.0, 0.0), math.pi / 2, (0.0, 0.0, 0.0), 12.0),
    (0.05, (-2.0, -30.0, 100.0), (1.3, -1.0, 4.0), -0.7, (0.3, 0.1, 0.25), -5.0),
    (2.0, (0.8, 3.0, 0.0), (0.7, 0.0, 0.0), 0.0, (0.013, 0.052, 0.013), 1.0),
    (0.5, (0.1, 10.0, 0.0), (math.radians(80), 0.0, 0.0), 0.4, (1.0, 2.0, 3.0), 2.0),
]


def section_a_precision(check):
    """dps=40 vs dps=60: the returned values agree far below 1e-13."""
    worst = 0.0
    times = []
    for t, ip, bp, ph, inert, TL in CASES:
        ia, _ = poly(*ip)
        ba, _ = poly(*bp)
        t0 = time.perf_counter()
        r40 = geometric_reference_mp(t, ia, ba, ph, inert, TL, dps=40)
        times.append(time.perf_counter() - t0)
        r60 = geometric_reference_mp(t, ia, ba, ph, inert, TL, dps=60)
        with mp.workdps(80):
            for k in KEYS:
                d = abs(r40[k] - r60[k]) / max(abs(r60[k]), 1)
                worst = max(worst, float(d))
    check("A dps40 vs dps60 (relative to max(|v|,1))", worst, 1e-30)
    print("A: max |dps40 - dps60| / max(|v|,1) = %.2e" % worst)
    print(
        "A: geometric_reference at dps=40: %.1f ms per call (max %.1f)"
        % (1e3 * np.mean(times), 1e3 * max(times))
    )


def section_b_identities(check):
    """Physical identities of the geometric reference."""
    for t, ip, bp, ph, inert, TL in CASES:
        ia, dia = poly(*ip)
        ba, dba = poly(*bp)
        r = geometric_reference_mp(t, ia, ba, ph, inert, TL, dps=40)
        with mp.workdps(40):
            w1 = mpf(dia(mpf(t)))
            bd = mpf(dba(mpf(t)))
            O = [r["crosspiece_angular_velocity_%d" % k] for k in (1, 2, 3)]
            Od = [r["crosspiece_angular_acceleration_%d" % k] for k in (1, 2, 3)]
            M = [r["crosspiece_torque_%d" % k] for k in (1, 2, 3)]
            I = [mpf(x) for x in inert]
            sc = max(abs(w1), 1)
            # Omega2^2 + Omega3^2 = omega1^2 (always)
            check("B Om2^2+Om3^2 = w1^2", abs(O[1] ** 2 + O[2] ** 2 - w1**2) / sc**2, 1e-30)
            w2 = r["output_speed"]
            if bd == 0:
                check(
                    "B Om1^2+Om3^2 = w2^2 (const bend)",
                    abs(O[0] ** 2 + O[2] ** 2 - w2**2) / sc**2,
                    1e-30,
                )
                check(
                    "B speed_ratio = w2/w1 (const bend)",
                    abs(r["speed_ratio"] * w1 - w2) / sc,
                    1e-30,
                )
            # Euler's equations (independent route from dH/dt)
            IO = [I[k] * O[k] for k in range(3)]
            OxIO = [
                O[1] * IO[2] - O[2] * IO[1],
                O[2] * IO[0] - O[0] * IO[2],
                O[0] * IO[1] - O[1] * IO[0],
            ]
            msc = max(max(I) * sc**2, mpf(1e-300))
            for k in range(3):
                check("B M = I dOm + Om x I Om", abs(M[k] - I[k] * Od[k] - OxIO[k]) / msc, 1e-30)
            # power balance on the cross:
            # T1 w1 - T_L w2 + bdot * hinge_torque = dE/dt
            Ef = lambda s: geometric_reference_mp(  # noqa: E731
                s, ia, ba, ph, inert, TL, dps=mp.dps
            )["crosspiece_kinetic_energy"]
            dE = mp.diff(Ef, mpf(t))
            P = r["input_torque"] * w1 - mpf(TL) * w2 + bd * r["hinge_torque"]
            psc = max(msc * sc, abs(TL) * sc, 1)
            check("B T1 w1 - TL w2 + bd*hinge = dE/dt", abs(P - dE) / psc, 1e-30)
            # quaternion: unit, reproduces R
            q = [r["crosspiece_quaternion_%d" % k] for k in range(4)]
            psi = ia(mpf(t)) + ph
            R, psi2 = construct(psi, ba(mpf(t)))
            Rq = rot_from_quat(q)
            check("B quaternion unit", abs(sum(x * x for x in q) - 1), 1e-35)
            check(
                "B quaternion -> R",
                max(abs(Rq[i][j] - R[i][j]) for i in range(3) for j in range(3)),
                1e-35,
            )
            check(
                "B quaternion sign",
                0 if q[0] * mp.cos(psi / 2) + q[3] * mp.sin(psi / 2) > 0.7 else 1,
                0,
            )
            # cardan error
            check(
                "B cardan_error = output - input",
                abs(r["cardan_error"] - (r["output_angle"] - r["input_angle"])),
                1e-35,
            )
            check("B |cardan_error| < pi/4", 0 if abs(r["cardan_error"]) < mp.pi / 4 else 1, 0)
            # reactions: constraints satisfied
    print("B: identities checked on %d cases" % len(CASES))


def section_c_sweeps(check):
    """Quaternion continuity and special values; float API."""
    # identity at psi = 0, b = 0
    r = geometric_reference(0.0, lambda t: 0 * t, lambda t: 0 * t)
    check(
        "C q(0) = (1,0,0,0)",
        max(
            abs(r["crosspiece_quaternion_0"] - 1),
            abs(r["crosspiece_quaternion_1"]),
            abs(r["crosspiece_quaternion_2"]),
            abs(r["crosspiece_quaternion_3"]),
        ),
        0,
    )
    check(
        "C float API keys",
        0 if set(r) == set(KEYS) and all(type(v) is float for v in r.values()) else 1,
        0,
    )
    # sweep psi over 0..4pi (+ a bit) with a varying bend: sign-continuous
    # quaternion, period 4 pi, continuous output angle
    prevq = None
    prevg2 = None
    n = 400
    for i in range(n + 1):
        t = 4.2 * math.pi * i / n
        ia = lambda s: mpf(1) * s  # noqa: E731
        ba = lambda s: 0.6 + 0.4 * mp.sin(s)  # noqa: E731
        r = geometric_reference(t, ia, ba, dps=20)
        q = np.array([r["crosspiece_quaternion_%d" % k] for k in range(4)])
        if prevq is not None:
            check("C quaternion sign-continuous (step dot)", 0 if q @ prevq > 0.9 else 1, 0)
            check("C output angle continuous", abs(r["output_angle"] - prevg2), 0.1)
        prevq = q
        prevg2 = r["output_angle"]
    # 4 pi periodicity, and sign change after 2 pi
    ia = lambda s: 0.4 + 0 * s  # noqa: E731
    ba = lambda s: 0.5 + 0 * s  # noqa: E731
    qa = [geometric_reference(0, ia, ba, yoke_phase=ph) for ph in (0.0, 2 * math.pi, 4 * math.pi)]
    qv = [np.array([x["crosspiece_quaternion_%d" % k] for k in range(4)]) for x in qa]
    check("C quaternion q(psi+2pi) = -q(psi)", np.max(np.abs(qv[1] + qv[0])), 1e-14)
    check("C quaternion q(psi+4pi) = q(psi)", np.max(np.abs(qv[2] - qv[0])), 1e-14)
    print("C: sweeps done")


def section_d_multibody(check, horizon=1.0):
    """Multibody simulation: energy, reaction consistency, cross-check."""
    # stencil derivatives vs mpmath.diff
    for g, b, ph in ((0.3, 0.5, 0.0), (2.1, 1.2, 0.4), (-7.0, 0.1, 1.5)):
        R, R1, R2, G = geometry_derivatives(g, b, ph)
        with mp.workdps(30):

            def el(i, j, s):
                return construct(s + ph, mpf(b))[0][i][j]

            def gg(s):
                return construct(s + ph, mpf(b))[1] - ph

            for i in range(3):
                for j in range(3):
                    d1 = mp.diff(lambda s: el(i, j, s), g)
                    d2 = mp.diff(lambda s: el(i, j, s), g, 2)
                    check(
                        "D stencil R' vs mp.diff (rel)",
                        abs(R1[i, j] - d1) / max(abs(d1), 1),
                        2.3e-16,
                    )
                    check(
                        "D stencil R'' vs mp.diff (rel)",
                        abs(R2[i, j] - d2) / max(abs(d2), 1),
                        2.3e-16,
                    )
            d1, d2 = mp.diff(gg, g), mp.diff(gg, g, 2)
            check("D stencil G' vs mp.diff (rel)", abs(G[1] - d1) / max(abs(d1), 1), 2.3e-16)
            check("D stencil G'' vs mp.diff (rel)", abs(G[2] - d2) / max(abs(d2), 1), 2.3e-16)

    runs = [
        dict(
            bend_angle=0.5,
            inertia=(0.01, 0.02, 0.015),
            J1=0.1,
            J2=0.2,
            motor_torque=lambda t: 1.0,
            external_torque=lambda t: 2.0,
            gamma1_0=0.0,
            omega1_0=10.0,
            yoke_phase=0.0,
        ),
        dict(
            bend_angle=math.pi / 6,
            inertia=(0.026, 0.026, 0.026),
            J1=0.05,
            J2=0.5,
            motor_torque=lambda t: 5 * math.sin(3 * t),
            external_torque=lambda t: 0.3 + 0.1 * t,
            gamma1_0=0.7,
            omega1_0=20.0,
            yoke_phase=math.pi / 2,
        ),
        dict(
            bend_angle=1.0,
            inertia=(0.0, 0.0, 0.0),
            J1=0.02,
            J2=0.03,
            motor_torque=lambda t: 0.0,
            external_torque=lambda t: 0.0,
            gamma1_0=-1.0,
            omega1_0=10.0,
            yoke_phase=0.25,
        ),
    ]
    for k, run in enumerate(runs):
        te = np.linspace(0.0, horizon, 201)
        t0 = time.perf_counter()
        r = simulate_multibody(te, diagnostics=True, **run)
        dt = time.perf_counter() - t0
        E = r["total_kinetic_energy"]
        W = r["external_work"]
        escale = max(np.max(np.abs(E)), np.max(np.abs(W)))
        eerr = np.max(np.abs(E - E[0] - W)) / escale
        check("D multibody energy balance (trajectory, rel)", eerr, 1e-10)
        print(
            "D: run %d: %.2f s for %g s simulated (%d RHS calls), energy "
            "balance %.1e relative" % (k, dt, horizon, r["nfev"], eerr)
        )
        J1, J2 = run["J1"], run["J2"]
        tsc = max(np.max(np.abs(r["input_torque"])), 1e-300)
        check(
            "D input_torque = T_motor - J1 a1",
            np.max(np.abs(r["input_torque"] - r["motor_torque"] + J1 * r["input_acceleration"]))
            / tsc,
            1e-14,
        )
        lsc = max(np.max(np.abs(r["load_torque"])), 1e-300)
        check(
            "D load_torque = J2 a2 + T_ext",
            np.max(np.abs(r["load_torque"] - J2 * r["output_acceleration"] - r["external_torque"]))
            / lsc,
            1e-14,
        )
        check("D linear-system residual (abs)", np.max(r["residual"]), 1e-12)
        if run["inertia"] == (0.0, 0.0, 0.0) and run["J2"] > 0:
            # massless cross: power through the joint is conserved
            P = r["input_torque"] * r["input_speed"] - r["load_torque"] * r["output_speed"]
            check(
                "D massless cross T1 w1 = TL w2",
                np.max(np.abs(P)) / np.max(np.abs(r["input_torque"] * r["input_speed"])),
                1e-13,
            )

        # cross-check against geometric_reference at sampled states
        worst = 0.0
        for n in range(0, len(te), 20):
            g1, w1 = r["input_angle"][n], r["input_speed"][n]
            a1 = r["input_acceleration"][n]
            ia = lambda s, g1=g1, w1=w1, a1=a1: g1 + w1 * s + a1 / 2 * s**2  # noqa
            ba = lambda s, b=run["bend_angle"]: b + 0 * s  # noqa
            g = geometric_reference(
                0.0, ia, ba, run["yoke_phase"], run["inertia"], r["load_torque"][n]
            )
            for key, scale in (
                ("output_angle", 1),
                ("output_speed", w1),
                ("output_acceleration", w1**2),
                ("input_torque", tsc),
                ("input_yoke_moment", tsc),
                ("output_yoke_moment", tsc),
            ):
                d = abs(g[key] - r[key][n]) / max(abs(scale), 1e-300)
                worst = max(worst, d)
        check("D multibody vs geometric_reference at same state", worst, 1e-13)
        print(
            "D: run %d: algebraic outputs vs geometric_reference at the "
            "same state: %.1e" % (k, worst)
        )


def section_e_contract(check):
    """The references against docs/UniversalJoint/README.md's own closed forms / numbers.

    (Contract cross-check; the references do not use these formulas.)
    """
    for t, ip, bp, ph, inert, TL in CASES:
        ia, dia = poly(*ip)
        ba, dba = poly(*bp)
        r = geometric_reference(t, ia, ba, ph, inert, TL)
        g1 = ia(t)
        psi = g1 + ph
        b, bd = ba(t), dba(t)
        w1 = dia(t)
        D = 1 - math.sin(b) ** 2 * math.cos(psi) ** 2
        w2 = (w1 * math.cos(b) + bd * math.sin(b) * math.sin(psi) * math.cos(psi)) / D
        Delta = math.atan(
            (1 - math.cos(b))
            * math.sin(psi)
            * math.cos(psi)
            / (math.cos(b) * math.cos(psi) ** 2 + math.sin(psi) ** 2)
        )
        check("E cardan_error vs PHYSICS Delta", abs(r["cardan_error"] - Delta), 1e-13)
        check(
            "E output_speed vs PHYSICS omega2", abs(r["output_speed"] - w2) / max(abs(w1), 1), 1e-13
        )
        check("E speed_ratio vs PHYSICS cos b / D", abs(r["speed_ratio"] - math.cos(b) / D), 1e-13)
    # seed 002: max cardan error at 10 deg is 0.43857 deg near gamma1 = 44.8
    b = math.radians(10)
    best = max(
        (
            geometric_reference(0, lambda s, g=g: mpf(g) + 0 * s, lambda s: mpf(b) + 0 * s)[
                "cardan_error"
            ],
            g,
        )
        for g in np.radians(np.arange(44.0, 46.0, 0.1))
    )
    check("E max cardan error 10 deg = 0.43857 deg", abs(math.degrees(best[0]) - 0.43857), 1e-5)
    # bound |Delta| <= atan((1 - cos b) / (2 sqrt(cos b))), attained
    from scipy.optimize import minimize_scalar

    for bdeg in (10, 20, 30, 60):
        b = math.radians(bdeg)
        f = lambda g, b=b: (
            -geometric_reference(  # noqa: E731
                0, lambda s: mpf(g) + 0 * s, lambda s: mpf(b) + 0 * s, dps=20
            )["cardan_error"]
        )
        m = minimize_scalar(f, bounds=(0.3, 1.2), method="bounded", options={"xatol": 1e-9})
        bound = math.atan((1 - math.cos(b)) / (2 * math.sqrt(math.cos(b))))
        check("E max |Delta| = PHYSICS bound", abs(-m.fun - bound), 1e-15)
    # constant omega1 and bend: M3 = (I2 - I1 - I3) Om1 Om2
    I = (0.011, 0.037, 0.019)
    r = geometric_reference(0.2, lambda s: 0.4 + 3 * s, lambda s: 0.7 + 0 * s, inertia=I)
    check(
        "E M3 = (I2-I1-I3) Om1 Om2 (const w1, b)",
        abs(
            r["crosspiece_torque_3"]
            - (I[1] - I[0] - I[2])
            * r["crosspiece_angular_velocity_1"]
            * r["crosspiece_angular_velocity_2"]
        ),
        1e-16,
    )
    # massless cross, constant bend: secondary couples
    for psi in (0.3, 1.1, 2.5, 4.0):
        b = 0.6
        r = geometric_reference(
            0, lambda s, p=psi: p + 10 * s, lambda s: b + 0 * s, load_torque=7.0
        )
        T1 = r["input_torque"]
        check(
            "E massless: input couple = T1 tan b |sin psi|",
            abs(r["input_yoke_moment"] - abs(T1) * math.tan(b) * abs(math.sin(psi))),
            1e-13,
        )
        psi2 = r["output_angle"]
        check(
            "E massless: output couple = TL tan b |cos psi2|",
            abs(r["output_yoke_moment"] - 7.0 * math.tan(b) * abs(math.cos(psi2))),
            1e-13,
        )
        check("E massless: T1 w1 = TL w2", abs(T1 * 10 - 7.0 * r["output_speed"]), 1e-12)
    # constant omega1 and bend, I2 = I1 + I3: M3 = 0
    r = geometric_reference(
        0.3, lambda s: 0.2 + 0.5 * s, lambda s: math.pi / 6 + 0 * s, inertia=(0.013, 0.026, 0.013)
    )
    check("E M3 = 0 when I2 = I1 + I3", abs(r["crosspiece_torque_3"]), 1e-16)
    print("E: contract cross-checks done")


SECTIONS = (
    section_a_precision,
    section_b_identities,
    section_c_sweeps,
    section_d_multibody,
    section_e_contract,
)


def main():
    t0 = time.perf_counter()
    check = Checks()
    for section in SECTIONS:
        section(check)
    print()
    for k in sorted(check.worst):
        print("  %-52s worst %.2e" % (k, check.worst[k]))
    print("total %.1f s" % (time.perf_counter() - t0))
    if check.failures:
        print("\nFAILED:")
        for f in check.failures:
            print("  " + f)
        sys.exit(1)
    print("\nALL CHECKS PASSED")


if __name__ == "__main__":
    main()
