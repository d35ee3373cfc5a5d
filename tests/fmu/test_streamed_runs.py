"""Run arguments checked once for the command and the Python API, long runs
streamed to a CSV equal to the run held in memory, a ramp without its rate
refused, and the FMU's warnings one line each."""

import subprocess
import sys

import numpy as np
import pytest
from conftest import cardan_joint_here

from cardan_joint import results
from cardan_joint.host import run_arguments
from cardan_joint.host.csv_run import column_units, simulate_to_csv
from cardan_joint.host.fmu_info import FmuInfo
from cardan_joint.host.run_arguments import RunTooLargeError
from cardan_joint.host.simulate import CHUNK_ROWS, RefusalError, flat_columns, simulate
from cardan_joint.names import UsageError


def test_a_run_too_large_for_the_disk_is_refused_at_once_naming_its_size(fmu_path, tmp_path):
    run = subprocess.run(
        [sys.executable, "-m", "cardan_joint.cli", "simulate", "--fmu", str(fmu_path)]
        + ["--stop-time", "1e9", "--step", "1e-3", "--output", str(tmp_path / "huge.csv")],
        capture_output=True,
        text=True,
        timeout=120,  # answered before the first step, not after minutes of running
    )
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert "1,000,000,000,000 steps" in run.stderr and "TB as CSV" in run.stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "arguments, named",
    [
        ({"stop_time": -1.0}, "stop time -1.0 s must be a finite number > 0"),
        ({"stop_time": 1.0, "output_interval": 0.0}, "(communication step) 0.0 s must be"),
        ({"stop_time": 0.1, "output_interval": 0.2}, "at most the stop time 0.1 s"),
    ],
)
def test_simulate_refuses_what_the_command_refuses(capsys, fmu_path, tmp_path, arguments, named):
    with pytest.raises(UsageError) as error:
        simulate(fmu_path, **arguments)
    assert named in str(error.value)
    options = [f"--{k.replace('_', '-')}" for k in arguments]
    flags = {"--stop-time": "--stop-time", "--output-interval": "--step"}
    run = cardan_joint_here(
        capsys,
        "simulate",
        "--fmu",
        fmu_path,
        "--output",
        tmp_path / "x.csv",
        *[item for o, v in zip(options, arguments.values()) for item in (flags[o], str(v))],
    )
    assert run.returncode == 2 and named in run.stderr


def test_a_result_too_large_for_memory_is_refused_before_the_first_step(fmu_path, monkeypatch):
    import fmpy

    monkeypatch.setattr(run_arguments, "available_memory", lambda: 1e6)
    monkeypatch.setattr(fmpy, "simulate_fmu", lambda *a, **k: pytest.fail("the run started"))
    with pytest.raises(RunTooLargeError, match=r"10,000 steps .* MB of memory, more than the 1 MB"):
        simulate(fmu_path, stop_time=10.0, output_interval=1e-3)


# FMI 2.0 on the build without life: 8,292 steps of streaming, which life would
# make four times dearer without touching what is streamed.
@pytest.mark.parametrize("fixture", ["fmu_without_life_path", "fmi3_path"])
def test_a_streamed_run_writes_the_csv_of_the_run_held_in_memory(request, fixture, tmp_path):
    fmu = request.getfixturevalue(fixture)
    steps = 2 * CHUNK_ROWS + 100  # chunks handed over during the run, and the rest after it
    arguments = {"stop_time": steps * 1e-3, "output_interval": 1e-3, "inputs": {"input_speed": 9.0}}
    held = flat_columns(simulate(fmu, **arguments))
    units = column_units(FmuInfo.read(fmu))  # the streamed CSV titles each column with its unit
    results.write_csv(held, tmp_path / "held.csv", units=units)
    run = simulate_to_csv(fmu, tmp_path / "streamed.csv", plot_rows=1000, **arguments)
    assert run.rows == len(held) == steps + 1
    assert (tmp_path / "streamed.csv").read_bytes() == (tmp_path / "held.csv").read_bytes()
    sample = run.sample()
    assert sample["time"][0] == 0.0 and sample["time"][-1] == held["time"][-1]
    assert len(sample) <= 1001 and np.all(np.isin(sample["time"], held["time"]))
    assert np.all(np.diff(sample["time"]) >= 0)
    for name in held.dtype.names:  # every peak of the run is in the figure's rows
        assert (sample[name].min(), sample[name].max()) == (held[name].min(), held[name].max())


def test_a_streamed_refused_run_writes_the_rows_up_to_the_refusal(fmu_path, tmp_path):
    u = np.array(
        [(0.0, 0.5), (5.0, 0.5), (5.0, 1.5), (10.0, 1.5)],
        dtype=[("time", float), ("bend_angle", float)],
    )
    with pytest.raises(RefusalError) as held:
        simulate(fmu_path, stop_time=10.0, output_interval=1e-3, inputs=u)
    path = tmp_path / "refused.csv"
    with pytest.raises(RefusalError) as streamed:
        simulate_to_csv(fmu_path, path, stop_time=10.0, output_interval=1e-3, inputs=u)
    assert str(streamed.value) == str(held.value)
    expected = flat_columns(held.value.result)
    written = results.read_csv(path)
    assert len(written) == len(expected) == 5001 and written["time"][-1] == 5.0
    for name in expected.dtype.names:
        np.testing.assert_array_equal(written[name], expected[name], err_msg=name)


@pytest.mark.parametrize(
    "start, said",
    [
        ({"bend_angle": 1.5}, "stopped at its start (t = 0 s)"),  # the first step refused
        ({"crosspiece_inertia_1": -1.0}, "stopped at its start (t = 0 s)"),  # initialization
    ],
)
def test_a_run_refused_at_its_start_writes_no_file(fmu_path, tmp_path, start, said):
    path = tmp_path / "none.csv"
    with pytest.raises(RefusalError) as refused:
        simulate_to_csv(fmu_path, path, stop_time=1.0, start_values=start)
    assert said in str(refused.value)
    assert list(tmp_path.iterdir()) == []


def test_an_input_csv_ramp_without_its_rate_is_refused(capsys, fmu_path, tmp_path):
    inputs = tmp_path / "ramp.csv"
    inputs.write_text("time,input_speed\n0,10\n0.5,15\n1,15\n")
    run = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--input", inputs, "--output", tmp_path / "x.csv"
    )
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert "input_speed ramps at 10 per s from t = 0 s to 0.5 s" in run.stderr
    assert "input_acceleration is held at 0 (no input_acceleration column)" in run.stderr
    given = results.read_csv(inputs)
    with pytest.raises(UsageError, match="contradictory"):  # the Python API alike
        simulate(fmu_path, stop_time=1.0, inputs=given)
    with_rate = tmp_path / "with_rate.csv"  # the same ramp with its rate runs
    with_rate.write_text(
        "time,input_speed,input_acceleration\n0,10,10\n0.5,15,10\n0.5,15,0\n1,15,0\n"
    )
    ok = cardan_joint_here(
        capsys, "simulate", "--fmu", fmu_path, "--input", with_rate, "--output", tmp_path / "y.csv"
    )
    assert ok.returncode == 0, ok.stderr


def test_the_fmus_warnings_print_one_line_each(capsys, propshaft_fmu_path, tmp_path):
    level = [f"--set=shaft_{k}_side_angle=0" for k in range(3)]  # joints below 0.5 deg
    run = cardan_joint_here(
        capsys,
        "simulate",
        "--fmu",
        propshaft_fmu_path,
        "--stop-time",
        "0.05",
        "--output",
        tmp_path / "w.csv",
        *level,
    )
    assert run.returncode == 0, run.stderr
    lines = run.stderr.splitlines()
    assert lines == [
        f"cardan-joint simulate: warning: Propshaft: joint {k} working angle 0.000 deg is below "
        "0.5 deg: its needle bearings do not rotate (Spicer rule 1)"
        for k in (1, 2)
    ]


def _earlier_sweep(folder):
    """An earlier sweep's files in `folder`: what a refused or failed sweep must keep."""
    earlier = {folder / "sweep.csv": b"earlier table\n", folder / "sweep.png": b"earlier figure"}
    for path, content in earlier.items():
        path.write_bytes(content)
    return earlier


def _serial_sweep(capsys, fmu_path, folder, *args):
    """`cardan-joint sweep --serial` at 1000 rpm into `folder`, with `args`."""
    return cardan_joint_here(
        capsys,
        "sweep",
        "--serial",
        "--fmu",
        fmu_path,
        "--speeds",
        "1000",
        "--out",
        folder,
        "--no-progress",
        *args,
    )


def test_a_value_out_of_the_joints_range_is_refused_before_any_case(capsys, fmu_path, tmp_path):
    earlier = _earlier_sweep(tmp_path)
    run = _serial_sweep(capsys, fmu_path, tmp_path, "--bend-angles", "10", "100")
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert "case 100 deg, 1000 rpm, T1 (--bend-angles)" in run.stderr
    assert "max_bend_angle" in run.stderr and "no case was run" in run.stderr
    assert "co-simulations" not in run.stdout  # refused before the sweep began
    assert {p: p.read_bytes() for p in earlier} == earlier
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sweep.csv", "sweep.png"]


def test_a_sweep_whose_every_case_failed_keeps_the_earlier_files(
    capsys, fmu_path, tmp_path, monkeypatch
):
    from cardan_joint.sweep import case

    def failing(*args):
        raise RuntimeError("the co-simulation broke")

    monkeypatch.setattr(case, "cosimulate", failing)
    earlier = _earlier_sweep(tmp_path)
    run = _serial_sweep(capsys, fmu_path, tmp_path, "--bend-angles", "5", "--distributions", "T1")
    assert run.returncode == 1 and "Traceback" not in run.stderr
    assert "every case failed, no table or figure written: 1 failed (5 deg, 1000 rpm, T1)" in (
        run.stderr
    )
    assert {p: p.read_bytes() for p in earlier} == earlier


def test_a_sweep_refuses_an_fmu_without_its_variables(capsys, propshaft_fmu_path, tmp_path):
    run = cardan_joint_here(
        capsys, "sweep", "--serial", "--fmu", propshaft_fmu_path, "--out", tmp_path
    )
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert "(Propshaft) lacks what the sweep sets and reads: inputs bend_angle" in run.stderr
    assert list(tmp_path.iterdir()) == []


def test_the_python_sweep_refuses_an_fmu_without_its_variables(propshaft_fmu_path):
    from cardan_joint import sweep

    spec = sweep.SweepSpec(bend_angles_deg=(5.0,), input_speeds_rpm=(1000.0,))
    with pytest.raises(UsageError, match=r"\(Propshaft\) lacks what the sweep sets and reads"):
        sweep.run_serial(propshaft_fmu_path, spec, progress=False)


def test_a_sweep_into_a_log_draws_no_progress_bar(capsys, fmu_path, tmp_path):
    args = ("sweep", "--serial", "--fmu", fmu_path, "--speeds", "1000", "--bend-angles", "5")
    quiet = cardan_joint_here(capsys, *args, "--distributions", "T1", "--out", tmp_path)
    assert quiet.returncode == 0 and "case/s" not in quiet.stderr  # not a terminal: no bar
    drawn = cardan_joint_here(capsys, *args, "--out", tmp_path / "again", "--progress")
    assert drawn.returncode == 0 and "case/s" in drawn.stderr
