"""The inputs of a command-line run: `--set NAME=VALUE` pairs and input CSVs
turned into FMPy's input signal, every mistake a `UsageError` naming it."""

from . import results
from . import variables as table


class UsageError(Exception):
    """Bad command-line input: the message names what is wrong."""


def parse_assignments(pairs):
    """--set NAME=VALUE ... -> (constant inputs, parameter start values)."""
    inputs, parameters = {}, {}
    for pair in pairs:
        name, sep, text = pair.partition("=")
        name = name.strip()
        if not sep:
            raise UsageError(f"--set takes NAME=VALUE, got {pair!r}")
        kind = _settable_kind(name, f"--set {pair}")
        try:
            value = float(text)
        except ValueError:
            raise UsageError(f"--set {pair}: {text.strip()!r} is not a number") from None
        (inputs if kind == "input" else parameters)[name] = value
    return inputs, parameters


def _settable_kind(name, where):
    variable = table.BY_NAME.get(name)
    if variable is None:
        raise UsageError(
            f"{where}: unknown variable {name!r}; inputs are "
            f"{', '.join(table.INPUTS)}; parameters are {', '.join(table.PARAMETERS)}"
        )
    if variable.causality not in ("input", "parameter"):
        raise UsageError(
            f"{where}: {name!r} is an {variable.causality}; only inputs and parameters can be set"
        )
    return variable.causality


def read_input_csv(path):
    """A CSV with a `time` column and input-name columns -> FMPy's structured array."""
    import numpy as np

    try:
        signal = results.read_csv(path)
    except results.ResultFileError as error:
        raise UsageError(f"input file {error}") from None
    header = list(signal.dtype.names)
    if "time" not in header:
        raise UsageError(f"{path}: no 'time' column (columns: {', '.join(header)})")
    for name in header:
        if name != "time" and _settable_kind(name, f"{path}, column {name!r}") != "input":
            raise UsageError(
                f"{path}, column {name!r}: a parameter is fixed for the run; "
                f"set it with --set {name}=VALUE"
            )
    for name in header:
        if not np.all(np.isfinite(signal[name])):
            raise UsageError(f"{path}, column {name!r}: every value must be a finite number")
    times = signal["time"]
    if not np.all(np.isfinite(times)) or np.any(np.diff(times) < 0):
        raise UsageError(f"{path}: the time column must be finite and non-decreasing")
    return signal


def input_signal(constants, csv_signal, defaults, stop_time):
    """Every input of the FMU as one signal: CSV columns as given, the others
    constant (from --set, else the FMU's start values), so no input is left unset."""
    import numpy as np

    given = set(csv_signal.dtype.names) - {"time"} if csv_signal is not None else set()
    clash = sorted(given & set(constants))
    if clash:
        raise UsageError(f"{', '.join(clash)} given both by --set and in the input CSV")
    times = csv_signal["time"] if csv_signal is not None else np.array([0.0, max(stop_time, 0.0)])
    signal = np.zeros(len(times), dtype=[("time", float)] + [(n, float) for n in table.INPUTS])
    signal["time"] = times
    for name in table.INPUTS:
        signal[name] = (
            csv_signal[name] if name in given else constants.get(name, defaults.get(name, 0.0))
        )
    return signal


def start_values(fmu):
    """The FMU's start values by name, and its default experiment."""
    from fmpy import read_model_description

    description = read_model_description(str(fmu))
    return (
        {v.name: float(v.start) for v in description.modelVariables if v.start is not None},
        description.defaultExperiment,
    )
