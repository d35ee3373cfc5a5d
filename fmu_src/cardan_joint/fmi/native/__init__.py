"""Put the native loader into a built FMU, so that C and C++ FMI hosts can run it.

pythonfmu's (and pythonfmu3's) binary needs a Python already in the process and
a C++ runtime. `install_loader` compiles the project's runtime instead, `loader.c`
(FMI 2.0) or `fmi3_loader.c` (FMI 3.0) and friends, with the machine's C
compiler ($CC, else `cc`; no Python headers needed) and puts it at
`binaries/<platform>/<id>.so`, in place of pythonfmu's binary: the runtime
constructs the slave and calls its Python methods itself. It records
in `resources/python_runtime.txt` what the FMU needs of a Python (a minimum
version, the build's minor as the preferred one), no machine paths, and in
`resources/variables.txt` each variable's reference, type, size and fixedness
(both loaders read it; hosts need not extract modelDescription.xml). Where the
host has no Python the loader finds one on the machine (python_discovery.c);
users point it elsewhere with the variables named in loader.h.
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

from ...codegen import FLOAT_FLAGS, Generated

# Shared by both FMI versions: logger routing, state machine entry, finding Python.
_COMMON = (
    "report.c",
    "calls.c",
    "fast_path.c",
    "fast_values.c",
    "fast_references.c",
    "generated.c",
    "state_book.c",
    "slave_object.c",
    "slave_values.c",
    "python_api.c",
    "python_runtime.c",
    "process_object.c",
    "python_start.c",
    "python_discovery.c",
    "python_present.c",
    "runtime_record.c",
    "record_check.c",
    "slave_module.c",
)
SOURCES = {
    2: (
        "loader.c",
        "fmi2_calls.c",
        "fmi2_unsupported.c",
        "fmu_states.c",
        *_COMMON,
    ),
    3: (
        "fmi3_loader.c",
        "fmi3_calls.c",
        "fmi3_states.c",
        "fmi3_unsupported.c",
        "fmi3_variables.c",
        *_COMMON,
    ),
}
# Where pythonfmu / pythonfmu3 put their Linux binary, which the runtime replaces.
BINARY_FOLDER = {2: "binaries/linux64", 3: "binaries/x86_64-linux"}
RECORD = "resources/python_runtime.txt"
# Each variable's value reference, type, size and fixedness, for both loaders
# (FMI 3.0: value count checks; both: the fixed-parameter guard). In resources/:
# hosts such as FMPy extract only resources/ and binaries/, not modelDescription.xml.
VARIABLES = "resources/variables.txt"
_HERE = Path(__file__).resolve().parent
# The STB_GNU_UNIQUE object through which every copy of the runtime in a process
# agrees on one interpreter start (process_object.c).
PROCESS_OBJECT = "cardan_joint_fmu_process_python_v1"


def fmi3_headers() -> Path:
    """The FMI 3.0 standard headers, as the installed pythonfmu3 (which builds the FMU)
    ships them. Found through its distribution: an FMU's resources folder, which
    pythonfmu3 puts on sys.path when it runs, holds a copy of its Python package."""
    from importlib.metadata import distribution

    return Path(str(distribution("pythonfmu3").locate_file("pythonfmu3/pythonfmu-export/src/fmi")))


MINIMUM_PYTHON = (3, 10)  # the oldest CPython the FMU's code and the loader support


# The manylinux2014 floor: the binary loads on glibc 2.17 and newer, wherever it is
# built. The header binds the functions glibc 2.34 moved into libc.so.6 to their old
# versions; an older glibc has them in libdl.so.2 and libpthread.so.0, needed here
# (no --as-needed: nothing of a new glibc's stubs is used, they must stay needed).
GLIBC_FLOOR = (2, 17)
GLIBC_FLOOR_COMPILE = ("-include", str(_HERE / "glibc_compat.h"))
GLIBC_FLOOR_LINK = ("-Wl,--no-as-needed", "-l:libdl.so.2", "-l:libpthread.so.0")


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


def runtime_record() -> str:
    lines = [
        "# What this FMU needs of a Python where its host has none: the loader finds",
        "# one on the machine, or set CARDAN_JOINT_FMU_PYTHON_LIBRARY (and ..._HOME,",
        "# ..._PATH); see docs/fmi-tools.md in the project.",
        "minimum = {}.{}".format(*MINIMUM_PYTHON),
        f"version = {sys.version_info.major}.{sys.version_info.minor}",
    ]
    return "\n".join(lines) + "\n"


# How the runtime is compiled, generated steps included (codegen.FLOAT_FLAGS: each
# floating-point operation rounds as CPython's does).
C_FLAGS = (
    "-std=gnu11",
    # -O3 over -O2: the generated life steps' node loops, unrolled and inlined,
    # cost a chain's step a quarter to a third less, a joint's at 1000 rad/s 3 %
    # (callgrind, benchmarks' step_alone; docs/codegen.md); no operation rounds
    # differently (FLOAT_FLAGS), so the bits are CPython's either way.
    "-O3",
    "-fPIC",
    # The version script keeps every symbol but the exports local, so nothing
    # can interpose on them: let the compiler inline across them (the value
    # calls' per-variable helpers cost a call each otherwise).
    "-fno-semantic-interposition",
    "-shared",
    "-pthread",
    "-Wall",
    *FLOAT_FLAGS,
    *GLIBC_FLOOR_COMPILE,
)


# The generated step's entry in the runtime (generated.c).
GENERATED_STEP = "generated_step"


def compile_loader(
    model_identifier: str, output: Path, fmi_version: int = 2, step: Generated | None = None
) -> Path:
    """The runtime, with the model's generated `step` (named generated_step) when
    there is one (docs/codegen.md)."""
    exports = output.parent / "exports.map"
    generated = []
    if step is not None:
        if step.name != GENERATED_STEP:
            raise NativeBuildError(f"the runtime calls the step {GENERATED_STEP}, not {step.name}")
        source = output.parent / "generated_step.c"
        source.write_text(step.source)
        # The C library's math (libm.so.6: the same soname since glibc 2.1).
        generated = ["-DGENERATED_STEP", str(source), "-l:libm.so.6"]
    # Only the fmi functions, and the process-wide start object every copy of the
    # runtime must find (python_runtime.c): nothing else may interpose in the host.
    exports.write_text(f"{{ global: fmi{fmi_version}*; {PROCESS_OBJECT}; local: *; }};\n")
    headers = [f"-I{fmi3_headers()}"] if fmi_version == 3 else []
    command = [
        *compiler(),
        *C_FLAGS,
        f"-DMODEL_IDENTIFIER=\"{model_identifier}\"",
        *headers,
        *(str(_HERE / source) for source in SOURCES[fmi_version]),
        *generated,
        "-Wl,-z,nodelete",
        f"-Wl,--version-script={exports}",
        *GLIBC_FLOOR_LINK,
        "-o",
        str(output),
    ]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        raise NativeBuildError(
            f"compiling the loader failed ({shlex.join(command)}):\n{run.stdout}{run.stderr}"
        )
    return output


def variables_record(model_description: bytes) -> str:
    """One line per variable (FMI 2.0 or 3.0): value reference, type, size, fixed (0/1), name."""
    import xml.etree.ElementTree as ElementTree

    lines = ["# valueReference type size fixed name (written by the build)"]
    variables = ElementTree.fromstring(model_description).find("ModelVariables")
    for variable in variables if variables is not None else []:
        size = 1
        for dimension in variable.iter("Dimension"):
            size *= int(dimension.get("start", 0))  # a structural size (0) is refused
        # FMI 2.0: <ScalarVariable> holds its type as the first child element.
        tag = variable[0].tag if variable.tag == "ScalarVariable" else variable.tag
        lines.append(
            " ".join(
                [
                    variable.get("valueReference", ""),
                    "Int64" if tag == "Enumeration" else tag,
                    str(size),
                    str(int(variable.get("variability") in ("fixed", "constant"))),
                    variable.get("name", ""),
                ]
            )
        )
    return "\n".join(lines) + "\n"


def install_loader(
    fmu_path, model_identifier: str, fmi_version: int = 2, step: Generated | None = None
) -> None:
    """Rewrite the .fmu in place: the runtime (with the model's generated `step`,
    if any) as the FMU's one binary, the records."""
    fmu_path = Path(fmu_path)
    folder = BINARY_FOLDER[fmi_version]
    binary = f"{folder}/{model_identifier}.so"
    with tempfile.TemporaryDirectory(prefix="cardan_joint_loader_") as workdir:
        loader = compile_loader(model_identifier, Path(workdir) / "loader.so", fmi_version, step)
        rewritten = Path(workdir) / fmu_path.name
        with (
            zipfile.ZipFile(fmu_path) as source,
            zipfile.ZipFile(rewritten, "w", zipfile.ZIP_DEFLATED) as target,
        ):
            if binary not in source.namelist():
                raise NativeBuildError(f"{fmu_path} has no {binary} to replace with the runtime")
            for item in source.infolist():
                if item.filename in (RECORD, VARIABLES, binary):
                    continue
                info = zipfile.ZipInfo(item.filename, item.date_time)
                info.external_attr, info.compress_type = item.external_attr, zipfile.ZIP_DEFLATED
                target.writestr(info, source.read(item))
            target.write(loader, binary)
            target.writestr(RECORD, runtime_record())
            target.writestr(VARIABLES, variables_record(source.read("modelDescription.xml")))
        shutil.move(str(rewritten), fmu_path)
