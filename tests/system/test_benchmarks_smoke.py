"""`python -m benchmarks` (the benchmarks package) runs end to end and writes its tables.

A smoke test only: `--quick` sizes measure nothing, so nothing here looks at a
time or at whether a goal is met.
"""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

SUMMARY_ROWS = (
    "| 1. FMU2Slave loop (set 6, doStep, get 20) vs plain floor,",
    "| 1. FMU2Slave loop vs bare floor (stricter),",
    "| 1. `simulate_fmu` (inputs set every step, 20 outputs recorded) vs plain floor,",
    "| 1. Life on vs off (docs/life.md): the default build vs the joint built `--no-life`,",
    "| 2. FMU output angle error after 1 s,",
    "| 2. RK4 (Tătaru's ODE) angle error ÷ FMU's at 1e-2 s,",
    "| 2. cost per step at 1e-4 s: RK4 in Python vs FMU under `simulate_fmu` |",
    "| 3. `joint_response` on numpy arrays, one call on",
    "| 3. the same in blocks of",
    "| 3. ceiling: the array path's 5 trigonometric calls alone",
    "| 4. FMU2Slave loop per step at",
    "| 4. memory:",
    "| 5. C host (tests/c_host, empty environment) vs FMPy low-level loop,",
    "| 6. C host: joint vs plain floor in the same host",
    "| 6. FMPy loop: joint vs plain floor",
    "| 6. the joint's Python per step, no host,",
    "| 7a. instructions per step (callgrind,",
    "| 7b. instructions per step (callgrind,",
    "| 7c. instructions per step (callgrind,",
    "| 7d. instructions per step (callgrind,",
)


def test_quick_run_writes_every_row(fmu_path, tmp_path):
    output = tmp_path / "results.md"
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "benchmarks",
            "--quick",
            "--output",
            str(output),
            "--fmu",
            str(fmu_path),
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=600,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    text = output.read_text()
    # A quick run says where its tables went instead of printing numbers that measure nothing.
    assert run.stdout.strip().endswith(f"tables in {output}")
    lines = text.splitlines()
    assert "| benchmark | result | goal | met |" in lines
    for row in SUMMARY_ROWS:
        matches = [line for line in lines if line.startswith(row)]
        assert len(matches) == 1, row
        assert matches[0].count(" | ") == 3, matches[0]
    for bend in ("2π/7", "2π/5"):
        for step in ("1e-01", "1e-02", "1e-03", "1e-04"):
            assert sum(line.startswith(f"| {bend} | {step} |") for line in lines) == 1

    # Section 7 alone replaces its own rows and says so; every other line stays.
    again = subprocess.run(
        [sys.executable, "-m", "benchmarks", "--quick", "--instructions-only",
         "--output", str(output), "--fmu", str(fmu_path)],
        capture_output=True, text=True, cwd=ROOT, timeout=600,
    )  # fmt: skip
    assert again.returncode == 0, again.stdout + again.stderr
    remeasured = output.read_text().splitlines()
    note = [i for i, line in enumerate(remeasured) if line.startswith("Rows 7a-7d")]
    assert len(note) == 1 and remeasured[note[0] + 1] == "" and remeasured[note[0] - 1] == ""
    del remeasured[note[0] : note[0] + 2]
    assert [line for line in remeasured if not line.startswith("| 7")] == [
        line for line in lines if not line.startswith("| 7")
    ]
    for row in SUMMARY_ROWS:
        assert sum(line.startswith(row) for line in remeasured) == 1, row


def test_the_floor_builder_makes_an_fmu_with_the_joints_variables(model_description, tmp_path):
    from fmpy import read_model_description

    build = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys; from benchmarks.floor import "
            "build_floor_fmu; print(build_floor_fmu(sys.argv[1], 'bare'))",
            str(tmp_path),
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=300,
    )
    assert build.returncode == 0, build.stderr
    floor = read_model_description(build.stdout.strip())

    def signature(description):
        # Start values to 15 digits: pythonfmu writes the floor's with 16 (one
        # rounding off the double), the joint's build the shortest exact text.
        return [
            (v.name, v.causality, v.variability, v.initial, v.start and f"{float(v.start):.15g}")
            for v in description.modelVariables
        ]

    # The floor mirrors the runtime's joint: the build without life (docs/life.md),
    # whose variables are the default build's without the life rows.
    from cardan_joint.models.universal_joint.variables import WITHOUT_LIFE

    joint = [row for row in signature(model_description) if row[0] in WITHOUT_LIFE.BY_NAME]
    assert len(joint) == len(WITHOUT_LIFE.VARIABLES)
    assert signature(floor) == joint
