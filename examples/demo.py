"""Demonstration co-simulation of the UniversalJoint FMU.

A driveline run-up through a bending joint: the input shaft accelerates from
300 to 1500 rpm in 2 s while the bend angle swings from 0 to 30 degrees and
back, against a 200 N.m load. Writes results/demo.csv and results/demo.png.

    python build_fmu.py && python examples/demo.py
"""

import math
import sys

import numpy as np
from _support import example_fmu, example_parser, output_folder, positive, run_example

from cardan_joint import results
from cardan_joint.host.csv_run import column_units
from cardan_joint.host.fmu_info import FmuInfo
from cardan_joint.host.plotting import pyplot, save_figure
from cardan_joint.host.simulate import simulate
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.units import RAD_PER_S_TO_RPM, RAD_TO_DEG, RPM_TO_RAD_PER_S


def demo_inputs(stop_time=2.0, step=1e-3):
    t = np.arange(0.0, stop_time + step / 2, step)
    signal = np.zeros(len(t), dtype=[("time", float)] + [(n, float) for n in table.INPUTS])
    signal["time"] = t
    ramp = (1500 - 300) * RPM_TO_RAD_PER_S / stop_time
    signal["input_speed"] = 300 * RPM_TO_RAD_PER_S + ramp * t
    signal["input_acceleration"] = ramp
    # Bend angle 15 deg (1 - cos(pi t)): 0 -> 30 deg -> 0, with exact rate and acceleration.
    w = 2 * math.pi / stop_time
    amplitude = math.radians(15)
    signal["bend_angle"] = amplitude * (1 - np.cos(w * t))
    signal["bend_angle_rate"] = amplitude * w * np.sin(w * t)
    signal["bend_angle_acceleration"] = amplitude * w * w * np.cos(w * t)
    signal["load_torque"] = 200.0
    return signal


def plot(result, inputs, path):
    plt = pyplot()
    t = result["time"]
    fig, axes = plt.subplots(4, 1, figsize=(9, 11), sharex=True)
    axes[0].plot(t, result["output_speed"] * RAD_PER_S_TO_RPM, lw=0.8, label="output shaft")
    axes[0].plot(
        inputs["time"], inputs["input_speed"] * RAD_PER_S_TO_RPM, "k--", lw=1, label="input shaft"
    )
    axes[0].set_ylabel("speed [rpm]")
    axes[0].legend(loc="upper left")
    axes[0].set_title("Run-up through a Cardan joint bending 0 -> 30 -> 0 deg, 200 N.m load")
    axes[1].plot(t, result["cardan_error"] * RAD_TO_DEG, lw=0.8, color="tab:purple")
    axes[1].set_ylabel("cardan error [deg]")
    # The Euler torque on the crosspiece, in its own frame: along the input yoke's
    # pin, along the output yoke's pin, and normal to both.
    components = ("input pin", "output pin", "normal to the pins")
    for k, color in enumerate(("tab:blue", "tab:orange", "tab:green"), 1):
        label = f"M{k}: {components[k - 1]}"
        axes[2].plot(t, result[f"crosspiece_torque_{k}"], lw=0.8, color=color, label=label)
    axes[2].set_ylabel("crosspiece torque [N.m]")
    axes[2].legend(loc="upper left")  # one column: clear of the peaks
    axes[3].plot(t, result["input_torque"], lw=0.8, label="input torque T1")
    axes[3].plot(t, result["input_yoke_moment"], lw=0.8, label="input yoke secondary couple")
    axes[3].plot(t, result["output_yoke_moment"], lw=0.8, label="output yoke secondary couple")
    axes[3].set_ylabel("torque [N.m]")
    axes[3].set_xlabel("time [s]")
    axes[3].set_ylim(top=axes[3].get_ylim()[1] * 1.3)
    axes[3].legend(loc="upper left", ncol=3, fontsize=8)
    save_figure(fig, path)


def main(argv=None):
    parser = example_parser(__doc__)
    parser.add_argument("--stop-time", type=positive, default=2.0, help="[s] (default 2)")
    args = parser.parse_args(argv)
    args.fmu = example_fmu(args)
    out = output_folder(args)
    inputs = demo_inputs(args.stop_time)
    result = simulate(
        args.fmu,
        stop_time=args.stop_time,
        output_interval=1e-3,
        inputs=inputs,
        start_values={
            "crosspiece_inertia_1": 0.004,
            "crosspiece_inertia_2": 0.004,
            "crosspiece_inertia_3": 0.008,
        },
    )
    # Each column titled with its SI unit, as `cardan-joint simulate` writes.
    results.write_csv(result, out / "demo.csv", units=column_units(FmuInfo.read(args.fmu)))
    plot(result, inputs, out / "demo.png")
    swing = result["output_speed"] / np.interp(
        result["time"], inputs["time"], inputs["input_speed"]
    )
    print(f"wrote {out / 'demo.csv'} ({len(result)} rows) and {out / 'demo.png'}")
    print(
        f"output/input speed ratio swung between {swing.min():.4f} and {swing.max():.4f}; "
        f"peak input torque {result['input_torque'].max():.1f} N.m, peak secondary couples "
        f"{result['input_yoke_moment'].max():.1f} / {result['output_yoke_moment'].max():.1f} N.m"
    )


if __name__ == "__main__":
    sys.exit(run_example(main))
