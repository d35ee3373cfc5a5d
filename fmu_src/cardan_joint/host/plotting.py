"""One plotting style for the examples and the command line.

Variables are plotted in their display units (the FMU's displayUnit: deg, rpm,
rpm/s, ...), so a figure from `cardan-joint simulate` reads like the examples'.
"""

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
    """Lay out, write and close a figure (its folder created); returns the path.
    The image is written whole or not at all (a temporary file, renamed)."""
    import matplotlib.pyplot as plt

    from ..results import replaced_whole

    path = Path(path)
    try:
        fig.tight_layout()
        with replaced_whole(path) as temporary:
            fig.savefig(temporary, dpi=dpi, format=path.suffix[1:] or "png")
    finally:
        plt.close(fig)
    return path
