"""Reading and writing results: the one place that knows file formats.

Time series (FMPy's structured result arrays, and any table of numbers) go to
CSV in FMPy's column format (the bytes `fmpy.util.write_csv` writes): a quoted
header, one column per variable (each title `name [unit]` when the writer
gives the units, as the command line's runs do; readers take either), values
printed as the shortest text that reads back to the same double. `CsvStream`
writes one chunk of rows at a time, so a long run never has to be held
whole. They are read back through pandas (FMPy's reader takes a space after a
comma for a vector column, which hand-written input files often have).

Every file is written under a temporary name beside its place and renamed into
it when whole: a file is there complete, or not at all (an interrupt, a full
disk or an error while writing leaves the earlier file, if any, untouched).
Tables with text columns (the design sweep's status
and message) go through pandas, also round-trip exact, and to Parquet when a
Parquet engine (pyarrow) is installed.
"""

import os
import tempfile
import uuid
from collections.abc import Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # pandas is imported where a table is written or read
    import pandas as pd

PathType = str | PathLike


class ResultFileError(ValueError):
    """A results file that cannot be read or written: the message names the file
    and the problem."""


def check_writable(path: PathType) -> Path:
    """`path` as a Path; ResultFileError if a file stands where a folder of it must be."""
    path = Path(path)
    blocking = next((p for p in path.parents if p.exists() and not p.is_dir()), None)
    if blocking is not None:
        raise ResultFileError(f"cannot write {path}: {blocking} is a file, not a folder")
    if path.is_dir():
        raise ResultFileError(f"cannot write {path}: it is a folder")
    return path


def check_output_path(path: PathType) -> Path:
    """A command's output `path`, checked before any work: `check_writable`; its
    folder exists, or lies inside the working folder (then it is made when the
    file is written: `results/` on a fresh clone), never elsewhere (a mistyped
    absolute path would make folders at the filesystem root); and a file can be
    created there. ResultFileError naming the missing or unwritable folder."""
    path = check_writable(path)
    folder = path.parent.resolve()
    existing = next(p for p in (folder, *folder.parents) if p.exists())
    if existing != folder and Path.cwd().resolve() not in (folder, *folder.parents):
        missing = next(p for p in reversed((folder, *folder.parents)) if not p.exists())
        raise ResultFileError(
            f"cannot write {path}: the folder {missing} does not exist (make it first; "
            "only folders inside the working folder are made)"
        )
    try:
        with tempfile.NamedTemporaryFile(dir=existing, prefix=".cardan_joint_"):
            pass
    except OSError as error:
        raise ResultFileError(
            f"cannot write {path}: no file can be created in {existing} ({error.strerror})"
        ) from None
    return path


def _parent_made(path: PathType) -> Path:
    path = check_writable(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    return path


def temporary_beside(path: PathType) -> tuple[Path, Path]:
    """(path, a fresh temporary name in its folder), the folder made."""
    path = _parent_made(path)
    return path, path.with_name(f".{path.name}.{uuid.uuid4().hex[:12]}.tmp")


@contextmanager
def replaced_whole(path: PathType) -> Iterator[Path]:
    """A temporary path beside `path` for the block to write; renamed onto
    `path` when the block ends normally, removed otherwise."""
    path, temporary = temporary_beside(path)
    try:
        yield temporary
        os.replace(temporary, path)
    finally:
        temporary.unlink(missing_ok=True)


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


def column_title(name: str, unit: str = "") -> str:
    """A CSV column's title: its name and, for a quantity with a unit, `[unit]`."""
    return f"{name} [{unit}]" if unit not in ("", "1") else name


def split_title(title: str) -> tuple[str, str]:
    """A column title -> (name, unit): `output_speed [rad/s]` and the bare
    `output_speed` (no unit: "") alike."""
    title = title.strip()
    name, bracket, unit = title.partition(" [")
    if bracket and unit.endswith("]"):
        return name.strip(), unit[:-1].strip()
    return title, ""


def write_csv(
    data: np.ndarray | Mapping[str, Iterable[float]],
    path: PathType,
    columns: Sequence[str] | None = None,
    units: Mapping[str, str] | None = None,
) -> Path:
    """Write a result (structured array, or {name: column} of numbers) in FMPy's CSV format.

    `columns`: the variables to write besides `time` (FMPy's convention; None: all).
    `units`: {name: unit} put in the header as `name [unit]` (None: bare names,
    as FMI's cross-check files and FMPy's reader of them need)."""
    if not isinstance(data, np.ndarray):
        data = structured(data)
    if columns is not None:
        data = data[["time", *columns]]
    with CsvStream(path, data.dtype.names or (), units) as stream:
        stream.write(data)
    return Path(path)


class CsvStream:
    """A CSV in FMPy's format written chunk by chunk under a temporary name:
    `commit` (or leaving `with` normally) renames it into place, `discard` (or
    leaving `with` on an exception) removes it. `rows`: the rows written."""

    def __init__(
        self, path: PathType, names: Sequence[str], units: Mapping[str, str] | None = None
    ) -> None:
        self.path, self._temporary = temporary_beside(path)
        self.names = tuple(names)
        self.rows = 0
        self._stream = open(self._temporary, "w")
        header = (column_title(name, (units or {}).get(name, "")) for name in self.names)
        self._stream.write(",".join(f'"{title}"' for title in header) + "\n")

    def write(self, data: np.ndarray) -> None:
        """Append rows (a structured array holding at least `names`)."""
        columns = [data[name].astype(float, copy=False).tolist() for name in self.names]
        # A float's repr is the shortest text that reads back to it, as FMPy's str(np.float64).
        self._stream.writelines(",".join(map(repr, row)) + "\n" for row in zip(*columns))
        self.rows += len(data)

    def commit(self) -> Path:
        try:
            self._stream.close()
            os.replace(self._temporary, self.path)
        finally:
            self.discard()
        return self.path

    def discard(self) -> None:
        self._stream.close()
        self._temporary.unlink(missing_ok=True)

    def __enter__(self) -> "CsvStream":
        return self

    def __exit__(self, kind, *_) -> None:
        if kind is None:
            self.commit()
        else:
            self.discard()


def read_csv(path: PathType) -> np.ndarray:
    """A CSV of numbers under a header line (FMPy's format, quoted names or not,
    spaces after commas allowed, each name with its `[unit]` or without) -> a
    structured float array named without the units, every value read back to
    the same double; raises ResultFileError naming the file, and the line and
    column of a value that is not a number."""
    return read_csv_units(path)[0]


def read_csv_units(path: PathType) -> tuple[np.ndarray, dict[str, str]]:
    """As `read_csv`, and {name: unit} of the columns whose title gives one."""
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
    columns, units = {}, {}
    for title in frame.columns:
        name, unit = split_title(str(title))
        numbers = pd.to_numeric(frame[title], errors="coerce")
        wrong = numbers.isna() & frame[title].notna()
        if wrong.any():
            row = int(np.argmax(wrong.to_numpy()))
            raise ResultFileError(
                f"{path}, line {row + 2}, column {name!r}: "
                f"{frame[title].iloc[row]!r} is not a number"
            )
        if name in columns:
            raise ResultFileError(f"{path}: column {name!r} appears twice")
        columns[name] = numbers.to_numpy(dtype=float)
        if unit:
            units[name] = unit
    return structured(columns), units


def write_rows(rows: Sequence[Mapping[str, object]], path: PathType) -> Path:
    """Write a list of row dicts (numbers and text; missing keys left empty) as CSV."""
    import pandas as pd

    with replaced_whole(path) as temporary:
        pd.DataFrame(list(rows)).to_csv(temporary, index=False)
    return Path(path)


def write_table(table: "pd.DataFrame", stem: PathType, parquet: bool = True) -> list[Path]:
    """Write a pandas table to <stem>.csv, and <stem>.parquet when `parquet` and
    a Parquet engine is installed; returns the paths written."""
    stem = Path(stem)
    written = [stem.with_suffix(".csv")]
    with replaced_whole(written[0]) as temporary:
        table.to_csv(temporary, index=False)
    if parquet:
        try:
            with replaced_whole(stem.with_suffix(".parquet")) as temporary:
                table.to_parquet(temporary, index=False)
            written.append(stem.with_suffix(".parquet"))
        except ImportError:
            pass  # no pyarrow/fastparquet: CSV only, as documented
    return written


def read_table(path: PathType) -> "pd.DataFrame":
    """A table written by `write_table` or `write_rows` (CSV or Parquet) as a DataFrame."""
    import pandas as pd

    path = Path(path)
    return pd.read_parquet(path) if path.suffix == ".parquet" else pd.read_csv(path)
