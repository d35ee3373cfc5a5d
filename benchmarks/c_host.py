"""5. Cost per step of the FMU in a C host next to FMPy's low-level loop (issue 11).

One step = set the 6 inputs, fmi2DoStep, get all outputs, as in `step_cost`.
The C host is tests/c_host (dlopen RTLD_LOCAL, empty environment: the FMU's
native loader starts Python itself and keeps one thread state for the host's
thread). Rounds interleave the hosts and FMUs, so the load other users put on
the machine hits every cell alike; the joint and the plain floor both carry
the native loader (see `floor`).
"""

import re
import statistics
import subprocess
import sys
import time

from .cases import Case
from .floor import JOINT
from .step_cost import instantiate, step_loop
from .timing import ROOT, met, us

HOSTS = ("C host", "FMPy loop")
GOAL = 1.0  # C host / FMPy loop, for the joint


def compile_c_host(workdir):
    sys.path.insert(0, str(ROOT / "tests"))
    try:
        from c_host.compile import compile_host
    finally:
        sys.path.remove(str(ROOT / "tests"))
    return compile_host(workdir / "c_host")


def c_host_seconds(host, unzipped, steps):
    run = subprocess.run(
        [str(host), "bench", unzipped, str(steps), *Case(JOINT).host_inputs()],
        env={"PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        check=True,
    )
    return 1e-6 * float(re.search(r"([0-9.]+) us/step", run.stdout).group(1))


def fmpy_loop_seconds(unzipped, steps):
    joint = instantiate(unzipped)
    try:
        began = time.perf_counter()
        step_loop(joint, steps)
        return (time.perf_counter() - began) / steps
    finally:
        joint.close()


def c_host_cost(host, fmus, sizes):
    """Median seconds per step {(fmu, host): s} over `sizes.runs` interleaved rounds."""
    chosen = {"joint": fmus["joint"], "plain": fmus["plain"]}
    times = {(name, where): [] for name in chosen for where in HOSTS}
    for _ in range(sizes.runs):
        for name, unzipped in chosen.items():
            times[name, "C host"].append(c_host_seconds(host, unzipped, sizes.steps))
            times[name, "FMPy loop"].append(fmpy_loop_seconds(unzipped, sizes.steps))
    return {key: statistics.median(values) for key, values in times.items()}


def c_host_rows(cost, sizes):
    ratio = cost["joint", "C host"] / cost["joint", "FMPy loop"]
    floor = cost["plain", "C host"] / cost["plain", "FMPy loop"]
    return [
        f"| 5. C host (tests/c_host, empty environment) vs FMPy low-level loop, same FMU, "
        f"median of {sizes.runs} interleaved rounds × {sizes.steps:,} steps | joint: C host "
        f"{us(cost['joint', 'C host'])}, FMPy {us(cost['joint', 'FMPy loop'])}: "
        f"**×{ratio:.2f}**; plain floor: C host {us(cost['plain', 'C host'])}, FMPy "
        f"{us(cost['plain', 'FMPy loop'])}: ×{floor:.2f} | ≤ ×{GOAL} | {met(ratio <= GOAL)} |",
    ]
