"""Compile the C test hosts with the machine's compiler ($CC, else cc): the FMI 2.0
host (host.c and friends) and the FMI 3.0 host (host3.c, on the standard's headers)."""

import subprocess
from pathlib import Path

from cardan_joint.fmi.native import compiler, fmi3_headers

HERE = Path(__file__).resolve().parent
NATIVE = HERE.parents[1] / "fmu_src" / "cardan_joint" / "fmi" / "native"
FMI3_HOST = sorted(HERE.glob("*3.c"))  # host3.c, fuzz3.c, threads3.c


def host_files(fmi3: bool = False) -> tuple:
    """(the header folder, the C sources) of the FMI 2.0 or the FMI 3.0 host."""
    if fmi3:
        return fmi3_headers(), FMI3_HOST
    return NATIVE, [c for c in sorted(HERE.glob("*.c")) if c not in FMI3_HOST]


def compile_command(output, include, sources, cc=None) -> list:
    """The command line compiling a host; `cc` (default: the machine's compiler) and
    the paths may be another machine's (tests/system compile in a Debian root)."""
    return [
        *(cc or compiler()),
        "-std=gnu11",
        "-O2",
        "-pthread",
        f"-I{include}",
        *map(str, sources),
        "-ldl",
        "-lm",
        "-o",
        str(output),
    ]


def compile_host(output: Path) -> Path:
    subprocess.run(compile_command(output, *host_files()), check=True)
    return output


def compile_host3(output: Path) -> Path:
    subprocess.run(compile_command(output, *host_files(fmi3=True)), check=True)
    return output


def compile_concurrent(output: Path) -> Path:
    """concurrent/concurrent.c: several FMUs (FMI 2.0 and 3.0) started from threads at once."""
    sources = [HERE / "concurrent" / "concurrent.c"]
    subprocess.run(compile_command(output, NATIVE, sources), check=True)
    return output


if __name__ == "__main__":
    import sys

    arguments = sys.argv[1:]
    fmi3 = arguments[:1] == ["--fmi3"]
    if len(arguments) != 1 + fmi3:
        sys.exit(
            "usage: python tests/c_host/compile.py [--fmi3] OUTPUT"
            "  (then: OUTPUT run DIR 1000 0.001)"
        )
    print((compile_host3 if fmi3 else compile_host)(Path(arguments[-1])))
