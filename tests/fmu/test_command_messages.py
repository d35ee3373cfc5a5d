"""What the commands say about a path, a figure format, a build that replaces
another, and the same mistake in `build` and `simulate` (the same exit status)."""

import uuid
from pathlib import Path

import pytest
from conftest import cardan_joint, cardan_joint_here


def test_an_output_in_a_missing_folder_outside_the_working_folder_is_refused(
    capsys, fmu_path, tmp_path
):
    missing = Path(f"/cardan_joint_missing_{uuid.uuid4().hex[:8]}")
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--stop-time", "0.01", "--output", missing / "x.csv"
    )
    assert run.returncode == 2, run.stderr
    assert f"the folder {missing} does not exist" in run.stderr
    assert not missing.exists()  # no folder made at the filesystem root


def test_a_missing_folder_inside_the_working_folder_is_made(fmu_path, tmp_path):
    run = cardan_joint(
        "simulate", "--fmu", fmu_path, "--stop-time", "0.01", "--output", "a/b/x.csv", cwd=tmp_path
    )
    assert run.returncode == 0, run.stderr
    assert (tmp_path / "a" / "b" / "x.csv").is_file()


def test_an_unwritable_folder_is_named_as_such(capsys, fmu_path):
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--stop-time", "0.01", "--output", "/proc/x.csv"
    )
    assert run.returncode == 2, run.stderr
    assert "cannot write /proc/x.csv: no file can be created in /proc" in run.stderr
    assert "available" not in run.stderr


def test_a_plot_format_matplotlib_cannot_write_is_refused_before_the_run(
    capsys, fmu_path, tmp_path
):
    out = tmp_path / "run.csv"
    out.write_text("earlier run\n")
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--output", out, "--plot", tmp_path / "y.xyz"
    )
    assert run.returncode == 2 and "--plot" in run.stderr and "not .xyz" in run.stderr
    assert out.read_text() == "earlier run\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.csv"]


@pytest.mark.parametrize(
    "setting, said",
    [
        ("bend_angel=0.1", "'bend_angel'; did you mean bend_angle"),
        ("bend_angle=abc", "'abc' is not a number"),
        ("bend_angle=2", "bend_angle = 2.0 rad (114.592 deg) is not below the limit"),
    ],
)
def test_build_and_simulate_exit_alike_for_the_same_mistake(
    capsys, fmu_path, tmp_path, setting, said
):
    built = cardan_joint_here(capsys, "build", "--dest", tmp_path / "dist", "--set", setting)
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--output", tmp_path / "x.csv", "--set", setting
    )
    assert built.returncode == run.returncode == 2, (built.stderr, run.stderr)
    assert said in built.stderr and said in run.stderr
    assert "cardan-joint build: " in built.stderr


def test_an_array_build_says_it_replaces_the_scalar_one_and_takes_the_folder_name(tmp_path):
    dest = tmp_path / "dist"
    scalar = cardan_joint("build", "--dest", dest, "--model", "universal_joint", "--fmi-version=3")
    assert scalar.returncode == 0, scalar.stderr
    assert "replaced" not in scalar.stdout
    arrays = cardan_joint(
        "build", "--dest", dest, "--model", "UniversalJoint", "--fmi-version=3", "--fmi3-arrays"
    )
    assert arrays.returncode == 0, arrays.stderr
    said = "replaced the earlier UniversalJoint.fmu of FMI 3 scalars with FMI 3 arrays"
    assert said in arrays.stdout
