"""8. 10^6 revolutions at 10 rad/s in steps of 0.5 s (issue 32): the default
build (UniversalJoint, life on) in the C host (tests/c_host `last`: every output
read at each step, the last row printed; empty environment), 1,256,638 steps;
the wall time of the whole run and the output angle's error at its end against
the exact angle (the input angle's whole turns counted in fractions, the Cardan
error from its closed form). `revolutions` shortens it (a quick run).
"""

import math
import subprocess
import time
from fractions import Fraction

from cardan_joint.physics import cardan_error

SPEED, STEP, BEND = 10.0, 0.5, 0.5  # rad/s, s, rad
REVOLUTIONS = 1_000_000
TWO_PI = Fraction("6.283185307179586476925286766559005768394")
GOALS = {"seconds": 60.0, "error": 1e-8}
GOAL_TEXT = "< 60 s, ≤ 1e-8 rad"


def steps_for(revolutions: int) -> int:
    return math.ceil(revolutions * 2 * math.pi / (SPEED * STEP))


def exact_output_angle(end: float) -> Fraction:
    """The output angle at `end` s: the input's, plus the Cardan error there."""
    gamma1 = Fraction(SPEED) * Fraction(end)
    fraction = float(gamma1 - math.floor(gamma1 / TWO_PI) * TWO_PI)
    return gamma1 + Fraction(cardan_error(fraction, BEND))


def long_run(host, joint, revolutions: int = REVOLUTIONS) -> dict:
    """The run of `revolutions` through the unzipped default build `joint`."""
    steps = steps_for(revolutions)
    command = [str(host), "last", joint, str(steps), repr(STEP), f"input_speed={SPEED!r}",
               f"bend_angle={BEND!r}"]  # fmt: skip
    began = time.perf_counter()
    with subprocess.Popen(command, stdout=subprocess.PIPE, text=True,
                          env={"PATH": "/usr/bin:/bin"}) as run:  # fmt: skip
        assert run.stdout is not None
        header, last = run.stdout.readline(), run.stdout.readline()
    seconds = time.perf_counter() - began
    if run.returncode != 0:
        raise RuntimeError(f"{command} failed")
    names = [name.strip('"') for name in header.strip().split(",")]
    row = dict(zip(names, map(float, last.split(",")), strict=True))
    error = float(Fraction(row["output_angle"]) - exact_output_angle(row["time"]))
    return {"seconds": seconds, "error": error, "time": row["time"], "steps": steps,
            "life_consumed": row["life_consumed"]}  # fmt: skip


def long_run_rows(found: dict) -> list[str]:
    revolutions = found["time"] * SPEED / (2 * math.pi)
    met = found["seconds"] < GOALS["seconds"] and abs(found["error"]) <= GOALS["error"]
    return [
        f"| 8. 10^6 revolutions: steps of {STEP} s at {SPEED:g} rad/s, bend {BEND} rad, the "
        f"default build (UniversalJoint, life on) in the C host, every output read at each "
        f"step: wall time of the run, output angle error at its end | {found['steps']:,} "
        f"steps, {revolutions:,.0f} revolutions in {found['seconds']:.1f} s, output angle "
        f"error {abs(found['error']):.1e} rad, life_consumed {found['life_consumed']:.3e} | "
        f"{GOAL_TEXT} | **{'yes' if met else 'NO'}** |"
    ]
