"""The model's step in C for the FMU's runtime (docs/codegen.md): generated from
the function its spec names for the build's settings, checked against the
runtime's convention, or None with a message when the step runs in Python."""

import sys
from collections.abc import Mapping

from ..codegen import Generated, Untranslatable, generate
from ..fmi.native import GENERATED_STEP, NativeBuildError, install_loader
from ..models import Model


class ConventionError(ValueError):
    """A step whose parameters are not (time, h, state, inputs, parameters)."""


def _check_convention(generated: Generated, spec: Model, settings: Mapping) -> None:
    """The arguments the runtime passes are the step's parameters, by name:
    time, h, the model's step state, then a prefix of its inputs and parameters."""
    model = spec.make(settings)
    state = len(model.step_state()) if hasattr(model, "step_state") else 0
    table = spec.table(settings)
    known = tuple(table.INPUTS + table.PARAMETERS)
    names = generated.arguments
    given = names[2 + state :]
    if state == 0 or names[:2] != ("time", "h") or given != known[: len(given)]:
        raise ConventionError(
            f"{generated.name}'s parameters {names} are not (time, h, the {state} values "
            f"of step_state(), then {known} in order)"
        )
    if len(given) < len(table.INPUTS):
        raise ConventionError(f"{generated.name} does not take every input {table.INPUTS}")


def generated_step(spec: Model, settings: Mapping, model_name: str) -> Generated | None:
    """The C of the model's step, or None (said on stderr when it cannot be made)."""
    function = spec.step(settings) if spec.step else None
    if function is None:
        return None
    try:
        generated = generate(function, GENERATED_STEP)  # type: ignore[arg-type]
        _check_convention(generated, spec, settings)
        return generated
    except (Untranslatable, ConventionError) as error:
        print(f"build_fmu: {model_name}'s step runs in Python: {error}", file=sys.stderr)
        return None


def install_runtime(fmu, model_name: str, fmi_version: int, step: Generated | None) -> None:
    """The runtime into the FMU, with the generated step if it compiles; a step
    C does not compile (a generator's fault) leaves the step in Python, said on
    stderr; a runtime that does not compile raises NativeBuildError."""
    if step is not None:
        try:
            install_loader(fmu, model_name, fmi_version, step)
            return
        except NativeBuildError as error:
            print(f"build_fmu: {model_name}'s step runs in Python: its C did not compile: "
                  f"{error}", file=sys.stderr)  # fmt: skip
    install_loader(fmu, model_name, fmi_version)
