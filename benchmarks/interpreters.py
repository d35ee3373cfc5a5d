"""Where section 6 counts instructions: each CPython minor, as pyenv's shared
build on this machine (3.10-3.13), or as the only CPython of a Debian sid root
(3.14, 3.15: the roots tests/system/sid_roots.py lays out and caches), where
the C host is compiled by the root's gcc and callgrind runs chrooted.

An interpreter runs a command, counted by callgrind or not, with the host's
environment for a default build (`model_env`: the runtime finds the CPython) or
for a floor (`floor_env`: libpython preloaded for pythonfmu's binary).
"""

import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import weakref
from pathlib import Path

from .timing import ROOT

PYENV = Path(os.environ.get("PYENV_ROOT", "/root/.pyenv"))
CALLGRIND = ("--tool=callgrind", "--callgrind-out-file=/dev/null")
# One hash seed in every counted process: str hashes set dict probe chains, and
# a random seed moved a C host's count by up to 1 k a step between runs.
SEEDED = {"PYTHONHASHSEED": "0"}
SYSTEM = ROOT / "tests" / "system"


class Here:
    """pyenv's CPython 3.<minor> on this machine."""

    def __init__(self, prefix: Path, minor: int):
        library = prefix / "lib" / f"libpython3.{minor}.so.1.0"
        self.prefix, self.version = prefix, prefix.name
        self.model_env = {**SEEDED, "CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(library)}
        self.floor_env = {**SEEDED, "LD_PRELOAD": str(library), "PYTHONHOME": str(prefix)}

    def place(self, path) -> str:
        return str(path)

    def host(self, compiled) -> str:
        """The C host as it runs here: the one compiled on this machine."""
        return str(compiled)

    def run(self, command: list, environment: dict, counted: bool):
        valgrind = ["nice", "-n", "10", "valgrind", *CALLGRIND] if counted else []
        return subprocess.run([*valgrind, *map(str, command)], capture_output=True, text=True,
                              env={"PATH": "/usr/bin:/bin", **environment})  # fmt: skip


class InRoot:
    """A Debian sid root whose only CPython is 3.<minor>: what runs there is
    copied into a scratch folder of the root (removed with this object), and
    this machine's valgrind with it."""

    def __init__(self, root: Path, minor: int):
        self.root = root
        library = f"/usr/lib/x86_64-linux-gnu/libpython3.{minor}.so.1.0"
        self.version = f"{debian_version(root, minor)} (Debian sid)"
        self.model_env = dict(SEEDED)  # the runtime finds the root's CPython itself
        self.floor_env = {**SEEDED, "LD_PRELOAD": library, "PYTHONHOME": "/usr"}
        self.here = Path(tempfile.mkdtemp(prefix="cardan-benchmarks-", dir=root / "tmp"))
        self.there = Path("/tmp") / self.here.name
        weakref.finalize(self, shutil.rmtree, self.here, True)
        valgrind = self.here / "valgrind"
        (valgrind / "lib").mkdir(parents=True)
        shutil.copy(shutil.which("valgrind.bin") or "/usr/bin/valgrind.bin", valgrind / "valgrind")
        for tool in ("callgrind-amd64-linux", "vgpreload_core-amd64-linux.so", "default.supp"):
            shutil.copy(Path("/usr/libexec/valgrind") / tool, valgrind / "lib")
        self.placed: dict[str, str] = {}

    def place(self, path) -> str:
        """`path` (a file or a folder) copied into the root once; its path there."""
        path = Path(path)
        if str(path) not in self.placed:
            name = f"{len(self.placed)}_{path.name}"
            copy = shutil.copytree if path.is_dir() else shutil.copy
            copy(path, self.here / name)
            self.placed[str(path)] = str(self.there / name)
        return self.placed[str(path)]

    def host(self, compiled) -> str:
        """tests/c_host's FMI 2.0 host, compiled in the root by its gcc (not the one
        `compiled` here: the root's glibc and headers); its path there."""
        if "host" in self.placed:
            return self.placed["host"]
        sys.path.insert(0, str(ROOT / "tests"))
        try:
            from c_host.compile import compile_command, host_files
        finally:
            sys.path.remove(str(ROOT / "tests"))
        include, sources = host_files()
        folder, inside = self.here / "c_host", self.there / "c_host"
        shutil.copytree(include, folder / "include")
        for source in [*sources, *Path(sources[0]).parent.glob("*.h")]:
            shutil.copy(source, folder)
        named = [inside / Path(source).name for source in sources]
        command = compile_command(inside / "host", inside / "include", named, cc=["gcc"])
        run = self.run(command, {}, counted=False)
        if run.returncode != 0:
            raise RuntimeError(f"compiling the C host in {self.root} failed:\n{run.stderr}")
        self.placed["host"] = str(inside / "host")
        return self.placed["host"]

    def run(self, command: list, environment: dict, counted: bool):
        valgrind = self.there / "valgrind"
        if counted:
            environment = {**environment, "VALGRIND_LIB": f"{valgrind}/lib"}
            command = ["nice", "-n", "10", f"{valgrind}/valgrind", *CALLGRIND, *command]
        words = ["env", "-i", "PATH=/usr/bin:/bin",
                 *(f"{name}={value}" for name, value in environment.items()), *command]  # fmt: skip
        return in_root()(self.root, " ".join(shlex.quote(str(word)) for word in words),
                         timeout=7200)  # fmt: skip


def in_root():
    sys.path.insert(0, str(SYSTEM))
    try:
        from debian_root import in_root as run_in_root
    finally:
        sys.path.remove(str(SYSTEM))
    return run_in_root


def debian_version(root: Path, minor: int) -> str:
    """The root's libpython3.<minor> package version, upstream part (3.15.2)."""
    status = (root / "var/lib/dpkg/status").read_text().split("\n\n")
    for entry in status:
        if f"Package: libpython3.{minor}\n" in entry + "\n":
            for line in entry.splitlines():
                if line.startswith("Version: "):
                    return line.split()[1].split("-")[0]
    return f"3.{minor}"


def sid_root(minor: int) -> Path | None:
    """The cached sid root of CPython 3.<minor>, if tests/system/sid_roots.py laid it out."""
    sys.path.insert(0, str(SYSTEM))
    try:
        from debian_root import DONE
        from sid_roots import MINORS, root_path
    finally:
        sys.path.remove(str(SYSTEM))
    root = root_path(minor) if minor in MINORS else None
    return root if root is not None and (root / DONE).exists() else None


def cpython(minor: int) -> Path | None:
    """pyenv's newest shared CPython 3.<minor>: its prefix, or None."""
    found = sorted((PYENV / "versions").glob(f"3.{minor}.*"))
    ok = [p for p in found if (p / "lib" / f"libpython3.{minor}.so.1.0").exists()]
    return ok[-1] if ok else None


def interpreter(minor: int) -> "Here | InRoot | None":
    """Where CPython 3.<minor> runs: pyenv's here, else its sid root; None without either."""
    prefix = cpython(minor)
    if prefix is not None:
        return Here(prefix, minor)
    root = sid_root(minor)
    return InRoot(root, minor) if root is not None else None
