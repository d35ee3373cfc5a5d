"""C from Python: a model's step, written once in Python, translated into C
that performs the same IEEE operations in the same order (docs/codegen.md).

`generate(function, name)` gives the C source of `function` and every function
it calls; a construct outside the subset raises `Untranslatable`, naming the
construct and its file:line. `function` may be an entry whose function takes
the flat arguments grouped into tuples (`framework.grouped_entry`).
`FLOAT_FLAGS` are the compiler flags the generated C needs to give CPython's
bits.
"""

from .types import Untranslatable
from .unit import Generated, generate

# No fused multiply-add, no reassociation: each operation rounds as CPython's does.
# Nothing reads errno after a math call (CPython's math checks its results
# itself): -fno-math-errno lets the compiler treat the C library's math as pure,
# so it drops a call whose result no one reads (a chain's offsets at a life
# node that no torque reads) and makes one call of several with the same
# arguments; no operation rounds differently.
FLOAT_FLAGS = ("-ffp-contract=off", "-fno-fast-math", "-fno-math-errno")

__all__ = ["FLOAT_FLAGS", "Generated", "Untranslatable", "generate"]
