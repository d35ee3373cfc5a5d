"""A motor driving a load inertia through the joint: the torque path in a power loop.

The master (FMPy's low-level API) closes the driveline around the FMU:

* the load side: `load_torque = J_load * output_acceleration + T_ext`, with
  T_ext = T_ext0 + c * output_speed (a viscous machine), fed back every step;
* the motor side: J_motor * a1 = T_motor - input_torque. The input torque
  depends on the input acceleration a1 (crosspiece and load inertia seen
  through the joint) and a1 on it: an algebraic loop. The FMU's direct
  feedthrough makes it exact to close: input_torque is affine in a1, so two
  probes give the root.
* Heun's method on the motor speed, with the FMU rolled back between predictor
  and corrector (fmi2GetFMUstate / fmi2SetFMUstate): second order in the step.

    python examples/motor_load.py            -> results/motor_load.{csv,png}
"""

import math
import sys

import numpy as np
from _support import (
    example_fmu,
    example_parser,
    legend_outside,
    output_folder,
    positive,
    run_example,
)

from cardan_joint import results
from cardan_joint.host.plotting import pyplot, save_figure
from cardan_joint.host.simulate import DEFAULT_FMU
from cardan_joint.units import RAD_PER_S_TO_RPM

# (A keyword dict like tests/test_robustness.py's inputs: alike in shape only.)
DEFAULTS = dict(
    bend_angle=math.radians(30.0),
    yoke_phase=0.0,
    inertia=(0.004, 0.004, 0.008),
    J_motor=0.05,
    J_load=0.5,
    motor_torque=60.0,
    external_torque=10.0,
    viscous=0.2,
    speed0=50.0,
)
RECORDED = (
    "input_angle",
    "output_angle",
    "output_speed",
    "output_acceleration",
    "input_torque",
    "input_yoke_moment",
    "output_yoke_moment",
    "crosspiece_kinetic_energy",
)


class Driveline:
    """The FMU instance plus the master's closure of the motor and load sides."""

    def __init__(self, fmu_path, p):
        from cardan_joint.host.instance import FmuInstance

        self.p = p
        i1, i2, i3 = p["inertia"]
        self.joint = FmuInstance.open(
            fmu_path,
            start_values=dict(
                bend_angle=p["bend_angle"],
                yoke_phase=p["yoke_phase"],
                crosspiece_inertia_1=i1,
                crosspiece_inertia_2=i2,
                crosspiece_inertia_3=i3,
                input_speed=p["speed0"],
            ),
        )
        self._set, self.get = self.joint.set, self.joint.get

    def _torque_residual(self, speed, acceleration):
        """J_motor a1 - (T_motor - T1(a1)), with the load fed back for this a1."""
        p = self.p
        self._set(input_speed=speed, input_acceleration=acceleration)
        out = self.get("output_speed", "output_acceleration")
        load = (
            p["J_load"] * out["output_acceleration"]
            + p["external_torque"]
            + p["viscous"] * out["output_speed"]
        )
        self._set(load_torque=load)
        t1 = self.get("input_torque")["input_torque"]
        return p["J_motor"] * acceleration - (p["motor_torque"] - t1)

    def close_loop(self, speed):
        """Solve for the input acceleration at this state; leave the FMU's inputs consistent."""
        r0 = self._torque_residual(speed, 0.0)
        r1 = self._torque_residual(speed, 1.0)
        acceleration = -r0 / (r1 - r0)
        self._torque_residual(speed, acceleration)
        return acceleration

    def heun_step(self, time, speed, h):
        joint = self.joint
        joint.time = time
        a_start = self.close_loop(speed)
        saved = joint.get_state()
        joint.step(h)
        a_end = self.close_loop(speed + a_start * h)
        joint.set_state(saved)
        joint.free_state(saved)
        joint.time = time
        a_mean = 0.5 * (a_start + a_end)
        self._set(input_speed=speed, input_acceleration=a_mean)
        joint.step(h)
        return speed + a_mean * h

    def close(self):
        self.joint.close()


def run(fmu_path=DEFAULT_FMU, stop_time=1.0, h=1e-3, **overrides):
    """Co-simulate; return a dict of arrays at every communication point."""
    p = {**DEFAULTS, **overrides}
    line = Driveline(fmu_path, p)
    n = int(round(stop_time / h))
    rows = {
        name: np.empty(n + 1)
        for name in ("time", "input_speed", "input_acceleration", "load_torque") + RECORDED
    }
    speed = p["speed0"]
    try:
        for k in range(n + 1):
            time = k * h
            acceleration = line.close_loop(speed)  # outputs consistent at this point
            values = line.get("load_torque", *RECORDED)
            rows["time"][k], rows["input_speed"][k], rows["input_acceleration"][k] = (
                time,
                speed,
                acceleration,
            )
            for name, value in values.items():
                rows[name][k] = value
            if k < n:
                speed = line.heun_step(time, speed, h)
    finally:
        line.close()
    return rows


def plot(rows, p, path, revolutions=4):
    plt = pyplot()
    last = rows["input_angle"][-1] - revolutions * 2 * math.pi
    window = rows["input_angle"] >= last
    t = rows["time"][window]
    fig, axes = plt.subplots(3, 1, figsize=(11, 8.5), sharex=True)
    axes[0].plot(t, rows["input_torque"][window], label="input torque T1 (motor side)")
    axes[0].plot(t, rows["load_torque"][window], "--", label="load torque T_L (load side)")
    axes[0].set_ylabel("torque [N.m]")
    axes[0].set_title(
        f"Motor -> Cardan joint at {math.degrees(p['bend_angle']):.0f} deg -> "
        f"load inertia: the last {revolutions} input revolutions"
    )
    axes[1].plot(t, rows["output_speed"][window] * RAD_PER_S_TO_RPM, label="output shaft")
    axes[1].plot(
        t, rows["input_speed"][window] * RAD_PER_S_TO_RPM, "k--", label="input shaft (motor)"
    )
    axes[1].set_ylabel("speed [rpm]")
    axes[2].plot(t, rows["input_yoke_moment"][window], label="input yoke")
    axes[2].plot(t, rows["output_yoke_moment"][window], label="output yoke")
    axes[2].set_ylabel("secondary couple [N.m]")
    axes[2].set_xlabel("time [s]")
    for ax in axes:
        legend_outside(ax)
    save_figure(fig, path)


def main(argv=None):
    parser = example_parser(__doc__)
    parser.add_argument("--stop-time", type=positive, default=1.0, help="[s] (default 1)")
    parser.add_argument("--step", type=float, default=1e-3)
    args = parser.parse_args(argv)
    args.fmu = example_fmu(args)
    out = output_folder(args)
    rows = run(args.fmu, args.stop_time, args.step)
    results.write_csv(rows, out / "motor_load.csv")
    plot(rows, DEFAULTS, out / "motor_load.png")
    t1, tl = rows["input_torque"][-200:], rows["load_torque"][-200:]
    print(f"wrote {out / 'motor_load.csv'} and {out / 'motor_load.png'}")
    print(
        f"last revolutions: input torque {t1.min():.1f}..{t1.max():.1f} N.m, load torque "
        f"{tl.min():.1f}..{tl.max():.1f} N.m, secondary couples up to "
        f"{rows['input_yoke_moment'].max():.1f} / {rows['output_yoke_moment'].max():.1f} N.m"
    )


if __name__ == "__main__":
    sys.exit(run_example(main))
