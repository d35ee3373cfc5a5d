"""The build is a library call too: it leaves the caller's process as it found it."""

import hashlib
import re
import sys
import zipfile

import pytest
from conftest import build_fmu

from cardan_joint import sweep
from cardan_joint.build import build
from cardan_joint.build.archive import normalise


def test_a_build_leaves_no_module_of_its_staged_copy_behind(tmp_path):
    before = set(sys.modules)
    build(tmp_path, validate=False)
    # pythonfmu imports the staged script and its hashed package to read the
    # model; a second build in this process must not pick them up.
    staged = [
        name
        for name in set(sys.modules) - before
        if name.split(".")[0].startswith(("cardan_joint_", "universaljoint_"))
    ]
    assert staged == []
    assert (tmp_path / "UniversalJoint.fmu").stat().st_size > 0


# --- issue 18, items 6 and 7: reproducible archives, Linux binaries only ---


@pytest.mark.parametrize(
    ("fixture", "option"),
    [
        ("fmu_path", ()),
        ("fmu_without_life_path", ("--no-life",)),  # with its generated step
        ("fmi3_path", ("--fmi-version=3", "--fmi3-arrays")),
        ("fmi3_scalar_path", ("--fmi-version=3",)),
    ],
)
def test_two_builds_of_the_same_source_are_byte_identical_and_a_sweep_resumes(
    request, tmp_path, fixture, option
):
    first = request.getfixturevalue(fixture)  # built in another temporary folder
    second = build_fmu(tmp_path / "again", *option)
    assert second.parent != first.parent
    assert (
        hashlib.sha256(second.read_bytes()).digest() == hashlib.sha256(first.read_bytes()).digest()
    )
    # The sweep's store keys its cases on the FMU's digest: the rebuild resumes.
    spec = sweep.SweepSpec()
    sweep.CaseStore(tmp_path / "store", spec, first)
    sweep.CaseStore(tmp_path / "store", spec, second)


@pytest.mark.parametrize(
    ("fixture", "platform"), [("fmu_path", "linux64"), ("fmi3_path", "x86_64-linux")]
)
def test_the_fmu_ships_linux_binaries_only_and_nothing_of_the_build_machine(
    request, fixture, platform
):
    with zipfile.ZipFile(request.getfixturevalue(fixture)) as fmu:
        entries = fmu.infolist()
    names = [e.filename for e in entries]
    assert {n.split("/")[1] for n in names if n.startswith("binaries/")} == {platform}
    assert names == sorted(names)
    assert not [n for n in names if "__pycache__" in n or n.endswith(".pyc")]
    assert {e.date_time for e in entries} == {(1980, 1, 1, 0, 0, 0)}
    assert {e.external_attr >> 16 for e in entries} == {0o100644, 0o100755}
    with zipfile.ZipFile(request.getfixturevalue(fixture)) as fmu:
        description = fmu.read("modelDescription.xml").decode()
    assert "generationDateAndTime" not in description


def test_normalising_drops_bytecode_foreign_binaries_sources_and_the_clock(tmp_path):
    """On an archive holding what a build may leave (the tree may hold no bytecode
    when the test runs, so the FMU above cannot show that it is dropped)."""
    description = (
        '<fmiModelDescription fmiVersion="2.0" modelName="M" guid="{%s}" '
        'generationDateAndTime="%s" generationTool="t"/>'
    )
    made = []
    for stamp in ("2026-01-01T00:00:00Z", "2027-02-02T00:00:00Z"):
        fmu = tmp_path / f"{len(made)}.fmu"
        with zipfile.ZipFile(fmu, "w") as archive:
            archive.writestr("resources/m/__pycache__/a.cpython-311.pyc", b"bytecode")
            archive.writestr("resources/m/a.py", b"x = 1\n")
            archive.writestr("resources/m/", b"")
            archive.writestr("binaries/win64/M.dll", b"MZ")
            archive.writestr("binaries/darwin64/M.dylib", b"mach-o")
            archive.writestr("binaries/linux64/M.so", b"ELF")
            archive.writestr("sources/src/cppfmu/cppfmu_cs.cpp", b"// pythonfmu3's")
            archive.writestr("modelDescription.xml", description % (stamp, stamp))
        normalise(fmu, 2)
        made.append(fmu.read_bytes())
    assert made[0] == made[1]
    with zipfile.ZipFile(fmu) as archive:
        assert archive.namelist() == [
            "binaries/linux64/M.so",
            "modelDescription.xml",
            "resources/m/a.py",
        ]
        text = archive.read("modelDescription.xml").decode()
    assert "generationDateAndTime" not in text and "2027" not in text
    assert re.search(
        r'guid="[0-9a-f]{8}-[0-9a-f]{4}-5[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}"', text
    )
