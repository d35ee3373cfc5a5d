"""The figure of one run (`cardan-joint simulate`): a few panels, one per
quantity, each variable in its display unit, and a title saying what ran.

Variables share a panel when they are the same quantity: the same display
unit and a magnitude (an accumulated angle of thousands of degrees does not
flatten a cardan error of a tenth of one); a unitless variable shares only
with its own family (a quaternion's four components), never a speed ratio
with a quaternion or a life fraction. Each axis is labelled with its variables
and unit. A variable that does not change, beyond rounding, is drawn flat and
its legend entry gives its value, or its range when it moves at all (a life
fraction rising to 5.6e-13 is not "0"): autoscaling would blow 1e-15 of
rounding noise up to fill the panel. A long run, more rows than the panel has
pixel columns, is drawn as its envelope, the least and greatest value in each
column, not as a band of overdrawn lines. Legends sit beside their panel,
never on the data.
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
# Units of a number without dimension: their variables share a panel by family only.
UNITLESS = ("", "1")
# Characters per line of an axis label (a 2.1 inch panel holds about 30 at 9 points).
LABEL_CHARACTERS = 30


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


def flat_label(name: str, values: np.ndarray) -> str:
    """The legend of a variable drawn flat (display units): its value when it
    never changes, else the range it moves in."""
    finite = values[np.isfinite(values)]
    if not finite.size:
        return f"{name} (no finite value)"
    low, high = float(finite.min()), float(finite.max())
    if low == high:
        return f"{name} = {low:.6g} (constant)"
    return f"{name} from {low:.3g} to {high:.3g} (flat at this scale)"


def envelope(time: np.ndarray, values: np.ndarray, columns: int):
    """(time, least, greatest) of `values` in each of `columns` equal spans of
    `time` (sorted): what a pixel column of the panel shows of them."""
    edges = np.linspace(time[0], time[-1], columns + 1)
    column = np.clip(np.searchsorted(edges, time, side="right") - 1, 0, columns - 1)
    starts = np.flatnonzero(np.r_[True, np.diff(column) > 0])
    return time[starts], np.fmin.reduceat(values, starts), np.fmax.reduceat(values, starts)


def family(name: str) -> str:
    """A variable's name without its index (`crosspiece_quaternion_2`: `crosspiece_quaternion`)."""
    stem, _, index = name.rpartition("_")
    return stem if stem and index.isdigit() else name


def quantity(name: str, unit: str) -> tuple[str, str]:
    """What a panel shows: the unit, and for a unitless variable its family too."""
    return (unit, family(name) if unit in UNITLESS else "")


def axis_label(group: Sequence[str], unit: str) -> str:
    """'crosspiece_quaternion_0..3 [1]': the panel's variables (a family's
    indices as a range) and their unit, wrapped to the panel's height."""
    stems: dict[str, list[str]] = {}
    for name in group:
        stems.setdefault(family(name), []).append(name)
    named = [
        members[0] if len(members) == 1 else f"{members[0]}..{members[-1].rpartition('_')[2]}"
        for members in stems.values()
    ]
    text = ", ".join(named) + f" [{unit or '1'}]"
    return "\n".join(textwrap.wrap(text, LABEL_CHARACTERS, break_long_words=False))


def panels(result, names: Sequence[str], unit_of: Callable[[str], str]) -> list[list[str]]:
    """`names` grouped by quantity (first appearance first), each quantity's
    varying variables split where their peaks differ by more than MAGNITUDE_RATIO;
    a constant joins its quantity's first panel."""
    by_unit: dict[tuple[str, str], list[str]] = {}
    for name in names:
        by_unit.setdefault(quantity(name, unit_of(name)), []).append(name)
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
    enveloped = False
    for ax, group in zip(axes.flat, groups):
        unit = display(group[0])[1]
        pixels = max(1, int(ax.get_window_extent().width))
        flat = []
        for k, name in enumerate(group):
            factor = display(name)[0]
            values = result[name] * factor
            if is_constant(result[name]):
                value = constant_value(result[name]) * factor
                ax.plot(
                    result["time"],
                    np.full(len(values), value),
                    lw=1.2,
                    ls="--",
                    color=f"C{k}",
                    label=flat_label(name, values),
                )
                flat.append(value)
            elif len(values) > 2 * pixels:
                time, low, high = envelope(result["time"], values, pixels)
                ax.fill_between(
                    time, low, high, step="post", color=f"C{k}", alpha=0.55, lw=0.4, label=name
                )
                enveloped = True
            else:
                ax.plot(result["time"], values, lw=0.9, color=f"C{k}", label=name)
        if len(flat) == len(group):  # only constants: centre them, not rounding noise
            middle, size = float(np.mean(flat)), max(abs(v) for v in flat)
            half = max(0.05 * size, float(np.ptp(flat))) or 1.0
            ax.set_ylim(middle - 1.2 * half, middle + 1.2 * half)
            ax.ticklabel_format(axis="y", useOffset=False)
        ax.set_ylabel(axis_label(group, unit), fontsize=8)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7.5, borderaxespad=0)
    for ax in axes.flat[len(groups) :]:
        ax.axis("off")
    for column in range(columns):  # the lowest panel of each column carries the time axis
        lowest = max(r for r in range(rows) if r * columns + column < len(groups))
        axes[lowest, column].set_xlabel("time [s]")
        axes[lowest, column].xaxis.set_tick_params(labelbottom=True)
    if enveloped:  # one line more for the title
        title += "\nShaded: a long run's least to greatest value in each pixel column."
        fig.set_size_inches(width, fig.get_size_inches()[1] + 0.18)
    fig.suptitle(title, fontsize=9, ha="left", x=0.01)
    return save_figure(fig, path, dpi=100)
