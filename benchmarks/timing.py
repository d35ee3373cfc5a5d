"""What every measurement shares: fresh worker processes, clocks, medians, formatting.

Every timing runs in a fresh process (`python -m benchmarks --worker REQUEST`,
the request and the answer in JSON): how earlier work left the interpreter and
malloc's heap changes times by up to 1.5x, and FMUs compared with each other
are then loaded together before anything is timed.
"""

import json
import math
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def run_checked(arguments, **kwargs):
    """Run this interpreter with `arguments`; raise with its output if it fails."""
    command = [sys.executable, *map(str, arguments)]
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    return result


def in_fresh_process(kind: str, **arguments):
    """The answer of the worker `kind` (benchmarks.runner.WORKERS) run in a new process."""
    request = json.dumps({"kind": kind, **arguments})
    result = run_checked(["-m", "benchmarks", "--worker", request], cwd=ROOT)
    return json.loads(result.stdout.strip().splitlines()[-1])


def chunks(steps, chunk):
    """(first step, length) of consecutive chunks covering `steps` steps."""
    return [(first, min(chunk, steps - first)) for first in range(0, steps, chunk)]


def best_time(function, repeats=5):
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def peak_rss_kib():
    """This process's peak resident set (VmHWM). Not getrusage's ru_maxrss: Linux
    carries that over fork and exec, so a worker would report its parent's peak."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1])
    return 0


class StepClock:
    """simulate_fmu's step_finished callback: times the stepping alone, without
    instantiation, initialisation and teardown."""

    def __init__(self):
        self.calls = 0
        self.first = self.last = (0.0, 0.0)

    def __call__(self, time_, recorder):
        self.last = (time.perf_counter(), time.process_time())
        if self.calls == 0:
            self.first = self.last
        self.calls += 1
        return True

    def per_step(self):
        steps = self.calls - 1
        return {
            "wall": (self.last[0] - self.first[0]) / steps,
            "cpu": (self.last[1] - self.first[1]) / steps,
        }


def against(runs, floor, clock="wall"):
    """Median per-step times of the joint and a floor over the runs, their ratio,
    and the range of the ratios within single runs."""
    joint_times = [run["times"]["joint"][clock] for run in runs]
    floor_times = [run["times"][floor][clock] for run in runs]
    joint, floor_median = statistics.median(joint_times), statistics.median(floor_times)
    within = [j / f for j, f in zip(joint_times, floor_times)]
    return {
        "joint": joint,
        "floor": floor_median,
        "ratio": joint / floor_median,
        "pair_min": min(within),
        "pair_max": max(within),
        "runs": len(runs),
    }


def us(seconds):
    return f"{seconds * 1e6:.1f} µs"


def met(ok):
    return "**yes**" if ok else "**NO**"


def machine():
    cpu = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return (
        f"{cpu} ({os.cpu_count()} cores), Python {platform.python_version()}, "
        f"{platform.system()} {platform.machine()}"
    )
