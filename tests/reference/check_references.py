"""Internal-consistency checks of the reference implementations.

Checks only the references against themselves, against physical identities
and against the contract's own statements in models/universal_joint/README.md
(section E). It never touches the production code. Collected by pytest through
tests/unit/test_reference_checks.py (section D on a shorter horizon); the full run,
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

from reference.check_dynamics import section_d_multibody, section_e_contract  # noqa: E402
from reference.check_support import CASES, Checks, poly, rot_from_quat  # noqa: E402
from reference.geometry import KEYS, construct, geometric_reference, geometric_reference_mp  # noqa: E402


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
