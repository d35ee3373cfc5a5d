"""Every shell command of the README and the docs runs as written, in page
order, on a fresh copy of the tree after the README's set-up (this venv plays
the one it makes); commands that take minutes are listed with why."""

import shutil
import subprocess
import sys

import doc_commands
import pytest
from conftest import ROOT

# Commands (by a part of their text) not run here, and why; the set-up steps
# (`python3 -m venv`, `pip install`) are left out of every command, this venv
# standing for the one they make (.ci/run makes it on a clean clone; the
# README's line that installs the system packages is not a venv command).
NOT_RUN = {
    ".venv/bin/python -m pytest": "the test suite itself",
    ".venv/bin/python -m mypy": "the checks .ci/run runs after the tests",
    "tests/system/debian_root.py": "about 20 min the first time (the CPython build): "
    "test_older_linux.py lays out the same root (debian_root.prepare)",
    ".venv/bin/python -m benchmarks": "tens of minutes (benchmarks/results.md says how long)",
    "tools/gallery.py": "about 70 s per example set",
    'tools/mutation.py --only "bend"': "minutes: rebuilds and tests per mutant",
    "tools/mutation.py                # all guards": "minutes: every mutant",
    "examples/design_sweep.py": "336 co-simulations, or a cluster at a named address",
    "dask scheduler": "a cluster on other machines",
    "dask worker": "a cluster on other machines",
}


def _runnable(command: str) -> str:
    """The part of `command` this test runs: the README's quick start without
    its set-up steps, which the test's venv stands for."""
    steps = [s.strip() for s in command.split("&&")]
    kept = [s for s in steps if not s.startswith(("python3 -m venv", ".venv/bin/pip install"))]
    return " && ".join(kept)


def _all_commands():
    for page in doc_commands.pages():
        for number, command in doc_commands.commands(page):
            yield f"{page.relative_to(ROOT)}:{number}", command


@pytest.fixture(scope="module")
def clone(tmp_path_factory):
    """The tracked files of the tree, as a fresh clone has them, and this venv."""
    listed = subprocess.run(
        ["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.split("\0")
    copy = tmp_path_factory.mktemp("clone")
    for name in filter(None, listed):
        if (ROOT / name).is_file():
            (copy / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / name, copy / name)
    (copy / ".venv").symlink_to(sys.prefix)
    return copy


def test_every_command_of_the_docs_runs_as_written(clone):
    failed, ran = [], 0
    for where, command in _all_commands():
        runnable = _runnable(command)
        if not runnable or any(part in runnable for part in NOT_RUN):
            continue
        ran += 1
        try:
            run = subprocess.run(
                ["bash", "-c", runnable], cwd=clone, capture_output=True, text=True, timeout=300
            )
        except subprocess.TimeoutExpired:
            failed.append(f"{where}: {command}: over 300 s")
            continue
        if run.returncode != 0:
            failed.append(f"{where}: {command}: exit {run.returncode}\n{run.stderr[-1500:]}")
    assert ran > 15
    assert failed == [], "\n".join(failed)
