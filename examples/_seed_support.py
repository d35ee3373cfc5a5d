"""Plumbing shared by the seed examples (examples/seed_*.py): command line, CSV, figures.

Every plotted number comes from co-simulating the FMU (`run`); the seeds'
formulas appear only as reference marks drawn over the FMU's curves.
"""

from pathlib import Path

import numpy as np
from _support import example_fmu, example_parser, output_folder

from cardan_joint import results
from cardan_joint.host.plotting import pyplot, save_figure  # noqa: F401 - pyplot: for the seed scripts
from cardan_joint.host.simulate import simulate

# Dark enough on white for thin lines, distinct for up to six bend angles.
COLORS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown")


def parse_args(doc, argv):
    parser = example_parser(doc, str(Path("results") / "seeds"))
    parser.add_argument(
        "--quick", action="store_true", help="coarse sampling and fewer runs (for the tests)"
    )
    args = parser.parse_args(argv)
    args.fmu = example_fmu(args)
    args.out = output_folder(args)
    return args


def run(fmu, stop_time, output_interval, output=None, **start_values):
    """One co-simulation of the FMU (a fresh instance) with constant inputs and parameters.

    `output`: the variables to record (FMPy's default: all outputs); inputs can be
    recorded too, and read back as the FMU holds them.
    """
    return simulate(
        fmu,
        stop_time=stop_time,
        output_interval=output_interval,
        start_values=start_values,
        output=output,
    )


class Outputs:
    """Writes the figures and their data, and remembers what it wrote for the summary."""

    def __init__(self, folder: Path):
        self.folder = folder
        self.paths = []

    def csv(self, name, columns: dict):
        # Round-trip precision: the tests check the seeds' numbers to 1e-9 from these files.
        path = results.write_csv(columns, self.folder / f"{name}.csv")
        self.paths.append(path)
        return path

    def figure(self, name, fig):
        path = save_figure(fig, self.folder / f"{name}.png", dpi=100)
        self.paths.append(path)
        return path

    def report(self):
        for path in self.paths:
            print(f"wrote {path}")


def parabola_peak(x, y):
    """Abscissa and height of the sampled maximum, refined through its two neighbours."""
    k = int(np.clip(np.argmax(y), 1, len(y) - 2))
    (x0, x1, _), (y0, y1, y2) = x[k - 1 : k + 2], y[k - 1 : k + 2]
    curvature = y0 - 2 * y1 + y2
    shift = 0.5 * (y0 - y2) / curvature if curvature else 0.0
    return x1 + shift * (x1 - x0), y1 - 0.25 * (y0 - y2) * shift
