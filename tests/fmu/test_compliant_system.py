"""Motor -> CompliantJoint -> InertiaLoad: a plain Jacobi master on FMPy's low-level
API, FMPy's simulate_ssp and libcosim, against one monolithic ODE (tests/reference)."""

import math
import re
import zipfile
from pathlib import Path

import numpy as np
import pytest
from jacobi import jacobi_master
from reference.compliant_driveline import simulate_compliant_driveline
from ssp_checks import check_ssp_for_every_host

from cardan_joint.host import driveline_system as system
from cardan_joint.host.ssp import SSPError, check_ssp, fmpy_parameter_set
from cardan_joint.models.compliant_joint.variables import COMPLIANT_JOINT

STOP_TIME = 0.1  # about; each run stops after a whole number of its steps
WIRING = dict(connections=system.COMPLIANT_CONNECTIONS, recorded=system.COMPLIANT_RECORDED)
COMPARED = ("Motor.speed", "Load.speed", "Drive.twist_angle")
COMPLIANT_JOINT_PAGE = Path(system.__file__).parents[1] / "models" / "compliant_joint" / "README.md"


@pytest.fixture(scope="module")
def compliant_fmus(motor_fmu_path, compliant_joint_fmu_path, inertia_load_fmu_path):
    return {
        "Motor": motor_fmu_path,
        system.DRIVE_INSTANCE: compliant_joint_fmu_path,
        "Load": inertia_load_fmu_path,
    }


def _ssp(fmus, folder, ratio):
    motor, drive, load, step = system.compliant_parameters(ratio)
    path = system.write_driveline_ssp(
        folder / f"Compliant{ratio:g}.ssp",
        fmus,
        "CompliantJoint",
        STOP_TIME,
        motor=motor,
        load=load,
        drive_parameters=drive,
        step_size=step,
        **WIRING,
    )
    return path, motor, drive, load, step


@pytest.fixture(scope="module", params=[1000.0, 0.1], ids=["ratio1000", "ratio0.1"])
def compliant_ssp(compliant_fmus, tmp_path_factory, request):
    return _ssp(compliant_fmus, tmp_path_factory.mktemp("compliant_ssp"), request.param)


def test_step_rule_keeps_a_tenth_radian_of_the_mode_per_step():
    omega_n, damping, step = system.torsional_step(1e4, 0.2, 200.0, 0.1)
    assert omega_n == pytest.approx((1e4 * (1 / 0.2 + 1 / 200.0)) ** 0.5)
    assert omega_n * step == pytest.approx(0.1)
    assert damping == pytest.approx(0.2 * (1e4 * 0.2 * 200.0 / 200.2) ** 0.5)
    # A lightly damped mode takes a step of zeta / omega_n.
    assert system.torsional_step(1e4, 0.2, 200.0, 0.02)[2] * omega_n == pytest.approx(0.02)


def error_table(page=COMPLIANT_JOINT_PAGE) -> dict:
    """The CompliantJoint page's error table: {(ratio, step): [motor, load, twist]}."""
    rows = re.findall(r"^\| ([\d.]+) \| ([^|]+?) \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$",
                      page.read_text(), re.MULTILINE)  # fmt: skip
    return {(float(r[0]), r[1]): [float(x) for x in r[2:]] for r in rows}


def test_jacobi_error_against_the_monolithic_ode_falls_at_first_order(compliant_ssp, request):
    """...and is what the CompliantJoint page's table says, to its two digits."""
    path, motor, drive, load, h = compliant_ssp
    n = round(STOP_TIME / h)
    reference = simulate_compliant_driveline(
        h * np.arange(1, n + 1), motor, {**COMPLIANT_JOINT.start_values(), **drive}, load
    )
    errors = []
    for refinement in (1, 4):
        rows = jacobi_master(path, n * h, h / refinement, None, **WIRING)
        errors.append(
            {
                key: np.max(np.abs(rows[key][refinement - 1 :: refinement] - reference[key]))
                / np.max(np.abs(reference[key]))
                for key in COMPARED
            }
        )
    for key in COMPARED:
        assert 3.0 < errors[0][key] / errors[1][key] < 5.5, (key, errors)
    assert max(errors[1].values()) < 0.05, errors
    ratio = request.node.callspec.params["compliant_ssp"]
    table = error_table()
    for step, measured in zip((f"{round(h * 1e6)} µs", "h/4"), errors, strict=True):
        stated = table[ratio, step]
        for value, key in zip(stated, COMPARED, strict=True):
            # Two significant digits: within half a unit of the second.
            assert abs(measured[key] - value) <= 0.5 * 10 ** (math.floor(math.log10(value)) - 1)


def test_both_ssp_hosts_finish_and_are_the_jacobi_master_with_their_first_inputs(compliant_ssp):
    path, _, _, _, h = compliant_ssp
    recorded = system.COMPLIANT_RECORDED
    n = round(STOP_TIME / h)
    fmpy_rows = system.run_fmpy(path, n * h, h, recorded=recorded)
    libcosim_rows = system.run_libcosim(path, n * h, h, recorded=recorded)
    assert len(fmpy_rows["time"]) == n and len(libcosim_rows["Motor.speed"]) == n + 1
    # FMPy feeds zeros first; libcosim its outputs after initialization (its t = 0 row).
    zeros = {key: 0.0 for key in recorded}
    initial = {key: libcosim_rows[key][0] for key in recorded}
    for rows, first, offset in ((fmpy_rows, zeros, 0), (libcosim_rows, initial, 1)):
        reference = jacobi_master(path, n * h, h, first, **WIRING)
        for key in recorded:
            scale = max(1.0, np.max(np.abs(reference[key])))
            assert np.max(np.abs(rows[key][offset:] - reference[key])) <= 1e-9 * scale, key


def test_every_component_binds_its_parameters_in_the_one_set_every_host_applies(
    compliant_ssp,
):
    path, motor, drive, load, _ = compliant_ssp
    # Valid for pyssp-standard (no warning), bound parameters no connectors, one set name,
    # OMSimulator's annotations.
    bound = check_ssp_for_every_host(path)
    assert bound == {"Motor": motor, "Drive": drive, "Load": load}
    # FMPy's one parameter set (hierarchical names) holds the same values.
    fmpy_values = {p.name: float(p.value) for p in fmpy_parameter_set(path).parameters}
    assert fmpy_values == {
        f"{component}.{name}": value
        for component, values in bound.items()
        for name, value in values.items()
    }


def test_a_missing_or_broken_ssp_is_named_without_a_traceback_of_temporary_files(tmp_path):
    with pytest.raises(SSPError, match="no such SSP file"):
        system.run_fmpy(tmp_path / "absent.ssp", 0.1, 0.01)
    broken = tmp_path / "broken.ssp"
    broken.write_text("not a zip")
    with pytest.raises(SSPError, match=r"broken\.ssp: not an SSP archive"):
        system.run_libcosim(broken, 0.1, 0.01)
    cases = {
        "empty.ssp": ({}, "has no SystemStructure.ssd"),
        "bad_xml.ssp": ({"SystemStructure.ssd": "<ssd:System"}, "not well-formed XML"),
        "no_component.ssp": ({"SystemStructure.ssd": "<s/>"}, "names no component"),
        "no_fmu.ssp": (
            {
                "SystemStructure.ssd": '<s xmlns:ssd="http://ssp-standard.org/SSP1/'
                'SystemStructureDescription"><ssd:Component source="resources/M.fmu"/></s>'
            },
            "lacks resources/M.fmu",
        ),
    }
    for name, (members, words) in cases.items():
        with zipfile.ZipFile(tmp_path / name, "w") as archive:
            for member, text in members.items():
                archive.writestr(member, text)
            if not members:
                archive.writestr("other.txt", "")
        with pytest.raises(SSPError, match=words):
            check_ssp(tmp_path / name)


def test_the_compliant_propshaft_runs_the_same_system_at_ratio_1000(
    motor_fmu_path, inertia_load_fmu_path, tmp_path_factory
):
    from conftest import build_fmu

    folder = tmp_path_factory.mktemp("compliant_propshaft_system")
    fmus = {
        "Motor": motor_fmu_path,
        system.DRIVE_INSTANCE: build_fmu(folder, "--model", "CompliantPropshaft"),
        "Load": inertia_load_fmu_path,
    }
    motor, drive, load, h = system.compliant_parameters(1000.0)
    # The propshaft's layout (its default Z-arrangement) instead of the joint's bend.
    drive.pop("bend_angle")
    path = system.write_driveline_ssp(
        folder / "p.ssp", fmus, "CompliantPropshaft", STOP_TIME, motor, load, drive, **WIRING
    )
    check_ssp_for_every_host(path)
    n = round(STOP_TIME / h)
    rows = jacobi_master(path, n * h, h, None, **WIRING)  # raises on a refused step
    assert len(rows["Motor.speed"]) == n and np.all(np.isfinite(rows["Drive.twist_angle"]))
    # The heavy load barely moves yet: the spring holds the motor near stall, its
    # torque passed on to the load (about the stall torque, less the inertia terms).
    assert 0.0 < rows["Load.speed"][-1] < 0.1 and abs(rows["Motor.speed"][-1]) < 1.0
    assert 0.5 * motor["stall_torque"] < rows["Drive.output_torque"][-1] < motor["stall_torque"]
