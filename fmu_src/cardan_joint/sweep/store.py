"""A sweep's results: each case saved the moment it is done, and the tidy table.

`CaseStore` keeps one small JSON file per finished case in a folder. Each file
is written under a temporary name and renamed into place (an atomic rename on
POSIX), so a file either holds a whole row or does not exist: a sweep killed at
any instant leaves only complete cases, and the next run computes just the
missing ones. Only the process that runs the sweep writes (workers return rows),
so a task that Dask runs again after losing a worker is still stored once.
"""

import hashlib
import json
import os
import uuid
from pathlib import Path
from typing import TYPE_CHECKING

from .spec import ACCELERATION_LIMIT, PEAKS, Case, SweepSpec

if TYPE_CHECKING:
    import pandas

SETTINGS_FILE = "settings.json"
COLUMNS = (
    [
        "bend_angle_deg",
        "input_speed_rpm",
        "inertia_distribution",
        "crosspiece_inertia_1",
        "crosspiece_inertia_2",
        "crosspiece_inertia_3",
        "load_torque",
        "status",
        "message",
    ]
    + list(PEAKS)
    + ["beyond_acceleration_limit"]
)


class SettingsMismatch(ValueError):
    """The store holds cases computed with other settings than the sweep's."""


def _write_atomically(path: Path, text: str):
    temporary = path.with_name(f".{path.name}.{uuid.uuid4().hex}.tmp")
    with open(temporary, "w") as stream:
        stream.write(text)
        stream.flush()
        os.fsync(stream.fileno())
    os.replace(temporary, path)


class CaseStore:
    """Finished cases of one sweep, one file each, in `folder`.

    `fmu`: the FMU file, whose digest joins the settings (a rebuilt FMU with
    other start values must not be mixed with the cases of the old one)."""

    def __init__(self, folder, spec: SweepSpec, fmu=None):
        self.folder = Path(folder)
        self.folder.mkdir(parents=True, exist_ok=True)
        self.written = 0  # cases written by this object: computed in this run
        settings = spec.settings()
        if fmu is not None:
            settings["fmu_sha256"] = hashlib.sha256(Path(fmu).read_bytes()).hexdigest()
        settings = json.loads(json.dumps(settings))
        saved = self.folder / SETTINGS_FILE
        if saved.is_file():
            found = json.loads(saved.read_text())
            if found != settings:
                differing = "; ".join(
                    f"{key} {found.get(key, '(unset)')!r} there, "
                    f"{settings.get(key, '(unset)')!r} now"
                    for key in sorted(set(found) | set(settings))
                    if found.get(key) != settings.get(key)
                )
                raise SettingsMismatch(
                    f"{self.folder} holds cases computed with other settings ({differing}): "
                    f"give the sweep another name or output folder, or start it afresh "
                    f"(--fresh)"
                )
        else:
            _write_atomically(saved, json.dumps(settings, indent=1))

    def _path(self, case: Case) -> Path:
        return self.folder / f"{case.key}.json"

    def missing(self, cases) -> list:
        return [case for case in cases if not self._path(case).is_file()]

    def write(self, row: dict):
        case = Case(row["bend_angle_deg"], row["input_speed_rpm"], row["inertia_distribution"])
        # json writes floats as their shortest exact text (NaN included): round-trip exact.
        _write_atomically(self._path(case), json.dumps(row))
        self.written += 1

    def rows(self, cases) -> list:
        return [
            json.loads(self._path(case).read_text()) for case in cases if self._path(case).is_file()
        ]


def to_table(rows, spec: SweepSpec) -> "pandas.DataFrame":
    """The tidy table, in the spec's order whatever order the tasks finished in."""
    import pandas as pd

    table = pd.DataFrame(rows).reindex(columns=COLUMNS)
    table["beyond_acceleration_limit"] = table["peak_output_acceleration"] > ACCELERATION_LIMIT
    order = {name: k for k, name in enumerate(spec.distributions)}
    table = table.sort_values(
        ["bend_angle_deg", "input_speed_rpm", "inertia_distribution"],
        key=lambda c: c.map(order) if c.name == "inertia_distribution" else c,
        kind="stable",
    )
    return table.reset_index(drop=True)
