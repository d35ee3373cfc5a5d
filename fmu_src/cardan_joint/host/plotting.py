"""One plotting style for the examples and the command line.

Variables are plotted in their display units (the FMU's displayUnit: deg, rpm,
rpm/s, ...), so a figure from `cardan-joint simulate` reads like the examples'.
"""

from collections.abc import Callable, Sequence
from pathlib import Path


def pyplot():
    """matplotlib.pyplot on the file-only Agg backend, with the project's style."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams.update(
        {"axes.grid": True, "grid.alpha": 0.3, "legend.fontsize": 8, "legend.framealpha": 0.9}
    )
    return plt


def save_figure(fig, path, dpi=110) -> Path:
    """Lay out, write and close a figure (its folder created); returns the path."""
    import matplotlib.pyplot as plt

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def plot_time_series(
    result, names: Sequence[str], path, title: str, display: Callable[[str], tuple[float, str]]
) -> Path:
    """One panel per variable over time, in display units; `display(name)` gives
    (factor, unit), e.g. `FmuInfo.display`: SI value * factor is the plotted value."""
    plt = pyplot()
    fig, axes = plt.subplots(
        len(names), 1, figsize=(9, 1.2 + 1.4 * len(names)), sharex=True, squeeze=False
    )
    for ax, name in zip(axes[:, 0], names):
        factor, unit = display(name)
        ax.plot(result["time"], result[name] * factor, lw=0.9)
        ax.set_ylabel(f"{name}\n[{unit}]", fontsize=8)
    axes[0, 0].set_title(title, fontsize=9)
    axes[-1, 0].set_xlabel("time [s]")
    return save_figure(fig, path, dpi=100)
