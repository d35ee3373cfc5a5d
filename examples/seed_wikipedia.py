"""Wikipedia's universal-joint figures (seed 000), co-simulated with the FMU.

Output shaft speed omega2 and angle gamma2 versus input angle gamma1 for bend
angles 0..50 deg at omega1 = 1 rad/s, one FMU run per bend angle, plus the
section's acceleration equation a2(gamma1). The section's formulas
(omega2 = omega1 cos b / (1 - sin^2 b cos^2 gamma1), gamma2 = atan2(sin gamma1,
cos b cos gamma1), and a2) are drawn as black dots over the FMU's curves.
Yoke phase 0 (the FMU's default) is Wikipedia's convention.

    python build_fmu.py && python examples/seed_wikipedia.py
"""

import math
import sys

import numpy as np
from _seed_support import COLORS, Outputs, parse_args, pyplot, run
from _support import run_example

from cardan_joint.units import RAD_TO_DEG

BENDS_DEG = (0, 10, 20, 30, 40, 50)
INPUT_SPEED = 1.0  # rad/s, so omega2 reads as the speed ratio and time as gamma1


def wikipedia_speed(gamma1, bend):
    return INPUT_SPEED * math.cos(bend) / (1 - math.sin(bend) ** 2 * np.cos(gamma1) ** 2)


def wikipedia_angle(gamma1, bend):
    # The section's atan2 form holds on (-pi, pi); unwrapping continues it over the turn.
    return np.unwrap(np.arctan2(np.sin(gamma1), math.cos(bend) * np.cos(gamma1)))


def wikipedia_acceleration(gamma1, bend):
    d = 1 - math.sin(bend) ** 2 * np.cos(gamma1) ** 2
    return -(INPUT_SPEED**2) * math.cos(bend) * math.sin(bend) ** 2 * np.sin(2 * gamma1) / d**2


def main(argv=None):
    args = parse_args(__doc__, argv)
    out = Outputs(args.out)
    samples_per_turn = 72 if args.quick else 360
    turn = 2 * math.pi / INPUT_SPEED
    runs = {
        b: run(
            args.fmu,
            turn,
            turn / samples_per_turn,
            input_speed=INPUT_SPEED,
            bend_angle=math.radians(b),
        )
        for b in BENDS_DEG
    }

    def stacked(field):
        return np.concatenate([r[field] for r in runs.values()])

    bends = np.concatenate([np.full(len(r), math.radians(b)) for b, r in runs.items()])
    common = {"bend_angle_rad": bends, "input_angle_rad": stacked("input_angle")}
    out.csv(
        "seed_wikipedia_output_speed",
        dict(
            common,
            input_speed_rad_s=np.full(len(bends), INPUT_SPEED),
            output_speed_rad_s=stacked("output_speed"),
        ),
    )
    out.csv("seed_wikipedia_output_angle", dict(common, output_angle_rad=stacked("output_angle")))
    out.csv(
        "seed_wikipedia_output_acceleration",
        dict(common, output_acceleration_rad_s2=stacked("output_acceleration")),
    )

    plt = pyplot()
    marks = np.radians(np.arange(0, 361, 15))
    figures = (
        (
            "output_speed",
            "output shaft speed $\\omega_2$ [rad/s]",
            wikipedia_speed,
            1.0,
            "Output speed vs input angle, $\\omega_1$ = 1 rad/s (Wikipedia, UJoint1)",
            "Wikipedia: $\\omega_1\\cos\\beta/(1-\\sin^2\\beta\\cos^2\\gamma_1)$",
        ),
        (
            "output_angle",
            "output shaft angle $\\gamma_2$ [deg]",
            wikipedia_angle,
            RAD_TO_DEG,
            "Output angle vs input angle (Wikipedia, UJoint2)",
            "Wikipedia: atan2(sin $\\gamma_1$, cos $\\beta$ cos $\\gamma_1$)",
        ),
        (
            "output_acceleration",
            "output shaft acceleration $a_2$ [rad/s$^2$]",
            wikipedia_acceleration,
            1.0,
            "Output acceleration vs input angle, $\\omega_1$ = 1 rad/s, $a_1$ = 0, "
            "$D = 1-\\sin^2\\beta\\cos^2\\gamma_1$",
            "Wikipedia: $-\\omega_1^2\\cos\\beta\\sin^2\\beta\\sin 2\\gamma_1/D^2$",
        ),
    )
    for field, ylabel, formula, scale, title, reference_label in figures:
        fig, ax = plt.subplots(figsize=(8, 5.2))
        for (bend_deg, r), color in zip(runs.items(), COLORS):
            ax.plot(
                r["input_angle"] * RAD_TO_DEG,
                r[field] * scale,
                color=color,
                lw=1.4,
                label=f"FMU, $\\beta$ = {bend_deg}°",
            )
            ax.plot(
                marks * RAD_TO_DEG,
                formula(marks, math.radians(bend_deg)) * scale,
                "k.",
                ms=4,
                label=reference_label if bend_deg == BENDS_DEG[-1] else None,
            )
        ax.set_xlabel("input shaft angle $\\gamma_1$ [deg]")
        ax.set_ylabel(ylabel)
        ax.set_xticks(range(0, 361, 45))
        ax.set_xlim(0, 360)
        ax.set_title(title, fontsize=11)
        ax.legend(loc="upper left" if field == "output_angle" else "upper right", ncol=2)
        if field == "output_angle":
            ax.set_yticks(range(0, 361, 45))
        else:
            ax.set_ylim(top=ax.get_ylim()[1] + 0.35 * (ax.get_ylim()[1] - ax.get_ylim()[0]))
        out.figure(f"seed_wikipedia_{field}", fig)

    out.report()
    for bend_deg, r in runs.items():
        bend = math.radians(bend_deg)
        worst = max(
            np.max(np.abs(r["output_speed"] - wikipedia_speed(r["input_angle"], bend))),
            np.max(
                np.abs(r["output_acceleration"] - wikipedia_acceleration(r["input_angle"], bend))
            ),
        )
        print(
            f"beta = {bend_deg:2d} deg: omega2 in [{r['output_speed'].min():.6f}, "
            f"{r['output_speed'].max():.6f}] rad/s (cos b = {math.cos(bend):.6f}, "
            f"1/cos b = {1 / math.cos(bend):.6f}); "
            f"largest deviation from Wikipedia's omega2 and a2: {worst:.1e}"
        )


if __name__ == "__main__":
    sys.exit(run_example(main))
