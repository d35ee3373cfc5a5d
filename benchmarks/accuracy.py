"""2. Accuracy after 1 s against Tătaru's numerical method (the seed's ODE under RK4).

Exact values: the closed form atan(tan psi / cos b) - psi at 40 digits (mpmath),
another formula text than the FMU's.
"""

import math
import statistics
import time

from .timing import StepClock, in_fresh_process, met, us

SEED_SPEED = 10.0  # Tataru: omega1 = 10 rad/s for 1 s
SEED_BENDS = (("2π/7", 2 * math.pi / 7), ("2π/5", 2 * math.pi / 5))
ACCURACY_STEPS = (1e-1, 1e-2, 1e-3, 1e-4)
ANGLE_ERROR_GOAL = 1e-12
RK4_FACTOR_GOAL = 1e6


def worker_accuracy(unzipped):
    """The FMU's output angle and speed after 1 s of Tataru's runs, at each step."""
    from fmpy import simulate_fmu

    runs = []
    for label, bend in SEED_BENDS:
        for step in ACCURACY_STEPS:
            clock = StepClock()
            result = simulate_fmu(
                unzipped,
                stop_time=1.0,
                output_interval=step,
                start_values={"input_speed": SEED_SPEED, "bend_angle": bend},
                output=["output_angle", "output_speed"],
                step_finished=clock,
            )
            last = result[-1]
            runs.append(
                {
                    "bend": label,
                    "step": step,
                    "time": float(last["time"]),
                    "angle": float(last["output_angle"]),
                    "speed": float(last["output_speed"]),
                    "wall": clock.per_step()["wall"],
                }
            )
    return {"runs": runs}


def tataru_rates(state, sin2, cos_bend):
    """The seed's system (eqs. 8-12) at constant input speed: (w1, w3, phi1, phi3)'."""
    w1, w3, phi1, _ = state
    cos_phi = math.cos(phi1)
    D = 1.0 - sin2 * cos_phi * cos_phi
    B = -(sin2 * cos_bend * math.sin(2.0 * phi1) / (D * D)) * w1  # eq. (9)
    return (0.0, B * w1, w1, w3)


def rk4_tataru(bend, step, stop_time=1.0):
    """Classical RK4 from phi1 = phi3 = 0 and w3 = w1 / cos(bend), the seed's start."""
    sin2, cos_bend = math.sin(bend) ** 2, math.cos(bend)
    state = (SEED_SPEED, SEED_SPEED / cos_bend, 0.0, 0.0)
    steps = round(stop_time / step)
    h = stop_time / steps
    for _ in range(steps):
        k1 = tataru_rates(state, sin2, cos_bend)
        k2 = tataru_rates([s + 0.5 * h * k for s, k in zip(state, k1)], sin2, cos_bend)
        k3 = tataru_rates([s + 0.5 * h * k for s, k in zip(state, k2)], sin2, cos_bend)
        k4 = tataru_rates([s + h * k for s, k in zip(state, k3)], sin2, cos_bend)
        state = tuple(
            s + h / 6.0 * (a + 2.0 * b + 2.0 * c + d)
            for s, a, b, c, d in zip(state, k1, k2, k3, k4)
        )
    return state


def exact_output(bend, at_time):
    """Output angle and speed at `at_time` (a double, taken exactly), at 40 digits,
    by atan(tan psi / cos b) - psi on the principal branch (models/universal_joint/README.md)."""
    import mpmath

    with mpmath.workdps(40):
        beta = mpmath.mpf(bend)
        psi = mpmath.mpf(SEED_SPEED) * mpmath.mpf(at_time)
        reduced = psi - mpmath.pi * mpmath.nint(psi / mpmath.pi)
        delta = mpmath.atan(mpmath.tan(reduced) / mpmath.cos(beta)) - reduced
        D = 1 - mpmath.sin(beta) ** 2 * mpmath.cos(psi) ** 2
        return psi + delta, SEED_SPEED * mpmath.cos(beta) / D


def rk4_cost_per_step(bend, step):
    start = time.perf_counter()
    rk4_tataru(bend, step)
    return (time.perf_counter() - start) / round(1.0 / step)


def accuracy(joint):
    bends = dict(SEED_BENDS)
    rows = []
    for run in in_fresh_process("accuracy", unzipped=joint)["runs"]:
        bend, step = bends[run["bend"]], run["step"]
        _, w3, _, phi3 = rk4_tataru(bend, step)
        exact_angle, exact_speed = exact_output(bend, 1.0)
        # The FMU against the exact value at the communication point it reached.
        fmu_angle, fmu_speed = exact_output(bend, run["time"])
        rows.append(
            {
                "bend": run["bend"],
                "step": step,
                "fmu_wall": run["wall"],
                "fmu_angle": abs(float(run["angle"] - fmu_angle)),
                "fmu_speed": abs(float(run["speed"] - fmu_speed)),
                "rk4_angle": abs(float(phi3 - exact_angle)),
                "rk4_speed": abs(float(w3 - exact_speed)),
            }
        )
    finest = min(ACCURACY_STEPS)
    return {
        "rows": rows,
        "rk4_wall": rk4_cost_per_step(SEED_BENDS[0][1], finest),
        "fmu_wall": statistics.median(r["fmu_wall"] for r in rows if r["step"] == finest),
    }


def accuracy_rows(acc):
    worst = max(r["fmu_angle"] for r in acc["rows"])
    at_1e2 = [r for r in acc["rows"] if r["step"] == 1e-2]
    # An exact FMU result (error 0) counts as one ulp of the angle.
    factor = min(r["rk4_angle"] / max(r["fmu_angle"], 2.0**-52 * 10) for r in at_1e2)
    return [
        f"| 2. FMU output angle error after 1 s, worst of both bends, steps 1e-1…1e-4 s | "
        f"{worst:.1e} rad | ≤ {ANGLE_ERROR_GOAL:.0e} rad | {met(worst <= ANGLE_ERROR_GOAL)} |",
        f"| 2. RK4 (Tătaru's ODE) angle error ÷ FMU's at 1e-2 s, smaller of both bends | "
        f"{factor:.1e} | ≥ {RK4_FACTOR_GOAL:.0e} | {met(factor >= RK4_FACTOR_GOAL)} |",
        f"| 2. cost per step at 1e-4 s: RK4 in Python vs FMU under `simulate_fmu` | "
        f"RK4 {us(acc['rk4_wall'])}, FMU {us(acc['fmu_wall'])} | (context) | |",
    ]


def accuracy_table(acc):
    lines = [
        "| bend | step (s) | FMU angle error (rad) | RK4 angle error (rad) | "
        "FMU speed error (rad/s) | RK4 speed error (rad/s) |",
        "|---|---|---|---|---|---|",
    ]
    lines += [
        f"| {r['bend']} | {r['step']:.0e} | {r['fmu_angle']:.1e} | {r['rk4_angle']:.1e} "
        f"| {r['fmu_speed']:.1e} | {r['rk4_speed']:.1e} |"
        for r in acc["rows"]
    ]
    return "\n".join(lines)
