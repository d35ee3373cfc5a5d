"""6. The one-call step (issue 21): the joint against the plain floor in each
host, and the joint's Python alone.

The goals compare the joint with a plain pythonfmu FMU of the same interface
and an empty `do_step` (the plain floor, `floor`) in the same host: in the C
host of section 5 (tests/c_host, native loader, host thread keeping its
Python thread state: the floor at its best) and in FMPy's low-level loop of
section 1. Those rows reuse those sections' side-by-side measurements; once
the native loader serves values in C and enters Python once per doStep, the
same rows measure it.

The Python rows time, in one fresh process and in turns of `CHUNK` steps, what
a step costs before any host: the physics (`CardanJoint.step` and every
output), the slave's normal path (set_real of 6 inputs, do_step, get_real of
every output) and the slave's one-call step (`fast_step` on buffers of doubles,
as the loader will call it).
"""

import json
import re
import shutil
import statistics
import subprocess
import sys
import time

# The runtime's joint and its floors: the joint built without life (docs/life.md).
from cardan_joint.models.universal_joint.variables import WITHOUT_LIFE as table

from .step_cost import STEP_SIZE, TIMING_INPUTS
from .timing import ROOT, against, chunks, in_fresh_process, met, us

C_HOST_GOAL = 0.5  # joint / plain floor, both in the C host
FMPY_GOAL = 0.8  # joint / plain floor, both in FMPy's low-level loop
CHUNK = 2_000
# Issue 24: the joint's whole step in a C host <= 0.6 x the plain floor's 67.9 k
# instructions, of which the runtime adds <= 10 % over the Python step.
PYTHON_STEP_GOAL = 35_000  # instructions per fast_step (step and every output)
COUNTED_STEPS = (2_000, 12_000)  # two run lengths: start-up cancels in the difference
PYTHON_PATHS = ("physics", "slave set/do_step/get", "slave fast_step")


def _physics_stepper():
    from cardan_joint.models.universal_joint.model import CardanJoint

    joint = CardanJoint(False, **TIMING_INPUTS)  # the runtime's joint: without life
    step, outputs = joint.step, joint.outputs

    def run(first, length):
        for _ in range(length):
            if step(STEP_SIZE):  # a refused step would cost less than one taken
                raise RuntimeError("the physics refused a timing step")
            outputs()

    return run


def _slave():
    from cardan_joint.fmi.slave import ModelSlave

    class Joint(ModelSlave):
        model_folder = "universal_joint"
        build_settings = {"life": False}  # the runtime's joint: without life

    slave = Joint(instance_name="benchmark")
    slave.setup_experiment(0.0)
    slave.set_real(_references(slave, slave._refs.all_inputs), list(TIMING_INPUTS.values()))
    slave.exit_initialization_mode()
    return slave


def _references(slave, flat):
    """The value references of flat indices, from the slave's own table."""
    return [slave._FLAT.index((i,)) for i in flat]


def _normal_stepper():
    slave = _slave()
    refs = slave._refs
    inputs = _references(slave, refs.all_inputs)
    values, outputs = list(TIMING_INPUTS.values()), _references(slave, refs.all_outputs)
    set_real, do_step, get_real = slave.set_real, slave.do_step, slave.get_real

    def run(first, length):
        for step in range(first, first + length):
            set_real(inputs, values)
            do_step(step * STEP_SIZE, STEP_SIZE)
            get_real(outputs)

    return run


def _fast_stepper():
    slave = _slave()
    fast_step = slave.fast_step
    inputs = tuple(TIMING_INPUTS.values())

    # The loader passes the inputs as a tuple it builds in C (at no Python cost)
    # and converts the reply in C.
    def run(first, length):
        for step in range(first, first + length):
            reply = fast_step(step * STEP_SIZE, STEP_SIZE, inputs)
            if reply.__class__ is not tuple:
                raise RuntimeError("the slave refused a timing step")

    return run


def worker_python_step(steps, chunk):
    """Per-step wall and CPU time of each Python path, in turns of `chunk` steps."""
    runners = dict(zip(PYTHON_PATHS, (_physics_stepper(), _normal_stepper(), _fast_stepper())))
    wall = dict.fromkeys(runners, 0.0)
    cpu = dict.fromkeys(runners, 0.0)
    order = list(runners)
    for first, length in chunks(steps, chunk):
        for name in order:
            start, start_cpu = time.perf_counter(), time.process_time()
            runners[name](first, length)
            wall[name] += time.perf_counter() - start
            cpu[name] += time.process_time() - start_cpu
        order.reverse()
    return {name: {"wall": wall[name] / steps, "cpu": cpu[name] / steps} for name in runners}


def worker_python_steps(path, steps):
    """`steps` steps of one Python path, nothing timed: what callgrind counts."""
    runner = dict(zip(PYTHON_PATHS, (_physics_stepper, _normal_stepper, _fast_stepper)))[path]()
    runner(0, steps)
    return {}


def _instructions(path, steps):
    """Instructions callgrind counts for a worker process making `steps` steps."""
    request = json.dumps({"kind": "python_steps", "path": path, "steps": steps})
    run = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", sys.executable]
        + ["-m", "benchmarks", "--worker", request],
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=True,
    )
    return int(re.search(r"Collected : (\d+)", run.stderr).group(1))


def python_step_instructions():
    """Instructions per step of each Python path (callgrind, CPython as run here):
    the difference of two run lengths, so that start-up cancels; None without
    valgrind."""
    if shutil.which("valgrind") is None:
        return None
    short, long = COUNTED_STEPS
    return {
        path: (_instructions(path, long) - _instructions(path, short)) / (long - short)
        for path in PYTHON_PATHS
    }


def python_step(sizes):
    runs = [
        in_fresh_process("python_step", steps=sizes.steps, chunk=min(CHUNK, sizes.steps))
        for _ in range(sizes.runs)
    ]
    times = {
        clock: {name: statistics.median(run[name][clock] for run in runs) for name in PYTHON_PATHS}
        for clock in ("wall", "cpu")
    }
    return {**times, "instructions": python_step_instructions()}


def one_call_rows(python, cost, c_host, sizes):
    c_ratio = c_host["joint", "C host"] / c_host["plain", "C host"]
    loop = against(cost["loop"], "plain", "wall")
    runs = f"median of {sizes.runs} runs × {sizes.steps:,} steps"
    physics, normal, fast = (python["wall"][name] for name in PYTHON_PATHS)
    cpu = python["cpu"]
    return [
        f"| 6. C host: joint vs plain floor in the same host (section 5's rounds) | joint "
        f"{us(c_host['joint', 'C host'])}, floor {us(c_host['plain', 'C host'])}: "
        f"**×{c_ratio:.2f}** | ≤ ×{C_HOST_GOAL} | {met(c_ratio <= C_HOST_GOAL)} |",
        f"| 6. FMPy loop: joint vs plain floor (section 1's runs) | joint {us(loop['joint'])}, "
        f"floor {us(loop['floor'])}: **×{loop['ratio']:.2f}** | ≤ ×{FMPY_GOAL} | "
        f"{met(loop['ratio'] <= FMPY_GOAL)} |",
        f"| 6. the joint's Python per step, no host, {runs}: physics (step and "
        f"{len(table.OUTPUTS)} outputs), slave set/do_step/get, slave `fast_step` | "
        f"{us(physics)}, {us(normal)}, {us(fast)}: ÷ set/do_step/get ×{physics / normal:.2f}, "
        f"×{fast / normal:.2f} (CPU time {', '.join(us(cpu[name]) for name in PYTHON_PATHS)}) "
        "| (context) | |",
        *instruction_rows(python.get("instructions")),
    ]


def instruction_rows(counts):
    if not counts:
        return ["| 6. the joint's Python per step in instructions | valgrind not found | | |"]
    physics, normal, fast = (counts[name] for name in PYTHON_PATHS)
    return [
        f"| 6. the joint's Python per step in instructions (callgrind, {COUNTED_STEPS[1]:,} − "
        f"{COUNTED_STEPS[0]:,} steps): physics (step and {len(table.OUTPUTS)} outputs), slave "
        f"set/do_step/get, slave `fast_step` | {physics / 1e3:.1f} k, {normal / 1e3:.1f} k, "
        f"**{fast / 1e3:.1f} k** | `fast_step` ≤ {PYTHON_STEP_GOAL / 1e3:.0f} k | "
        f"{met(fast <= PYTHON_STEP_GOAL)} |"
    ]
