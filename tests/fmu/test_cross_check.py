"""`build_fmu.py --cross-check`: the fmi-cross-check folder, and the FMU reproducing it."""

import numpy as np
import pytest
from conftest import build_fmu, run_build
from fmpy import simulate_fmu
from fmpy.cross_check import validate_result
from fmpy.cross_check.validate_vendor_repo import validate_test_fmu
from fmpy.util import read_csv, read_ref_opt_file
from session_files import shared

from cardan_joint.build import cross_check

FILES = {
    "UniversalJoint.fmu",
    "UniversalJoint_in.csv",
    "UniversalJoint_ref.opt",
    "UniversalJoint_ref.csv",
    "README.md",
}


def _build(dest):
    build_fmu(dest, "--cross-check")
    return (
        dest
        / "cross-check"
        / "fmus"
        / "2.0"
        / "cs"
        / "linux64"
        / "cardan_joint"
        / cross_check.tool_version()
        / "UniversalJoint"
    )


@pytest.fixture(scope="module")
def folder(pytestconfig, tmp_path_factory):
    """The --cross-check build's folder, made once for all workers."""
    return shared(pytestconfig, tmp_path_factory, "cross_check", _build)


def test_the_folder_holds_the_cross_check_files_and_passes_fmpys_validator(folder):
    assert {p.name for p in folder.iterdir()} == FILES
    assert validate_test_fmu(str(folder)) == []
    reference = read_csv(folder / "UniversalJoint_ref.csv")
    assert len(reference.dtype.names) <= 10
    assert (folder / "UniversalJoint_ref.csv").stat().st_size <= 1e6


# FMPy's validator imports scipy.ndimage.filters, deprecated in SciPy 1.x: FMPy's to fix.
@pytest.mark.filterwarnings("ignore:Please import:DeprecationWarning")
def test_the_fmu_reproduces_the_reference_with_the_options_and_inputs(folder):
    options = read_ref_opt_file(str(folder / "UniversalJoint_ref.opt"))
    reference = read_csv(folder / "UniversalJoint_ref.csv")
    names = list(reference.dtype.names[1:])
    result = simulate_fmu(
        str(folder / "UniversalJoint.fmu"),
        start_time=options["StartTime"],
        stop_time=options["StopTime"],
        output_interval=options["StepSize"],
        input=read_csv(folder / "UniversalJoint_in.csv"),
        output=names,
    )
    assert validate_result(result, reference, options["StartTime"], options["StopTime"]) is None
    np.testing.assert_array_equal(result["time"], reference["time"])
    for name in names:
        scale = np.max(np.abs(reference[name]))
        error = np.max(np.abs(result[name] - reference[name]))
        assert error <= 1e-12 * scale, (name, error, scale)  # measured: <= 7e-15


def test_the_folder_holds_the_model_folders_committed_reference_and_page(folder):
    from cardan_joint.models import discover

    spec = discover()["UniversalJoint"]
    for committed in cross_check.reference_files("UniversalJoint"):
        assert (folder / committed.name).read_bytes() == committed.read_bytes()
    assert (folder / "README.md").read_bytes() == spec.page.read_bytes()


@pytest.mark.parametrize(
    "args",
    [
        ("--set", "bend_angle=0.1"),
        ("--name", "OtherJoint"),
        ("--fmi-version", "3"),
        ("--model", "Propshaft", "--joints", "2"),
        ("--model", "Motor"),
    ],
)
def test_cross_check_refuses_a_build_its_reference_run_does_not_fit(tmp_path, args):
    run = run_build(tmp_path, "--cross-check", *args)
    assert run.returncode == 2
    assert "--cross-check takes a model with a reference run" in run.stderr
    assert not any(tmp_path.iterdir())
