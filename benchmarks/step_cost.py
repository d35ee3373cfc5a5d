"""1. Cost per step of the joint next to the floors, under FMPy's low-level loop
and under `simulate_fmu`.

The FMUs compared are loaded in one fresh process, then stepped in turns of
`LOOP_CHUNK` steps: a change in the load other users put on the machine hits
all of them within milliseconds, so their ratio holds where absolute times do not.
"""

import time

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models import discover

from .cases import STEP, Case
from .floor import JOINT
from .timing import StepClock, against, chunks, in_fresh_process, met, peak_rss_kib, us

# The joint's inputs at the benchmarks' operating point (every term of the
# physics active: speed ramp, bend rate, load), by name.
TIMING_INPUTS = Case(JOINT).inputs()
STEP_SIZE = STEP
# FMUs timed side by side take turns every this many steps (~30 ms; ~0.5 s
# under simulate_fmu, whose set-up is not timed but should stay rare).
LOOP_CHUNK = 1_000
SIMULATE_CHUNK = 10_000
GOALS = {"loop": 0.7, "simulate": 0.8}  # issue 32: the joint / the plain floor


def instantiate(unzipped):
    from fmpy import read_model_description

    return FmuInstance(read_model_description(unzipped), unzipped, name="benchmark")


def step_loop(joint, steps, first_step=0):
    """The low-level master: set all inputs, step, read all outputs. On the FMU's
    own methods, bound once: the helper's name lookup is not what is measured."""
    references = joint.references
    inputs = [references[name] for name in TIMING_INPUTS]
    values = list(TIMING_INPUTS.values())
    outputs = [references[name] for name in discover()[JOINT].table().OUTPUTS]
    set_real, do_step, get_real = joint.fmu.setReal, joint.fmu.doStep, joint.fmu.getReal
    h = STEP_SIZE
    for step in range(first_step, first_step + steps):
        set_real(inputs, values)
        do_step(step * h, h)
        get_real(outputs)


def worker_loop(fmus, steps, chunk):
    """All FMUs loaded first, then stepped in turns of `chunk` steps: no load or
    unload happens while anything is timed."""
    instances = {name: instantiate(unzipped) for name, unzipped in fmus.items()}
    wall = dict.fromkeys(fmus, 0.0)
    cpu = dict.fromkeys(fmus, 0.0)
    order = list(fmus)
    peak_before = peak_rss_kib()
    for first, length in chunks(steps, chunk):
        for name in order:
            # CPU time beside wall time: on a shared machine the process is
            # descheduled at times, which wall time counts and CPU time does not.
            start, start_cpu = time.perf_counter(), time.process_time()
            step_loop(instances[name], length, first)
            wall[name] += time.perf_counter() - start
            cpu[name] += time.process_time() - start_cpu
        order.reverse()  # nobody always runs right after the same one
    peak_after = peak_rss_kib()
    for joint in instances.values():
        joint.close()
    return {
        "times": {name: {"wall": wall[name] / steps, "cpu": cpu[name] / steps} for name in fmus},
        "peak_rss_kib": peak_after,
        "peak_rss_growth_kib": peak_after - peak_before,
    }


def constant_input_signal(stop_time):
    import numpy as np

    signal = np.zeros(2, dtype=[("time", float)] + [(name, float) for name in TIMING_INPUTS])
    signal["time"] = (0.0, stop_time)
    for name, value in TIMING_INPUTS.items():
        signal[name] = value
    return signal


def worker_simulate(fmus, steps, chunk):
    """`simulate_fmu` runs of `chunk` steps, the FMUs taking turns, until each has
    made `steps` steps; the stepping is timed, not instantiation and teardown."""
    from fmpy import simulate_fmu

    wall = dict.fromkeys(fmus, 0.0)
    cpu = dict.fromkeys(fmus, 0.0)
    done = dict.fromkeys(fmus, 0)
    order = list(fmus)
    for _, length in chunks(steps, chunk):
        stop_time = length * STEP_SIZE
        for name in order:
            clock = StepClock()
            simulate_fmu(
                fmus[name],
                stop_time=stop_time,
                output_interval=STEP_SIZE,
                input=constant_input_signal(stop_time),
                step_finished=clock,
            )
            wall[name] += clock.last[0] - clock.first[0]
            cpu[name] += clock.last[1] - clock.first[1]
            done[name] += clock.calls - 1
        order.reverse()
    return {
        "times": {
            name: {"wall": wall[name] / done[name], "cpu": cpu[name] / done[name]} for name in fmus
        }
    }


def side_by_side(kind, fmus: dict, runs, steps, chunk):
    """Runs, each in a fresh process in which the FMUs take turns; per run
    {name: {"wall", "cpu"} per step}, plus the run's peak RSS."""
    return [
        in_fresh_process(kind, fmus=fmus, steps=steps, chunk=min(chunk, steps)) for _ in range(runs)
    ]


def step_cost(fmus, sizes):
    """The loop over every FMU of `fmus` side by side; `simulate_fmu` over the
    joint and the plain floor."""
    simulated = {name: fmus[name] for name in ("plain", "joint")}
    return {
        "loop": side_by_side("loop", fmus, sizes.runs, sizes.steps, LOOP_CHUNK),
        "simulate": side_by_side(
            "simulate", simulated, sizes.simulate_runs, sizes.steps, SIMULATE_CHUNK
        ),
    }


def cost_cell(runs, floor):
    wall, cpu = against(runs, floor, "wall"), against(runs, floor, "cpu")
    return (
        f"joint {us(wall['joint'])}, floor {us(wall['floor'])}: **×{wall['ratio']:.2f}** "
        f"(single runs ×{wall['pair_min']:.2f}–{wall['pair_max']:.2f}); CPU time: joint "
        f"{us(cpu['joint'])}, floor {us(cpu['floor'])}: ×{cpu['ratio']:.2f}"
    ), wall["ratio"]


def cost_rows(cost, sizes):
    def runs(kind):
        return f"median of {len(cost[kind])} interleaved runs × {sizes.steps:,} steps"

    outputs = len(discover()[JOINT].table().OUTPUTS)
    plain, loop_ratio = cost_cell(cost["loop"], "plain")
    bare, _ = cost_cell(cost["loop"], "bare")
    simulate, simulate_ratio = cost_cell(cost["simulate"], "plain")
    return [
        f"| 1. FMU2Slave loop (set {len(TIMING_INPUTS)}, doStep, get {outputs}): the default "
        f"build (UniversalJoint) vs its plain floor, {runs('loop')} | {plain} | "
        f"≤ ×{GOALS['loop']} | {met(loop_ratio <= GOALS['loop'])} |",
        f"| 1. FMU2Slave loop vs bare floor (stricter), {runs('loop')} | {bare} | (context) | |",
        f"| 1. `simulate_fmu` (inputs set every step, {outputs} outputs recorded) vs plain "
        f"floor, {runs('simulate')} | {simulate} | ≤ ×{GOALS['simulate']} | "
        f"{met(simulate_ratio <= GOALS['simulate'])} |",
    ]
