"""Reading and writing results: the one place that knows file formats.

Time series (FMPy's structured result arrays, and any table of numbers) go to
CSV in FMPy's column format through `fmpy.util.write_csv`: a quoted header, one
column per variable, values printed as the shortest text that reads back to the
same double. They are read back through pandas (FMPy's reader takes a space
after a comma for a vector column, which hand-written input files often have).
Tables with text columns (the design sweep's status
and message) go through pandas, also round-trip exact, and to Parquet when a
Parquet engine (pyarrow) is installed.
"""

from collections.abc import Iterable, Mapping, Sequence
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # pandas is imported where a table is written or read
    import pandas as pd

PathType = str | PathLike


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


def write_csv(
    data: np.ndarray | Mapping[str, Iterable[float]],
    path: PathType,
    columns: Sequence[str] | None = None,
) -> Path:
    """Write a result (structured array, or {name: column} of numbers) in FMPy's CSV format.

    `columns`: the variables to write besides `time` (FMPy's convention; None: all)."""
    if not isinstance(data, np.ndarray):
        data = structured(data)
    from fmpy.util import write_csv as fmpy_write_csv

    path = _parent_made(path)
    fmpy_write_csv(str(path), data, columns=list(columns) if columns is not None else None)
    return path


def read_csv(path: PathType) -> np.ndarray:
    """A CSV of numbers under a header line (FMPy's format, quoted names or not,
    spaces after commas allowed) -> a structured float array, every value read
    back to the same double; raises ResultFileError naming the file, and the
    line and column of a value that is not a number."""
    import pandas as pd

    path = Path(path)
    if not path.is_file():
        raise ResultFileError(f"{path} does not exist")
    # pandas 3 reads every double back exactly by default and deprecates the
    # option pandas 2 needs for that.
    exact = {} if int(pd.__version__.split(".")[0]) >= 3 else {"float_precision": "round_trip"}
    try:
        frame = pd.read_csv(path, skipinitialspace=True, **exact)
    except (pd.errors.EmptyDataError, pd.errors.ParserError, UnicodeDecodeError) as error:
        raise ResultFileError(
            f"{path}: not a table under one header line ({' '.join(str(error).split())})"
        ) from None
    if frame.empty:
        raise ResultFileError(f"{path}: a header line but no data rows")
    columns = {}
    for name in frame.columns:
        numbers = pd.to_numeric(frame[name], errors="coerce")
        wrong = numbers.isna() & frame[name].notna()
        if wrong.any():
            row = int(np.argmax(wrong.to_numpy()))
            raise ResultFileError(
                f"{path}, line {row + 2}, column {str(name).strip()!r}: "
                f"{frame[name].iloc[row]!r} is not a number"
            )
        columns[str(name).strip()] = numbers.to_numpy(dtype=float)
    return structured(columns)


def write_rows(rows: Sequence[Mapping[str, object]], path: PathType) -> Path:
    """Write a list of row dicts (numbers and text; missing keys left empty) as CSV."""
    import pandas as pd

    path = _parent_made(path)
    pd.DataFrame(list(rows)).to_csv(path, index=False)
    return path


def write_table(table: "pd.DataFrame", stem: PathType, parquet: bool = True) -> list[Path]:
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
            pass  # no pyarrow/fastparquet: CSV only, as documented
    return written


def read_table(path: PathType) -> "pd.DataFrame":
    """A table written by `write_table` or `write_rows` (CSV or Parquet) as a DataFrame."""
    import pandas as pd

    path = Path(path)
    return pd.read_parquet(path) if path.suffix == ".parquet" else pd.read_csv(path)
