"""A vehicle propshaft layout: measured shaft angles to working angles, the joint
makers' checks, the best yoke phasing, and the Propshaft FMU run before and after.

The layout (angles as measured with an inclinometer; side view positive rising
toward the rear, top view positive toward +y):

    shaft 0, gearbox output   side -3.0 deg   top 0.0 deg
    shaft 1, propshaft        side -1.0 deg   top 2.5 deg   (axle offset sideways)
    shaft 2, axle pinion      side -3.0 deg   top 5.0 deg

In the side view this is a Z (gearbox and pinion parallel), in the top view a
W: the two joints bend in different planes, so yokes in one plane (phasing 0)
leave a fluctuation, and the phasing the helper returns (the angle between the
joint planes) cancels it.

    python build_fmu.py --model Propshaft && python examples/propshaft_layout.py
        -> results/propshaft_layout.png (docs/img: python tools/gallery.py)
"""

import math
import sys
import warnings

import numpy as np
from _support import example_fmu, example_parser, legend_outside, output_folder, run_example

from cardan_joint.host.plotting import pyplot, save_figure
from cardan_joint.host.simulate import simulate
from cardan_joint.models.propshaft import angle_report, best_phasing, layout
from cardan_joint.units import RAD_PER_S_TO_RPM

SIDE_DEG = (-3.0, -1.0, -3.0)
TOP_DEG = (0.0, 2.5, 5.0)
SPEED_RPM = 4000.0
LOAD = 300.0  # N.m at the axle pinion
SHAFT_INERTIA = 0.05  # kg.m2, the propshaft tube
CROSSPIECE = (0.0004, 0.0004, 0.0007)


def run(fmu, phase, revolutions=2, points=720):
    speed = SPEED_RPM / RAD_PER_S_TO_RPM
    stop = revolutions * 2.0 * math.pi / speed
    start = {f"shaft_{k}_side_angle": math.radians(a) for k, a in enumerate(SIDE_DEG)}
    start.update({f"shaft_{k}_top_angle": math.radians(a) for k, a in enumerate(TOP_DEG)})
    start.update(
        shaft_1_yoke_phase=phase,
        shaft_1_inertia=SHAFT_INERTIA,
        crosspiece_inertia_1=CROSSPIECE[0],
        crosspiece_inertia_2=CROSSPIECE[1],
        crosspiece_inertia_3=CROSSPIECE[2],
    )
    with warnings.catch_warnings():
        # The checks were printed from the report already; the FMU logs them again.
        warnings.simplefilter("ignore", RuntimeWarning)
        return simulate(
            fmu,
            stop_time=stop,
            output_interval=stop / points,
            inputs=dict(input_speed=speed, input_acceleration=0.0, load_torque=LOAD),
            start_values=start,
        )


def plot(before, after, phase, path):
    plt = pyplot()
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(10, 6))
    for result, label in (
        (before, "yokes in one plane (phasing 0)"),
        (after, f"phasing {math.degrees(phase):.2f} deg (helper)"),
    ):
        revolutions = result["input_angle"] / (2.0 * math.pi)
        top.plot(revolutions, result["output_speed"] * RAD_PER_S_TO_RPM, label=label)
        bottom.plot(revolutions, result["input_torque"], label=label)
    top.set_ylabel("output speed [rpm]")
    bottom.set_ylabel("input torque [N.m]")
    bottom.set_xlabel("input revolutions")
    top.set_title(f"Propshaft at {SPEED_RPM:.0f} rpm, {LOAD:.0f} N.m at the pinion")
    legend_outside(top)
    return save_figure(fig, path)


def main(argv=None):
    parser = example_parser(__doc__, model="Propshaft")
    args = parser.parse_args(argv)
    args.fmu = example_fmu(args)
    out = output_folder(args)
    side = [math.radians(a) for a in SIDE_DEG]
    top = [math.radians(a) for a in TOP_DEG]
    geometry = layout(side, top, [0.0])
    report = angle_report(geometry, SPEED_RPM / RAD_PER_S_TO_RPM)
    print(
        "Working angles: "
        + ", ".join(
            f"joint {k} {math.degrees(b):.3f} deg (shop formula {_shop_formula(side, top, k):.3f})"
            for k, b in enumerate(report.working_angles, start=1)
        )
    )
    print(
        f"Phasing 0: speed-ratio fluctuation {report.speed_ratio_fluctuation:.4g} "
        f"(equivalent single joint {math.degrees(report.equivalent_angle):.3f} deg)"
    )
    for warning in report.warnings or ("no warnings",):
        print(f"  check: {warning}")
    phases, left = best_phasing(geometry)
    after = angle_report(geometry.with_phases(phases), SPEED_RPM / RAD_PER_S_TO_RPM)
    print(f"Best phasing {math.degrees(phases[0]):.3f} deg: fluctuation {left:.3g}")
    for warning in after.warnings or ("no warnings",):
        print(f"  check: {warning}")
    run_before, run_after = run(args.fmu, 0.0), run(args.fmu, phases[0])
    for name, result in (("phasing 0", run_before), ("best phasing", run_after)):
        ratio = result["output_speed"] / (SPEED_RPM / RAD_PER_S_TO_RPM)
        spread = np.ptp(result["output_speed"]) * RAD_PER_S_TO_RPM
        print(
            f"FMU, {name}: output speed {spread:.2f} rpm peak to "
            f"peak (ratio {np.ptp(ratio):.3g}), input torque "
            f"{result['input_torque'].min():.2f} .. {result['input_torque'].max():.2f} N.m"
        )
    path = plot(run_before, run_after, phases[0], out / "propshaft_layout.png")
    print(f"wrote {path}")


def _shop_formula(side, top, k):
    """sqrt(theta^2 + psi^2) of the differences, in deg (Spicer's compound angle)."""
    return math.degrees(math.hypot(side[k] - side[k - 1], top[k] - top[k - 1]))


if __name__ == "__main__":
    sys.exit(run_example(main))
