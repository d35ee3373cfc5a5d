"""Joint life over a vehicle duty cycle: the FMU's damage beside the catalogue's hand method.

A propshaft joint behind a five-speed gearbox runs through blocks of gear,
engine torque, engine speed and working angle (docs/life.md). The master
(FMPy through `FmuInstance`) co-simulates the UniversalJoint FMU block by
block and reads `life_consumed`, Miner's sum of the catalogue life rule at
every instant. Beside it, the catalogue's hand method: for each block of
constant torque T, speed n and angle A, L_i = K / (A n) (T_r / T)^p and the
damage sum q_i t / (3600 L_i) (doi-free, as in every maker's design guide).

The two differ by the cardan torque fluctuation: at a working angle the input
torque swings between T cos b and T / cos b twice a turn, and the life rule
raises it to the power p = 10/3. For a massless cross the ratio per block is
the mean of (cos b / D)^p over a turn (D = 1 - sin^2 b cos^2 psi), shown
beside it. A second run with every angle at 0 (the rule's 3-degree floor
then applies, and the torque is constant) checks the FMU against the block sum.

    python examples/duty_cycle.py            -> results/duty_cycle.{csv,png}
"""

import math
import sys

import numpy as np
from _support import example_fmu, example_parser, legend_outside, output_folder, run_example

from cardan_joint import results
from cardan_joint.host.plotting import pyplot, save_figure
from cardan_joint.units import DEG_TO_RAD, RPM_TO_RAD_PER_S

# (gear, gear ratio, engine torque N.m, engine speed rpm, working angle deg, share of time)
BLOCKS = (
    ("1st", 3.8, 250.0, 1800.0, 6.0, 0.02),
    ("2nd", 2.1, 280.0, 2500.0, 5.0, 0.06),
    ("3rd", 1.4, 300.0, 2800.0, 4.0, 0.15),
    ("4th", 1.0, 250.0, 2600.0, 3.5, 0.32),
    ("5th", 0.8, 150.0, 2200.0, 2.5, 0.45),
)
JOINT = dict(
    rated_torque=1200.0,
    life_constant=1.5e6,
    life_exponent=10.0 / 3.0,
    life_min_angle=3.0 * DEG_TO_RAD,
    bearing_radius=0.022,
)
CROSS = dict(crosspiece_inertia_1=0.0, crosspiece_inertia_2=0.0, crosspiece_inertia_3=0.0)
CYCLE = 10.0  # s of simulated driving per cycle; the shares scale it
STEP = 1e-3


def block_inputs(block, straight=False):
    """The joint's inputs in a block: propshaft speed and torque behind the gear."""
    _, ratio, torque, rpm, angle, _ = block
    return dict(
        input_speed=rpm / ratio * RPM_TO_RAD_PER_S,
        input_acceleration=0.0,
        bend_angle=0.0 if straight else angle * DEG_TO_RAD,
        bend_angle_rate=0.0,
        bend_angle_acceleration=0.0,
        load_torque=torque * ratio,
    )


def catalogue_life_hours(torque, rpm, angle_deg, joint=JOINT):
    """The hand method's L_h for one block of constant torque, speed and angle."""
    angle = max(angle_deg, joint["life_min_angle"] / DEG_TO_RAD)
    return (
        joint["life_constant"]
        / (angle * rpm)
        * (joint["rated_torque"] / torque) ** joint["life_exponent"]
    )


def block_sum(blocks=BLOCKS, cycle=CYCLE, straight=False):
    """Miner's sum of the blocks by the hand method, over `cycle` s."""
    total = 0.0
    for block in blocks:
        _, ratio, torque, rpm, angle, share = block
        life = catalogue_life_hours(torque * ratio, rpm / ratio, 0.0 if straight else angle)
        total += share * cycle / (3600.0 * life)
    return total


def fluctuation_factor(angle_deg, p=JOINT["life_exponent"], samples=4096):
    """Mean of (cos b / D)^p over a turn: the massless cross's damage over the
    hand method's at constant load and speed (the periodic trapezoid rule)."""
    b = angle_deg * DEG_TO_RAD
    psi = np.linspace(0.0, 2.0 * math.pi, samples, endpoint=False)
    return float(np.mean((math.cos(b) / (1.0 - math.sin(b) ** 2 * np.cos(psi) ** 2)) ** p))


def run(fmu_path, blocks=BLOCKS, cycle=CYCLE, h=STEP, straight=False):
    """Co-simulate the cycle; rows of (time, block, input torque, life rate, life consumed)."""
    from cardan_joint.host.instance import FmuInstance

    rows = []
    time = 0.0
    with FmuInstance.open(fmu_path, start_values={**JOINT, **CROSS}) as joint:
        for index, block in enumerate(blocks):
            joint.set(**block_inputs(block, straight))
            for _ in range(round(block[-1] * cycle / h)):
                joint.step(h)
                time += h
                out = joint.get("input_torque", "life_rate", "life_consumed")
                rows.append(
                    (time, index, out["input_torque"], out["life_rate"], out["life_consumed"])
                )
    names = ("time", "block", "input_torque", "life_rate", "life_consumed")
    return np.array(rows, dtype=[(n, float) for n in names])


def block_table(rows, blocks=BLOCKS, cycle=CYCLE):
    """Per block: its damage in the FMU, by the hand method, their ratio and the
    fluctuation factor the ratio should approach."""
    lines = []
    previous = 0.0
    for index, block in enumerate(blocks):
        name, ratio, torque, rpm, angle, share = block
        end = rows["life_consumed"][rows["block"] == index][-1]
        fmu, previous = end - previous, end
        hand = share * cycle / (3600.0 * catalogue_life_hours(torque * ratio, rpm / ratio, angle))
        lines.append((name, fmu, hand, fmu / hand, fluctuation_factor(angle)))
    return lines


def plot(rows, hand_rows, path, blocks=BLOCKS):
    plt = pyplot()
    fig, (ax, rate) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True, height_ratios=(2, 1))
    ax.plot(rows["time"], rows["life_consumed"], label="FMU: life_consumed")
    ax.plot(hand_rows[0], hand_rows[1], "--", label="catalogue hand method (block sum)")
    rate.plot(
        rows["time"],
        rows["life_rate"] / (3600.0 * hand_rows[2]),
        label="FMU life_rate / hand method's",
    )
    for index, block in enumerate(blocks):
        times = rows["time"][rows["block"] == index]
        for axes in (ax, rate):
            axes.axvspan(times[0], times[-1], alpha=0.08 * (index % 2 + 1), color="grey")
        label = f"{block[0]} {block[4]:g}°"
        middle = 0.5 * (times[0] + times[-1])
        ax.text(middle, 0.02, label, rotation=90, ha="center", va="bottom", fontsize=8,
                transform=ax.get_xaxis_transform())  # fmt: skip
    ax.set_ylabel("damage (Miner's sum, 1 = B10 life)")
    ax.set_title("Joint damage over a duty cycle")
    rate.set_xlabel("time in the cycle (s)")
    rate.set_ylabel("rate ratio")
    legend_outside(ax)
    legend_outside(rate)
    save_figure(fig, path)


def hand_curve(rows, blocks=BLOCKS, cycle=CYCLE):
    """The block sum over the FMU's time points: (time, damage, damage rate 1/s)."""
    rate = np.zeros(len(rows))
    for index, block in enumerate(blocks):
        _, ratio, torque, rpm, angle, _ = block
        life = catalogue_life_hours(torque * ratio, rpm / ratio, angle)
        rate[rows["block"] == index] = 1.0 / (3600.0 * life)
    step = np.diff(np.concatenate(([0.0], rows["time"])))
    return rows["time"], np.cumsum(rate * step), rate


def main(argv=None):
    parser = example_parser(__doc__, model="UniversalJoint")
    args = parser.parse_args(argv)
    args.fmu = example_fmu(args)
    out = output_folder(args)
    rows = run(args.fmu)
    results.write_csv(rows, out / "duty_cycle.csv")
    plot(rows, hand_curve(rows), out / "duty_cycle.png")
    print("block  FMU damage   hand method  FMU/hand  mean (cos b/D)^p")
    for name, fmu, hand, ratio, factor in block_table(rows):
        print(f"{name:5}  {fmu:.4e}  {hand:.4e}   {ratio:.5f}   {factor:.5f}")
    fmu_total, hand_total = rows["life_consumed"][-1], block_sum()
    print(
        f"cycle of {CYCLE:g} s: FMU {fmu_total:.6e}, hand method {hand_total:.6e} "
        f"(x{fmu_total / hand_total:.4f}: the cardan torque fluctuation); B10 life "
        f"{CYCLE / 3600.0 / fmu_total:,.0f} h of this driving (hand method "
        f"{CYCLE / 3600.0 / hand_total:,.0f} h)"
    )
    print(
        "the fluctuation's factor grows with the angle: "
        + ", ".join(f"{a} deg x{fluctuation_factor(a):.4f}" for a in (5, 10, 15, 20, 30))
    )
    straight = run(args.fmu, straight=True)["life_consumed"][-1]
    print(
        f"check, every angle at 0 (constant torque, the 3-degree floor): FMU {straight:.12e}, "
        f"block sum {block_sum(straight=True):.12e}"
    )
    print(f"wrote {out / 'duty_cycle.csv'} and {out / 'duty_cycle.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(run_example(main))
