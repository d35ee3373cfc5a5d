"""A life report's files: the parts as CSV, the summary as JSON, and the figure
of damage accumulated over the cycle and added by each block or span."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from ..results import replaced_whole, write_rows
from .life_report import LifeReport, default_paths
from .plotting import pyplot, save_figure


def part_rows(report: LifeReport) -> list[dict]:
    """One row per block or span, its damage per joint (columns with units)."""
    rows = []
    for part in report.parts:
        row = {"part": part["label"], "start [s]": part["start"], "seconds [s]": part["seconds"]}
        row.update({f"{j} damage [1]": part["damage"][j] for j in report.joints})
        row["share_of_damage [1]"] = part["share_of_damage"]
        rows.append(row)
    return rows


def _json_safe(value):
    if isinstance(value, float) and not math.isfinite(value):
        return None  # JSON has no infinity: a B10 life without damage is null
    if isinstance(value, dict):
        return {k: _json_safe(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_json_safe(v) for v in value]
    return value


def write_report(report: LifeReport, output: str | Path) -> dict[str, Path]:
    """The CSV, JSON and PNG beside `output` (its suffix replaced); their paths."""
    paths = default_paths(output)
    write_rows(part_rows(report), paths["csv"])
    units = {
        "cycle_seconds": "s",
        "life_used": "1 (Miner's sum per cycle; 1 = the B10 life)",
        "b10_hours": "h",
        "peak_torque": "N.m",
        "rated_torque": "N.m",
        "peak_bearing_force": "N",
        "rated_bearing_force": "N (the force at rated_torque: rated_torque / (2 bearing_radius))",
    }
    text = json.dumps(_json_safe({**report.summary(), "units": units}), indent=2)
    with replaced_whole(paths["json"]) as temporary:
        temporary.write_text(text + "\n")
    plot_report(report, paths["png"])
    return paths


def plot_report(report: LifeReport, path: str | Path) -> Path:
    """Damage accumulated over the cycle (each joint), the parts shaded; below,
    the damage each part adds (each joint's bar)."""
    plt = pyplot()
    fig, (over, by_part) = plt.subplots(2, 1, figsize=(9, 6.5), height_ratios=(3, 2))
    history = report.history
    time = np.concatenate(([history["time"][0] - _first_step(report)], history["time"]))
    for joint in report.joints:
        over.plot(time, np.concatenate(([0.0], history[f"{joint} life"])), label=joint)
    for index, part in enumerate(report.parts):
        start, end = part["start"], part["start"] + part["seconds"]
        over.axvspan(start, end, alpha=0.06 * (index % 2 + 1), color="grey")
        over.text(0.5 * (start + end), 0.98, part["label"], rotation=90, ha="center",
                  va="top", fontsize=7, transform=over.get_xaxis_transform())  # fmt: skip
    over.set_xlabel("time in the cycle [s]")
    over.set_ylabel("life_consumed [1] (1 = B10 life)")
    over.set_title(f"{report.model}: damage over the duty cycle ({report.kind})")
    over.legend(loc="lower right")
    labels = [p["label"] for p in report.parts]
    width = 0.8 / len(report.joints)
    for k, joint in enumerate(report.joints):
        damage = [p["damage"][joint] for p in report.parts]
        x = np.arange(len(labels)) + (k - (len(report.joints) - 1) / 2) * width
        by_part.bar(x, damage, width, label=joint)
    by_part.set_xticks(np.arange(len(labels)), labels, rotation=30, ha="right", fontsize=8)
    by_part.set_ylabel("damage per part [1]")
    by_part.set_title("damage by block" if report.kind == "blocks" else "damage by time span")
    if len(report.joints) > 1:
        by_part.legend(loc="upper right")
    return save_figure(fig, path)


def _first_step(report: LifeReport) -> float:
    part = report.parts[0]
    return float(report.history["time"][0] - part["start"])
