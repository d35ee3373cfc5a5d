"""The figure of `cardan-joint simulate` (host/run_plot.py): panels by unit and
magnitude, constants drawn flat, legends beside the data, a title saying what ran."""

import numpy as np
import pytest

from cardan_joint.host import run_plot

UNITS = {"angle": "deg", "error": "deg", "speed": "rpm", "ratio": "1", "noise": "1", "zero": "deg"}


def _result(rows=200):
    t = np.linspace(0.0, 1.0, rows)
    columns = {
        "time": t,
        "angle": 600.0 * t,  # accumulates: thousands of degrees
        "error": 1.3 * np.sin(12 * t),  # a degree: its own panel
        "speed": 190 + 10 * np.sin(12 * t),
        "ratio": 1.0 + 0.05 * np.sin(12 * t),
        "noise": 3.3e-16 * np.sin(40 * t),  # rounding noise around zero
        "zero": np.zeros(rows),
    }
    data = np.zeros(rows, dtype=[(name, float) for name in columns])
    for name, values in columns.items():
        data[name] = values
    return data


def test_outputs_are_grouped_by_unit_and_magnitude():
    groups = run_plot.panels(_result(), list(UNITS), UNITS.__getitem__)
    # A ratio and rounding noise share a unit ("1") but are not one quantity.
    assert groups == [["angle", "zero"], ["error"], ["speed"], ["ratio"], ["noise"]]


def test_unitless_variables_share_a_panel_by_family_only():
    names = ["speed_ratio", "quaternion_0", "quaternion_1", "life_consumed"]
    rows = 50
    data = np.zeros(rows, dtype=[("time", float)] + [(n, float) for n in names])
    for k, name in enumerate(names):
        data[name] = np.sin(np.linspace(0, 3, rows) + k)
    groups = run_plot.panels(data, names, lambda name: "1")
    assert groups == [["speed_ratio"], ["quaternion_0", "quaternion_1"], ["life_consumed"]]
    assert run_plot.axis_label(groups[1], "1") == "quaternion_0..1 [1]"
    assert run_plot.axis_label(["output_speed"], "rpm") == "output_speed [rpm]"


def test_a_near_constant_is_called_by_its_range_not_zero(monkeypatch, tmp_path):
    figures = []
    monkeypatch.setattr(run_plot, "save_figure", lambda fig, path, dpi: figures.append(fig))
    data = _result()
    data["noise"] = np.linspace(0.0, 5.6e-13, len(data))  # a life fraction, rising
    run_plot.plot_run(data, ["noise", "zero"], tmp_path / "x.png", "title", lambda n: (1.0, "1"))
    texts = [
        t.get_text() for ax in figures[0].axes if ax.lines for t in ax.get_legend().get_texts()
    ]
    assert texts == ["noise from 0 to 5.6e-13 (flat at this scale)", "zero = 0 (constant)"]


def test_a_long_run_is_drawn_as_its_envelope_per_pixel_column(monkeypatch, tmp_path):
    figures = []
    monkeypatch.setattr(run_plot, "save_figure", lambda fig, path, dpi: figures.append(fig))
    short, long = _result(200), _result(20_000)
    for data in (short, long):
        run_plot.plot_run(data, ["error"], tmp_path / "x.png", "t", lambda n: (1.0, "deg"))
    (drawn,), (shaded,) = ([a for a in fig.axes if a.has_data()] for fig in figures)
    assert len(drawn.lines) == 1 and not drawn.collections  # a line through every row
    assert not shaded.lines and len(shaded.collections) == 1  # the envelope
    assert "least to greatest value in each pixel column" in figures[1]._suptitle.get_text()
    time, low, high = run_plot.envelope(long["time"], long["error"], 100)
    assert len(time) == 100 and np.all(low <= high)
    assert low.min() == long["error"].min() and high.max() == long["error"].max()
    column = (long["time"] >= time[3]) & (long["time"] < time[4])
    assert (low[3], high[3]) == (long["error"][column].min(), long["error"][column].max())


def test_rounding_noise_is_a_constant_and_reads_as_zero():
    data = _result()
    assert run_plot.is_constant(data["noise"]) and run_plot.is_constant(data["zero"])
    assert not run_plot.is_constant(data["ratio"]) and not run_plot.is_constant(data["error"])
    assert run_plot.constant_value(data["noise"]) == 0.0
    assert run_plot.is_constant(np.full(5, 1e5) + np.array([0, 1e-11, 0, -1e-11, 0]))


def test_a_panel_of_constants_is_centred_on_them_not_on_noise(monkeypatch, tmp_path):
    figures = []
    monkeypatch.setattr(run_plot, "save_figure", lambda fig, path, dpi: figures.append(fig))
    run_plot.plot_run(_result(), ["noise"], tmp_path / "x.png", "title", lambda n: (1.0, "1"))
    (ax,) = [a for a in figures[0].axes if a.get_visible() and a.lines]
    low, high = ax.get_ylim()
    assert low < 0 < high and high - low > 1.0  # not a 1e-16 wide axis
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "noise from -3.3e-16 to 3.3e-16 (flat at this scale)"
    ]


def test_every_legend_sits_beside_its_panel(monkeypatch, tmp_path):
    figures = []
    monkeypatch.setattr(run_plot, "save_figure", lambda fig, path, dpi: figures.append(fig))
    display = {name: (1.0, unit) for name, unit in UNITS.items()}
    run_plot.plot_run(_result(), list(UNITS), tmp_path / "x.png", "t", display.__getitem__)
    fig = figures[0]
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    used = [ax for ax in fig.axes if ax.lines]
    assert len(used) == 5
    for ax in used:
        legend = ax.get_legend().get_window_extent(renderer)
        assert legend.x0 >= ax.get_window_extent(renderer).x1  # right of the data, never on it


def test_the_title_names_model_version_inputs_and_refusal():
    title = run_plot.run_title(
        "UniversalJoint",
        "2.0",
        {"input_speed": "= 20 rad/s", "bend_angle, bend_angle_rate": "from ramp.csv"},
        "refused after 39 of 100 steps of 0.01 s (t = 0.39 s)",
        "Refused: input bend_angle reaches 1.4 rad",
    )
    assert title.startswith("UniversalJoint (FMI 2.0), refused after 39 of 100 steps")
    flowing = title
    assert "input_speed = 20 rad/s; bend_angle, bend_angle_rate from ramp.csv" in flowing
    assert title.splitlines()[-1] == "Refused: input bend_angle reaches 1.4 rad"


@pytest.mark.parametrize("count, columns", [(3, 1), (4, 1), (5, 2), (8, 2)])
def test_more_than_four_panels_go_in_two_columns(monkeypatch, tmp_path, count, columns):
    figures = []
    monkeypatch.setattr(run_plot, "save_figure", lambda fig, path, dpi: figures.append(fig))
    data = _result()
    names = [f"s{k}" for k in range(count)]  # each its own unit: a panel each
    rows = np.zeros(len(data), dtype=[("time", float)] + [(n, float) for n in names])
    rows["time"] = data["time"]
    for name in names:
        rows[name] = data["speed"]
    run_plot.plot_run(rows, names, tmp_path / "x.png", "t", lambda n: (1.0, n))
    width = figures[0].get_size_inches()[0]
    assert width == pytest.approx(7.2 * columns)
    labelled = [ax for ax in figures[0].axes if ax.get_xlabel() == "time [s]"]
    assert len(labelled) == columns


@pytest.mark.parametrize("count", [3, 8])  # one column, two
def test_every_label_title_and_legend_lies_inside_the_image(monkeypatch, tmp_path, count):
    """Panels in one or two columns, a long title: nothing clipped, nothing overlapping."""
    from cardan_joint.host import plotting

    figures = []

    def keep(fig, path, dpi):
        fig.tight_layout()  # as save_figure lays it out
        fig.canvas.draw()
        figures.append((fig, fig.canvas.get_renderer()))
        return plotting.save_figure(fig, path, dpi)

    monkeypatch.setattr(run_plot, "save_figure", keep)
    data = _result()
    names = [f"a_rather_long_variable_name_{k}" for k in range(count)]
    rows = np.zeros(len(data), dtype=[("time", float)] + [(n, float) for n in names])
    rows["time"] = data["time"]
    for k, name in enumerate(names):
        rows[name] = data["speed"] * 100.0**k  # a panel each
    title = run_plot.run_title(
        "Model", "3.0", {n: "= 1 rad/s" for n in names}, "10 steps", "x" * 150
    )
    path = run_plot.plot_run(rows, names, tmp_path / "x.png", title, lambda n: (1.0, "rad/s"))
    assert path.stat().st_size > 0
    fig, renderer = figures[0]
    inside = fig.bbox
    texts = [fig._suptitle] + [
        artist
        for ax in fig.axes
        if ax.get_visible() and ax.lines
        for artist in (ax.yaxis.label, ax.xaxis.label, ax.get_legend(), *ax.get_yticklabels())
        if artist is not None
        and artist.get_visible()
        and getattr(artist, "get_text", lambda: "x")()
    ]
    for artist in texts:
        box = artist.get_window_extent(renderer)
        assert inside.x0 - 1 <= box.x0 and box.x1 <= inside.x1 + 1, artist
        assert inside.y0 - 1 <= box.y0 and box.y1 <= inside.y1 + 1, artist
    used = [ax for ax in fig.axes if ax.lines]
    title_bottom = fig._suptitle.get_window_extent(renderer).y0
    assert all(ax.get_window_extent(renderer).y1 <= title_bottom for ax in used)  # no overlap
    legends = [ax.get_legend().get_window_extent(renderer) for ax in used]
    frames = [ax.get_window_extent(renderer) for ax in used]
    for legend in legends:
        assert not any(legend.overlaps(frame) for frame in frames)
