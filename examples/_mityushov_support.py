"""The paper's frame for `examples/seed_mityushov_misyura.py` (its docstring
explains the axis change): the paper's joint, its inertias and vectors on the
FMU's axes, its quaternion and formulas (2)-(4), and the kinematics figure."""

import math

import numpy as np

INPUT_SPEED = 0.5  # rad/s
BEND = math.pi / 6
YOKE_PHASE = math.pi / 2


def fmu_inertia(paper_inertia):
    """FMU start values for inertias given in the paper's axis order."""
    i1, i2, i3 = paper_inertia
    return {"crosspiece_inertia_1": i1, "crosspiece_inertia_2": i3, "crosspiece_inertia_3": i2}


def physics_md_inertia(paper_inertia):
    """models/universal_joint/README.md's reading: the paper's index k taken as the FMU's axis k."""
    return {f"crosspiece_inertia_{k}": value for k, value in enumerate(paper_inertia, start=1)}


def in_paper_frame(r, quantity):
    """The FMU's body-frame vector `quantity` ("angular_velocity", "torque") on the paper's axes."""
    v1, v2, v3 = (r[f"crosspiece_{quantity}_{k}"] for k in (1, 2, 3))
    return -v1, v3, v2


def quaternion_product(p, q):
    p0, p1, p2, p3 = p
    q0, q1, q2, q3 = q
    return np.array(
        [
            p0 * q0 - p1 * q1 - p2 * q2 - p3 * q3,
            p0 * q1 + p1 * q0 + p2 * q3 - p3 * q2,
            p0 * q2 - p1 * q3 + p2 * q0 + p3 * q1,
            p0 * q3 + p1 * q2 - p2 * q1 + p3 * q0,
        ]
    )


def axis_quaternion(axis, angle):
    q = np.zeros(4)
    q[0], q[1 + "xyz".index(axis)] = math.cos(angle / 2), math.sin(angle / 2)
    return q


def paper_quaternion(q_fmu):
    """The FMU's quaternion in the paper's frames.

    The paper's fixed x1 is the FMU's y (its input pin starts there) and its body
    axes are (-1, 3, 2) of the FMU's: R_paper = Rz(pi/2) R Rz(-pi) Rx(pi/2).
    """
    fixed = axis_quaternion("z", math.pi / 2)
    body = quaternion_product(axis_quaternion("z", -math.pi), axis_quaternion("x", math.pi / 2))
    q = quaternion_product(quaternion_product(fixed[:, None], q_fmu), body[:, None])
    # Both the FMU's quaternion and (4) are continuous in time: one sign fits all.
    return q if q[0, 0] >= 0 else -q


def roll_from_quaternion(q):
    q0, q1, q2, q3 = q
    return np.arctan2(2 * (q0 * q1 + q2 * q3), q0**2 - q1**2 - q2**2 + q3**2)


def paper_formulas(t):
    """The paper's (2), (3) and (4) at constant omega1: references drawn as dots."""
    theta = INPUT_SPEED * t
    gamma = math.pi / 2 - np.arctan(math.tan(BEND) * np.cos(theta))
    output_angle = np.unwrap(np.arctan2(np.sin(theta) * math.cos(BEND), np.cos(theta)))
    q = np.array(
        [
            np.cos(theta / 2) * np.cos(gamma / 2),
            np.cos(theta / 2) * np.sin(gamma / 2),
            np.sin(theta / 2) * np.sin(gamma / 2),
            np.sin(theta / 2) * np.cos(gamma / 2),
        ]
    )
    return gamma, output_angle, q


def kinematics_figure(plt, t, equal, rho, omega_paper, marks, gamma_ref, output_angle_ref):
    """Figures 3, 4 and 6 of one run (`equal`) against the paper's formulas."""
    fig, axes = plt.subplots(2, 2, figsize=(12, 8), sharex=True)
    roll, velocity, angle, lead = axes.flat
    roll.plot(
        t,
        np.degrees(math.pi / 2 - rho),
        color="tab:blue",
        lw=1.5,
        label="paper's roll $\\gamma = \\pi/2 - \\rho$ (FMU quaternion)",
    )
    roll.plot(
        t,
        np.degrees(rho),
        color="tab:orange",
        lw=1.5,
        label="roll $\\rho$ of R = Rz($\\psi$) Rx($\\rho$) (FMU quaternion)",
    )
    roll.plot(
        marks,
        np.degrees(gamma_ref),
        "k.",
        ms=5,
        label="paper (3): $\\pi/2$ - arctg(tg $\\alpha$ cos $\\vartheta$)",
    )
    roll.set_ylabel("roll angle [deg]")
    roll.set_title("Fig. 3: roll angle of the crosspiece", fontsize=10)
    roll.set_ylim(-40, 200)
    roll.legend(loc="upper center")
    names = ("$\\Omega_1$ (input pin)", "$\\Omega_2$ (cross normal)", "$\\Omega_3$ (output pin)")
    for component, name, color in zip(omega_paper, names, ("tab:blue", "tab:orange", "tab:green")):
        velocity.plot(t, component, color=color, lw=1.5, label=f"{name}, FMU")
    velocity.plot(
        t,
        np.hypot(omega_paper[1], omega_paper[2]),
        color="tab:purple",
        lw=3,
        alpha=0.45,
        label="$\\sqrt{\\Omega_2^2 + \\Omega_3^2}$, FMU",
    )
    velocity.axhline(
        INPUT_SPEED, color="k", ls="--", lw=1, label=f"$\\omega_1$ = {INPUT_SPEED} rad/s (paper)"
    )
    velocity.set_ylabel("crosspiece angular velocity [rad/s]")
    velocity.set_title(
        "Fig. 6: angular velocity on the crosspiece axes (paper's frame)", fontsize=10
    )
    velocity.set_ylim(-0.35, 0.9)
    velocity.legend(loc="upper center", ncol=2)
    angle.plot(
        t,
        np.degrees(equal["output_angle"]),
        color="tab:red",
        lw=1.5,
        label="driven shaft $\\varphi_{II}$ (FMU)",
    )
    angle.plot(
        t,
        np.degrees(equal["input_angle"]),
        "k--",
        lw=0.8,
        label="main shaft $\\varphi_I = \\omega_1 t$",
    )
    angle.plot(
        marks,
        np.degrees(output_angle_ref),
        "k.",
        ms=5,
        label="paper (2): tg $\\varphi_{II}$ = tg $\\varphi_I$ cos $\\alpha$ (continued)",
    )
    angle.set_ylabel("shaft angle [deg]")
    angle.set_yticks(range(0, 721, 90))
    angle.set_title("Fig. 4: rotation angle of the driven shaft", fontsize=10)
    angle.legend(loc="upper left")
    # On the scale of fig. 4 the driven shaft's lead and lag are invisible.
    lead.plot(
        t,
        np.degrees(equal["output_angle"] - equal["input_angle"]),
        color="tab:red",
        lw=1.5,
        label="$\\varphi_{II} - \\varphi_I$ (FMU)",
    )
    lead.plot(
        marks, np.degrees(output_angle_ref - INPUT_SPEED * marks), "k.", ms=5, label="paper (2)"
    )
    lead.set_ylabel("driven shaft lead $\\varphi_{II} - \\varphi_I$ [deg]")
    lead.set_title("Fig. 4 magnified: the driven shaft's lead and lag", fontsize=10)
    lead.set_ylim(-6, 8)
    lead.legend(loc="upper center", ncol=2)
    for ax in (angle, lead):
        ax.set_xlabel("time t [s]")
    fig.suptitle(
        "Mityushov & Misyura: $\\omega_1$ = 0.5 rad/s, $\\alpha = \\pi/6$, yoke phase 90°",
        fontsize=12,
    )
    return fig
