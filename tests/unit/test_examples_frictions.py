"""The examples' and benchmarks' frictions stay gone: a missing FMU names the build
command of the right model (no traceback), the benchmarks name their extra, and
the legends of motor_load and propshaft_layout sit outside the data."""

import subprocess
import sys

import numpy as np
import pytest
from conftest import ROOT, load_example

BUILDS = {
    "demo": "python build_fmu.py --model UniversalJoint`",
    "driveshaft": "python build_fmu.py --model UniversalJoint`",
    "duty_cycle": "python build_fmu.py --model UniversalJoint`",
    "motor_load": "python build_fmu.py --model UniversalJoint`",
    "propshaft_layout": "python build_fmu.py --model Propshaft`",
    "seed_wikipedia": "python build_fmu.py --model UniversalJoint`",
    "seed_maker": "python build_fmu.py --model UniversalJoint`",
    "seed_tataru": "python build_fmu.py --model UniversalJoint`",
    "seed_mityushov_misyura": "python build_fmu.py --model UniversalJoint`",
}


@pytest.mark.parametrize("name", sorted(BUILDS))
def test_a_missing_fmu_names_the_build_command_of_its_model(name, tmp_path):
    example = load_example(name)
    missing = tmp_path / "dist" / "Nothing.fmu"
    with pytest.raises(SystemExit) as stop:
        example.main(["--fmu", str(missing), "--out", str(tmp_path / "out")])
    message = str(stop.value.code)
    assert message.startswith(f"{missing} does not exist"), message
    assert f"`{BUILDS[name]}" in message, message


def test_the_default_fmu_is_the_one_the_named_command_builds():
    parser = load_example("_support").example_parser("doc", model="Propshaft")
    args = parser.parse_args([])
    assert args.fmu.endswith("dist/Propshaft.fmu")
    assert "--model Propshaft" in parser.format_help()


def test_a_missing_fmu_ends_without_a_traceback(tmp_path):
    run = subprocess.run(
        [sys.executable, "examples/propshaft_layout.py", "--fmu", str(tmp_path / "P.fmu")],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=120,
    )
    assert run.returncode == 1
    assert "Traceback" not in run.stderr
    assert "`python build_fmu.py --model Propshaft`" in run.stderr


def test_benchmarks_without_mpmath_name_their_extra():
    run = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys; sys.modules['mpmath'] = None; from benchmarks.runner import main; "
            "sys.exit(main(['--quick', '--output', 'unused.md']))",
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=120,
    )
    assert run.returncode == 1, run.stdout + run.stderr
    assert "Traceback" not in run.stderr
    assert "needs mpmath" in run.stderr and "pip install -e '.[bench]'" in run.stderr
    pyproject = (ROOT / "pyproject.toml").read_text()
    assert 'bench = ["mpmath' in pyproject and "parquet,bench]" in pyproject


def _legend_overlaps(fig) -> list:
    """Axes whose legend's box overlaps the axes' data area, once laid out."""
    fig.tight_layout()
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    return [
        ax.get_ylabel()
        for ax in fig.axes
        if ax.get_legend() is not None
        and ax.get_legend().get_window_extent(renderer).overlaps(ax.get_window_extent(renderer))
    ]


def _captured(monkeypatch, module):
    figures = []
    monkeypatch.setattr(module, "save_figure", lambda fig, path, **_: figures.append(fig))
    return figures


def test_motor_load_legends_sit_outside_the_data(monkeypatch, tmp_path):
    example = load_example("motor_load")
    figures = _captured(monkeypatch, example)
    t = np.linspace(0.0, 1.0, 200)
    names = ("input_torque", "load_torque", "output_speed", "input_speed")
    rows = {"time": t, "input_angle": 60.0 * t, **{n: np.sin(9 * t) for n in names}}
    rows.update(input_yoke_moment=np.cos(9 * t), output_yoke_moment=np.sin(5 * t))
    example.plot(rows, example.DEFAULTS, tmp_path / "motor_load.png")
    assert len(figures[0].axes) == 3 and not _legend_overlaps(figures[0])


def test_propshaft_layout_legend_sits_outside_the_data(monkeypatch, tmp_path):
    example = load_example("propshaft_layout")
    figures = _captured(monkeypatch, example)
    angle = np.linspace(0.0, 4.0 * np.pi, 200)
    run = {"input_angle": angle, "output_speed": 400 + np.sin(angle), "input_torque": np.cos(angle)}
    example.plot(run, run, 1.79, tmp_path / "propshaft_layout.png")
    assert figures[0].axes[0].get_legend() is not None
    assert not _legend_overlaps(figures[0])


@pytest.mark.parametrize(
    "args, said",
    [
        (["examples/motor_load.py", "--stop-time", "-1"], "--stop-time: -1 must be a finite"),
        (["examples/demo.py", "--stop-time", "nan"], "--stop-time: nan must be a finite"),
        (["examples/driveline_ssp.py", "--drive", "Nope"], "argument --drive: invalid choice"),
        (["examples/demo.py", "--fmu", "README.md"], "README.md is not a readable FMU"),
    ],
)
def test_a_bad_argument_ends_in_one_line_and_exit_2(args, said):
    run = subprocess.run(
        [sys.executable, *args], capture_output=True, text=True, cwd=ROOT, timeout=120
    )
    assert run.returncode == 2, run.stderr
    assert "Traceback" not in run.stderr and said in run.stderr
    assert said in run.stderr.splitlines()[-1]


@pytest.mark.parametrize(
    "raised, status, said",
    [
        (KeyboardInterrupt(), 130, "interrupted"),
        (ValueError("unused"), None, None),  # a bug keeps its traceback
    ],
)
def test_an_example_interrupted_says_so_in_one_line(capsys, raised, status, said):
    run_example = load_example("_support").run_example

    def main():
        raise raised

    if status is None:
        with pytest.raises(ValueError):
            run_example(main)
        return
    assert run_example(main) == status
    assert capsys.readouterr().err.splitlines()[-1].endswith(f": {said}")
