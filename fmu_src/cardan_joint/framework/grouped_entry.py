"""A step entry whose function takes its flat arguments grouped into tuples
(docs/codegen.md, "Arguments in groups"): the runtime passes the arguments
flat, by the variable table's names, and the function takes the ones a
formula uses together as one tuple (a joint layout, the Miner's sums). So one
definition serves every number of joints and no entry lists its arguments
one by one. The generator (`codegen.generate`) reads the same plan: the
function, its bound values, each group's size and the flat arguments."""

import inspect
from collections.abc import Callable, Mapping, Sequence
from fnmatch import fnmatchcase

# What a group gives its parameter: the names (or `fnmatch` patterns) of the
# flat arguments it gathers into a tuple, or one name it passes alone.
Group = str | tuple[str, ...]


def _taken(parameter: str, group: Group | None, names: Sequence[str], start: int) -> int:
    """How many of `names` from `start` the parameter takes (no group: its own
    name; a str: that name; patterns: the longest run each matching one)."""
    if group is None or isinstance(group, str):
        wanted = parameter if group is None else group
        return 1 if start < len(names) and names[start] == wanted else 0
    end = start
    while end < len(names) and any(fnmatchcase(names[end], p) for p in group):
        end += 1
    return end - start


class GroupedEntry:
    """The step entry `name`: `function` called with the first of the flat
    arguments `names` (time, h, the step state's names, the table's inputs
    and parameters) that its parameters take, in order. A parameter that
    `groups` does not name takes the argument of its own name; one it names
    takes that group (`Group`); one in `bound` takes that module or function,
    which C binds at translation time, as it binds `math`."""

    def __init__(
        self,
        name: str,
        function: Callable,
        names: Sequence[str],
        groups: Mapping[str, Group] | None = None,
        bound: Mapping[str, object] | None = None,
    ) -> None:
        self.__name__ = name
        self.function = function
        self.bound = dict(bound or {})
        groups = dict(groups or {})
        # Per parameter of `function`: None where it takes one flat argument,
        # the size of the tuple it takes, or its bound value's name.
        plan: list[int | str | None] = []
        start = 0
        for parameter in inspect.signature(function).parameters:
            if parameter in self.bound:
                plan.append(parameter)
                continue
            group = groups.pop(parameter, None)
            count = _taken(parameter, group, names, start)
            if count == 0:
                found = names[start] if start < len(names) else "none left"
                raise TypeError(f"{name}: {function.__name__}'s parameter {parameter} takes "
                                f"{group or parameter!r}, not the argument {found!r}")  # fmt: skip
            plan.append(None if group is None or isinstance(group, str) else count)
            start += count
        if groups:
            raise TypeError(f"{name}: {function.__name__} has no parameter {sorted(groups)}")
        self.plan = tuple(plan)
        self.arguments = tuple(names[:start])
        # `inspect.signature` of the entry: its flat arguments.
        self.__signature__ = inspect.Signature(
            [inspect.Parameter(n, inspect.Parameter.POSITIONAL_ONLY) for n in self.arguments]
        )

    @property
    def sizes(self) -> tuple[int | None, ...]:
        """Per parameter the flat arguments fill: None for one value, else its tuple's size."""
        return tuple(p for p in self.plan if not isinstance(p, str))

    def __call__(self, *values):
        """The step of the flat arguments (the runtime's order), as C takes it."""
        if len(values) != len(self.arguments):
            raise TypeError(
                f"{self.__name__} takes {len(self.arguments)} arguments ({len(values)} given)"
            )
        grouped = []
        start = 0
        for part in self.plan:
            if isinstance(part, str):
                grouped.append(self.bound[part])
            elif part is None:
                grouped.append(values[start])
                start += 1
            else:
                grouped.append(tuple(values[start : start + part]))
                start += part
        return self.function(*grouped)
