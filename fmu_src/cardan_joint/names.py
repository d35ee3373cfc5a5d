"""Names a user types (`--set NAME=VALUE`, input columns, start values, plot
variables), checked against the names that exist, with the nearest valid ones
suggested: the one place a misspelt name becomes an error.

Standard library only: the build imports it as well as the host tools.
"""

import difflib
from collections.abc import Collection, Iterable


class UsageError(ValueError):
    """Bad user input (a name, a NAME=VALUE pair, a file): the message names what is wrong."""


class UnknownNameError(UsageError, KeyError):
    """A name that is not one of the valid ones; the message suggests the nearest."""

    def __str__(self) -> str:  # KeyError would quote the message
        return str(self.args[0])


def unknown(name: str, valid: Collection[str], kind: str = "variable") -> str:
    """'unknown input 'bend_angel'; did you mean bend_angle? (inputs: ...)'."""
    near = difflib.get_close_matches(name, list(valid), n=3, cutoff=0.6)
    hint = f"; did you mean {' or '.join(near)}?" if near else ""
    return f"unknown {kind} {name!r}{hint} (valid: {', '.join(sorted(valid)) or 'none'})"


def check_known(names: Iterable[str], valid: Collection[str], kind: str = "variable") -> None:
    """Raise UnknownNameError naming the first name not in `valid`."""
    for name in names:
        if name not in valid:
            raise UnknownNameError(unknown(name, valid, kind))


def parse_assignments(pairs: Iterable[str], option: str = "--set") -> dict[str, float]:
    """['NAME=VALUE', ...] -> {NAME: float(VALUE)}; a malformed pair is a UsageError."""
    values: dict[str, float] = {}
    for pair in pairs:
        name, sep, text = pair.partition("=")
        name = name.strip()
        if not sep or not name:
            raise UsageError(f"{option} takes NAME=VALUE, got {pair!r}")
        try:
            values[name] = float(text)
        except ValueError:
            raise UsageError(f"{option} {pair}: {text.strip()!r} is not a number") from None
    return values
