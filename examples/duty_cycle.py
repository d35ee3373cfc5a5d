"""Joint life over a vehicle duty cycle read from a block table: the FMU's damage
beside the catalogue's hand method.

A propshaft joint behind a five-speed gearbox runs through the blocks of
`duty_cycle_blocks.csv` (gear, share of time, propshaft speed and torque,
working angle: a maker's load-duration table). `life_report` (what
`cardan-joint life` runs, docs/life.md) drives the UniversalJoint FMU through
them and reads `life_consumed`, Miner's sum of the catalogue life rule at every
instant. Beside it, the catalogue's hand method: for each block of constant
torque T, speed n and angle A, L_i = K / (A n) (T_r / T)^p and the damage sum
q_i t / (3600 L_i), as in every maker's design guide.

The two differ by the cardan torque fluctuation: at a working angle the input
torque swings between T cos b and T / cos b twice a turn, and the life rule
raises it to the power p = 10/3. For a massless cross the ratio per block is
the mean of (cos b / D)^p over a turn (D = 1 - sin^2 b cos^2 psi), shown
beside it. A second run with every angle at 0 (the rule's 3-degree floor then
applies, and the torque is constant) checks the FMU against the block sum.

    python examples/duty_cycle.py    -> results/duty_cycle.{csv,json,png}
"""

import dataclasses
import math
import sys
from pathlib import Path

import numpy as np
from _support import example_fmu, example_parser, output_folder, run_example

from cardan_joint.host.duty_cycle import read_block_table
from cardan_joint.host.life_files import write_report
from cardan_joint.host.life_report import life_report, report_text
from cardan_joint.units import DEG_TO_RAD, RAD_PER_S_TO_RPM, RAD_TO_DEG

BLOCKS = Path(__file__).with_name("duty_cycle_blocks.csv")
JOINT = dict(
    rated_torque=1200.0,
    life_constant=1.5e6,
    life_exponent=10.0 / 3.0,
    life_min_angle=3.0 * DEG_TO_RAD,
    bearing_radius=0.022,
)
CROSS = dict(crosspiece_inertia_1=0.0, crosspiece_inertia_2=0.0, crosspiece_inertia_3=0.0)
CYCLE = 10.0  # s of simulated driving per cycle; the shares divide it
STEP = 1e-3


def read_cycle(cycle=CYCLE, straight=False, blocks=BLOCKS):
    """The block table as steps; `straight`: every angle at 0."""
    steps = read_block_table(blocks, cycle_time=cycle, step=STEP)
    if not straight:
        return steps
    inputs = {**steps.inputs, "bend_angle": np.zeros(len(steps.steps))}
    return dataclasses.replace(steps, inputs=inputs)


def run(fmu_path, cycle=CYCLE, straight=False):
    """The life report of the cycle (`straight`: every angle at 0)."""
    return life_report(read_cycle(cycle, straight), fmu_path, start_values={**JOINT, **CROSS})


def catalogue_life_hours(torque, rpm, angle_deg, joint=JOINT):
    """The hand method's L_h for one block of constant torque, speed and angle."""
    angle = max(angle_deg, joint["life_min_angle"] / DEG_TO_RAD)
    return (
        joint["life_constant"]
        / (angle * rpm)
        * (joint["rated_torque"] / torque) ** joint["life_exponent"]
    )


def blocks_of(cycle=CYCLE, straight=False):
    """(name, seconds, torque N.m, rpm, angle deg) of each block."""
    steps = read_cycle(cycle, straight)
    rows = []
    for index, name in enumerate(steps.labels):
        at = steps.part == index
        first = np.flatnonzero(at)[0]
        rows.append(
            (
                name,
                math.fsum(steps.steps[at]),
                steps.inputs["load_torque"][first],
                steps.inputs["input_speed"][first] * RAD_PER_S_TO_RPM,
                steps.inputs["bend_angle"][first] * RAD_TO_DEG,
            )
        )
    return rows


def block_sum(cycle=CYCLE, straight=False):
    """Miner's sum of the blocks by the hand method, over `cycle` s."""
    return sum(
        seconds / (3600.0 * catalogue_life_hours(torque, rpm, angle))
        for _, seconds, torque, rpm, angle in blocks_of(cycle, straight)
    )


def fluctuation_factor(angle_deg, p=JOINT["life_exponent"], samples=4096):
    """Mean of (cos b / D)^p over a turn: the massless cross's damage over the
    hand method's at constant load and speed (the periodic trapezoid rule)."""
    b = angle_deg * DEG_TO_RAD
    psi = np.linspace(0.0, 2.0 * math.pi, samples, endpoint=False)
    return float(np.mean((math.cos(b) / (1.0 - math.sin(b) ** 2 * np.cos(psi) ** 2)) ** p))


def block_table(report, cycle=CYCLE):
    """Per block: its damage in the FMU, by the hand method, their ratio and the
    fluctuation factor the ratio should approach."""
    lines = []
    for part, (name, seconds, torque, rpm, angle) in zip(report.parts, blocks_of(cycle)):
        fmu = part["damage"]["joint"]
        hand = seconds / (3600.0 * catalogue_life_hours(torque, rpm, angle))
        lines.append((name, fmu, hand, fmu / hand, fluctuation_factor(angle)))
    return lines


def main(argv=None):
    parser = example_parser(__doc__, model="UniversalJoint")
    args = parser.parse_args(argv)
    args.fmu = example_fmu(args)
    out = output_folder(args)
    report = run(args.fmu)
    paths = write_report(report, out / "duty_cycle.csv")
    print(report_text(report))
    print("block  FMU damage   hand method  FMU/hand  mean (cos b/D)^p")
    for name, fmu, hand, ratio, factor in block_table(report):
        print(f"{name:5}  {fmu:.4e}  {hand:.4e}   {ratio:.5f}   {factor:.5f}")
    fmu_total, hand_total = report.life_used["joint"], block_sum()
    print(
        f"cycle of {CYCLE:g} s: FMU {fmu_total:.6e}, hand method {hand_total:.6e} "
        f"(x{fmu_total / hand_total:.4f}: the cardan torque fluctuation); B10 life "
        f"{report.b10_hours['joint']:,.0f} h of this driving (hand method "
        f"{CYCLE / 3600.0 / hand_total:,.0f} h)"
    )
    print(
        "the fluctuation's factor grows with the angle: "
        + ", ".join(f"{a} deg x{fluctuation_factor(a):.4f}" for a in (5, 10, 15, 20, 30))
    )
    straight = run(args.fmu, straight=True).life_used["joint"]
    print(
        f"check, every angle at 0 (constant torque, the 3-degree floor): FMU {straight:.12e}, "
        f"block sum {block_sum(straight=True):.12e}"
    )
    print("wrote " + ", ".join(str(p) for p in paths.values()))
    return 0


if __name__ == "__main__":
    sys.exit(run_example(main))
