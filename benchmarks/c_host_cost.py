"""Cost per step of the FMU in a C host against FMPy's low-level loop (issue 11).

    .venv/bin/python benchmarks/c_host_cost.py [--steps N] [--rounds R]

One step = set the 6 inputs, fmi2DoStep, get all outputs, as in
run_benchmarks.py. Measured side by side in one run, rounds interleaved so that
the load other users put on the machine hits every row alike:

- the UniversalJoint FMU in tests/c_host (dlopen RTLD_LOCAL, empty environment,
  Python started by the FMU's own loader);
- the same FMU in FMPy's FMU2Slave loop in this Python process;
- run_benchmarks.py's plain pythonfmu floor FMU (the same variables, a do_step
  that does nothing), given the same loader, in both hosts: what pythonfmu and
  the host cost by themselves.

Prints a markdown table of the median µs per step.
"""

import argparse
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path[:0] = [str(ROOT / "fmu_src"), str(ROOT / "tests")]

from run_benchmarks import STEP_SIZE, TIMING_INPUTS, build_floor_fmu  # noqa: E402

from c_host.compile import compile_host  # noqa: E402
from cardan_joint import variables as table  # noqa: E402
from cardan_joint.native import install_loader  # noqa: E402


def c_host_us(host, unzipped, steps):
    run = subprocess.run([str(host), "bench", unzipped, str(steps)], env={"PATH": "/usr/bin:/bin"},
                         capture_output=True, text=True, check=True)
    return float(re.search(r"([0-9.]+) us/step", run.stdout).group(1))


def fmpy_loop_us(unzipped, steps):
    from fmpy import read_model_description
    from fmpy.fmi2 import FMU2Slave

    description = read_model_description(unzipped)
    fmu = FMU2Slave(guid=description.guid, unzipDirectory=unzipped,
                    modelIdentifier=description.coSimulation.modelIdentifier, instanceName="bench")
    fmu.instantiate()
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    references = {v.name: v.valueReference for v in description.modelVariables}
    inputs, values = [references[n] for n in TIMING_INPUTS], list(TIMING_INPUTS.values())
    outputs = [references[n] for n in table.OUTPUTS]
    set_real, do_step, get_real, h = fmu.setReal, fmu.doStep, fmu.getReal, STEP_SIZE
    began = time.perf_counter()
    for step in range(steps):
        set_real(inputs, values)
        do_step(step * h, h)
        get_real(outputs)
    elapsed = time.perf_counter() - began
    fmu.terminate()
    fmu.freeInstance()
    return 1e6 * elapsed / steps


def prepare(workdir: Path):
    from fmpy import extract

    subprocess.run([sys.executable, str(ROOT / "build_fmu.py"), "--dest", str(workdir)],
                   check=True, capture_output=True)
    floor = build_floor_fmu("plain", workdir)
    install_loader(floor, floor.stem)
    return {name: str(extract(str(fmu), unzipdir=str(workdir / name)))
            for name, fmu in (("UniversalJoint", workdir / "UniversalJoint.fmu"),
                              ("pythonfmu floor", floor))}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=100_000)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="c_host_bench_") as workdir:
        workdir = Path(workdir)
        host = compile_host(workdir / "host")
        fmus = prepare(workdir)
        times = {(name, where): [] for name in fmus for where in ("C host", "FMPy loop")}
        for _ in range(args.rounds):
            for name, unzipped in fmus.items():
                times[name, "C host"].append(c_host_us(host, unzipped, args.steps))
                times[name, "FMPy loop"].append(fmpy_loop_us(unzipped, args.steps))
    median = {key: statistics.median(values) for key, values in times.items()}
    print(f"Median µs per step (set 6 inputs, doStep, get {len(table.OUTPUTS)} outputs), "
          f"{args.steps} steps, {args.rounds} interleaved rounds\n")
    print("| FMU | C host | FMPy low-level loop | C host / FMPy |\n|---|---|---|---|")
    for name in fmus:
        c, loop = median[name, "C host"], median[name, "FMPy loop"]
        print(f"| {name} | {c:.1f} | {loop:.1f} | {c / loop:.2f} |")


if __name__ == "__main__":
    main()
