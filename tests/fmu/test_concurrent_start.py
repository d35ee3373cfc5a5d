"""Issue 24 item 2: different FMUs (different binaries, each loaded RTLD_LOCAL, FMI 2.0
and 3.0 mixed) first instantiated at the same moment from threads of a C host without
Python: every run completes and equals the serial run (one interpreter start for the
whole process, agreed on by every copy of the runtime). Three runs here, a quick
check in the developer's loop; thirty in tests/system/test_long_runs.py."""

import subprocess
from pathlib import Path

QUICK_RUNS = 3
INPUTS = {"input_speed": 12.0, "load_torque": 3.0}


def fmu_argument(folder) -> str:
    """concurrent.c's description of one extracted FMU: version, binary, resources,
    token, inputs and scalar Float64/Real outputs, from its modelDescription."""
    from fmpy import read_model_description

    folder = Path(folder)
    description = read_model_description(str(folder))
    version = int(description.fmiVersion[0])
    platform = "linux64" if version == 2 else "x86_64-linux"
    identifier = description.coSimulation.modelIdentifier
    inputs = [
        f"{v.valueReference}={INPUTS[v.name]!r}"
        for v in description.modelVariables
        if v.name in INPUTS and v.causality == "input"
    ]
    outputs = [
        str(v.valueReference)
        for v in description.modelVariables
        if v.causality == "output" and v.type in ("Real", "Float64") and not v.dimensions
    ]
    return "|".join(
        [
            str(version),
            str(folder / "binaries" / platform / f"{identifier}.so"),
            (folder / "resources").as_uri(),
            description.guid if version == 2 else description.instantiationToken,
            ",".join(inputs),
            ",".join(outputs),
        ]
    )


def started_together(concurrent_host, folders, runs: int, python: dict | None = None) -> None:
    """`runs` starts of the FMUs in `folders` at once each equal the serial run;
    `python`: the $CARDAN_JOINT_FMU_PYTHON_* variables naming the Python to start."""
    arguments = [fmu_argument(folder) for folder in folders]
    environment = {"PATH": "/usr/bin:/bin", **(python or {})}
    serial = subprocess.run(
        [str(concurrent_host), "serial", *arguments],
        env=environment,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert serial.returncode == 0, serial.stdout + serial.stderr
    assert serial.stdout.count("fmu ") == 3 and "failed" not in serial.stdout
    outcomes = []
    for _ in range(runs):
        try:
            run = subprocess.run(
                [str(concurrent_host), "together", *arguments],
                env=environment,
                capture_output=True,
                text=True,
                timeout=60,
            )
            outcomes.append((run.returncode, run.stdout, run.stderr[-500:]))
        except subprocess.TimeoutExpired:
            outcomes.append(("hang", "", ""))
    bad = [outcome for outcome in outcomes if outcome[:2] != (0, serial.stdout)]
    assert not bad, f"{len(bad)} of {runs} runs failed; first: {bad[0]}"


def test_different_fmus_started_at_once_three_of_three(
    concurrent_host, unzipped_fmu, propshaft_unzipped, fmi3_unzipped
):
    folders = (unzipped_fmu, propshaft_unzipped, fmi3_unzipped)
    started_together(concurrent_host, folders, QUICK_RUNS)
