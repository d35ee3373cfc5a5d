"""Compile a generated step (`cardan_joint.codegen`) as the runtime compiles its
C, and call it through ctypes with the Python step's arguments."""

import ctypes
import struct
import subprocess
from pathlib import Path

from cardan_joint.codegen import Generated
from cardan_joint.fmi.native import C_FLAGS, compiler


class CStep:
    """The generated `int name(const double *arguments, double *results)`."""

    def __init__(self, generated: Generated, folder: Path, strict: bool = True) -> None:
        source = folder / f"{generated.name}.c"
        library = folder / f"{generated.name}.so"
        source.write_text(generated.source)
        # Strict: the generated C compiles without a warning (a mutant of the
        # generator need not).
        warnings = ["-Werror"] if strict else ["-w"]
        command = [*compiler(), *C_FLAGS, *warnings, str(source), "-o", str(library), "-lm"]
        run = subprocess.run(command, capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        self.function = getattr(ctypes.CDLL(str(library)), generated.name)
        self.function.restype = ctypes.c_int
        self.arguments = (ctypes.c_double * len(generated.arguments))()
        self.results = (ctypes.c_double * generated.results)()

    def __call__(self, *arguments: float) -> tuple | None:
        for k, value in enumerate(arguments):
            self.arguments[k] = float(value)
        if not self.function(self.arguments, self.results):
            return None
        return tuple(self.results)


def mismatches(step, c_step, cases) -> tuple[int, int, int]:
    """(cases whose bits or decision differ, steps taken, steps refused): the
    Python step and its C on each case's arguments."""
    differ = taken = count = 0
    for arguments in cases:
        python = step(*arguments)
        differ += bits(python) != bits(c_step(*arguments))
        taken += python is not None
        count += 1
    return differ, taken, count - taken


def bits(values) -> bytes | None:
    """The exact bits of a result (ints as the doubles C hands back), None for None."""
    if values is None:
        return None
    if not isinstance(values, tuple):  # a function of one result
        values = (values,)
    return struct.pack(f"{len(values)}d", *(float(v) for v in values))
