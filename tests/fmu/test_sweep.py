"""Design sweeps: Dask and serial runs agree exactly; failures are reported."""

import math

import pytest

from cardan_joint import sweep

TINY = sweep.SweepSpec(
    bend_angles_deg=(10.0, 85.0),
    input_speeds_rpm=(1000.0, 3000.0),
    distributions=("T1", "T2"),
    revolutions=1,
    steps_per_revolution=72,
)


@pytest.fixture(scope="module")
def client():
    with sweep.connect(None, n_workers=2) as (client, _, _):
        yield client


@pytest.fixture(scope="module")
def serial(fmu_path):
    return sweep.run_serial(fmu_path, TINY, progress=False)


def test_dask_and_serial_tables_are_identical(client, fmu_path, serial):
    import pandas as pd

    assert len(client.scheduler_info()["workers"]) == 2
    on_dask = sweep.run_dask(fmu_path, TINY, client, progress=False)
    pd.testing.assert_frame_equal(on_dask, serial, check_exact=True)


def test_every_case_has_a_row_in_the_specs_order(serial):
    assert len(serial) == 8
    assert list(serial["inertia_distribution"][:2]) == ["T1", "T2"]
    assert list(serial["bend_angle_deg"]) == sorted(serial["bend_angle_deg"])


def test_a_bend_beyond_the_guard_is_reported_failed_with_the_fmus_message(serial):
    failed = serial[serial["bend_angle_deg"] == 85.0]
    assert len(failed) == 4
    assert (failed["status"] == sweep.FAILED).all()
    for message in failed["message"]:
        assert "bend_angle" in message and "max_bend_angle" in message
    assert failed["peak_output_acceleration"].isna().all()


def test_successful_cases_carry_the_joints_numbers(serial):
    ok = serial[serial["status"] == sweep.OK]
    assert len(ok) == 4 and (ok["message"] == "").all()
    beta = math.radians(10)
    # Sampled every 5 deg, the speed's extremes (pin in and normal to the bend
    # plane) are hit: the fluctuation is the single joint's tan b sin b.
    assert ok["speed_fluctuation"].to_numpy() == pytest.approx(
        math.tan(beta) * math.sin(beta), rel=1e-9
    )
    # Output acceleration does not depend on the crosspiece; its torque does.
    t1, t2 = ok[ok["inertia_distribution"] == "T1"], ok[ok["inertia_distribution"] == "T2"]
    assert t1["peak_output_acceleration"].to_numpy() == pytest.approx(
        t2["peak_output_acceleration"].to_numpy(), rel=1e-12
    )
    assert (
        t1["peak_crosspiece_torque"].to_numpy() != t2["peak_crosspiece_torque"].to_numpy()
    ).all()
    assert list(ok["beyond_acceleration_limit"]) == list(ok["peak_output_acceleration"] > 1000.0)


def test_a_missing_fmu_fails_the_tasks_cases_with_a_message(tmp_path):
    rows = sweep.run_task(str(tmp_path / "missing.fmu"), TINY, TINY.tasks()[0])
    assert [r["status"] for r in rows] == [sweep.FAILED] * 2
    assert "not found" in rows[0]["message"]


def test_table_and_heatmap_are_written(serial, tmp_path):
    written = sweep.write_table(serial, tmp_path / "tiny")
    assert written[0].name == "tiny.csv" and written[0].stat().st_size > 0
    sweep.plot_heatmaps(serial, TINY, tmp_path / "tiny.png")
    assert (tmp_path / "tiny.png").stat().st_size > 0


def test_cell_edges_lie_halfway_between_uneven_grid_values():
    np = pytest.importorskip("numpy")
    assert sweep.cell_edges([1, 2, 3, 4, 6, 8, 30]).tolist() == [0.5, 1.5, 2.5, 3.5, 5, 7, 19, 41]
    assert sweep.cell_edges([10]).tolist() == [9.5, 10.5]
    assert np.all(np.diff(sweep.cell_edges([500, 1000, 4000])) > 0)


def test_the_heatmap_spaces_an_uneven_bend_axis_truthfully(monkeypatch, tmp_path):
    """Each cell spans its bend angle's true interval on a linear degree axis."""
    from matplotlib.collections import QuadMesh

    uneven = sweep.SweepSpec(
        bend_angles_deg=(1.0, 2.0, 10.0), input_speeds_rpm=(1000.0,), distributions=("T1",)
    )
    table = sweep.to_table(
        [
            {
                "bend_angle_deg": b,
                "input_speed_rpm": 1000.0,
                "inertia_distribution": "T1",
                "status": "ok",
                "peak_output_acceleration": 10.0 * b,
                "peak_crosspiece_torque": b,
            }
            for b in (1.0, 2.0, 10.0)
        ],
        uneven,
    )
    figures = []
    monkeypatch.setattr(sweep.heatmap, "save_figure", lambda fig, path, dpi: figures.append(fig))
    sweep.plot_heatmaps(table, uneven, tmp_path / "uneven.png")
    mesh = next(c for c in figures[0].axes[0].collections if isinstance(c, QuadMesh))
    assert mesh.get_coordinates()[0, :, 0].tolist() == [0.5, 1.5, 6.0, 14.0]


def _legend_texts(table, spec, monkeypatch, tmp_path):
    figures = []
    monkeypatch.setattr(sweep.heatmap, "save_figure", lambda fig, path, dpi: figures.append(fig))
    sweep.plot_heatmaps(table, spec, tmp_path / "legend.png")
    fig = figures[0]
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend()] + fig.legends
    return [text.get_text() for legend in legends for text in legend.get_texts()]


def test_the_heatmap_legend_lists_only_what_is_drawn(serial, monkeypatch, tmp_path):
    both = _legend_texts(serial, TINY, monkeypatch, tmp_path)  # 85 deg failed
    assert any(text.startswith("failed run") for text in both)
    one = sweep.SweepSpec(
        bend_angles_deg=(10.0,), input_speeds_rpm=(1000.0,), distributions=("T1", "T2")
    )
    clean = serial[(serial["bend_angle_deg"] == 10.0) & (serial["input_speed_rpm"] == 1000.0)]
    assert (clean["status"] == sweep.OK).all()
    texts = _legend_texts(clean, one, monkeypatch, tmp_path)
    assert not any(text.startswith("failed run") for text in texts)
