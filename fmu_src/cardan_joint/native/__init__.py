"""Put the native loader into a built FMU, so that C and C++ FMI hosts can run it.

pythonfmu's binary needs a Python already in the process. `install_loader`
compiles `loader.c` and friends with the machine's C compiler ($CC, else `cc`;
no Python headers needed), moves pythonfmu's binary to
`binaries/linux64/<id>_pythonfmu.so`, puts the loader at `binaries/linux64/<id>.so`
and records in `resources/python_runtime.txt` what the FMU needs of a Python (a
minimum version, the build's as the preferred one) and, as an optional hint, the
build's Python. Where the host has no Python the loader finds one on the machine
(python_discovery.c); users point it elsewhere with the variables named in loader.h.
"""

import os
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import zipfile
from pathlib import Path

SOURCES = (
    "loader.c",
    "fmi2_calls.c",
    "fmu_states.c",
    "python_runtime.c",
    "python_discovery.c",
    "runtime_record.c",
)
RECORD = "resources/python_runtime.txt"
_HERE = Path(__file__).resolve().parent
MINIMUM_PYTHON = (3, 10)  # the oldest CPython the FMU's code and the loader support
_EXPORTS = "{ global: fmi2*; local: *; };\n"  # nothing else may interpose in the host


class NativeBuildError(RuntimeError):
    pass


def compiler() -> list:
    command = shlex.split(os.environ.get("CC") or "cc")
    if not command or not shutil.which(command[0]):
        raise NativeBuildError(
            f"no C compiler: {command[0] if command else '$CC'!r} not found; install one "
            f"(e.g. `apt-get install gcc`) or set $CC to its path. The FMU needs it to build "
            f"the loader that lets C hosts run it"
        )
    return command


def shared_libpython() -> str:
    """The build's libpython, or "" for a Python linked statically."""
    directory, name = sysconfig.get_config_var("LIBDIR"), sysconfig.get_config_var("INSTSONAME")
    if not sysconfig.get_config_var("Py_ENABLE_SHARED") or not directory or not name:
        return ""
    path = Path(directory) / name
    return str(path) if path.exists() else ""


def search_path() -> list:
    """The build's module search path: its standard library and site-packages."""
    stdlib = Path(sysconfig.get_path("stdlib"))
    candidates = [
        stdlib.parent / f"python{sys.version_info.major}{sys.version_info.minor}.zip",
        stdlib,
        stdlib / "lib-dynload",
        Path(sysconfig.get_path("purelib")),
        Path(sysconfig.get_path("platlib")),
    ]
    paths = []
    for path in candidates:
        if path.exists() and str(path) not in paths:
            paths.append(str(path))
    return paths


def build_hint() -> list:
    """The build's Python, which the loader tries first where it still exists. Only
    a hint (the FMU runs without it): these are the record's only machine paths."""
    library = shared_libpython()
    if not library:
        return []
    lines = ["# The build's Python, tried first where it still exists:"]
    lines += [f"library = {library}", f"home = {sys.base_prefix}"]
    return lines + [f"path = {path}" for path in search_path()]


def runtime_record() -> str:
    lines = [
        "# What this FMU needs of a Python where its host has none; the loader finds",
        "# one on the machine, or set CARDAN_JOINT_FMU_PYTHON_LIBRARY (and ..._HOME,",
        "# ..._PATH); see the README, 'Using the FMU in an FMI tool'.",
        "minimum = {}.{}".format(*MINIMUM_PYTHON),
        f"version = {sys.version_info.major}.{sys.version_info.minor}",
    ]
    return "\n".join(lines + build_hint()) + "\n"


def compile_loader(model_identifier: str, output: Path) -> Path:
    exports = output.parent / "exports.map"
    exports.write_text(_EXPORTS)
    command = [
        *compiler(),
        "-std=gnu11",
        "-O2",
        "-fPIC",
        "-shared",
        "-pthread",
        "-Wall",
        f"-DMODEL_IDENTIFIER=\"{model_identifier}\"",
        *(str(_HERE / source) for source in SOURCES),
        "-Wl,-z,nodelete",
        f"-Wl,--version-script={exports}",
        "-ldl",
        "-o",
        str(output),
    ]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        raise NativeBuildError(
            f"compiling the loader failed ({shlex.join(command)}):\n{run.stdout}{run.stderr}"
        )
    return output


def install_loader(fmu_path, model_identifier: str) -> None:
    """Rewrite the .fmu in place: loader in front of pythonfmu's binary, runtime record."""
    fmu_path = Path(fmu_path)
    binary = f"binaries/linux64/{model_identifier}.so"
    with tempfile.TemporaryDirectory(prefix="cardan_joint_loader_") as workdir:
        loader = compile_loader(model_identifier, Path(workdir) / "loader.so")
        rewritten = Path(workdir) / fmu_path.name
        with (
            zipfile.ZipFile(fmu_path) as source,
            zipfile.ZipFile(rewritten, "w", zipfile.ZIP_DEFLATED) as target,
        ):
            if binary not in source.namelist():
                raise NativeBuildError(f"{fmu_path} has no {binary} to put the loader in front of")
            for item in source.infolist():
                if item.filename == RECORD:
                    continue
                name = (
                    f"binaries/linux64/{model_identifier}_pythonfmu.so"
                    if item.filename == binary
                    else item.filename
                )
                info = zipfile.ZipInfo(name, item.date_time)
                info.external_attr, info.compress_type = item.external_attr, zipfile.ZIP_DEFLATED
                target.writestr(info, source.read(item))
            target.write(loader, binary)
            target.writestr(RECORD, runtime_record())
        shutil.move(str(rewritten), fmu_path)
