"""A user's mistake with a file (a corrupt FMU, a file where a folder must be)
is a message naming the file and what is wrong, never a traceback."""

import zipfile

import pytest
from conftest import cardan_joint, run_build

from cardan_joint import results
from cardan_joint.host.fmu_info import BadFMUError, FmuInfo
from cardan_joint.host.instance import FmuInstance


def _zip(path, members):
    with zipfile.ZipFile(path, "w") as archive:
        for name, text in members.items():
            archive.writestr(name, text)
    return path


@pytest.mark.parametrize(
    "make, problem",
    [
        (lambda p: p.write_text("not a zip"), "not a zip archive"),
        (lambda p: _zip(p, {"readme.txt": "x"}), "a zip archive without modelDescription.xml"),
        (lambda p: _zip(p, {"modelDescription.xml": "<fmiModelDescr"}), "XMLSyntaxError"),
    ],
)
def test_a_corrupt_fmu_is_named_with_what_is_wrong(tmp_path, make, problem):
    fmu = tmp_path / "Broken.fmu"
    make(fmu)
    for read in (FmuInfo.read, FmuInstance.open):
        with pytest.raises(BadFMUError) as error:
            read(fmu)
        assert str(error.value).startswith(f"{fmu} is not a readable FMU: ")
        assert problem in str(error.value)
    run = cardan_joint("simulate", "--fmu", fmu, "--output", tmp_path / "x.csv")
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert f"{fmu} is not a readable FMU" in run.stderr and problem in run.stderr


def test_build_onto_an_existing_file_is_refused_naming_it(tmp_path):
    existing = tmp_path / "UniversalJoint.fmu"
    existing.write_text("keep me")
    for dest in (existing, existing / "sub"):
        run = run_build(dest)
        assert run.returncode == 2 and "Traceback" not in run.stderr
        assert f"{existing} is a file, not a folder" in run.stderr
    assert existing.read_text() == "keep me"


def test_a_result_under_a_file_is_refused_naming_it(tmp_path):
    blocking = tmp_path / "plain"
    blocking.write_text("x")
    with pytest.raises(results.ResultFileError, match="plain is a file, not a folder"):
        results.write_csv({"time": [0.0]}, blocking / "run.csv")
    with pytest.raises(results.ResultFileError, match="it is a folder"):
        results.write_csv({"time": [0.0]}, tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain"]
