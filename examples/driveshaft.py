"""A two-joint driveshaft: two UniversalJoint instances in one FMPy master loop.

Joint 1 turns at a prescribed input speed; joint 2's input is the intermediate
shaft, i.e. joint 1's output speed and acceleration. With equal bend angles and
the intermediate shaft's yokes in one plane (joint 2's yoke_phase = 90 deg when
joint 1's is 0, models/universal_joint/README.md) the output turns exactly with the input.

Arrangements. Joint 2's frame has z' along joint 1's output shaft
z2 = (sin b, 0, cos b) and the same hinge axis y, so x' = (cos b, 0, -sin b).
Its output shaft is z3 = sin(b2) x' + cos(b2) z'. Z (output parallel to
input, z3 = z): sin(b2) = z . x' = -sin b, so b2 = -b. W (output bent by 2b,
z3 = (sin 2b, 0, cos 2b)): b2 = +b. Both cancel the speed fluctuation
identically (measured: the two runs agree to the last bit), because the joint's
speed depends on the bend angle only through cos b and sin^2 b; the sign
shows in the crosspiece's pose and the yoke couples.

Why the co-simulated cancellation is not exact. Joint 2 does not see joint 1's
output angle: it integrates its own input angle from the speed and acceleration
it receives, exactly for a speed that is linear over the step. The intermediate
shaft's speed is not linear, so each step loses jerk * h^3 / 6 of angle, and
the angle error settles at delta(t) = -(h^2/6) (a2(t) - a2(0)): second order
in the communication step h. Through joint 2's kinematics that leaves a speed
fluctuation of (omega1 h)^2 tan^2 b sin^2 b / 6 relative to omega1, i.e. a
cancellation ratio of 6 / (tan b sin b (omega1 h)^2) against a single joint's
tan b sin b. Measured (omega1 = 10 rad/s, b = 30 deg, `hold` coupling, sampled
at the communication points): 1.50e-4, 1.40e-6, 1.39e-8 for h = 1e-2, 1e-3,
1e-4 s, ratio 2.06e5 at 1 ms, order 2.00. The ratio goes with omega1 h, not h:
at 3000 rpm and 5 deg a 1 ms step gives 7.3e3. Couplings compared:

- `lead`: step joint 1, read its outputs, set them on joint 2, step joint 2
  over the same [t, t+h]: joint 2 runs on speeds one step ahead, first order
  (ratio 2.5e2 at 1 ms).
- `hold`: both joints advance over [t, t+h] on inputs valid at t (joint 1's
  outputs read before it steps): second order, as above.
- `angle`: as `hold`, but after joint 1 has stepped the master sets joint 2's
  input acceleration to 2 (Delta gamma2 - omega2 h) / h^2, the value that lands
  joint 2's input angle on joint 1's output angle at t + h. The intermediate
  angle is then consistent at every communication point and the cancellation
  is exact to rounding (~1e-15) at any step. The master uses only outputs the
  FMU publishes, and joint 2's outputs are sampled before the correction is
  set, so they see joint 1's true a2.

Sampling. Outputs are sampled at each communication point after joint 2's
inputs are set (direct feedthrough: everything consistent at t). Sampled at
the end of a step instead, as FMPy's recorder does, joint 2 still holds its
speed extrapolated over the step (omega2 + a2 h), an O(h^2) error that is not
carried over: 5.8e-5 at 1 ms for `hold`, 1.9e-5 for `angle`.

Yoke phase error. With joint 2's yoke_phase = 90 deg + e the intermediate
yokes are out of plane and the fluctuation grows as 2 e tan b sin b (e in rad):
each degree of phase error gives back 3.5 % of a single joint's fluctuation,
10 deg gives 35 %. The co-simulation follows the closed-form composition of
the two joints to 4 digits (its own O(h^2) residual added).

    python build_fmu.py && python examples/driveshaft.py

Writes results/driveshaft_steps.csv (step dependence), results/driveshaft_phase.csv
(yoke phase error sweep) and results/driveshaft.png.
"""

import math
import sys

import numpy as np
from _driveshaft_support import (
    COUPLINGS,
    exact_fluctuation,
    fluctuation,
    plot,
    predicted_hold_fluctuation,
    single_joint_fluctuation,
)
from _support import example_fmu, example_parser, output_folder, positive, run_example

from cardan_joint import results
from cardan_joint.host.instance import ExtractedFMU

ARRANGEMENTS = {"Z": -1.0, "W": 1.0}  # sign of joint 2's bend angle
ROUNDING = 1e-12


def cosimulate(
    fmu: ExtractedFMU,
    bend_angle=math.pi / 6,
    input_speed=10.0,
    step=1e-3,
    revolutions=2,
    arrangement="Z",
    phase_error=0.0,
    coupling="hold",
    input_acceleration=0.0,
):
    """Run the driveshaft for `revolutions` of the input at its initial speed.

    Joint 1's input speed is prescribed: input_speed + input_acceleration * t
    (constant by default). Returns a dict of arrays: time, input_speed,
    intermediate_speed (joint 1's output), output_speed (joint 2's, at the
    communication points with consistent inputs) and output_speed_at_step_end
    (joint 2's before its inputs are refreshed).
    """
    if coupling not in COUPLINGS:
        raise ValueError(f"coupling must be one of {COUPLINGS}, got {coupling!r}")
    steps = int(round(revolutions * 2 * math.pi / input_speed / step))
    joint1 = fmu.instance(
        "joint1",
        start_values={
            "bend_angle": bend_angle,
            "yoke_phase": 0.0,
            "input_angle_start": 0.0,
            "input_speed": input_speed,
            "input_acceleration": input_acceleration,
        },
    )
    # Joint 2's input shaft starts where joint 1's output shaft is.
    (start_angle,) = joint1.values("output_angle")
    joint2 = fmu.instance(
        "joint2",
        start_values={
            "bend_angle": ARRANGEMENTS[arrangement] * bend_angle,
            "yoke_phase": math.pi / 2 + phase_error,
            "input_angle_start": start_angle,
        },
    )
    intermediate, output, output_at_end = [], [], []
    with joint1, joint2:
        for k in range(steps + 1):
            joint1.set(
                input_speed=input_speed + input_acceleration * k * step,
                input_acceleration=input_acceleration,
            )
            speed, acceleration, angle = joint1.values(
                "output_speed", "output_acceleration", "output_angle"
            )
            # Set for every coupling: the sample below then sees consistent inputs at t.
            joint2.set(input_speed=speed, input_acceleration=acceleration)
            intermediate.append(speed)
            output.append(joint2.values("output_speed")[0])
            if k == steps:
                break
            joint1.step(step)
            if coupling == "lead":
                lead = joint1.get("output_speed", "output_acceleration")
                joint2.set(
                    input_speed=lead["output_speed"], input_acceleration=lead["output_acceleration"]
                )
            elif coupling == "angle":
                (next_angle,) = joint1.values("output_angle")
                joint2.set(
                    input_acceleration=2.0 * ((next_angle - angle) - speed * step) / (step * step)
                )
            joint2.step(step)
            output_at_end.append(joint2.values("output_speed")[0])
    time = step * np.arange(steps + 1)
    return {
        "time": time,
        "input_speed": input_speed + input_acceleration * time,
        "intermediate_speed": np.array(intermediate),
        "output_speed": np.array(output),
        "output_speed_at_step_end": np.array(output_at_end),
    }


def step_table(fmu, bend_angle, input_speed, steps, revolutions):
    rows = []
    for coupling in COUPLINGS:
        for step in steps:
            run = cosimulate(fmu, bend_angle, input_speed, step, revolutions, "Z", 0.0, coupling)
            residual = fluctuation(run["output_speed"], input_speed)
            rows.append(
                {
                    "coupling": coupling,
                    "step": step,
                    "fluctuation": residual,
                    "reduction": single_joint_fluctuation(bend_angle) / residual
                    if residual > 0
                    else math.inf,
                    "fluctuation_at_step_end": fluctuation(
                        run["output_speed_at_step_end"], input_speed
                    ),
                }
            )
            if coupling == "hold":
                rows[-1]["predicted"] = predicted_hold_fluctuation(bend_angle, input_speed, step)
    for previous, row in zip(rows, rows[1:]):
        # An order from residuals at the rounding level would be noise.
        if previous["coupling"] == row["coupling"] and row["fluctuation"] > ROUNDING:
            row["order"] = math.log(previous["fluctuation"] / row["fluctuation"]) / math.log(
                previous["step"] / row["step"]
            )
    return rows


def phase_table(fmu, bend_angle, input_speed, step, revolutions, errors_deg):
    rows = []
    for error in errors_deg:
        run = cosimulate(
            fmu, bend_angle, input_speed, step, revolutions, "Z", math.radians(error), "hold"
        )
        rows.append(
            {
                "phase_error_deg": error,
                "fluctuation": fluctuation(run["output_speed"], input_speed),
                "exact": exact_fluctuation(bend_angle, math.radians(error)),
                "single_joint": single_joint_fluctuation(bend_angle),
            }
        )
    return rows


def main(argv=None):
    parser = example_parser(__doc__)
    parser.add_argument("--bend-angle", type=float, default=30.0, help="deg (default 30)")
    parser.add_argument("--input-speed", type=positive, default=10.0, help="rad/s (default 10)")
    parser.add_argument(
        "--revolutions", type=int, default=2, help="input revolutions per run (default 2)"
    )
    parser.add_argument(
        "--steps",
        type=float,
        nargs="+",
        default=[1e-2, 1e-3, 1e-4],
        help="communication steps of the step-dependence table [s]",
    )
    parser.add_argument(
        "--phase-step",
        type=float,
        default=1e-3,
        help="communication step of the phase-error sweep [s]",
    )
    parser.add_argument(
        "--phase-errors",
        type=float,
        nargs="+",
        default=[0, 0.1, 0.25, 0.5, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10],
        help="yoke phase errors of joint 2 [deg]",
    )
    args = parser.parse_args(argv)
    args.fmu = example_fmu(args)
    out = output_folder(args)
    bend = math.radians(args.bend_angle)
    speed = args.input_speed
    single = single_joint_fluctuation(bend)

    with ExtractedFMU(args.fmu) as fmu:
        z = cosimulate(fmu, bend, speed, 1e-3, args.revolutions, "Z")
        w = cosimulate(fmu, bend, speed, 1e-3, args.revolutions, "W")
        steps_rows = step_table(fmu, bend, speed, args.steps, args.revolutions)
        phase_rows = phase_table(
            fmu, bend, speed, args.phase_step, args.revolutions, args.phase_errors
        )
    results.write_rows(steps_rows, out / "driveshaft_steps.csv")
    results.write_rows(phase_rows, out / "driveshaft_phase.csv")
    plot(steps_rows, phase_rows, bend, speed, args.phase_step, out / "driveshaft.png")

    print(
        f"Driveshaft, equal bend angles {args.bend_angle:g} deg, omega1 = {speed:g} rad/s, "
        f"{args.revolutions} revolutions; single joint fluctuation tan b sin b = {single:.6g}"
    )
    for name, run in (("Z (b2 = -b)", z), ("W (b2 = +b)", w)):
        residual = fluctuation(run["output_speed"], speed)
        print(
            f"  {name}, hold coupling, h = 1 ms: fluctuation {residual:.3e}, "
            f"{single / residual:.3g} times smaller than one joint's"
        )
    same = np.array_equal(z["output_speed"], w["output_speed"])
    print(f"  Z and W output speeds {'identical' if same else 'differ'}")
    print(
        "\nStep dependence (Z); fluctuation at the communication points, "
        "and sampled at the step ends:"
    )
    print(
        f"  {'coupling':8} {'h [s]':>7} {'fluctuation':>12} {'reduction':>10} {'order':>6} "
        f"{'at step end':>12} {'predicted':>10}"
    )
    for r in steps_rows:
        order = f"{r['order']:.2f}" if "order" in r else ""
        predicted = f"{r['predicted']:.3e}" if "predicted" in r else ""
        print(
            f"  {r['coupling']:8} {r['step']:7.0e} {r['fluctuation']:12.3e} "
            f"{r['reduction']:10.3g} {order:>6} {r['fluctuation_at_step_end']:12.3e} "
            f"{predicted:>10}"
        )
    print(f"\nYoke phase error (Z, hold coupling, h = {args.phase_step:g} s):")
    print(f"  {'error [deg]':>11} {'co-simulated':>13} {'exact':>11} {'/ single':>9}")
    for r in phase_rows:
        print(
            f"  {r['phase_error_deg']:11g} {r['fluctuation']:13.4e} {r['exact']:11.4e} "
            f"{r['fluctuation'] / single:9.3g}"
        )
    print(
        f"\nwrote {out / 'driveshaft_steps.csv'}, {out / 'driveshaft_phase.csv'}, "
        f"{out / 'driveshaft.png'}"
    )


if __name__ == "__main__":
    sys.exit(run_example(main))
