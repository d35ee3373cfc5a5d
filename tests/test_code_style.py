"""The habits the next engineer expects: ruff (lint and format) and mypy pass,
with the settings in pyproject.toml, on the whole tree."""

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize(
    "command",
    [
        ("ruff", "check", "."),
        ("ruff", "format", "--check", "."),
        # mypy's files and options come from pyproject.toml; its cache keeps a rerun fast.
        ("mypy",),
    ],
    ids=["ruff-check", "ruff-format", "mypy"],
)
def test_tool_passes(command):
    run = subprocess.run([sys.executable, "-m", *command], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, (
        f"`{' '.join(command)}` failed ({run.returncode}):\n{run.stdout}{run.stderr}"
    )
