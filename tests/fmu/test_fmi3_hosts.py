"""The FMI 3.0 FMU in its hosts: the package's entry point, the CLI, a host with no logger."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

from cardan_joint.host.simulate import SimulationError, flat_columns, simulate
from cardan_joint.models.universal_joint import variables as table


def test_simulate_with_input_signals_matches_fmi2(fmu_path, fmi3_path):
    from fmpy import simulate_fmu

    # Two ramps, each with its rate (a ramp without one is refused as contradictory).
    names = ("time", "input_speed", "input_acceleration", "bend_angle", "bend_angle_rate")
    signal = np.array(
        [
            (0, 10, 400, 0.1, 4),
            (0.1, 50, 400, 0.5, 4),
            (0.1, 50, -300, 0.5, -2),
            (0.2, 20, -300, 0.3, -2),
        ],
        dtype=[(name, float) for name in names],
    )
    runs = [
        simulate(
            fmu, stop_time=0.2, output_interval=0.01, inputs=signal, output=list(table.OUTPUTS)
        )
        for fmu in (fmu_path, fmi3_path)
    ]
    assert runs[1].dtype["crosspiece_quaternion"].shape == (4,)
    assert runs[1]["time"][-1] == pytest.approx(0.2)
    fmi2, fmi3 = flat_columns(runs[0]), flat_columns(runs[1])
    assert fmi2.dtype.names == fmi3.dtype.names == ("time",) + table.OUTPUTS
    for name in fmi2.dtype.names:
        np.testing.assert_array_equal(fmi3[name], fmi2[name], err_msg=name)
    plain = simulate_fmu(str(fmi3_path), stop_time=0.2, output_interval=0.01, input=signal)
    np.testing.assert_array_equal(plain["crosspiece_torque"], runs[1]["crosspiece_torque"])


# The FMI 2.0 counterpart, alike in shape: test_refusal.py's
# test_simulate_raises_the_refusal_with_its_fields.
def test_simulate_raises_with_the_message_and_the_result_so_far(fmi3_path):
    signal = np.array(
        [(0.0, 0.3), (0.2, 0.3), (0.2, 1.5), (0.5, 1.5)],
        dtype=[("time", float), ("bend_angle", float)],
    )
    with pytest.raises(SimulationError) as refused:
        simulate(fmi3_path, stop_time=0.5, output_interval=0.1, inputs=signal)
    assert "bend_angle = 1.5 rad" in str(refused.value) and "max_bend_angle" in str(refused.value)
    assert refused.value.result["time"][-1] == pytest.approx(0.2)


def test_a_host_without_a_logger_gets_the_message_on_stderr(fmi3_path, tmp_path):
    # FMI 3.0 lets a host pass no logMessage callback; pythonfmu3 would call NULL.
    script = textwrap.dedent(f"""
        from pathlib import Path
        from fmpy import extract, read_model_description
        from fmpy.fmi3 import FMU3Slave, fmi3LogMessageCallback, fmi3IntermediateUpdateCallback
        md = read_model_description({str(fmi3_path)!r})
        unzipped = extract({str(fmi3_path)!r}, unzipdir={str(tmp_path)!r})
        fmu = FMU3Slave(guid=md.guid, unzipDirectory=unzipped, instanceName="silent",
                        modelIdentifier=md.coSimulation.modelIdentifier)
        fmu.logMessage, fmu.intermediateUpdate = (fmi3LogMessageCallback(),
                                                  fmi3IntermediateUpdateCallback())
        resources = (Path(unzipped, "resources").as_uri() + "/").encode()
        fmu.component = fmu.fmi3InstantiateCoSimulation(
            b"silent", md.guid.encode(), resources, False, False, False, False, None, 0,
            None, fmu.logMessage, fmu.intermediateUpdate)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        fmu.setFloat64([4], [1.5])  # bend_angle: time, input_speed, input_acceleration first
        try:
            fmu.doStep(0.0, 0.1)
        except Exception as refusal:
            print("refused", refusal.status)
    """)
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert "refused 3" in run.stdout  # a refused step: fmi3Error
    assert "Error: t = 0.0 s: input bend_angle = 1.5 rad" in run.stderr


def test_the_cli_writes_the_same_columns_for_either_fmu(fmu_path, fmi3_path, tmp_path):
    from cardan_joint.cli import main

    tables = []
    for fmu in (fmu_path, fmi3_path):
        out = tmp_path / f"{fmu.parent.name}.csv"
        assert (
            main(
                [
                    "simulate",
                    "--fmu",
                    str(fmu),
                    "--set",
                    "bend_angle=0.4",
                    "--stop-time",
                    "0.05",
                    "--step",
                    "0.01",
                    "--output",
                    str(out),
                    "--no-progress",
                ]
            )
            == 0
        )
        tables.append(out.read_text())
    assert tables[0] == tables[1]
