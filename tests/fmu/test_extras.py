"""A missing optional dependency gives the extra to install, not a traceback."""

import subprocess
import sys
from pathlib import Path

import pytest

from cardan_joint.extras import MissingExtra, require

ROOT = Path(__file__).resolve().parents[2]


def test_require_names_the_module_and_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "libcosimpy", None)  # as if not installed
    with pytest.raises(MissingExtra, match=r"needs libcosimpy.*pip install -e '\.\[cosim\]'"):
        require("libcosimpy", "cosim", "running in libcosim")
    require("numpy", "core", "anything")  # installed: no error


def test_libcosim_runs_without_libcosimpy_say_which_extra(monkeypatch, tmp_path):
    from cardan_joint.host.cosim import run_libcosim, run_libcosim_ssp

    monkeypatch.setitem(sys.modules, "libcosimpy", None)
    with pytest.raises(MissingExtra, match=r"\[cosim\]"):
        run_libcosim_ssp(tmp_path / "none.ssp", 1.0, 1e-3, ["Motor.speed"])
    with pytest.raises(MissingExtra, match=r"\[cosim\]"):
        run_libcosim(tmp_path / "none.fmu", 1.0, 1e-3, {}, ["output_speed"])


def test_a_libcosim_log_level_typo_is_named():
    from cardan_joint.host.cosim import run_libcosim_ssp

    with pytest.raises(ValueError, match="log_level 'warn' is none of trace, debug"):
        run_libcosim_ssp("none.ssp", 1.0, 1e-3, ["Motor.speed"], log_level="warn")


def test_a_dask_sweep_without_dask_stops_with_the_extra(monkeypatch, fmu_path, tmp_path, capsys):
    from cardan_joint.sweep import main

    monkeypatch.setitem(sys.modules, "distributed", None)
    assert main(["--fmu", str(fmu_path), "--out", str(tmp_path)]) == 1
    assert "pip install -e '.[sweep]'" in capsys.readouterr().err
    assert not list(tmp_path.iterdir())  # stopped before any work


def test_the_driveline_example_without_host_extras_writes_the_ssp_and_names_them(tmp_path):
    # Writing the SSP needs no host package; running it names each extra it lacks.
    run = subprocess.run(
        [
            sys.executable,
            "-c",
            "import runpy, sys; sys.modules['libcosimpy'] = sys.modules['ecospy'] = None; "
            "runpy.run_path('examples/driveline_ssp.py')['main'](['--out', sys.argv[1]])",
            str(tmp_path / "out"),
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=300,
    )
    assert run.returncode == 1
    assert "Traceback" not in run.stderr, run.stderr
    for words in ("Driveline.ssp;", "pip install -e '.[cosim]'", "pip install -e '.[ecos]'"):
        assert words in run.stderr, run.stderr
    assert [p.name for p in (tmp_path / "out").iterdir()] == ["Driveline.ssp"]
