"""The driveshaft example's measures and figure (`examples/driveshaft.py`): the
speed fluctuation of a run, its closed-form references and the two-panel plot."""

import math

import numpy as np

from cardan_joint.host.plotting import pyplot, save_figure
from cardan_joint.physics import quantities

COUPLINGS = ("lead", "hold", "angle")


def fluctuation(speed, input_speed):
    """(max - min) / omega1 of a speed sampled over whole revolutions."""
    return float((np.max(speed) - np.min(speed)) / input_speed)


def single_joint_fluctuation(bend_angle):
    return float(quantities.degree_of_unevenness(bend_angle))


def predicted_hold_fluctuation(bend_angle, input_speed, step):
    """Leading-order residual of the `hold` coupling (driveshaft.py's docstring)."""
    return (input_speed * step) ** 2 * math.tan(bend_angle) ** 2 * math.sin(bend_angle) ** 2 / 6


def exact_fluctuation(bend_angle, phase_error, samples=200_001):
    """The closed-form composition of the two joints, no co-simulation: joint 2
    turned by joint 1's exact output angle."""
    gamma1 = np.linspace(0.0, 2 * math.pi, samples)
    gamma2 = quantities.output_angle(gamma1, bend_angle)
    ratio = quantities.speed_ratio(gamma1, bend_angle) * quantities.speed_ratio(
        gamma2 + math.pi / 2 + phase_error, bend_angle
    )
    return float(ratio.max() - ratio.min())


def plot(steps_rows, phase_rows, bend_angle, input_speed, phase_step, path):
    plt = pyplot()
    single = single_joint_fluctuation(bend_angle)
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    markers = {"lead": "v", "hold": "o", "angle": "s"}
    labels = {
        "lead": "lead: joint 2 fed joint 1's outputs at t + h",
        "hold": "hold: inputs valid at t (O(h$^2$))",
        "angle": "angle: hold + angle-matching acceleration",
    }
    for coupling in COUPLINGS:
        rows = [r for r in steps_rows if r["coupling"] == coupling]
        # Rounding-level residuals are floored so the log axis can show them.
        left.loglog(
            [r["step"] for r in rows],
            [max(r["fluctuation"], 1e-16) for r in rows],
            marker=markers[coupling],
            label=labels[coupling],
        )
    h = np.array(sorted({r["step"] for r in steps_rows}))
    left.loglog(
        h,
        [predicted_hold_fluctuation(bend_angle, input_speed, x) for x in h],
        "k:",
        label=r"$(\omega_1 h)^2\tan^2\beta\,\sin^2\beta/6$",
    )
    left.axhline(single, color="tab:red", ls="--", label=r"single joint $\tan\beta\sin\beta$")
    left.set_xlabel("communication step h [s]")
    left.set_ylabel(r"output speed fluctuation $(\max-\min)/\omega_1$")
    left.set_title(
        f"Z driveshaft, {math.degrees(bend_angle):g} deg, "
        f"$\\omega_1$ = {input_speed:g} rad/s: step dependence",
        fontsize=10,
    )
    left.legend(fontsize=8, loc="center right", bbox_to_anchor=(1.0, 0.3))
    left.grid(alpha=0.3, which="both")

    errors = np.linspace(0.0, max(r["phase_error_deg"] for r in phase_rows), 101)
    right.semilogy(
        errors[1:],
        [exact_fluctuation(bend_angle, math.radians(e), 20_001) for e in errors[1:]],
        "k-",
        lw=1,
        label="exact (closed forms)",
    )
    right.semilogy(
        [r["phase_error_deg"] for r in phase_rows],
        [r["fluctuation"] for r in phase_rows],
        "o",
        color="tab:blue",
        label=f"co-simulated, hold coupling, h = {phase_step:g} s",
    )
    right.axhline(single, color="tab:red", ls="--", label="single joint")
    right.set_xlabel("joint 2 yoke phase error [deg] (yoke_phase = 90 deg + error)")
    right.set_ylabel(r"output speed fluctuation $(\max-\min)/\omega_1$")
    right.set_title("Yoke phase error on the intermediate shaft", fontsize=10)
    right.legend(fontsize=8, loc="lower right")
    right.grid(alpha=0.3, which="both")
    save_figure(fig, path)
