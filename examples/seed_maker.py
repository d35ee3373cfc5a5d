"""The joint maker's kinematics figures 10-13 (seed 002), co-simulated with the FMU.

Fig. 10: output angle alpha2 vs input angle alpha1 (synchronous line A, curve B).
Fig. 11: cardan error (twist-angle difference) for bend angles 10/20/30 deg with
the maker's maxima +-0.438, +-1.782, +-4.117 deg at 44.8, 44.1, 42.9 deg marked,
and the stationary line D through the maxima of every bend angle.
Figs. 12, 13: the largest cardan error and the degree of unevenness
u = (omega2max - omega2min) / omega1 vs bend angle, against the maker's
closed forms atan((1 - cos b) / (2 sqrt(cos b))) and tan b sin b.

One FMU run per bend angle (omega1 = 1 rad/s over half a turn, so time in s
reads as input angle in rad). The maxima are refined by a parabola through the
three largest samples. The maker's table mixes truncation (10 deg: 0.43856 ->
0.438) and rounding (20 deg: 1.78168 -> 1.782), so both readings are printed.

    python build_fmu.py && python examples/seed_maker.py
"""

import math
import sys

import numpy as np
from _seed_support import COLORS, Outputs, parabola_peak, parse_args, pyplot, run
from _support import run_example

from cardan_joint.units import RAD_TO_DEG

# (bend angle, largest cardan error, at input angle), all deg, as printed by the maker.
MAKER_TABLE = ((10, 0.438, 44.8), (20, 1.782, 44.1), (30, 4.117, 42.9))
CURVE_B_BENDS_DEG = (30, 60)
INPUT_SPEED = 1.0
SAMPLE_STEP = math.pi / 360  # 0.5 deg of input angle: the parabola then locates 1e-3 deg


def maker_max_error(bend):
    return math.atan((1 - math.cos(bend)) / (2 * math.sqrt(math.cos(bend))))


def maker_unevenness(bend):
    return np.tan(bend) * np.sin(bend)


def half_turn(fmu, bend_deg):
    return run(
        fmu,
        math.pi / INPUT_SPEED,
        SAMPLE_STEP / INPUT_SPEED,
        input_speed=INPUT_SPEED,
        bend_angle=math.radians(bend_deg),
    )


def truncated(value, digits=3):
    return math.floor(value * 10**digits) / 10**digits


def main(argv=None):
    args = parse_args(__doc__, argv)
    out = Outputs(args.out)
    plt = pyplot()

    # Fig. 10 needs a whole turn.
    whole_turns = {
        b: run(
            args.fmu,
            2 * math.pi,
            SAMPLE_STEP * (4 if args.quick else 2),
            input_speed=INPUT_SPEED,
            bend_angle=math.radians(b),
        )
        for b in CURVE_B_BENDS_DEG
    }
    sweep_step = 5.0 if args.quick else 2.5
    sweep_bends = np.arange(0.0, 45.0 + sweep_step / 2, sweep_step)
    sweep = {float(b): half_turn(args.fmu, b) for b in sweep_bends}
    table_runs = {b: sweep[float(b)] for b, _, _ in MAKER_TABLE}

    # Fig. 10: output angle vs input angle.
    first = next(iter(whole_turns.values()))
    out.csv(
        "seed_maker_output_angle",
        dict(
            input_angle_deg=first["input_angle"] * RAD_TO_DEG,
            **{
                f"output_angle_deg_beta{b}": r["output_angle"] * RAD_TO_DEG
                for b, r in whole_turns.items()
            },
        ),
    )
    fig, ax = plt.subplots(figsize=(7, 6))
    ax.plot(
        first["input_angle"] * RAD_TO_DEG,
        first["input_angle"] * RAD_TO_DEG,
        "k--",
        lw=1.2,
        label="A: synchronous line $\\alpha_2 = \\alpha_1$",
    )
    for (b, r), color in zip(whole_turns.items(), COLORS[1:]):
        ax.plot(
            r["input_angle"] * RAD_TO_DEG,
            r["output_angle"] * RAD_TO_DEG,
            color=color,
            lw=1.5,
            label=f"B: FMU, $\\beta$ = {b}°",
        )
    ax.set_xlabel("input (drive) shaft angle $\\alpha_1$ [deg]")
    ax.set_ylabel("output (driven) shaft angle $\\alpha_2$ [deg]")
    ax.set_xticks(range(0, 361, 45))
    ax.set_yticks(range(0, 361, 45))
    ax.set_xlim(0, 360)
    ax.set_ylim(0, 360)
    ax.set_title(
        "Maker fig. 10: $\\alpha_2$ = arctan(tan $\\alpha_1$ / cos $\\beta$), continued",
        fontsize=11,
    )
    ax.legend(loc="upper left")
    out.figure("seed_maker_output_angle", fig)

    # Maxima of each bend angle: the stationary line D and figs. 12/13.
    peaks = {b: parabola_peak(r["input_angle"], r["cardan_error"]) for b, r in sweep.items()}
    unevenness = {
        b: (r["output_speed"].max() - r["output_speed"].min()) / INPUT_SPEED
        for b, r in sweep.items()
    }
    out.csv(
        "seed_maker_maxima",
        {
            "bend_angle_deg": [b for b, _, _ in MAKER_TABLE],
            "max_cardan_error_deg": [peaks[b][1] * RAD_TO_DEG for b, _, _ in MAKER_TABLE],
            "at_input_angle_deg": [peaks[b][0] * RAD_TO_DEG for b, _, _ in MAKER_TABLE],
            "sampled_max_cardan_error_deg": [
                table_runs[b]["cardan_error"].max() * RAD_TO_DEG for b, _, _ in MAKER_TABLE
            ],
            "sampled_min_cardan_error_deg": [
                table_runs[b]["cardan_error"].min() * RAD_TO_DEG for b, _, _ in MAKER_TABLE
            ],
        },
    )

    # Fig. 11: cardan error vs input angle.
    out.csv(
        "seed_maker_cardan_error",
        dict(
            input_angle_deg=table_runs[10]["input_angle"] * RAD_TO_DEG,
            **{
                f"cardan_error_deg_beta{b}": r["cardan_error"] * RAD_TO_DEG
                for b, r in table_runs.items()
            },
        ),
    )
    fig, ax = plt.subplots(figsize=(8, 6))
    for (b, printed, at), color, curve in zip(MAKER_TABLE, COLORS, "ABC"):
        r = table_runs[b]
        ax.plot(
            r["input_angle"] * RAD_TO_DEG,
            r["cardan_error"] * RAD_TO_DEG,
            color=color,
            lw=1.5,
            label=f"{curve}: FMU, $\\beta$ = {b}°",
        )
        for sign in (1, -1):
            location = at if sign > 0 else 180 - at
            ax.plot(
                location,
                sign * printed,
                "o",
                color=color,
                mfc="white",
                mew=1.5,
                ms=7,
                label="maker's $\\Delta\\alpha_{max}$ and location"
                if (b, sign) == (30, 1)
                else None,
            )
            ax.annotate(
                f"{sign * printed:+.3f}° at {location:.1f}°",
                (location, sign * printed),
                xytext=(10, 9 * sign),
                textcoords="offset points",
                fontsize=8,
                color=color,
                va="center",
            )
    # A straight joint has no maximum to locate; past 35 deg the line leaves the plotted range.
    locus_bends = [b for b in sweep if 0 < b <= 35]
    at_deg = np.array([peaks[b][0] for b in locus_bends]) * RAD_TO_DEG
    height_deg = np.array([peaks[b][1] for b in locus_bends]) * RAD_TO_DEG
    ax.plot(
        at_deg,
        height_deg,
        "k:",
        lw=1.2,
        label="D: stationary line of $\\Delta\\alpha_{max}$ "
        f"(FMU, $\\beta$ = {locus_bends[0]:g}..{locus_bends[-1]:g}°)",
    )
    ax.plot(180 - at_deg, -height_deg, "k:", lw=1.2)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlabel("input (drive) shaft angle $\\alpha_1$ [deg]")
    ax.set_ylabel("cardan error $\\Delta\\alpha = \\alpha_2 - \\alpha_1$ [deg]")
    ax.set_xticks(range(0, 181, 15))
    ax.set_xlim(0, 180)
    ax.set_title("Maker fig. 11: cardan error (twist-angle difference)", fontsize=11)
    ax.legend(loc="upper right")
    out.figure("seed_maker_cardan_error", fig)

    # Figs. 12 and 13: amplitude of the cardan error and degree of unevenness vs bend angle.
    bends_deg = np.array(list(sweep))
    amplitude_deg = np.array([peaks[b][1] for b in sweep]) * RAD_TO_DEG
    u = np.array([unevenness[b] for b in sweep])
    out.csv(
        "seed_maker_amplitude_unevenness",
        {
            "bend_angle_deg": bends_deg,
            "max_cardan_error_deg": amplitude_deg,
            "at_input_angle_deg": np.array([peaks[b][0] if b else math.nan for b in sweep])
            * RAD_TO_DEG,
            "unevenness": u,
        },
    )
    fine = np.radians(np.linspace(0, bends_deg[-1], 200))
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.8))
    left.plot(bends_deg, amplitude_deg, "o", color="tab:blue", ms=5, label="FMU runs")
    left.plot(
        fine * RAD_TO_DEG,
        [maker_max_error(b) * RAD_TO_DEG for b in fine],
        "k--",
        lw=1,
        label="maker: arctan$\\frac{1-\\cos\\beta}{2\\sqrt{\\cos\\beta}}$",
    )
    for (b, printed, _), color in zip(MAKER_TABLE, COLORS):
        left.plot(b, printed, "s", color=color, mfc="none", ms=11, mew=1.5)
        left.annotate(
            f"{printed:.3f}°",
            (b, printed),
            xytext=(-40, 8),
            textcoords="offset points",
            fontsize=8,
            color=color,
        )
    left.set_xlabel("bend (deflection) angle $\\beta$ [deg]")
    left.set_ylabel("largest cardan error $\\Delta\\alpha_{max}$ [deg]")
    left.set_title(
        "Maker fig. 12: $\\Delta\\alpha_{max}$ vs bend angle (squares: table)", fontsize=10
    )
    left.legend(loc="upper left")
    right.plot(
        bends_deg,
        u,
        "o",
        color="tab:green",
        ms=5,
        label="FMU: $(\\omega_{2max} - \\omega_{2min})/\\omega_1$",
    )
    right.plot(
        fine * RAD_TO_DEG,
        maker_unevenness(fine),
        "k--",
        lw=1,
        label="maker: tan $\\beta$ $\\cdot$ sin $\\beta$",
    )
    right.set_xlabel("bend (deflection) angle $\\beta$ [deg]")
    right.set_ylabel("degree of unevenness u [-]")
    right.set_title("Maker fig. 13: degree of unevenness vs bend angle", fontsize=10)
    right.legend(loc="upper left")
    out.figure("seed_maker_amplitude_unevenness", fig)

    out.report()
    print("maker's table vs the FMU (largest cardan error, deg, at input angle, deg):")
    for b, printed, at in MAKER_TABLE:
        at_fmu, peak = (value * RAD_TO_DEG for value in peaks[b])
        print(
            f"  beta = {b} deg: maker {printed:.3f} at {at:.1f}; FMU {peak:.5f} at {at_fmu:.2f} "
            f"(truncated {truncated(peak):.3f}, rounded {peak:.3f}, location {at_fmu:.1f}); "
            f"sampled extremes {table_runs[b]['cardan_error'].max() * RAD_TO_DEG:+.5f} / "
            f"{table_runs[b]['cardan_error'].min() * RAD_TO_DEG:+.5f}"
        )
    worst_u = max(abs(unevenness[b] - maker_unevenness(math.radians(b))) for b in sweep)
    worst_amplitude = max(abs(peaks[b][1] - maker_max_error(math.radians(b))) for b in sweep)
    print(
        f"over beta = 0..{bends_deg[-1]:.0f} deg: unevenness vs tan b sin b within {worst_u:.1e}, "
        f"largest error vs the maker's closed form within {worst_amplitude * RAD_TO_DEG:.1e} deg "
        f"(parabola through samples {SAMPLE_STEP * RAD_TO_DEG:.1f} deg apart)"
    )


if __name__ == "__main__":
    sys.exit(run_example(main))
