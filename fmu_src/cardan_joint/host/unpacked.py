"""An FMU unzipped into a folder this process owns, removed when done.

FMPy's `simulate_fmu` and `extract` unzip into a fresh `$TMPDIR/tmpXXXX` and
remove it only after a run that ended normally: a refused start, a damaged FMU
or an interrupt leaves 1.2 MB behind each time. Every run here unzips through
`ExtractedFMU`, whose folder goes in `close` (or on leaving `with`) however the
run ended; an unzipped folder given to it is used as it is and left alone.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path
from typing import Any

from .fmu_info import BadFMUError, read_model_description

# The prefix of every folder this project unzips into (`$TMPDIR/cardan_joint_XXXX`).
PREFIX = "cardan_joint_"


class ExtractedFMU:
    """An FMU unzipped once, for any number of instances or runs; a directory is used as is.

    `model_description`: the FMU's, when already read (not read again)."""

    def __init__(self, fmu: str | Path, model_description: Any = None) -> None:
        import zipfile

        from fmpy import extract

        self.model_description = model_description or read_model_description(fmu)
        self._owned = not Path(fmu).is_dir()
        if not self._owned:
            self.directory = str(fmu)
            return
        self.directory = tempfile.mkdtemp(prefix=PREFIX)
        try:
            extract(str(fmu), unzipdir=self.directory)
        except (zipfile.BadZipFile, OSError, EOFError) as error:
            self.close()
            raise BadFMUError(f"{fmu} is not a readable FMU: cannot unzip it ({error})") from None
        except BaseException:
            self.close()
            raise
        binary = self.binary()
        if not binary.is_file():
            self.close()
            raise BadFMUError(
                f"{fmu} is not a runnable FMU here: it has no binary for this platform "
                f"({binary.relative_to(self.directory)} is missing)"
            )

    def binary(self) -> Path:
        """The shared library a host on this platform loads from the unzipped FMU."""
        from fmpy import platform, platform_tuple, sharedLibraryExtension

        description = self.model_description
        fmi3 = description.fmiVersion.startswith("3")
        identifier = description.coSimulation.modelIdentifier
        folder = platform_tuple if fmi3 else platform
        return Path(self.directory, "binaries", folder, identifier + sharedLibraryExtension)

    def instance(self, name: str = "instance", **arguments: Any):
        from .instance import FmuInstance

        return FmuInstance(self.model_description, self.directory, name=name, **arguments)

    def close(self) -> None:
        if self._owned:
            shutil.rmtree(self.directory, ignore_errors=True)
            self._owned = False

    def __enter__(self) -> ExtractedFMU:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
