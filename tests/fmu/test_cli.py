"""The `cardan-joint` command, run as a user runs it (separate processes)."""

import re
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import cardan_joint
from session_files import shared

from cardan_joint import cli, results
from cardan_joint.models.universal_joint import variables as table


def _build(dest):
    run = cardan_joint("build", "--dest", dest, "--name", "CliJoint", "--set", "bend_angle=0.2")
    assert run.returncode == 0, run.stderr
    fmu = dest / "CliJoint.fmu"
    assert fmu.is_file()
    return fmu


@pytest.fixture(scope="module")
def built_fmu(pytestconfig, tmp_path_factory):
    """The command's own build, made once for all workers."""
    return shared(pytestconfig, tmp_path_factory, "cli_build", _build)


def test_console_script_is_installed():
    assert (Path(sys.executable).parent / "cardan-joint").is_file()


def test_simulate_from_constant_inputs(built_fmu, tmp_path):
    out = tmp_path / "run.csv"
    run = cardan_joint(
        "simulate",
        "--fmu",
        built_fmu,
        "--set",
        "input_speed=20",
        "--set",
        "crosspiece_inertia_2=0.01",
        "--stop-time",
        "0.2",
        "--step",
        "1e-3",
        "--output",
        out,
    )
    assert run.returncode == 0, run.stderr
    rows = results.read_csv(out)
    assert len(rows) == 201
    assert float(rows[0]["input_speed"]) == 20.0
    assert float(rows[0]["bend_angle"]) == 0.2  # the build's start value
    assert out.with_suffix(".png").stat().st_size > 0


def test_simulate_from_an_input_csv(built_fmu, tmp_path):
    inputs = tmp_path / "inputs.csv"
    inputs.write_text(
        "time,input_speed,input_acceleration,bend_angle,bend_angle_rate\n"
        "0,10,10,0.1,0.4\n0.5,15,10,0.3,0.4\n"
    )
    out, plot = tmp_path / "csv_run.csv", tmp_path / "plots" / "csv_run.png"
    run = cardan_joint(  # run in tmp_path: a missing folder inside the working folder is made
        "simulate",
        "--fmu",
        built_fmu,
        "--input",
        inputs,
        "--set",
        "load_torque=50",
        "--output",
        out,
        "--plot",
        plot,
        "--plot-variables",
        "output_speed",
        "input_torque",
        cwd=tmp_path,
    )
    assert run.returncode == 0, run.stderr
    rows = results.read_csv(out)
    assert float(rows[-1]["time"]) == pytest.approx(0.5)  # the CSV's last time
    assert float(rows[250]["input_speed"]) == pytest.approx(12.5)
    assert float(rows[-1]["load_torque"]) == 50.0
    assert plot.stat().st_size > 0


@pytest.mark.parametrize(
    "args, named",
    [
        (("--set", "bend_angle=1.5"), "bend_angle"),  # refused by the FMU's guard
        (("--set", "bend_angel=0.5"), "bend_angel"),  # no such variable
        (("--set", "output_speed=1"), "output_speed"),  # not settable
        (("--set", "load_torque=abc"), "load_torque"),
    ],
)
def test_bad_input_exits_non_zero_naming_the_variable(built_fmu, tmp_path, args, named):
    run = cardan_joint(
        "simulate",
        "--fmu",
        built_fmu,
        "--stop-time",
        "0.1",
        "--output",
        tmp_path / "bad.csv",
        *args,
    )
    assert run.returncode != 0
    assert named in run.stderr
    assert "Traceback" not in run.stderr


def test_bad_input_csv_column_is_named(built_fmu, tmp_path):
    inputs = tmp_path / "typo.csv"
    inputs.write_text("time,input_sped\n0,1\n1,2\n")
    run = cardan_joint(
        "simulate", "--fmu", built_fmu, "--input", inputs, "--output", tmp_path / "bad.csv"
    )
    assert run.returncode != 0 and "input_sped" in run.stderr
    assert "Traceback" not in run.stderr


@pytest.mark.parametrize(
    "where, said",
    [
        ({"--output": "plain/run.csv"}, "cannot write {tmp}/plain/run.csv: {tmp}/plain is a file"),
        ({"--plot": "plain/run.png"}, "cannot write {tmp}/plain/run.png: {tmp}/plain is a file"),
        ({"--output": "."}, "cannot write {tmp}: it is a folder"),
        ({"--input": "missing.csv"}, "input file {tmp}/missing.csv does not exist"),
    ],
)
def test_a_bad_path_is_named_before_the_run(built_fmu, tmp_path, where, said):
    (tmp_path / "plain").write_text("x")
    paths = {option: str(tmp_path / name) for option, name in where.items()}
    options = {"--output": str(tmp_path / "run.csv"), **paths}
    args = [item for option, value in options.items() for item in (option, value)]
    run = cardan_joint("simulate", "--fmu", built_fmu, "--stop-time", "0.01", *args)
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert said.format(tmp=tmp_path) in run.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain"]  # nothing written


def test_missing_fmu_is_a_message_not_a_traceback(tmp_path):
    run = cardan_joint("simulate", "--fmu", tmp_path / "none.fmu")
    assert run.returncode != 0 and "does not exist" in run.stderr
    assert "Traceback" not in run.stderr


def test_sweep_subcommand_runs_the_shared_sweep(built_fmu, tmp_path):
    run = cardan_joint(
        "sweep",
        "--serial",
        "--fmu",
        built_fmu,
        "--bend-angles",
        "5",
        "--speeds",
        "1000",
        "--distributions",
        "T1",
        "--revolutions",
        "1",
        "--steps-per-revolution",
        "36",
        "--out",
        tmp_path,
        "--no-progress",
    )
    assert run.returncode == 0, run.stderr
    rows = results.read_table(tmp_path / "sweep.csv")  # the CLI's own name
    assert list(rows["status"]) == ["ok"]
    assert (tmp_path / "sweep.png").stat().st_size > 0
    assert not (tmp_path / "design_sweep.csv").exists()  # the example's is left alone


def test_a_refused_run_writes_what_it_computed_and_says_where_it_stopped(built_fmu, tmp_path):
    inputs = tmp_path / "bend_ramp.csv"  # the bend reaches the 80 deg guard at 0.4 s
    inputs.write_text("time,bend_angle,bend_angle_rate\n0,1.0,1\n1,2.0,1\n")
    out = tmp_path / "refused.csv"
    run = cardan_joint(
        "simulate", "--fmu", built_fmu, "--input", inputs, "--step", "0.1", "--output", out
    )
    assert run.returncode == 1
    assert "stopped at t = 0.3 s of 1 s" in run.stderr  # rounded, not 0.30000000000000004
    assert f"{out} (" in run.stderr and "Traceback" not in run.stderr
    rows = results.read_csv(out)
    assert rows["time"][-1] == pytest.approx(0.3) and len(rows) >= 4
    assert out.with_suffix(".png").stat().st_size > 0


def test_an_overwritten_output_is_named_as_replaced(built_fmu, tmp_path):
    out = tmp_path / "again.csv"
    args = ("simulate", "--fmu", built_fmu, "--stop-time", "0.01", "--output", out)
    assert "replaced" not in cardan_joint(*args).stdout
    assert re.search(rf"{re.escape(str(out))} \(\d+ rows, replaced\)", cardan_joint(*args).stdout)


def test_every_option_has_help():
    from cardan_joint import sweep

    for parser in (cli._parser(), _sweep_parser(sweep)):
        for action in _actions(parser):
            assert action.help, f"{action.option_strings} has no help"


def _sweep_parser(sweep):
    import argparse

    parser = argparse.ArgumentParser()
    sweep.add_arguments(parser)
    return parser


def _actions(parser):
    import argparse

    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                yield from _actions(sub)
        elif action.option_strings:
            yield action


def test_the_command_leaves_argv_and_stderr_alone(built_fmu, tmp_path, monkeypatch):
    """Run in-process, as a host would: no redirection or argv rewrite while it works."""
    import cardan_joint.build
    import cardan_joint.host.csv_run

    argv0, stderr = sys.argv[0], sys.stderr
    seen = []

    def fake_simulate(fmu, stop_time, output_interval, inputs, rows_to=None, **options):
        seen.append((sys.argv[0], sys.stderr))
        result = np.zeros(
            2, dtype=[("time", float)] + [(n, float) for n in table.INPUTS + table.OUTPUTS]
        )
        result["time"] = (0.0, stop_time)
        rows_to(result)  # the command streams the run to its CSV
        return result[:0]

    def fake_build(argv, prog=None):
        seen.append((sys.argv[0], sys.stderr))
        return 0

    monkeypatch.setattr(cardan_joint.host.csv_run, "simulate", fake_simulate)
    monkeypatch.setattr(cardan_joint.build, "main", fake_build)
    assert (
        cli.main(
            [
                "simulate",
                "--fmu",
                str(built_fmu),
                "--stop-time",
                "0.1",
                "--output",
                str(tmp_path / "s.csv"),
                "--no-progress",
            ]
        )
        == 0
    )
    assert cli.main(["build", "--dest", str(tmp_path)]) == 0
    assert seen == [(argv0, stderr)] * 2
