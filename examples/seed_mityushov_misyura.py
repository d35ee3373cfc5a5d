"""Mityushov & Misyura's crosspiece figures 3-8 (seed 001), co-simulated with the FMU.

omega1 = 0.5 rad/s, alpha = pi/6, yoke phase 90 deg (the paper's formula (1)),
two input revolutions; one FMU run per inertia distribution.

The paper's frame is not the FMU's. Its quaternion (4), with the roll law (3)
gamma = pi/2 - atan(tan(alpha) cos(theta)), puts its crosspiece axis 1 along the
input-yoke pin (opposite sense), axis 2 along the cross normal and axis 3 along
the output-yoke pin; the FMU (models/universal_joint/README.md) has 1 = input pin, 2 = output pin,
3 = normal. Numerically, the paper's Omega = (-Omega1, Omega3, Omega2) of the
FMU, and its equations (5) hold only in that order. So this script gives the
FMU the paper's inertias on the paper's axes (I1 -> input pin, I2 -> normal,
I3 -> output pin) and plots every vector in the paper's frame, the quaternion
as well (a constant change of fixed and body frames of the FMU's quaternion).
The paper's M3 = 0 for I1 = I3 = I2/2 is then the FMU's output-pin torque
vanishing for a flat cross (normal moment = sum of the pin moments).
models/universal_joint/README.md reads the paper's indices as the FMU's axes instead (its M3 = 0
when I2 = I1 + I3, equally true of the FMU); the energy figure shows that
reading beside the paper's for comparison.

Roll angle: the crosspiece matrix is R = Rz(psi) Rx(rho), psi = input angle +
yoke phase, so rho = atan2(R32, R33) = atan2(2 (q0 q1 + q2 q3),
q0^2 - q1^2 - q2^2 + q3^2) from the FMU's quaternion, sign-independent.
rho = 2 atan2(q1, q0) holds only modulo 2 pi (q0 changes sign each other turn).
The paper's roll is gamma = pi/2 - rho.

The paper's T4 distribution (I1 = 7/9, I2 = 1/9, I3 = 10/9 I0) breaks the
triangle inequality of principal moments (I3 > I1 + I2): no rigid body has it.
It is plotted as the paper did, and labelled so.

    python build_fmu.py && python examples/seed_mityushov_misyura.py
"""

import math
import sys

import numpy as np
from _mityushov_support import (
    BEND,
    INPUT_SPEED,
    YOKE_PHASE,
    fmu_inertia,
    in_paper_frame,
    kinematics_figure,
    paper_formulas,
    paper_quaternion,
    physics_md_inertia,
    roll_from_quaternion,
)
from _seed_support import Outputs, parse_args, pyplot, run
from _support import run_example

DURATION = 2 * 2 * math.pi / INPUT_SPEED  # two input revolutions, s
TORQUE_INERTIA = 0.026  # kg.m2, figure 7
I0 = 0.039  # kg.m2, figure 8: I0 = (I1 + I2 + I3) / 2
# The paper's (I1, I2, I3), in its own axis order (1 input pin, 2 normal, 3 output pin).
DISTRIBUTIONS = {
    "T1": (2 / 3 * I0, 2 / 3 * I0, 2 / 3 * I0),
    "T2": (1 / 3 * I0, 4 / 3 * I0, 1 / 3 * I0),
    "T3": (5 / 6 * I0, 1 / 3 * I0, 5 / 6 * I0),
    "T4": (7 / 9 * I0, 1 / 9 * I0, 10 / 9 * I0),
}
FLAT_CROSS = (0.5 * TORQUE_INERTIA, TORQUE_INERTIA, 0.5 * TORQUE_INERTIA)  # I1 = I3 = I2 / 2


def main(argv=None):
    args = parse_args(__doc__, argv)
    out = Outputs(args.out)
    plt = pyplot()
    interval = DURATION / (100 if args.quick else 500)
    joint = {"input_speed": INPUT_SPEED, "bend_angle": BEND, "yoke_phase": YOKE_PHASE}

    def paper_run(inertia_start_values):
        return run(args.fmu, DURATION, interval, **joint, **inertia_start_values)

    equal = paper_run(fmu_inertia((TORQUE_INERTIA,) * 3))
    flat = paper_run(fmu_inertia(FLAT_CROSS))
    energies = {name: paper_run(fmu_inertia(i)) for name, i in DISTRIBUTIONS.items()}
    energies_physics_md = {
        name: paper_run(physics_md_inertia(i)) for name, i in DISTRIBUTIONS.items()
    }

    t = equal["time"]
    q_fmu = np.array([equal[f"crosspiece_quaternion_{k}"] for k in range(4)])
    q_paper = paper_quaternion(q_fmu)
    rho = roll_from_quaternion(q_fmu)
    omega_paper = in_paper_frame(equal, "angular_velocity")
    marks = np.linspace(0, DURATION, 33)
    gamma_ref, output_angle_ref, q_ref = paper_formulas(marks)

    out.csv(
        "seed_mityushov_misyura_kinematics",
        {
            "time_s": t,
            "input_angle_rad": equal["input_angle"],
            "output_angle_rad": equal["output_angle"],
            "roll_rho_rad": rho,
            "paper_roll_gamma_rad": math.pi / 2 - rho,
            **{f"fmu_omega{k}_rad_s": equal[f"crosspiece_angular_velocity_{k}"] for k in (1, 2, 3)},
            **{f"paper_omega{k}_rad_s": omega_paper[k - 1] for k in (1, 2, 3)},
        },
    )
    out.csv(
        "seed_mityushov_misyura_quaternion",
        {
            "time_s": t,
            **{f"fmu_q{k}": q_fmu[k] for k in range(4)},
            **{f"paper_q{k}": q_paper[k] for k in range(4)},
        },
    )

    fig = kinematics_figure(plt, t, equal, rho, omega_paper, marks, gamma_ref, output_angle_ref)
    out.figure("seed_mityushov_misyura_kinematics", fig)

    # Figure 5: quaternion.
    fig, axes = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True)
    colors = ("tab:blue", "tab:orange", "tab:green", "tab:red")
    for k, color in enumerate(colors):
        axes[0].plot(t, q_paper[k], color=color, lw=1.5, label=f"$q_{k}$, FMU in the paper's frame")
        axes[0].plot(
            marks,
            q_ref[k],
            ".",
            color="k",
            ms=4,
            label="paper (4) with roll (3)" if k == 0 else None,
        )
        axes[1].plot(t, q_fmu[k], color=color, lw=1.5, label=f"$q_{k}$, FMU output")
    axes[0].set_ylabel("quaternion, paper's frame [-]")
    axes[0].set_title(
        "Fig. 5: orientation quaternion of the crosspiece (paper's frames)", fontsize=10
    )
    axes[1].set_ylabel("quaternion, FMU frame [-]")
    axes[1].set_title(
        "The FMU's crosspiece_quaternion_0..3 (model page: R = Rz($\\psi$) Rx($\\rho$))",
        fontsize=10,
    )
    axes[1].set_xlabel("time t [s]")
    for ax in axes:
        ax.set_ylim(-1.1, 1.6)
        ax.legend(loc="upper center", ncol=3)
    out.figure("seed_mityushov_misyura_quaternion", fig)

    # Figure 7: torques on the crosspiece, and the paper's M3 = 0 for a flat cross.
    torques_equal = in_paper_frame(equal, "torque")
    torques_flat = in_paper_frame(flat, "torque")
    out.csv(
        "seed_mityushov_misyura_torques",
        {
            "time_s": t,
            **{f"paper_M{k}_equal_N_m": torques_equal[k - 1] for k in (1, 2, 3)},
            **{f"paper_M{k}_flat_cross_N_m": torques_flat[k - 1] for k in (1, 2, 3)},
        },
    )
    fig, axes = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True)
    names = ("$M_1$ (input pin)", "$M_2$ (cross normal)", "$M_3$ (output pin)")
    for values, ax in ((torques_equal, axes[0]), (torques_flat, axes[1])):
        for component, name, color in zip(values, names, ("tab:blue", "tab:orange", "tab:green")):
            ax.plot(t, component * 1e3, color=color, lw=1.5, label=f"{name}, FMU")
        ax.set_ylabel("torque on the crosspiece [mN.m]")
        low, high = ax.get_ylim()
        ax.set_ylim(low, high + 0.3 * (high - low))
        ax.legend(loc="upper center", ncol=3)
    axes[0].set_title(f"Fig. 7: $I_1 = I_2 = I_3$ = {TORQUE_INERTIA} kg.m$^2$", fontsize=10)
    axes[1].set_title(
        f"Paper §5: $I_1 = I_3 = I_2/2$ ($I_2$ = {FLAT_CROSS[1]} kg.m$^2$ about "
        "the normal, a flat cross) gives $M_3 \\equiv 0$",
        fontsize=10,
    )
    axes[1].set_xlabel("time t [s]")
    out.figure("seed_mityushov_misyura_torques", fig)

    # Figure 8: kinetic energy for the four distributions with the same I0.
    out.csv(
        "seed_mityushov_misyura_energy",
        {
            "time_s": t,
            **{f"{name}_J": r["crosspiece_kinetic_energy"] for name, r in energies.items()},
            **{
                f"{name}_physics_md_reading_J": r["crosspiece_kinetic_energy"]
                for name, r in energies_physics_md.items()
            },
        },
    )
    fig, axes = plt.subplots(2, 1, figsize=(9, 8), sharex=True)
    labels = {
        "T1": "T1: $I_1 = I_2 = I_3 = \\frac{2}{3}I_0$",
        "T2": "T2: $I_1 = I_3 = \\frac{1}{3}I_0,\\ I_2 = \\frac{4}{3}I_0$",
        "T3": "T3: $I_1 = I_3 = \\frac{5}{6}I_0,\\ I_2 = \\frac{1}{3}I_0$",
        "T4": "T4: $I_1 = \\frac{7}{9}, I_2 = \\frac{1}{9}, I_3 = \\frac{10}{9}I_0$ "
        "(no rigid body: $I_3 > I_1 + I_2$)",
    }
    colors = dict(zip(DISTRIBUTIONS, ("tab:blue", "tab:orange", "tab:green", "tab:red")))
    for ax, runs, title in (
        (
            axes[0],
            energies,
            "Fig. 8: kinetic energy, the paper's axes (2 = cross normal, 3 = output pin)",
        ),
        (
            axes[1],
            energies_physics_md,
            "The same numbers on the model page's axes (2 = output pin, 3 = cross normal)",
        ),
    ):
        for name, r in runs.items():
            ax.plot(
                t,
                r["crosspiece_kinetic_energy"] * 1e3,
                color=colors[name],
                lw=1.5,
                ls=":" if name == "T4" else "-",
                label=labels[name],
            )
        ax.set_ylabel("crosspiece kinetic energy [mJ]")
        ax.set_title(title, fontsize=10)
        ax.set_ylim(0, ax.get_ylim()[1] * 1.45)
        ax.legend(loc="upper center", ncol=2, fontsize=7.5)
    axes[1].set_xlabel("time t [s]")
    fig.suptitle(
        f"Mityushov & Misyura: $I_0$ = {I0} kg.m$^2$, $\\omega_1$ = 0.5 rad/s, $\\alpha = \\pi/6$",
        fontsize=12,
    )
    out.figure("seed_mityushov_misyura_energy", fig)

    out.report()
    psi = equal["input_angle"] + YOKE_PHASE
    rho_expected = np.arctan(math.tan(BEND) * np.sin(psi))
    half_angle_roll = 2 * np.arctan2(q_fmu[1], q_fmu[0])
    wrapped = np.angle(np.exp(1j * (half_angle_roll - rho_expected)))
    print(
        "roll from the quaternion vs atan(tan a sin psi): "
        f"{np.max(np.abs(rho - rho_expected)):.1e} rad; 2 atan2(q1, q0) differs by up to "
        f"{np.max(np.abs(half_angle_roll - rho_expected)):.4f}"
        f" rad, {np.max(np.abs(wrapped)):.1e} rad modulo 2 pi"
    )
    print(
        f"paper's quaternion (4) vs the FMU's in the paper's frames: "
        f"{np.max(np.abs(q_paper - paper_formulas(t)[2])):.1e}; "
        f"|q| - 1 up to {np.max(np.abs(np.linalg.norm(q_fmu, axis=0) - 1)):.1e}"
    )
    print(
        f"Omega2^2 + Omega3^2 - omega1^2 up to "
        f"{np.max(np.abs(omega_paper[1] ** 2 + omega_paper[2] ** 2 - INPUT_SPEED**2)):.1e} "
        f"rad2/s2; roll gamma in [{np.degrees((math.pi / 2 - rho).min()):.3f}, "
        f"{np.degrees((math.pi / 2 - rho).max()):.3f}] deg"
    )
    print(
        f"torques, I = {TORQUE_INERTIA} kg.m2: |M1|, |M2|, |M3| up to "
        + ", ".join(f"{np.max(np.abs(m)):.3e}" for m in torques_equal)
        + f" N.m; flat cross I1 = I3 = I2/2: |M3| up to {np.max(np.abs(torques_flat[2])):.1e} N.m"
    )
    for name in DISTRIBUTIONS:
        e, e_md = (
            runs[name]["crosspiece_kinetic_energy"] for runs in (energies, energies_physics_md)
        )
        print(
            f"{name}: energy {e.min() * 1e3:.4f}..{e.max() * 1e3:.4f} mJ, mean {e.mean() * 1e3:.4f}"
            f" mJ (model page reading {e_md.min() * 1e3:.4f}..{e_md.max() * 1e3:.4f} mJ)"
        )


if __name__ == "__main__":
    sys.exit(run_example(main))
