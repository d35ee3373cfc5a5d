"""The driveline SSP system (Motor -> drive element -> Load) in FMPy, libcosim and
Ecos, and what it carries for OMSimulator and pyssp-standard."""

import math
import subprocess
import sys
import zipfile

import numpy as np
import pytest
from jacobi import jacobi_master
from session_files import shared
from ssp_checks import check_ssp_for_every_host

from cardan_joint.host import driveline_system as system
from cardan_joint.host.ssp import Component, write_ssp


@pytest.fixture(scope="module")
def driveline_ssp(motor_fmu_path, load_fmu_path, request, pytestconfig, tmp_path_factory):
    """The SSP of the session's FMUs, written once for all workers."""
    # The session's FMU of the drive model (built once for all tests).
    session_fixture = {"UniversalJoint": "fmu_path", "Propshaft": "propshaft_fmu_path"}
    drive = request.getfixturevalue(session_fixture[system.DRIVE])
    fmus = {
        "Motor": motor_fmu_path,
        system.DRIVE_INSTANCE: drive,
        "Load": load_fmu_path,
    }
    return shared(
        pytestconfig,
        tmp_path_factory,
        "driveline_ssp",
        lambda folder: system.write_driveline_ssp(folder / "Driveline.ssp", fmus),
    )


@pytest.fixture(scope="module")
def system_ssp(pytestconfig, tmp_path_factory):
    """The SSP of FMUs built at the system's parameter values, as the example writes it."""

    def make(folder):
        # In a process of its own, as the example builds them: in this one, after an
        # FMU has run, `pythonfmu` is that FMU's shipped copy, which lacks the binaries
        # a build packs.
        script = (
            "import sys; from cardan_joint.host import driveline_system as s; "
            "fmus = s.build_fmus(sys.argv[1], parameters=s.system_parameters()); "
            "s.write_driveline_ssp(sys.argv[1] + '/Driveline.ssp', fmus)"
        )
        run = subprocess.run(
            [sys.executable, "-c", script, str(folder)], capture_output=True, text=True
        )
        assert run.returncode == 0, run.stderr
        return folder / "Driveline.ssp"

    return shared(pytestconfig, tmp_path_factory, "driveline_system_ssp", make)


# --- the SSP system --------------------------------------------------------


def test_ssp_holds_the_three_fmus_connections_and_parameter_sets(driveline_ssp):
    from fmpy.ssp.ssd import read_ssd

    # Valid for pyssp-standard (no warning), each connector of its FMU causality's kind,
    # bound parameters no connectors, one set name for Ecos, OMSimulator's annotations.
    assert check_ssp_for_every_host(driveline_ssp) == {
        "Motor": system.MOTOR_PARAMETERS,
        system.DRIVE_INSTANCE: system.DRIVE_PARAMETERS[system.DRIVE],
        "Load": system.LOAD_PARAMETERS,
    }

    ssd = read_ssd(str(driveline_ssp))  # validates against the SSP schema
    assert [c.name for c in ssd.system.elements] == ["Motor", system.DRIVE_INSTANCE, "Load"]
    assert len(ssd.system.connections) == 6
    names = zipfile.ZipFile(driveline_ssp).namelist()
    assert {
        "resources/Motor.fmu",
        f"resources/{system.DRIVE}.fmu",
        "resources/Load.fmu",
        "resources/Motor.ssv",
        "resources/Drive.ssv",
        "resources/Load.ssv",
    } <= set(names)


def test_the_universal_joint_ssp_binds_its_input_bend_angle_without_a_connector(
    fmu_path, motor_fmu_path, load_fmu_path, tmp_path
):
    fmus = {"Motor": motor_fmu_path, system.DRIVE_INSTANCE: fmu_path, "Load": load_fmu_path}
    ssp = system.write_driveline_ssp(tmp_path / "Driveline.ssp", fmus, "UniversalJoint")
    # No connector for it (an FMU input declared a parameter before), and pyssp-standard
    # has no warning: check_ssp_for_every_host asserts both.
    bound = check_ssp_for_every_host(ssp)
    assert bound[system.DRIVE_INSTANCE] == system.DRIVE_PARAMETERS["UniversalJoint"]


def test_ssp_writer_refuses_a_connector_or_binding_the_fmu_contradicts(tmp_path, motor_fmu_path):
    for connectors, parameters, words in (
        ({"load_torque": "output"}, {}, "'load_torque' is declared an output, but the FMU"),
        ({"torque": "output"}, {}, "'torque' is declared an output, but the FMU .* no variable"),
        ({}, {"speed": 1.0}, "'speed' is bound, but the FMU Motor.fmu has it as output"),
    ):
        motor = Component("Motor", motor_fmu_path, connectors, parameters)
        with pytest.raises(ValueError, match=words):
            write_ssp(tmp_path / "x.ssp", "X", [motor], [], 1.0, 0.1)


def test_ssp_writer_refuses_a_connection_to_a_missing_connector(tmp_path, motor_fmu_path):
    motor = Component("Motor", motor_fmu_path, {"speed": "output"})
    with pytest.raises(ValueError, match="Motor has no input connector 'speed'"):
        write_ssp(
            tmp_path / "x.ssp", "X", [motor], [("Motor", "speed", "Motor", "speed")], 1.0, 0.1
        )


def test_ssp_writer_refuses_a_parameter_that_is_also_connected_and_a_bad_step(
    tmp_path, motor_fmu_path
):
    motor = Component("Motor", motor_fmu_path, {"load_torque": "input"}, {"load_torque": 1.0})
    with pytest.raises(ValueError, match="'load_torque' is bound as a parameter but connected"):
        write_ssp(tmp_path / "x.ssp", "X", [motor], [], 1.0, 0.1)
    motor = Component("Motor", motor_fmu_path, {}, {"stall_torque": 1.0})
    for step in (0.0, -1e-3, math.nan, 2.0):
        with pytest.raises(ValueError, match="step_size .* must be in \\(0, stop_time = 1.0\\]"):
            write_ssp(tmp_path / "x.ssp", "X", [motor], [], 1.0, step)


def test_both_hosts_apply_the_parameter_sets_and_differ_only_by_the_first_step(driveline_ssp):
    differences = {}
    for h in (1e-3, 5e-4):
        fmpy_rows = system.run_fmpy(driveline_ssp, 0.2, h)
        libcosim_rows = system.run_libcosim(driveline_ssp, 0.2, h)
        differences[h] = system.host_difference(fmpy_rows, libcosim_rows)["Motor.speed"]
        # The parameter sets reached the FMUs in both hosts: motor torque = 120 (1 - w / w0).
        for rows in (fmpy_rows, libcosim_rows):
            expected = 120.0 * (1 - rows["Motor.speed"] / system.MOTOR_PARAMETERS["no_load_speed"])
            np.testing.assert_allclose(rows["Motor.motor_torque"], expected, rtol=1e-12, atol=1e-9)
    # libcosim starts from the initial outputs, FMPy from zeros: the difference is one
    # step's impulse, so it halves with the step.
    assert 1.9 < differences[1e-3] / differences[5e-4] < 2.1, differences


def test_ecos_applies_the_one_parameter_set_and_differs_from_fmpy_by_the_first_step(
    driveline_ssp,
):
    # Ecos applies the one set named at initialisation: named after the system, it
    # holds every component's parameters (with a component's name it held one only,
    # and the run diverged).
    differences = {}
    for h in (1e-3, 5e-4):
        fmpy_rows = system.run_fmpy(driveline_ssp, 0.2, h)
        ecos_rows = system.run_ecos(driveline_ssp, 0.2, h)
        expected = 120.0 * (1 - ecos_rows["Motor.speed"] / system.MOTOR_PARAMETERS["no_load_speed"])
        np.testing.assert_allclose(ecos_rows["Motor.motor_torque"], expected, rtol=1e-12, atol=1e-9)
        differences[h] = system.host_difference(fmpy_rows, ecos_rows)["Motor.speed"]
    # Ecos, as libcosim, passes initial outputs through first: a first-step impulse,
    # halving with the step. (With the drive's and load's defaults instead of the
    # set's, the torque loop ran away: -7.6e4 rad/s at 0.2 s.)
    assert 1.9 < differences[1e-3] / differences[5e-4] < 2.1, differences


def test_ecos_with_no_set_named_applies_every_parameter_and_differs_from_fmpy_by_the_first_step(
    system_ssp,
):
    # Ecos applies an SSP's parameters only from a set named at initialisation; with
    # none named, each FMU runs on its own start values, which `build_fmus` made the
    # system's. (On FMUs at their defaults: 2 of 7, the motor at 8.9e4 rad/s at 0.5 s.)
    from cardan_joint.host.ecos import run_ecos_ssp

    expected = {
        f"{instance}.{name}": value
        for instance, parameters in system.system_parameters().items()
        for name, value in parameters.items()
    }
    differences = {}
    for h in (1e-3, 5e-4):
        ecos_rows = run_ecos_ssp(system_ssp, 0.2, h, [*system.RECORDED, *expected], None)
        assert {name: ecos_rows[name][0] for name in expected} == expected  # 7 of 7
        fmpy_rows = system.run_fmpy(system_ssp, 0.2, h)
        differences[h] = system.host_difference(fmpy_rows, ecos_rows)["Motor.speed"]
    assert len(expected) == 7
    assert 1.9 < differences[1e-3] / differences[5e-4] < 2.1, differences


def test_fmpy_given_no_parameter_set_runs_the_system_as_bound(system_ssp):
    # FMPy's simulate_ssp applies no binding of its own: as a user calls it, with
    # none passed, the FMUs' start values are the bound ones.
    from fmpy.ssp.simulation import simulate_ssp

    h = 1e-3
    plain = simulate_ssp(str(system_ssp), stop_time=99.5 * h, step_size=h)
    bound = system.run_fmpy(system_ssp, 100 * h, h)
    for key in system.RECORDED:
        assert np.array_equal(plain[key], bound[key]), key


def test_each_host_is_exactly_a_jacobi_master_with_its_own_first_inputs(driveline_ssp):
    h, stop_time = 1e-3, 0.1
    fmpy_rows = system.run_fmpy(driveline_ssp, stop_time, h)
    libcosim_rows = system.run_libcosim(driveline_ssp, stop_time, h)
    zeros = {key: 0.0 for key in system.RECORDED}
    initial = {key: libcosim_rows[key][0] for key in system.RECORDED}
    for rows, first, offset in ((fmpy_rows, zeros, 0), (libcosim_rows, initial, 1)):
        reference = jacobi_master(driveline_ssp, stop_time, h, first)
        for key in system.RECORDED:
            scale = max(1.0, np.max(np.abs(reference[key])))
            assert np.max(np.abs(rows[key][offset:] - reference[key])) <= 1e-9 * scale, key
