"""10^6 revolutions at 10 rad/s in steps of 0.5 s (issue 32): the default build
(UniversalJoint, life on, its step in C) in the C host (tests/c_host `last`:
every output read at each step, the last row printed; empty environment),
1,256,638 steps; the wall time of the whole run and the
output angle's error at its end against the exact angle (the input angle's
whole turns counted in fractions, the Cardan error from its closed form).

    .venv/bin/python -m benchmarks.long_run

writes its row, 8c, into benchmarks/results.md after rows 8a and 8b.
"""

import math
import subprocess
import tempfile
import time
from fractions import Fraction
from pathlib import Path

from cardan_joint.physics import cardan_error

from .c_host import compile_c_host
from .floor import build_joint_fmu, unzip
from .generated_step import RESULTS, with_rows

SPEED, STEP, BEND = 10.0, 0.5, 0.5  # rad/s, s, rad
STEPS = math.ceil(1e6 * 2 * math.pi / (SPEED * STEP))
TWO_PI = Fraction("6.283185307179586476925286766559005768394")


def exact_output_angle(end: float) -> Fraction:
    """The output angle at `end` s: the input's, plus the Cardan error there."""
    gamma1 = Fraction(SPEED) * Fraction(end)
    fraction = float(gamma1 - math.floor(gamma1 / TWO_PI) * TWO_PI)
    return gamma1 + Fraction(cardan_error(fraction, BEND))


def measure(work: Path) -> dict:
    host = compile_c_host(work)
    joint = unzip(build_joint_fmu(work, life=True), work)
    command = [str(host), "last", joint, str(STEPS), repr(STEP), f"input_speed={SPEED!r}",
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
    return {"seconds": seconds, "error": error, "time": row["time"],
            "life_consumed": row["life_consumed"]}  # fmt: skip


def main() -> None:
    with tempfile.TemporaryDirectory(prefix="cardan_joint_long_") as work:
        found = measure(Path(work))
    revolutions = found["time"] * SPEED / (2 * math.pi)
    met = found["seconds"] < 60.0 and abs(found["error"]) <= 1e-8
    row = (
        f"| 8c. 10^6 revolutions: {STEPS:,} steps of {STEP} s at {SPEED:g} rad/s, bend {BEND} "
        f"rad, the default build (life on, its step in C) in the C host, every output read "
        f"at each step: wall time of the run, output angle error at its end | "
        f"{revolutions:,.0f} revolutions in {found['seconds']:.1f} s, output angle error "
        f"{abs(found['error']):.1e} rad, life_consumed {found['life_consumed']:.3e} | "
        f"< 60 s, ≤ 1e-8 rad | **{'yes' if met else 'NO'}** |"
    )
    RESULTS.write_text(with_rows(RESULTS.read_text(), [row], ("| 8c. ",)))
    print(row)


if __name__ == "__main__":
    main()
