"""The sweep's figure: peaks over bend angle x input speed, one panel per quantity.

Cells are drawn with pcolormesh between edges halfway between neighbouring grid
values, so an uneven axis (1, 2, 3, 4, 6, 8 ... 30 deg) is spaced truthfully.
"""

import math
from pathlib import Path

import numpy as np

from ..host.plotting import pyplot, save_figure
from .spec import ACCELERATION_LIMIT, SweepSpec

HATCH_COLOR, FAILED_COLOR = "0.55", "0.75"  # seen on dark and light cells


def cell_edges(values) -> np.ndarray:
    """Edges of the cells centred on sorted grid values: midpoints inside,
    half a neighbouring gap outside (a lone value gets a cell of width 1)."""
    centres = np.asarray(values, dtype=float)
    if len(centres) == 1:
        return centres[0] + np.array([-0.5, 0.5])
    middles = 0.5 * (centres[1:] + centres[:-1])
    return np.concatenate([[2 * centres[0] - middles[0]], middles, [2 * centres[-1] - middles[-1]]])


def _grid(table, distribution, column, bends, speeds):
    values = np.full((len(speeds), len(bends)), np.nan)
    rows = table[table["inertia_distribution"] == distribution]
    for bend, speed, value in zip(rows["bend_angle_deg"], rows["input_speed_rpm"], rows[column]):
        values[speeds.index(speed), bends.index(bend)] = value
    return values


def _log_norm(values):
    from matplotlib.colors import LogNorm

    positive = values[np.isfinite(values) & (values > 0)]
    return LogNorm(positive.min(), positive.max()) if positive.size else None


def _mark(ax, mask, x, y, **style):
    from matplotlib.patches import Rectangle

    for i, j in zip(*np.nonzero(mask)):
        ax.add_patch(Rectangle((x[j], y[i]), x[j + 1] - x[j], y[i + 1] - y[i], **style))


def plot_heatmaps(table, spec: SweepSpec, path) -> Path:
    """Peak output acceleration and peak crosspiece torque over bend x speed,
    hatched where the output acceleration exceeds ACCELERATION_LIMIT."""
    from matplotlib.patches import Patch

    plt = pyplot()
    bends, speeds = sorted(set(spec.bend_angles_deg)), sorted(set(spec.input_speeds_rpm))
    x, y = cell_edges(bends), cell_edges(speeds)
    first = spec.distributions[0]
    acceleration = _grid(table, first, "peak_output_acceleration", bends, speeds)
    panels = [
        (
            "peak output acceleration [rad/s$^2$]\n(any inertia distribution)",
            acceleration,
            "viridis",
        )
    ]
    panels += [
        (
            f"peak crosspiece torque |M| [N.m], {name}",
            _grid(table, name, "peak_crosspiece_torque", bends, speeds),
            "magma",
        )
        for name in spec.distributions
    ]
    torque_norm = _log_norm(np.concatenate([p[1].ravel() for p in panels[1:]]))

    columns = 3 if len(panels) > 4 else len(panels)
    fig, axes = plt.subplots(
        math.ceil(len(panels) / columns),
        columns,
        squeeze=False,
        figsize=(5.2 * columns, 4.2 * math.ceil(len(panels) / columns)),
    )
    for k, (ax, (title, values, cmap)) in enumerate(zip(axes.flat, panels)):
        mesh = ax.pcolormesh(
            x,
            y,
            np.ma.masked_invalid(values),
            cmap=cmap,
            norm=_log_norm(values) if k == 0 else torque_norm,
        )
        fig.colorbar(mesh, ax=ax, shrink=0.9)
        _mark(
            ax,
            acceleration > ACCELERATION_LIMIT,
            x,
            y,
            fill=False,
            hatch="///",
            edgecolor=HATCH_COLOR,
            linewidth=0,
        )
        _mark(ax, np.isnan(acceleration), x, y, color=FAILED_COLOR)
        ax.set_xticks(bends, [f"{b:g}" for b in bends], fontsize=8)
        ax.set_yticks(speeds, [f"{s:g}" for s in speeds], fontsize=8)
        ax.set_xlabel("bend angle [deg]")
        ax.set_ylabel("input speed [rpm]")
        ax.set_title(title, fontsize=9)
        ax.grid(False)
    # The legend explains what is drawn, and nothing that is not.
    handles = []
    if (acceleration > ACCELERATION_LIMIT).any():
        handles.append(
            Patch(
                facecolor="none",
                edgecolor=HATCH_COLOR,
                hatch="///",
                label=f"output acceleration > {ACCELERATION_LIMIT:g} rad/s$^2$\n"
                "(beyond the usual driveline limit)",
            )
        )
    if np.isnan(acceleration).any():
        handles.append(Patch(color=FAILED_COLOR, label="failed run (see the table's message)"))
    spare = list(axes.flat[len(panels) :])
    for ax in spare:
        ax.axis("off")
    if spare and handles:
        spare[0].legend(handles=handles, loc="center", fontsize=9, frameon=False)
    elif handles:
        fig.legend(handles=handles, loc="lower center", ncol=2, fontsize=8)
    fig.suptitle(
        f"Cardan joint design sweep: I0 = {spec.total_inertia:g} kg.m$^2$, "
        f"load {spec.load_torque:g} N.m, constant speed and bend",
        fontsize=11,
    )
    return save_figure(fig, path, dpi=100)
