"""The last step of every build: make the .fmu a function of its contents alone.

pythonfmu and pythonfmu3 stamp each build with the clock (zip timestamps,
`generationDateAndTime`, a time-based GUID or instantiation token), leave
permissions to the umask and ship binaries for platforms this project never
runs. Rewritten here, after everything else has written into the archive, the
same source and settings give the same bytes (a sweep then resumes after a
rebuild: `sweep.store` keys its cases on the FMU's digest):

- entries in name order, each dated 1980-01-01 (the zip epoch), mode 644, or
  755 for the shared libraries under `binaries/`, deflated;
- no `__pycache__`/`.pyc` and no directory entries;
- binaries for Linux x86_64 only (`linux64` in FMI 2, `x86_64-linux` in FMI 3):
  the only platform whose binary this project builds, tests and can say how
  it runs (pythonfmu's Windows binary is untested here);
- no `sources/`: pythonfmu3 adds its C++ wrapper's sources, from which the
  FMU's binary (this project's own C runtime) is not built;
- no `generationDateAndTime`; the GUID (FMI 3: instantiation token) is a
  digest of everything else in the FMU, so it still changes with any content.
"""

import hashlib
import re
import shutil
import tempfile
import uuid
import zipfile
from pathlib import Path

PLATFORMS = {2: "linux64", 3: "x86_64-linux"}
_EPOCH = (1980, 1, 1, 0, 0, 0)
_DESCRIPTION = "modelDescription.xml"
_STAMP = re.compile(rb'\s+generationDateAndTime="[^"]*"')
_TOKEN = re.compile(rb'(\s(?:guid|instantiationToken)=")[^"]*(")')


class ArchiveError(RuntimeError):
    pass


def _shipped(name: str, fmi_version: int) -> bool:
    parts = name.split("/")
    if name.endswith("/") or "__pycache__" in parts or name.endswith(".pyc"):
        return False
    if parts[0] == "sources":
        return False
    return parts[0] != "binaries" or parts[1:2] == [PLATFORMS[fmi_version]]


def _identified(entries: dict) -> dict:
    """The model description without its time stamp, its token the digest of the rest."""
    description, found = _TOKEN.subn(rb"\1\2", _STAMP.sub(b"", entries[_DESCRIPTION]), count=1)
    if found != 1:
        raise ArchiveError(f"{_DESCRIPTION} has no guid or instantiationToken to make stable")
    digest = hashlib.sha256()
    for name, data in sorted({**entries, _DESCRIPTION: description}.items()):
        digest.update(hashlib.sha256(name.encode()).digest() + hashlib.sha256(data).digest())
    token = str(uuid.UUID(bytes=digest.digest()[:16], version=5)).encode()
    return {**entries, _DESCRIPTION: _TOKEN.sub(rb"\g<1>" + token + rb"\2", description, count=1)}


def normalise(fmu: Path, fmi_version: int) -> None:
    """Rewrite `fmu` in place as described above."""
    with zipfile.ZipFile(fmu) as source:
        entries = {
            item.filename: source.read(item)
            for item in source.infolist()
            if _shipped(item.filename, fmi_version)
        }
    if _DESCRIPTION not in entries:
        raise ArchiveError(f"{fmu} has no {_DESCRIPTION}")
    entries = _identified(entries)
    with tempfile.TemporaryDirectory(prefix="cardan_joint_archive_") as workdir:
        rewritten = Path(workdir) / fmu.name
        with zipfile.ZipFile(rewritten, "w") as target:
            for name in sorted(entries):
                info = zipfile.ZipInfo(name, _EPOCH)
                info.create_system = 3  # Unix, so that the mode below is read
                library = name.startswith("binaries/")
                info.external_attr = (0o100755 if library else 0o100644) << 16
                info.compress_type = zipfile.ZIP_DEFLATED
                target.writestr(info, entries[name])
        shutil.move(str(rewritten), fmu)
