"""Tătaru's cardanic-transmission figures (seed 003), co-simulated with the FMU.

omega1 = 10 rad/s for 1 s at alpha = 2 pi/7 and 2 pi/5 (one FMU run each): the
angular speeds omega1, omega3 and angles phi1, phi3 against time and against
the leading element's angle phi1 (his figs. 2-13), with his extremes
omega3min = omega1 cos(alpha) at phi1 = pi/2, 3 pi/2 and
omega3max = omega1 / cos(alpha) at phi1 = 0, pi, 2 pi as dashed lines, and his
"average" (32)-(35), omega1 (1 + cos^2 alpha) / (2 cos alpha), dotted.

The samples fall exactly on phi1 = k pi/2 (the communication step divides a
quarter turn), so the extremes are read off the FMU's samples, not interpolated.
Tătaru's average is the mean of the two extremes; the time-mean of omega3 over
whole half-turns is omega1 itself (the output keeps pace with the input), which
the script prints as well.

    python build_fmu.py && python examples/seed_tataru.py
"""

import math
import sys

import numpy as np
from _seed_support import Outputs, parse_args, pyplot, run
from _support import run_example

INPUT_SPEED = 10.0  # rad/s
DURATION = 1.0  # s
ALPHAS = {"2pi_7": (2 * math.pi / 7, "2π/7"), "2pi_5": (2 * math.pi / 5, "2π/5")}
RECORDED = ["input_angle", "input_speed", "output_angle", "output_speed"]


def extremes(alpha):
    low, high = INPUT_SPEED * math.cos(alpha), INPUT_SPEED / math.cos(alpha)
    return low, high, INPUT_SPEED * (1 + math.cos(alpha) ** 2) / (2 * math.cos(alpha))


def plot(plt, r, alpha, label):
    low, high, middle = extremes(alpha)
    t, phi1 = r["time"], r["input_angle"]
    quarter_turns = np.arange(0, phi1[-1] + 1e-9, math.pi / 2)
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    for ax, abscissa, xlabel in (
        (axes[0, 0], t, "time t [s]"),
        (axes[0, 1], phi1, "leading element angle $\\varphi_1$ [rad]"),
    ):
        ax.plot(
            abscissa,
            r["input_speed"],
            color="tab:blue",
            lw=1.5,
            label="$\\omega_1$ (leading element)",
        )
        ax.plot(
            abscissa,
            r["output_speed"],
            color="tab:red",
            lw=1.5,
            label="$\\omega_3$ (led element), FMU",
        )
        ax.axhline(
            high, color="k", ls="--", lw=1, label=f"$\\omega_1/\\cos\\alpha$ = {high:.4f} rad/s"
        )
        ax.axhline(
            low, color="k", ls="-.", lw=1, label=f"$\\omega_1\\cos\\alpha$ = {low:.4f} rad/s"
        )
        ax.axhline(
            middle,
            color="tab:gray",
            ls=":",
            lw=1.2,
            label=f"$\\omega_1(1+\\cos^2\\alpha)/(2\\cos\\alpha)$ = {middle:.4f} rad/s",
        )
        at = quarter_turns if abscissa is phi1 else quarter_turns / INPUT_SPEED
        ax.plot(
            at,
            np.where(np.arange(len(at)) % 2 == 0, high, low),
            "ko",
            mfc="white",
            ms=5,
            label="extremes at $\\varphi_1 = k\\pi/2$ (Tătaru)",
        )
        ax.set_xlabel(xlabel)
        ax.set_ylabel("angular speed [rad/s]")
        ax.set_ylim(0, high * 1.65)
        ax.legend(loc="upper right", fontsize=7.5)
    for ax, abscissa, xlabel in (
        (axes[1, 0], t, "time t [s]"),
        (axes[1, 1], phi1, "leading element angle $\\varphi_1$ [rad]"),
    ):
        ax.plot(abscissa, phi1, color="tab:blue", lw=1.5, label="$\\varphi_1$ (leading element)")
        ax.plot(
            abscissa,
            r["output_angle"],
            color="tab:red",
            lw=1.5,
            label="$\\varphi_3$ (led element), FMU",
        )
        ax.set_xlabel(xlabel)
        ax.set_ylabel("angle [rad]")
        ax.legend(loc="upper left")
    fig.suptitle(
        f"Tătaru: $\\omega_1$ = {INPUT_SPEED:g} rad/s for {DURATION:g} s, "
        f"$\\alpha$ = {label} ({math.degrees(alpha):.1f}°)",
        fontsize=12,
    )
    return fig


def main(argv=None):
    args = parse_args(__doc__, argv)
    out = Outputs(args.out)
    plt = pyplot()
    steps_per_quarter_turn = 10 if args.quick else 100
    interval = math.pi / 2 / INPUT_SPEED / steps_per_quarter_turn
    summary = []
    for name, (alpha, label) in ALPHAS.items():
        r = run(
            args.fmu, DURATION, interval, output=RECORDED, input_speed=INPUT_SPEED, bend_angle=alpha
        )
        out.csv(
            f"seed_tataru_alpha_{name}",
            {
                "time_s": r["time"],
                "input_angle_rad": r["input_angle"],
                "input_speed_rad_s": r["input_speed"],
                "output_angle_rad": r["output_angle"],
                "output_speed_rad_s": r["output_speed"],
            },
        )
        out.figure(f"seed_tataru_alpha_{name}", plot(plt, r, alpha, label))
        summary.append((label, alpha, r))

    out.report()
    for label, alpha, r in summary:
        low, high, middle = extremes(alpha)
        w3 = r["output_speed"]
        at_max = r["input_angle"][np.isclose(w3, w3.max(), rtol=1e-12, atol=0)] / (math.pi / 2)
        at_min = r["input_angle"][np.isclose(w3, w3.min(), rtol=1e-12, atol=0)] / (math.pi / 2)
        half_turns = math.floor(r["input_angle"][-1] / math.pi)
        k = int(np.argmin(np.abs(r["input_angle"] - half_turns * math.pi)))
        time_mean = r["output_angle"][k] / r["time"][k]
        print(
            f"alpha = {label}: omega3 max {w3.max():.12f} (omega1/cos a = {high:.12f}, "
            f"rel {w3.max() / high - 1:+.1e}) at phi1 = {np.round(at_max, 6).tolist()} x pi/2; "
            f"min {w3.min():.12f} (omega1 cos a = {low:.12f}, rel {w3.min() / low - 1:+.1e}) "
            f"at phi1 = {np.round(at_min, 6).tolist()} x pi/2"
        )
        print(
            f"    mean of the extremes {(w3.max() + w3.min()) / 2:.12f} rad/s (Tătaru (35): "
            f"{middle:.12f}); time-mean of omega3 over {half_turns} half-turns "
            f"{time_mean:.12f} rad/s = omega1"
        )


if __name__ == "__main__":
    sys.exit(run_example(main))
