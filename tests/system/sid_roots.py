"""Debian sid roots whose only CPython is one new minor: 3.14 (sid's python3) and
3.15 (packaged beside it). debootstrap lays out one sid root with a C compiler;
each minor's root is a copy of it (cp -a --one-file-system) with Debian's
libpython3.X installed by apt; with `fmpy`, sid's python3 with FMPy's
dependencies from Debian and the FMPy wheel this machine's pip gives (Debian
packages no FMPy). Cached like tests/system/debian_root.py's root
(same cache folder, same completion mark, same chroot helper), named by a hash
of this recipe."""

import hashlib
import shutil
import subprocess
import sys
import time
from pathlib import Path

from debian_root import CACHE, DONE, MIRROR, RootUnavailable, _check_machine, _step, in_root

SUITE = "sid"
BASE_PACKAGES = ("gcc", "libc6-dev")  # compile the hosts in the root
MINORS = (14, 15)
# The archive a cache replays may be older than its Release file's Valid-Until.
APT = "apt-get -q -o Acquire::Check-Valid-Until=false"
FMPY_DEPENDENCIES = ("python3", "python3-pip", "python3-numpy", "python3-lxml", "python3-attr",
                     "python3-jinja2", "python3-msgpack", "python3-lark")  # fmt: skip


def recipe_key() -> str:
    recipe = repr((SUITE, MIRROR, BASE_PACKAGES, APT, _install_script(0), FMPY_DEPENDENCIES))
    return hashlib.sha256(recipe.encode()).hexdigest()[:12]


def root_path(minor: int, cache: Path = CACHE, fmpy: bool = False) -> Path:
    return cache / f"{SUITE}-python3.{minor}{'-fmpy' if fmpy else ''}-{recipe_key()}"


def _install_script(minor: int, wheel: str = "") -> str:
    packages = " ".join(FMPY_DEPENDENCIES) if wheel else f"libpython3.{minor}"
    lines = [
        "set -e",
        f"{APT} update >/dev/null",
        f"DEBIAN_FRONTEND=noninteractive {APT} install -y {packages} >/dev/null",
        "apt-get clean",
    ]
    if wheel:
        lines.append(f"python3 -m pip install -q --break-system-packages --no-deps {wheel}")
    return "\n".join(lines)


def _fmpy_wheel(folder: Path) -> Path:
    """The wheel of the FMPy this machine runs, by its own pip (pure Python)."""
    from importlib.metadata import version

    run = subprocess.run(
        [sys.executable, "-m", "pip", "download", "-q", "--no-deps", f"fmpy=={version('fmpy')}",
         "-d", str(folder)],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    _step("pip download fmpy", run)
    return next(folder.glob("fmpy-*.whl"))


def _fresh(root: Path) -> None:
    """Remove what an interrupted set-up left, never through what it mounted."""
    if root.exists():
        subprocess.run(["rm", "-rf", "--one-file-system", str(root)], check=True)


def _base(cache: Path, log) -> Path:
    base = cache / f"{SUITE}-base-{recipe_key()}"
    if (base / DONE).exists():
        return base
    _fresh(base)
    started = time.monotonic()
    run = subprocess.run(
        ["debootstrap", "--variant=minbase", f"--include={','.join(BASE_PACKAGES)}",
         SUITE, str(base), MIRROR],
        capture_output=True, text=True, timeout=1800,
    )  # fmt: skip
    _step("debootstrap sid", run)
    shutil.copy("/etc/resolv.conf", base / "etc" / "resolv.conf")  # apt-get install
    (base / DONE).write_text(f"{time.monotonic() - started:.0f} s\n")
    log(f"debootstrap {SUITE}: {time.monotonic() - started:.0f} s")
    return base


def prepare(minor: int, cache: Path = CACHE, log=print, fmpy: bool = False) -> Path:
    """The sid root whose only CPython is 3.<minor> (with `fmpy`: and FMPy on it),
    laid out or reused; its path."""
    root = root_path(minor, cache, fmpy)
    if (root / DONE).exists():
        return root
    _check_machine()
    cache.mkdir(parents=True, exist_ok=True)
    base = _base(cache, log)
    _fresh(root)
    subprocess.run(["cp", "-a", "--one-file-system", str(base), str(root)], check=True)
    (root / DONE).unlink()
    began = time.monotonic()
    wheel = ""
    if fmpy:
        wheel = f"/tmp/{_fmpy_wheel(root / 'tmp').name}"
    _step(
        f"installing CPython 3.{minor}", in_root(root, _install_script(minor, wheel), timeout=1800)
    )
    found = sorted(p.name for p in (root / "usr/lib").glob("python3.*"))
    if found != [f"python3.{minor}"]:
        raise RootUnavailable(f"{root} holds {found}, not CPython 3.{minor} alone")
    (root / DONE).write_text(f"{time.monotonic() - began:.0f} s\n")
    log(f"sid root with CPython 3.{minor} ready in {time.monotonic() - began:.0f} s: {root}")
    return root
