"""The figure of one run (`cardan-joint simulate`): a few panels, one per
quantity, each variable in its display unit, and a title saying what ran.

Variables share a panel when they share a display unit and a magnitude (an
accumulated angle of thousands of degrees does not flatten a cardan error of
a tenth of one). A variable that does not change, beyond rounding, is drawn
flat at its value and its legend entry says so: autoscaling would blow 1e-15
of rounding noise up to fill the panel. Legends sit beside their panel, never
on the data.
"""

import math
import textwrap
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import numpy as np

from .plotting import pyplot, save_figure

# Peaks further apart than this factor go to separate panels of the same unit.
MAGNITUDE_RATIO = 30.0
# A change below this fraction of a variable's size (SI, at least 1) is rounding.
ROUNDING = 1e-9
# Characters of the 9-point title per inch of figure width (measured: about
# 8 px a character at 100 dpi, with a margin).
TITLE_CHARACTERS_PER_INCH = 11.5


def is_constant(values: np.ndarray) -> bool:
    """No change beyond rounding (NaN-free values, SI units)."""
    finite = values[np.isfinite(values)]
    if not finite.size:
        return True
    return float(np.ptp(finite)) <= ROUNDING * max(float(np.abs(finite).max()), 1.0)


def constant_value(values: np.ndarray) -> float:
    """A constant variable's value (SI), rounding noise around zero read as zero."""
    finite = values[np.isfinite(values)]
    value = float(np.mean(finite)) if finite.size else math.nan
    return 0.0 if abs(value) <= ROUNDING else value


def panels(result, names: Sequence[str], unit_of: Callable[[str], str]) -> list[list[str]]:
    """`names` grouped by display unit (first appearance first), each unit's
    varying variables split where their peaks differ by more than MAGNITUDE_RATIO;
    a constant joins its unit's first panel."""
    by_unit: dict[str, list[str]] = {}
    for name in names:
        by_unit.setdefault(unit_of(name), []).append(name)
    groups: list[list[str]] = []
    for members in by_unit.values():
        varying = [n for n in members if not is_constant(result[n])]
        peak = {n: float(np.nanmax(np.abs(result[n]))) for n in varying}
        split: list[list[str]] = []
        for name in sorted(varying, key=lambda n: -peak[n]):
            if split and peak[split[-1][0]] <= MAGNITUDE_RATIO * max(peak[name], 1e-300):
                split[-1].append(name)
            else:
                split.append([name])
        constants = [n for n in members if n not in peak]
        if constants:
            split = [constants] if not split else [split[0] + constants] + split[1:]
        # Each panel in the order the variables were named.
        groups += [sorted(group, key=members.index) for group in split]
    return groups


def run_title(
    model: str,
    fmi_version: str,
    inputs: Mapping[str, str],
    length_text: str,
    refusal: str | None = None,
) -> str:
    """'<model> (FMI x), <length>. Inputs: ...', and the refusal on a line of its own
    (`plot_run` wraps the lines to the figure's width)."""
    given = "; ".join(f"{name} {how}" for name, how in inputs.items()) or "start values"
    text = f"{model} (FMI {fmi_version}), {length_text}. Inputs: {given}"
    return f"{text}\n{refusal}" if refusal else text


def plot_run(
    result,
    names: Sequence[str],
    path,
    title: str,
    display: Callable[[str], tuple[float, str]],
) -> Path:
    """The run's figure: `names` over time in display units (`display(name)`:
    (factor, unit), SI value * factor is the plotted value), grouped by `panels`."""
    plt = pyplot()
    groups = panels(result, names, lambda name: display(name)[1])
    columns = 2 if len(groups) > 4 else 1
    rows = math.ceil(len(groups) / columns)
    width = 7.2 * columns
    title = "\n".join(
        wrapped
        for line in title.splitlines()
        for wrapped in textwrap.wrap(line, int(width * TITLE_CHARACTERS_PER_INCH))
    )
    fig, axes = plt.subplots(
        rows,
        columns,
        figsize=(width, 1.0 + 0.18 * title.count("\n") + 2.1 * rows),
        sharex=True,
        squeeze=False,
    )
    for ax, group in zip(axes.flat, groups):
        unit = display(group[0])[1]
        flat = []
        for name in group:
            factor = display(name)[0]
            values = result[name] * factor
            if is_constant(result[name]):
                value = constant_value(result[name]) * factor
                ax.plot(
                    result["time"],
                    np.full(len(values), value),
                    lw=1.2,
                    ls="--",
                    label=f"{name} = {value:.6g} (constant)",
                )
                flat.append(value)
            else:
                ax.plot(result["time"], values, lw=0.9, label=name)
        if len(flat) == len(group):  # only constants: centre them, not rounding noise
            middle, size = float(np.mean(flat)), max(abs(v) for v in flat)
            half = max(0.05 * size, float(np.ptp(flat))) or 1.0
            ax.set_ylim(middle - 1.2 * half, middle + 1.2 * half)
            ax.ticklabel_format(axis="y", useOffset=False)
        ax.set_ylabel(f"[{unit}]", fontsize=9)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7.5, borderaxespad=0)
    for ax in axes.flat[len(groups) :]:
        ax.axis("off")
    for column in range(columns):  # the lowest panel of each column carries the time axis
        lowest = max(r for r in range(rows) if r * columns + column < len(groups))
        axes[lowest, column].set_xlabel("time [s]")
        axes[lowest, column].xaxis.set_tick_params(labelbottom=True)
    fig.suptitle(title, fontsize=9, ha="left", x=0.01)
    return save_figure(fig, path, dpi=100)
