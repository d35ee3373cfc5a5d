"""Compile the C test host (host.c and friends) with the machine's compiler ($CC, else cc)."""

import subprocess
from pathlib import Path

from cardan_joint.native import compiler

HERE = Path(__file__).resolve().parent
NATIVE = HERE.parents[1] / "fmu_src" / "cardan_joint" / "native"


def compile_host(output: Path) -> Path:
    subprocess.run(
        [
            *compiler(),
            "-std=gnu11",
            "-O2",
            "-pthread",
            f"-I{NATIVE}",
            *map(str, sorted(HERE.glob("*.c"))),
            "-ldl",
            "-lm",
            "-o",
            str(output),
        ],
        check=True,
    )
    return output


if __name__ == "__main__":
    import sys

    if len(sys.argv) != 2:
        sys.exit("usage: python tests/c_host/compile.py OUTPUT  (then: OUTPUT run DIR 1000 0.001)")
    print(compile_host(Path(sys.argv[1])))
