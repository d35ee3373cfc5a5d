"""The stepped-model runtime every model's physics runs in: no equation here.

`stepped.py` is a step top to bottom (inputs, checks, the model's advance,
the clock, outputs); `written_step.py` the same step taken by a model's one
written step function, which the build also generates into C, and
`rotor_model.py` the rotor models' base on it; `api.py` the model API the FMU
slaves rely on (`Stepped`) and what it reads of a variable table; `refusal.py`
why a step, an input or a parameter is refused, as data; `values.py` ranges,
start values and the saved state. The equations (closed forms, exact angle
arithmetic, the rotor's exact step) are in `physics/`, each model's own in its
folder.
"""

from .refusal import Reason, Refusal, register_reasons

__all__ = ["Reason", "Refusal", "register_reasons"]
