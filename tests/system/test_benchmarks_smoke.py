"""`python -m benchmarks` (the benchmarks package) runs end to end and writes its tables.

A smoke test only: `--quick` sizes measure nothing, so nothing here looks at a
time or at whether a goal is met.
"""

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

SUMMARY_ROWS = (
    "| 1. FMU2Slave loop (set 6, doStep, get 24): the default build (UniversalJoint) vs its "
    "plain floor,",
    "| 1. FMU2Slave loop vs bare floor (stricter),",
    "| 1. `simulate_fmu` (inputs set every step, 24 outputs recorded) vs plain floor,",
    "| 2. FMU output angle error after 1 s,",
    "| 2. RK4 (Tătaru's ODE) angle error ÷ FMU's at 1e-2 s,",
    "| 2. cost per step at 1e-4 s: RK4 in Python vs FMU under `simulate_fmu` |",
    "| 3. `joint_response` on numpy arrays, one call on",
    "| 3. the same in blocks of",
    "| 3. ceiling: the array path's 5 trigonometric calls alone",
    "| 4. FMU2Slave loop per step at",
    "| 4. memory:",
    "| 5. C host (tests/c_host, empty environment) vs FMPy low-level loop,",
    "| 6. instructions per step (callgrind, all threads, runs of 3 − 1 steps), FMPy's",
    "| 8. 10^6 revolutions:",
)
# Sections 6 and 7: one row per case of the models asked for (the quick run
# asks for two: callgrind starts each process slowly), each model by name.
MODELS = ("UniversalJoint", "Load")
CASES = ("UniversalJoint,", "UniversalJoint at 1000 rad/s,", "Load,")
PER_MODEL = (
    "| 6. instructions per step (callgrind, all threads, runs of 3 − 1 steps), C host",
    "| 7. instructions per step (callgrind, all threads, runs of 3 − 1 steps):",
)


def run_benchmarks(*arguments):
    run = subprocess.run([sys.executable, "-m", "benchmarks", "--quick", *map(str, arguments)],
                         capture_output=True, text=True, cwd=ROOT, timeout=1200)  # fmt: skip
    assert run.returncode == 0, run.stdout + run.stderr
    return run


def model_rows(lines, lead):
    """Which cases the rows starting with `lead` name, in order."""
    keys = [line.split(" | ", 1)[0] for line in lines if line.startswith(lead)]
    return [key[len(lead) :].split(": ", 1)[-1].split(" the ")[0].strip() for key in keys]


def test_every_model_found_has_a_case(monkeypatch):
    from benchmarks import cases
    from cardan_joint.models import discover

    assert {case.model for case in cases.cases_of(None)} == set(discover())
    assert [case.label for case in cases.cases_of(["Load", "UniversalJoint"])] == [
        "Load", "UniversalJoint", "UniversalJoint at 1000 rad/s"]  # fmt: skip
    # A model the cases do not name gets one at the operating point.
    monkeypatch.setattr(cases, "CASES", ())
    assert cases.cases_of(["Propshaft"]) == [cases.Case("Propshaft")]
    assert cases.Case("Propshaft").inputs() == {
        "input_speed": 100.0, "input_acceleration": 5.0, "load_torque": 50.0}  # fmt: skip


def test_quick_run_writes_every_row(fmu_path, tmp_path):
    output = tmp_path / "results.md"
    run = run_benchmarks("--output", output, "--fmu", fmu_path, "--models", *MODELS)
    # A quick run says where its tables went instead of printing numbers that measure nothing.
    assert run.stdout.strip().endswith(f"tables in {output}")
    lines = output.read_text().splitlines()
    assert "| benchmark | result | goal | met |" in lines
    for row in SUMMARY_ROWS:
        matches = [line for line in lines if line.startswith(row)]
        assert len(matches) == 1, row
        assert matches[0].count(" | ") == 3, matches[0]
    for lead in PER_MODEL:
        assert model_rows(lines, lead) == list(CASES), lead
        assert all(line.count(" | ") == 3 for line in lines if line.startswith(lead))
    for bend in ("2π/7", "2π/5"):
        for step in ("1e-01", "1e-02", "1e-03", "1e-04"):
            assert sum(line.startswith(f"| {bend} | {step} |") for line in lines) == 1

    # One section and one model alone replace their own rows and say so; every
    # other line stays.
    run_benchmarks("instructions", "--models", "Load", "--output", output, "--fmu", fmu_path)
    again = output.read_text().splitlines()
    note = [i for i, line in enumerate(again) if line.startswith("Re-measured alone")]
    assert len(note) == 1 and again[note[0] + 1] == "" and again[note[0] - 1] == ""
    assert "`python -m benchmarks instructions --models Load --quick`" in again[note[0]]
    del again[note[0] : note[0] + 2]
    load = [i for i, line in enumerate(lines) if line.startswith(PER_MODEL[0]) and "Load" in line]
    assert len(load) == 1
    assert [line for i, line in enumerate(again) if i not in load] == [
        line for i, line in enumerate(lines) if i not in load
    ]
    assert again[load[0]].split(" | ")[0] == lines[load[0]].split(" | ")[0]


@pytest.mark.parametrize("model, fixture", [("UniversalJoint", "fmu_path"),
                                            ("Propshaft", "propshaft_fmu_path")])  # fmt: skip
def test_the_floor_builder_makes_an_fmu_with_the_models_variables(request, model, fixture,
                                                                  tmp_path):  # fmt: skip
    from fmpy import read_model_description

    build = subprocess.run(
        [sys.executable, "-c", "import sys; from benchmarks.floor import build_floor_fmu; "
         "print(build_floor_fmu(sys.argv[1], 'bare', model=sys.argv[2]))", str(tmp_path), model],
        capture_output=True, text=True, cwd=ROOT, timeout=300,
    )  # fmt: skip
    assert build.returncode == 0, build.stderr
    floor = read_model_description(build.stdout.strip())
    built = read_model_description(str(request.getfixturevalue(fixture)))

    def signature(description):
        # Start values to 15 digits: pythonfmu writes the floor's with 16 (one
        # rounding off the double), the model's build the shortest exact text.
        return [
            (v.name, v.causality, v.variability, v.initial, v.start and f"{float(v.start):.15g}")
            for v in description.modelVariables
        ]

    # The floor mirrors the model's default build, every variable.
    assert signature(floor) == signature(built)
