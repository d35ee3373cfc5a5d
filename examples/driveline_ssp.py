"""Motor -> drive element -> Load as an SSP system, run by FMPy, OSP libcosim and Ecos.

    python examples/driveline_ssp.py [--drive Propshaft|UniversalJoint] [--out results]

Builds the Motor, Load and drive FMUs (each starting at the system's parameter
values), writes results/Driveline.ssp (the three FMUs, their connections, one
parameter set per component, all named "Driveline", OMSimulator's
annotations), which needs no host; then runs it with FMPy's `simulate_ssp`,
with libcosim and with Ecos (the `cosim` and `ecos` extras: without them it
stops after writing the SSP and names them), writes
results/driveline_ssp_fmpy.csv, results/driveline_ssp_libcosim.csv,
results/driveline_ssp_ecos.csv and results/driveline_ssp.png, and prints how
far the hosts differ at three step sizes and the torque loop's stability
against the load-to-motor inertia ratio.
"""

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

from cardan_joint import results
from cardan_joint.extras import MissingExtra, require
from cardan_joint.host import driveline_system as system
from cardan_joint.host.ecos import require_ecos
from cardan_joint.host.plotting import pyplot, save_figure
from cardan_joint.units import RAD_PER_S_TO_RPM

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _support import output_folder, run_example  # noqa: E402

STOP_TIME, STEP = 1.0, 1e-3


def host_convergence(ssp, steps=(1e-3, 5e-4, 2.5e-4), stop_time=0.5):
    """{step: (largest |FMPy - libcosim|, |FMPy - Ecos|) of the motor speed}: the hosts
    differ only in the first step's inputs (see docs/cosimulation.md), so this falls in
    proportion to the step."""
    outcome = {}
    for h in steps:
        fmpy_rows = system.run_fmpy(ssp, stop_time, h)
        outcome[h] = tuple(
            system.host_difference(fmpy_rows, run(ssp, stop_time, h))["Motor.speed"]
            for run in (system.run_libcosim, system.run_ecos)
        )
    return outcome


def loop_stability(fmus, drive, folder, ratios=(0.5, 0.9, 2.0), steps=(1e-3, 1e-4), n_steps=200):
    """{(inertia ratio, step): True if the torque loop stays bounded over `n_steps`} on a
    straight, massless drive element (the load's inertia meets the motor's unchanged).
    Run in libcosim, which applies the bindings: the FMUs are the main system's."""
    motor_inertia = system.MOTOR_PARAMETERS["rotor_inertia"]
    rigid = system.MOTOR_PARAMETERS["stall_torque"] / motor_inertia
    outcome = {}
    for ratio in ratios:
        ssp = system.write_driveline_ssp(
            Path(folder) / f"ratio_{ratio}.ssp",
            fmus,
            drive,
            drive_parameters=system.STRAIGHT_DRIVE_PARAMETERS.get(drive),
            load={"inertia": ratio * motor_inertia},
        )
        for h in steps:
            try:
                # A straight drive warns of its working angles, a runaway of its
                # inputs: both expected here, so libcosim shows errors only.
                rows = system.run_libcosim(ssp, n_steps * h, h, log_level="error")
                outcome[ratio, h] = bool(np.max(np.abs(rows["Motor.acceleration"])) < 10 * rigid)
            except RuntimeError:  # a step refused: the loop ran away
                outcome[ratio, h] = False
    return outcome


def plot(fmpy_rows, libcosim_rows, path, drive):
    plt = pyplot()
    fig, axes = plt.subplots(3, 1, figsize=(11, 8), sharex=True)
    rpm = RAD_PER_S_TO_RPM
    for rows, style, host in ((libcosim_rows, "-", "libcosim"), (fmpy_rows, "--", "FMPy")):
        axes[0].plot(rows["time"], rows["Motor.speed"] * rpm, style, label=f"motor ({host})")
        axes[0].plot(
            rows["time"],
            rows["Drive.output_speed"] * rpm,
            style,
            lw=0.7,
            label=f"load shaft ({host})",
        )
        axes[1].plot(
            rows["time"],
            rows["Drive.input_torque"],
            style,
            lw=0.7,
            label=f"drive input torque ({host})",
        )
        axes[1].plot(
            rows["time"], rows["Load.torque"], style, lw=0.7, label=f"load torque ({host})"
        )
    difference = fmpy_rows["Motor.speed"] - libcosim_rows["Motor.speed"][1:]
    axes[2].plot(fmpy_rows["time"], difference * rpm)
    axes[0].set_ylabel("speed [rpm]")
    axes[1].set_ylabel("torque [N.m]")
    axes[2].set_ylabel("motor speed\nFMPy - libcosim [rpm]")
    axes[2].set_xlabel("time [s]")
    axes[0].set_title(f"SSP system Motor -> {drive} -> Load, step {STEP:g} s")
    for ax in axes:  # beside the panel: a legend on the data hid the torque minima
        if ax.get_legend_handles_labels()[0]:
            ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7, borderaxespad=0)
    save_figure(fig, path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--drive",
        default=system.DRIVE,
        choices=sorted(system.DRIVE_PARAMETERS),
        help="drive element model (default: %(default)s)",
    )
    parser.add_argument("--out", default="results", help="folder for the results")
    args = parser.parse_args(argv)
    out = output_folder(args)
    with tempfile.TemporaryDirectory(prefix="driveline_ssp_") as work:
        parameters = system.system_parameters(args.drive)
        fmus = system.build_fmus(work, args.drive, parameters=parameters)
        ssp = system.write_driveline_ssp(out / "Driveline.ssp", fmus, args.drive, STOP_TIME)
        missing = []
        for check in (
            lambda: require("libcosimpy", "cosim", "running it in libcosim"),
            lambda: require_ecos("running it in Ecos"),
        ):
            try:
                check()
            except MissingExtra as error:
                missing.append(str(error))
        if missing:
            sys.exit(f"driveline_ssp: wrote {ssp}; {'; '.join(missing)}")
        fmpy_rows = system.run_fmpy(ssp, STOP_TIME, STEP)
        libcosim_rows = system.run_libcosim(ssp, STOP_TIME, STEP)
        ecos_rows = system.run_ecos(ssp, STOP_TIME, STEP)
        written = [ssp]
        for host, rows in (("fmpy", fmpy_rows), ("libcosim", libcosim_rows), ("ecos", ecos_rows)):
            written.append(results.write_csv(rows, out / f"driveline_ssp_{host}.csv"))
        plot(fmpy_rows, libcosim_rows, out / "driveline_ssp.png", args.drive)
        print(f"wrote {', '.join(map(str, written))} and {out / 'driveline_ssp.png'}")
        print("largest difference of the motor speed over 0.5 s, FMPy - libcosim, FMPy - Ecos:")
        for h, (libcosim, ecos) in host_convergence(ssp).items():
            print(f"  step {h:g} s: {libcosim:.3e} rad/s, {ecos:.3e} rad/s")
        print("torque loop bounded (load/motor inertia ratio, step):")
        for (ratio, h), bounded in loop_stability(fmus, args.drive, work).items():
            print(f"  ratio {ratio:g}, step {h:g} s: {'bounded' if bounded else 'DIVERGES'}")


if __name__ == "__main__":
    sys.exit(run_example(main))
