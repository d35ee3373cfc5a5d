"""An older Linux to run the FMUs on: a Debian 11 (bullseye: glibc 2.31, GCC 10's
C++ runtime, CPython 3.9) root laid out by debootstrap, with a shared CPython 3.11
built inside it from Debian's own source package (bookworm's python3.11: upstream's
tarball; ./configure --enable-shared, no PGO, no tests) into /usr/local, as a user
of an older distribution installs a newer Python.

The root is kept in a cache folder outside the repository, named by a hash of this
recipe, so that a rerun (or the next test session) reuses it; a root whose set-up
did not finish is made again. Needs root, debootstrap, unshare, and Debian's archive.

    python tests/system/debian_root.py [CACHE]    lay it out (or reuse it); print its path
"""

import hashlib
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

SUITE = "bullseye"
MIRROR = "http://deb.debian.org/debian"
PACKAGES = (
    "gcc", "libc6-dev", "make", "xz-utils",  # compile the hosts and CPython
    "zlib1g-dev", "libffi-dev",  # CPython's zlib and ctypes
    "libpython3.9",  # the distribution's own CPython (too old for the FMU)
)  # fmt: skip
CPYTHON_SOURCE = ("bookworm", "python3.11")  # Debian suite, source package
CONFIGURE = ("--enable-shared", "--prefix=/usr/local", "--without-ensurepip")
CACHE = Path(os.environ.get("CARDAN_JOINT_ROOT_CACHE", "/var/cache/cardan-joint"))
DONE = ".cardan-joint-root-complete"
# CPython: the library the loader discovers, and the standard library beside it.
LIBPYTHON = "usr/local/lib/libpython3.11.so.1.0"


class RootUnavailable(RuntimeError):
    """This machine cannot lay out the root (not root, no debootstrap, no archive)."""


def recipe_key() -> str:
    recipe = repr((SUITE, MIRROR, PACKAGES, CPYTHON_SOURCE, CONFIGURE, _build_script()))
    return hashlib.sha256(recipe.encode()).hexdigest()[:12]


def root_path(cache: Path = CACHE) -> Path:
    return cache / f"{SUITE}-{recipe_key()}"


def in_root(root: Path, script: str, *, hide=(), timeout: float = 1800, env=None):
    """`sh -c script` chrooted into root, with /proc and /dev mounted in a private
    mount namespace (nothing stays mounted after it); the root's folders `hide`
    (e.g. "/usr/local") are empty there."""
    mounts = (
        f"mount --make-rprivate / && mount -t proc proc {root}/proc && "
        f"mount --rbind /dev {root}/dev && "
        + "".join(f"mount -t tmpfs tmpfs {root}/{folder.lstrip('/')} && " for folder in hide)
    )
    command = ["unshare", "-m", "sh", "-c", mounts + 'exec chroot "$0" /bin/sh -c "$1"']
    return subprocess.run(
        [*command, str(root), script],
        capture_output=True,
        text=True,
        timeout=timeout,
        env=env or {"PATH": "/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin", "LC_ALL": "C"},
    )


def _build_script() -> str:
    suite, package = CPYTHON_SOURCE
    return "\n".join(
        [
            "set -e",
            f"echo 'deb-src {MIRROR} {suite} main' > /etc/apt/sources.list.d/cpython-src.list",
            "apt-get -q update >/dev/null",
            "mkdir -p /build && cd /build",
            f"apt-get -q source --download-only {package} >/dev/null",
            "tar xf *.orig.tar.* && cd Python-*/",
            f"./configure -q {' '.join(CONFIGURE)} >/dev/null",
            "make -s -j$(nproc) >/dev/null 2>&1",
            "make -s altinstall >/dev/null 2>&1",
            "cd / && rm -rf /build",
        ]
    )


def _check_machine() -> None:
    if os.geteuid() != 0:
        raise RootUnavailable("laying out a Debian root needs root (debootstrap, chroot)")
    for tool in ("debootstrap", "unshare", "chroot"):
        if not shutil.which(tool):
            raise RootUnavailable(f"needs {tool} (apt-get install debootstrap)")


def _step(what: str, run: subprocess.CompletedProcess) -> None:
    if run.returncode != 0:
        raise RootUnavailable(
            f"{what} failed ({run.returncode}):\n{run.stdout[-3000:]}{run.stderr[-3000:]}"
        )


def prepare(cache: Path = CACHE, log=print) -> Path:
    """The root, laid out (debootstrap, CPython 3.11 built) or reused; its path."""
    root = root_path(cache)
    if (root / DONE).exists():
        return root
    _check_machine()
    if root.exists():  # an unfinished set-up; never into what an interrupted one mounted
        subprocess.run(["rm", "-rf", "--one-file-system", str(root)], check=True)
    root.parent.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    run = subprocess.run(
        ["debootstrap", "--variant=minbase", f"--include={','.join(PACKAGES)}",
         SUITE, str(root), MIRROR],
        capture_output=True, text=True, timeout=1800,
    )  # fmt: skip
    _step("debootstrap", run)
    log(f"debootstrap {SUITE}: {time.monotonic() - started:.0f} s")
    shutil.copy("/etc/resolv.conf", root / "etc" / "resolv.conf")  # apt-get source
    began = time.monotonic()
    _step(f"building CPython from {CPYTHON_SOURCE}", in_root(root, _build_script()))
    log(f"CPython 3.11 built in the root: {time.monotonic() - began:.0f} s")
    if not (root / LIBPYTHON).exists():
        raise RootUnavailable(f"the CPython build left no {LIBPYTHON} in {root}")
    (root / DONE).write_text(f"{time.monotonic() - started:.0f} s\n")
    log(f"root ready in {time.monotonic() - started:.0f} s: {root}")
    return root


if __name__ == "__main__":
    arguments = sys.argv[1:]
    if len(arguments) > 1:
        sys.exit("usage: python tests/system/debian_root.py [CACHE]")
    try:
        print(prepare(Path(arguments[0]) if arguments else CACHE))
    except RootUnavailable as error:
        sys.exit(str(error))
