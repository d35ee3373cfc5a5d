"""Issue 24, item 3: the FMUs' binaries load where FMI tools run, the manylinux2014
floor: no symbol version above GLIBC_2.17 and no C++ runtime (GLIBCXX, CXXABI),
whatever glibc built them. Read from each binary's version needs (what the dynamic
linker checks at load time, `objdump -p`), not from running it."""

import os
import re
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest

from cardan_joint.codegen import generate
from cardan_joint.fmi.native import GENERATED_STEP, GLIBC_FLOOR, compile_loader
from cardan_joint.models.universal_joint.step import joint_step

C_RUNTIME = ("GLIBCXX_", "CXXABI_", "libstdc++", "libgcc_s")


def needs(binary: Path) -> dict:
    """{library: [version names]} from the binary's version references, plus its
    needed libraries (under "NEEDED")."""
    if not shutil.which("objdump"):
        pytest.skip("needs objdump (binutils) to read the binaries' symbol versions")
    dump = subprocess.run(["objdump", "-p", str(binary)], capture_output=True, text=True)
    assert dump.returncode == 0, dump.stderr
    found, library = {"NEEDED": []}, None
    for line in dump.stdout.splitlines():
        words = line.split()
        if words[:1] == ["NEEDED"]:
            found["NEEDED"].append(words[1])
        elif line.startswith("  required from "):
            library = line.split("required from ", 1)[1].rstrip(":")
            found[library] = []
        elif library and line.startswith("    0x") and len(words) == 4:
            found[library].append(words[3])
        elif not line.startswith("    "):
            library = None
    return found


def glibc_version(name: str) -> tuple:
    match = re.fullmatch(r"GLIBC_(\d+(?:\.\d+)*)", name)
    return tuple(int(part) for part in match.group(1).split(".")) if match else ()


def above_the_floor(binary: Path) -> list:
    """What keeps the binary from loading on glibc 2.17 without a C++ runtime."""
    problems = []
    for library, names in needs(binary).items():
        for name in names:
            if any(word in name for word in C_RUNTIME):
                problems.append(f"{library}: {name}")
            elif glibc_version(name) > GLIBC_FLOOR:
                problems.append(f"{library}: {name}")
    return problems


def test_the_reading_sees_what_a_new_glibc_binds_by_default(tmp_path):
    """Without the build's flags, dlopen binds GLIBC_2.34 on this glibc (>= 2.34):
    the check must see it, or it proves nothing."""
    source = tmp_path / "plain.c"
    source.write_text('#include <dlfcn.h>\nvoid *f(void) { return dlopen("x", RTLD_NOW); }\n')
    binary = tmp_path / "plain.so"
    subprocess.run(["cc", "-shared", "-fPIC", source, "-o", binary], check=True)
    machine = os.confstr("CS_GNU_LIBC_VERSION") or ""  # "glibc 2.36"
    if glibc_version(machine.replace("glibc ", "GLIBC_")) < (2, 34):
        pytest.skip("this glibc is older than 2.34: dlopen's default version is old")
    assert above_the_floor(binary) == ["libc.so.6: GLIBC_2.34"]


@pytest.mark.parametrize("generated", [False, True], ids=["python-step", "generated-step"])
@pytest.mark.parametrize("fmi_version", [2, 3])
def test_the_runtime_needs_nothing_above_glibc_2_17(tmp_path, fmi_version, generated):
    """The runtime as the build compiles it (the FMU's own C layer), with a
    generated step (its math from libm) and without."""
    step = generate(joint_step, GENERATED_STEP) if generated else None
    binary = compile_loader("UniversalJoint", tmp_path / "runtime.so", fmi_version, step)
    assert above_the_floor(binary) == []
    # An older glibc has dlopen and pthread_key_create in these, not in libc.so.6.
    assert {"libdl.so.2", "libpthread.so.0"} <= set(needs(binary)["NEEDED"])


@pytest.mark.parametrize("fmu", ["fmu_path", "fmi3_path"])
def test_every_binary_of_both_fmus_needs_nothing_above_glibc_2_17(request, tmp_path, fmu):
    archive = zipfile.ZipFile(request.getfixturevalue(fmu))
    binaries = [name for name in archive.namelist() if name.endswith(".so")]
    assert binaries
    problems = {}
    for name in binaries:
        found = above_the_floor(Path(archive.extract(name, tmp_path)))
        if found:
            problems[name] = found
    assert problems == {}
