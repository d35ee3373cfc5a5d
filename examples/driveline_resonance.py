"""Run-up of a bent compliant joint through the driveline's torsional resonance.

    python examples/driveline_resonance.py [--out results]

The CompliantJoint FMU (bent 20 deg) drives the InertiaLoad FMU through its
spring-damper, co-simulated by a plain Jacobi master (FMPy's low-level API); the
input shaft runs up slowly at a constant rate (the master prescribes its
motion). The joint's output angle carries a second-order fluctuation (twice the
input speed, plus a weaker fourth order); it meets the torsional mode
omega_n = sqrt(k / J_load) at the input speed omega_n / 2. Writes
driveline_resonance.png (twist and output torque against input speed, the
predicted resonance speed marked), driveline_resonance_orders.png (spectrum of
the output torque against input speed with the 2nd and 4th order lines) and
driveline_resonance.csv to --out (tools/gallery.py copies the PNGs into
docs/img); prints the peak.
"""

import argparse
import math
import sys
import tempfile
from pathlib import Path

import numpy as np

from cardan_joint import results
from cardan_joint.build import build
from cardan_joint.host.driveline_system import torsional_step
from cardan_joint.host.instance import FmuInstance
from cardan_joint.host.plotting import pyplot, save_figure
from cardan_joint.units import RAD_PER_S_TO_RPM

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _support import output_folder, positive, run_example  # noqa: E402

BEND = math.radians(20.0)
STIFFNESS, LOAD_INERTIA, DAMPING_RATIO = 2000.0, 0.5, 0.05
OMEGA_N = math.sqrt(STIFFNESS / LOAD_INERTIA)  # the input motion is prescribed: J_in = inf
PREDICTED = OMEGA_N / 2  # input speed where the 2nd order meets the mode
RATE = 0.5  # rad/s2: slow against the mode's build-up time 1 / (zeta omega_n)


def run_up(joint_fmu, load_fmu, speed_start, speed_stop, rate=RATE) -> dict:
    """Rows (time, input_speed, twist_angle, output_torque) of a run-up from
    `speed_start` to `speed_stop` [rad/s] at `rate` [rad/s2], the step by the
    stability rule (`torsional_step`)."""
    _, damping, h = torsional_step(STIFFNESS, math.inf, LOAD_INERTIA, DAMPING_RATIO)
    joint_start = {
        "bend_angle": BEND,
        "input_speed": speed_start,
        "input_acceleration": rate,
        "output_speed": speed_start,
        "torsional_stiffness": STIFFNESS,
        "torsional_damping": damping,
    }
    load_start = {"inertia": LOAD_INERTIA, "drag": 0.0, "constant_torque": 0.0}
    load_start["speed_start"] = speed_start
    n = int((speed_stop - speed_start) / rate / h)
    rows = {key: np.empty(n) for key in ("time", "input_speed", "twist_angle", "output_torque")}
    with (
        FmuInstance.open(joint_fmu, name="joint", start_values=joint_start) as joint,
        FmuInstance.open(load_fmu, name="load", start_values=load_start) as load,
    ):
        for k in range(n):
            out = joint.get("input_speed", "twist_angle", "output_torque")
            motion = load.get("speed", "acceleration")
            joint.set(output_speed=motion["speed"], output_acceleration=motion["acceleration"])
            load.set(drive_torque=out["output_torque"])
            for instance in (joint, load):
                instance.time = k * h
                instance.step(h)
            rows["time"][k] = k * h
            for key in ("input_speed", "twist_angle", "output_torque"):
                rows[key][k] = out[key]
    return rows


def envelope(rows, key="twist_angle"):
    """(mean input speed, half peak-to-peak of `key`) over windows of one mode period."""
    window = max(1, int(2 * math.pi / OMEGA_N / (rows["time"][1] - rows["time"][0])))
    m = len(rows["time"]) // window
    cut = lambda name: rows[name][: m * window].reshape(m, window)  # noqa: E731
    return cut("input_speed").mean(axis=1), np.ptp(cut(key), axis=1) / 2


def resonance_speed(rows) -> float:
    """Input speed [rad/s] at the largest twist amplitude."""
    speed, amplitude = envelope(rows)
    return float(speed[np.argmax(amplitude)])


def plot_run_up(rows, path):
    plt = pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    rpm = rows["input_speed"] * RAD_PER_S_TO_RPM
    for ax, key, unit, factor in (
        (axes[0], "twist_angle", "deg", 180 / math.pi),
        (axes[1], "output_torque", "N.m", 1.0),
    ):
        ax.plot(rpm, rows[key] * factor, lw=0.4)
        ax.axvline(PREDICTED * RAD_PER_S_TO_RPM, color="C3", ls="--", label="omega_n / 2")
        ax.set_ylabel(f"{key} [{unit}]")
        ax.legend(loc="upper left")
    speed = resonance_speed(rows)
    axes[0].set_title(
        f"Run-up, bend {math.degrees(BEND):g} deg: peak at {speed * RAD_PER_S_TO_RPM:.1f} rpm, "
        f"predicted {PREDICTED * RAD_PER_S_TO_RPM:.1f} rpm"
    )
    axes[1].set_xlabel("input speed [rpm]")
    return save_figure(fig, path)


def plot_orders(rows, path, seconds=2.0):
    """Spectrum of the output torque over windows of `seconds`, against input speed."""
    plt = pyplot()
    h = rows["time"][1] - rows["time"][0]
    window = int(seconds / h)
    m = len(rows["time"]) // window
    torque = rows["output_torque"][: m * window].reshape(m, window)
    torque = (torque - torque.mean(axis=1, keepdims=True)) * np.hanning(window)
    spectrum = np.abs(np.fft.rfft(torque, axis=1)) * 4 / window
    frequency = np.fft.rfftfreq(window, h)
    speed = rows["input_speed"][: m * window].reshape(m, window).mean(axis=1) * RAD_PER_S_TO_RPM
    shown = frequency <= 5 * speed.max() / 60
    fig, ax = plt.subplots(figsize=(9, 5))
    mesh = ax.pcolormesh(
        speed, frequency[shown], 20 * np.log10(spectrum[:, shown].T + 1e-9), shading="nearest"
    )
    fig.colorbar(mesh, label="output torque amplitude [dB re 1 N.m]")
    for order in (2, 4):
        ax.plot(speed, order * speed / 60, "w--", lw=0.8)
        ax.annotate(f"order {order}", (speed[-1], order * speed[-1] / 60), color="w", ha="right")
    ax.axhline(OMEGA_N / (2 * math.pi), color="C3", ls=":", label="natural frequency")
    ax.set_xlabel("input speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.legend(loc="upper left")
    ax.set_title("Order view of the output torque during the run-up")
    return save_figure(fig, path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="results", help="folder for the results")
    parser.add_argument("--rate", type=positive, default=RATE, help="run-up rate [rad/s2]")
    args = parser.parse_args(argv)
    out = output_folder(args)
    with tempfile.TemporaryDirectory(prefix="driveline_resonance_") as work:
        joint, load = (build(work, model=m) for m in ("CompliantJoint", "InertiaLoad"))
        rows = run_up(joint, load, 0.4 * PREDICTED, 1.6 * PREDICTED, args.rate)
    results.write_csv(rows, out / "driveline_resonance.csv")
    figures = [
        plot_run_up(rows, out / "driveline_resonance.png"),
        plot_orders(rows, out / "driveline_resonance_orders.png"),
    ]
    speed = resonance_speed(rows)
    print(
        f"twist peak at input speed {speed:.3f} rad/s, predicted omega_n / 2 = {PREDICTED:.3f} "
        f"rad/s ({100 * (speed / PREDICTED - 1):+.2f} %); wrote {', '.join(map(str, figures))}"
    )


if __name__ == "__main__":
    sys.exit(run_example(main))
