"""Reference checks D and E: the multibody simulation and the contract."""

import math
import time

import numpy as np
from mpmath import mp, mpf

from reference.check_support import CASES, poly
from reference.geometry import construct, geometric_reference
from reference.multibody import geometry_derivatives, simulate_multibody


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
    """The references against models/universal_joint/README.md's own closed forms / numbers.

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
