"""Reading and writing results: the one place that knows file formats.

Time series (FMPy's structured result arrays, and any table of numbers) go to
CSV in FMPy's column format, through `fmpy.util.write_csv`/`read_csv`: a quoted
header, one column per variable, values printed as the shortest text that reads
back to the same double. Tables with text columns (the design sweep's status
and message) go through pandas, also round-trip exact, and to Parquet when a
Parquet engine (pyarrow) is installed.
"""

from os import PathLike
from pathlib import Path
from typing import Iterable, Mapping, Sequence, Union

import numpy as np

PathType = Union[str, PathLike]


class ResultFileError(ValueError):
    """A results file that cannot be read: the message names the file and the problem."""


def _parent_made(path: PathType) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    return path


def structured(columns: Mapping[str, Iterable[float]]) -> np.ndarray:
    """A structured float array from {name: column}, in the mapping's order."""
    arrays = {name: np.asarray(values, dtype=float) for name, values in columns.items()}
    lengths = {len(a) for a in arrays.values()}
    if len(lengths) > 1:
        raise ValueError(f"columns of different lengths: {sorted(lengths)}")
    data = np.zeros(lengths.pop() if lengths else 0, dtype=[(name, float) for name in arrays])
    for name, values in arrays.items():
        data[name] = values
    return data


def write_csv(data: Union[np.ndarray, Mapping[str, Iterable[float]]], path: PathType,
              columns: Sequence[str] = None) -> Path:
    """Write a result (structured array, or {name: column} of numbers) in FMPy's CSV format.

    `columns`: the variables to write besides `time` (FMPy's convention; None: all)."""
    if not isinstance(data, np.ndarray):
        data = structured(data)
    from fmpy.util import write_csv as fmpy_write_csv

    path = _parent_made(path)
    fmpy_write_csv(str(path), data, columns=list(columns) if columns is not None else None)
    return path


def read_csv(path: PathType) -> np.ndarray:
    """A CSV of numbers with a header line (FMPy's format, quoted names or not) ->
    a structured float array; raises ResultFileError naming the file and the problem."""
    from fmpy.util import read_csv as fmpy_read_csv

    path = Path(path)
    if not path.is_file():
        raise ResultFileError(f"{path} does not exist")
    try:
        return fmpy_read_csv(str(path))
    except IndexError:
        raise ResultFileError(f"{path}: no header line and data rows") from None
    except (ValueError, TypeError) as error:
        # FMPy names the bad literal ("could not convert string to float: 'abc'")
        # or reports a row whose length differs from the header's.
        raise ResultFileError(f"{path}: not a table of numbers under one header line "
                              f"({error})") from None


def write_rows(rows: Sequence[Mapping[str, object]], path: PathType) -> Path:
    """Write a list of row dicts (numbers and text; missing keys left empty) as CSV."""
    import pandas as pd

    path = _parent_made(path)
    pd.DataFrame(list(rows)).to_csv(path, index=False)
    return path


def write_table(table, stem: PathType, parquet: bool = True) -> list:
    """Write a pandas table to <stem>.csv, and <stem>.parquet when `parquet` and
    a Parquet engine is installed; returns the paths written."""
    stem = _parent_made(stem)
    written = [stem.with_suffix(".csv")]
    table.to_csv(written[0], index=False)
    if parquet:
        try:
            table.to_parquet(stem.with_suffix(".parquet"), index=False)
            written.append(stem.with_suffix(".parquet"))
        except ImportError:
            pass                         # no pyarrow/fastparquet: CSV only, as documented
    return written


def read_table(path: PathType):
    """A table written by `write_table` or `write_rows` (CSV or Parquet) as a DataFrame."""
    import pandas as pd

    path = Path(path)
    return pd.read_parquet(path) if path.suffix == ".parquet" else pd.read_csv(path)
