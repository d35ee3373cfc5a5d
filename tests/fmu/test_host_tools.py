"""The host tools read the FMU, not a Python table: `cardan-joint simulate` runs
every model the build offers, and a misspelt name is refused naming the right one.
The command runs in this process (`cardan_joint_here`, its `main` as a host calls
it): its own process is tests/fmu/test_cli.py's subject."""

import subprocess
import sys

import numpy as np
import pytest
from conftest import ROOT, cardan_joint_here, run_build

from cardan_joint import results
from cardan_joint.host.fmu_info import FmuInfo, build_command
from cardan_joint.models import MODELS

# Every model the build offers, for every FMI version it offers.
BUILDS = [(key, version) for key, spec in MODELS.items() for version in spec.fmi_versions]
# The command reads an FMI 3.0 FMU one way for every model (FmuInfo; each model's
# FMI 3.0 build equals its FMI 2.0 build, checked below): every model through
# FMI 2.0, FMI 3.0 through a single joint and a propshaft with build settings.
RUNS = [(key, 2) for key in MODELS] + [("UniversalJoint", 3), ("CompliantPropshaft", 3)]
# Building what the message names takes a build per case: one FMI 2.0 model and
# one FMI 3.0 model with a build setting run it; every build's command is read
# back below without building.
REBUILT = [("UniversalJoint", 2), ("CompliantPropshaft", 3)]


@pytest.mark.parametrize("key, version", RUNS)
def test_simulate_writes_a_csv_and_a_png_for_every_model(capsys, built, key, version, tmp_path):
    fmu = built(key, version)
    out = tmp_path / "run.csv"
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu, "--stop-time", "0.05", "--output", out
    )
    assert run.returncode == 0, run.stderr
    info = FmuInfo.read(fmu)
    rows = results.read_csv(out)
    assert set(info.columns("input", "output")) <= set(rows.dtype.names)
    assert len(rows) == 51 and out.with_suffix(".png").stat().st_size > 0


@pytest.mark.parametrize(
    "args, wrong, right",
    [
        (("--set", "bend_angel=0.5"), "bend_angel", "bend_angle"),
        (("--set", "crosspiece_inertia2=0.01"), "crosspiece_inertia2", "crosspiece_inertia_2"),
        (("--plot-variables", "output_sped"), "output_sped", "output_speed"),
    ],
)
def test_a_misspelt_cli_name_is_refused_naming_the_right_one(
    capsys, built, tmp_path, args, wrong, right
):
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", built("UniversalJoint"), "--output", tmp_path / "x.csv", *args
    )
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert f"{wrong!r}; did you mean {right}" in run.stderr
    assert not (tmp_path / "x.csv").exists()


def test_a_misspelt_input_csv_column_is_refused_naming_the_right_one(capsys, built, tmp_path):
    inputs = tmp_path / "typo.csv"
    inputs.write_text("time,load_torqe\n0,1\n1,2\n")
    run = cardan_joint_here(capsys, "simulate", "--fmu", built("Propshaft"), "--input", inputs)
    assert run.returncode == 2 and "'load_torqe'; did you mean load_torque" in run.stderr


def test_a_misspelt_build_start_value_is_refused_naming_the_right_one(tmp_path):
    run = run_build(tmp_path, "--set", "bend_angel=0.2")
    assert run.returncode != 0 and "'bend_angel'; did you mean bend_angle" in run.stderr
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize(
    "setting, reason",
    [
        ("bend_angle=1.5", "bend_angle = 1.5 rad"),  # the first step refused
        ("crosspiece_inertia_1=-1", "crosspiece_inertia_1 = -1.0 kg.m2"),  # initialization
    ],
)
def test_a_run_refused_at_the_start_says_so_and_writes_nothing(
    capsys, built, tmp_path, setting, reason
):
    out = tmp_path / "refused.csv"
    args = ("simulate", "--fmu", built("UniversalJoint"), "--output", out)
    run = cardan_joint_here(capsys, *args, "--set", setting)
    assert run.returncode == 2 and "Traceback" not in run.stderr  # as `build` for the mistake
    assert "refused the run at its start (t = 0 s)" in run.stderr
    assert reason in run.stderr  # the FMU's own, not FMPy's bare status
    assert not out.exists() and not out.with_suffix(".png").exists()


def test_a_constant_bend_angle_with_a_nonzero_rate_is_refused(capsys, built, tmp_path):
    run = cardan_joint_here(
        capsys,
        "simulate",
        "--fmu",
        built("UniversalJoint"),
        "--set",
        "bend_angle=0.3",
        "--set",
        "bend_angle_rate=0.5",
        "--output",
        tmp_path / "x.csv",
    )
    assert run.returncode == 2 and "contradictory" in run.stderr
    assert "bend_angle = 0.3" in run.stderr and "bend_angle_rate = 0.5" in run.stderr


@pytest.mark.parametrize("key, version", REBUILT)
def test_a_missing_fmu_names_the_command_that_builds_it(capsys, built, key, version, tmp_path):
    """The named command, run as given, writes exactly the missing file."""
    fmu = built(key, version)
    missing = tmp_path / fmu.relative_to(fmu.parents[1 if version == 3 else 0])
    run = cardan_joint_here(capsys, "simulate", "--fmu", missing)
    assert run.returncode == 2 and "Traceback" not in run.stderr
    command = build_command(missing)
    assert f"build it with `{command}`" in run.stderr
    python, script, *flags = command.split()
    assert (python, script) == ("python", "build_fmu.py")
    built_now = subprocess.run(
        [sys.executable, script, *flags], capture_output=True, text=True, cwd=ROOT
    )
    assert built_now.returncode == 0, built_now.stderr
    assert missing.is_file()


@pytest.mark.parametrize("key, version", BUILDS)
def test_every_builds_missing_fmu_command_names_its_model_and_version(key, version):
    spec = MODELS[key]
    name = spec.default_name(spec.default_settings)
    path = f"dist/fmi3/{name}.fmu" if version == 3 else f"dist/{name}.fmu"
    flags = build_command(path).split()[2:]
    assert flags[flags.index("--model") + 1] == key
    assert ("--fmi-version" in flags) == (version == 3)


def test_the_missing_fmu_command_carries_the_joints_and_fmi_version():
    propshaft3 = "python build_fmu.py --model Propshaft --joints 3"
    assert build_command("dist/Propshaft3.fmu") == propshaft3
    assert build_command("dist/fmi3/UniversalJoint.fmu") == (
        "python build_fmu.py --model UniversalJoint --fmi-version 3"
    )


def test_every_quantity_in_the_cli_help_names_its_unit():
    """simulate --set is SI, sweep takes deg and rpm: each help text says which."""
    import argparse
    import re

    from cardan_joint import cli, sweep

    sweep_parser = argparse.ArgumentParser()
    sweep.add_arguments(sweep_parser)
    simulate_parser = cli._parser()._subparsers._group_actions[0].choices["simulate"]
    unit = re.compile(r"\[[^\]]+\]|\bSI\b|\bdeg\b|\brpm\b")
    for parser in (simulate_parser, sweep_parser):
        for action in parser._actions:
            quantity = action.type is float or action.metavar in ("NAME=VALUE", "CSV")
            if quantity:
                assert unit.search(action.help or ""), action.option_strings


@pytest.mark.parametrize(
    "arguments, wrong, right",
    [
        ({"inputs": {"bend_angel": 0.3}}, "bend_angel", "bend_angle"),
        ({"start_values": {"yoke_phse": 0.1}}, "yoke_phse", "yoke_phase"),
        ({"output": ["cardan_eror"]}, "cardan_eror", "cardan_error"),
    ],
)
def test_simulate_refuses_a_misspelt_name_naming_the_right_one(fmu_path, arguments, wrong, right):
    from cardan_joint.host.simulate import simulate
    from cardan_joint.names import UnknownNameError

    with pytest.raises(UnknownNameError, match=f"'{wrong}'; did you mean {right}"):
        simulate(fmu_path, stop_time=0.01, output_interval=1e-3, **arguments)


def test_simulate_refuses_a_constant_bend_angle_with_a_nonzero_rate(fmu_path):
    from cardan_joint.host.simulate import simulate
    from cardan_joint.names import UsageError

    with pytest.raises(UsageError, match="bend_angle = 0.3 is given as a constant"):
        simulate(fmu_path, stop_time=0.01, inputs={"bend_angle": 0.3, "bend_angle_rate": 1.0})
    with pytest.raises(UsageError, match="contradictory"):  # the rate from a start value
        simulate(
            fmu_path,
            stop_time=0.01,
            inputs={"bend_angle": 0.3},
            start_values={"bend_angle_rate": 1.0},
        )


def test_simulate_names_the_build_command_of_a_missing_fmu(tmp_path):
    from cardan_joint.host.fmu_info import MissingFMUError
    from cardan_joint.host.simulate import simulate

    with pytest.raises(MissingFMUError, match="`python build_fmu.py --model Motor --dest "):
        simulate(tmp_path / "Motor.fmu")


def test_setting_an_output_says_it_is_an_output(capsys, built, tmp_path):
    run = cardan_joint_here(
        capsys,
        "simulate",
        "--fmu",
        built("Motor"),
        "--set",
        "speed=3",
        "--output",
        tmp_path / "x.csv",
    )
    assert run.returncode == 2
    assert "'speed' is an output of Motor, not an input or parameter" in run.stderr


@pytest.mark.parametrize("key", sorted(MODELS))
def test_every_models_fmi3_build_validates_and_equals_its_fmi2_build(built, key):
    from fmpy.validation import validate_fmu

    from cardan_joint.simulate import flat_columns, simulate

    fmi2, fmi3 = built(key, 2), built(key, 3)
    assert validate_fmu(str(fmi3)) == []
    assert FmuInfo.read(fmi3).model_description.fmiVersion == "3.0"
    runs = [
        flat_columns(simulate(fmu, stop_time=0.05, output_interval=1e-3)) for fmu in (fmi2, fmi3)
    ]
    outputs = FmuInfo.read(fmi2).columns("output")
    assert outputs and len(runs[0]) == len(runs[1]) == 51
    for name in outputs:
        np.testing.assert_array_equal(runs[1][name], runs[0][name], err_msg=f"{key}: {name}")
