"""A stepped model whose step is written once, as one function of floats in
its folder's `step.py`: the model's `run` calls it, and the build translates
the same function into the FMU's C runtime (docs/codegen.md, "How a model opts
in"), so Python and C take the same steps to the same bits.

The function takes (time, h, the model's `step_state()`, its inputs, its
parameters: the table's orders) and gives (the state after the step, the
inputs after it, the outputs), or None for a step it does not take; the
model's checks (`SteppedModel.run`) then name the refusal: variable, value,
limit, time.
"""

import math
from collections.abc import Callable, Mapping, Sequence

from .grouped_entry import Group, GroupedEntry
from .refusal import Refusal
from .stepped import SteppedModel, values_getter


def sound_step(h: float, parameters_valid: bool) -> bool:
    """Whether the step's size and the parameters (checked at `start`) let a step
    be taken: the first two of every model's checks. NaN fails the comparison."""
    return 0.0 < h < math.inf and parameters_valid


def grouped_step(
    name: str,
    function: Callable,
    state: Sequence[str],
    table,
    groups: Mapping[str, Group] | None = None,
    bound: Mapping[str, object] | None = None,
) -> GroupedEntry:
    """The step entry `name`: `function` takes the runtime's flat arguments (time,
    h, the step state's names `state`, then the table's inputs and parameters)
    grouped into tuples as `groups` says, or bound (`grouped_entry.GroupedEntry`)."""
    names = ("time", "h", *state, *table.INPUTS, *table.PARAMETERS)
    return GroupedEntry(name, function, names, groups, bound)


class WrittenStep(SteppedModel):
    """`run` by the model's one written step (`written_step`)."""

    def written_step(self) -> Callable[..., tuple | None]:
        """The model's step function for its settings (the one its spec names)."""
        raise NotImplementedError(f"{type(self).__name__} must name its step")

    def step_state(self) -> tuple:
        """The state the step advances beside the inputs, in its parameters' order
        (the FMU's runtime keeps these values in C between steps)."""
        raise NotImplementedError(f"{type(self).__name__} must give its step state")

    def set_step_state(self, state: Sequence[float]) -> None:
        """Take back a state the step advanced (`step_state`'s values, as floats)."""
        raise NotImplementedError(f"{type(self).__name__} must take its step state")

    def run(self, time: float, step_size: float, inputs) -> "tuple | Refusal":
        """The FMU's step (`SteppedModel.run`), taken by the written step; a step
        it does not take goes through the checks, which name the refusal."""
        self.set_inputs(inputs)
        state = self.step_state()
        parameters = values_getter(self.table.PARAMETERS)(self)
        taken = self.written_step()(time, step_size, *state, *inputs, *parameters)
        if taken is None:
            return super().run(time, step_size, inputs)
        moved_end = len(state) + len(inputs)
        self.set_step_state(taken[: len(state)])
        moved = taken[len(state) : moved_end]
        self.set_inputs(moved)
        self.time = time + step_size
        return taken[moved_end:], moved
