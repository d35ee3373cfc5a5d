"""A duty cycle run through a jointed FMU, and the life it uses (docs/life.md).

`life_report(cycle, fmu)` drives the FMU through the cycle's steps
(`duty_cycle`) and reads the FMU's own outputs: each joint's `life_consumed`
(Miner's sum of the catalogue rule), the input torque and the trunnion
bearing forces. Any FMU whose inputs take a cycle runs it: an input shaft
speed and a load torque, its joints' life outputs; the cycle's angle drives
a `bend_angle` input, and a model without one (its working angles are its
layout's parameters) takes no angle column. Others are refused by name.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..names import UsageError
from .duty_cycle import DutyCycle, read_duty_cycle
from .fmu_info import FmuInfo

NEEDED_INPUTS = ("input_speed", "load_torque")


@dataclass
class LifeReport:
    """What a cycle does to the joints: per joint its life used over the cycle
    and B10 hours at this cycle's rate; per part (block or span) its damage;
    the peaks against the ratings. `history` holds the run, step by step."""

    model: str
    source: str
    kind: str
    cycle_seconds: float
    joints: list[str]
    life_used: dict[str, float]
    b10_hours: dict[str, float]
    governing_joint: str
    parts: list[dict]
    most_damaging: dict[str, Any]
    peak_torque: float
    rated_torque: float
    peak_bearing_force: float
    rated_bearing_force: float
    history: dict[str, np.ndarray] = field(repr=False, default_factory=dict)

    def summary(self) -> dict:
        """Everything but the history, for JSON."""
        return {k: v for k, v in self.__dict__.items() if k != "history"}


def life_outputs(info: FmuInfo) -> dict[str, tuple[str, str, str]]:
    """Joint label -> its (life_consumed, input bearing force, output bearing
    force) outputs; refuses an FMU that cannot run a duty cycle, naming it."""
    outputs = set(info.outputs)
    names = ("life_consumed", "input_bearing_force", "output_bearing_force")
    joints = {"joint": names}
    if "life_consumed" not in outputs:
        joints = {
            f"joint {k}": (
                f"joint_{k}_{names[0]}",
                f"joint_{k}_{names[1]}",
                f"joint_{k}_{names[2]}",
            )
            for k in range(1, 65)
            if f"joint_{k}_life_consumed" in outputs
        }
    missing = [n for n in NEEDED_INPUTS if n not in info.inputs]
    if not joints or missing:
        why = f"it has no {' or '.join(missing)} input" if missing else "it has no joint life"
        raise UsageError(
            f"{info.model_name} cannot run a duty cycle: {why} (a cycle drives the input "
            f"shaft's speed and the load torque, and reads each joint's life_consumed)"
        )
    return joints


def _check_angle(info: FmuInfo, cycle: DutyCycle) -> None:
    bends = "bend_angle" in info.inputs
    if bends and not cycle.has_angle:
        raise UsageError(
            f"{cycle.source} gives no angle, and {info.model_name} takes one (bend_angle)"
        )
    if cycle.has_angle and not bends:
        raise UsageError(
            f"{cycle.source} gives an angle, but {info.model_name} takes its working angles "
            f"from its layout's parameters (set them with --set): leave the angle column out"
        )


def run_cycle(fmu, cycle: DutyCycle, start_values=None) -> tuple[str, dict, dict[str, float]]:
    """(model name, the history at each step's end, the ratings) of `cycle` run
    through `fmu` from `start_values` (parameters); a refused step is a
    UsageError naming the cycle and the FMU's reason (variable, value, limit, time)."""
    from .instance import FmuInstance, StepRefusedError

    start_values = dict(start_values or {})
    # The cycle sets the inputs: only parameters start elsewhere than it says.
    FmuInfo.read(fmu).check(start_values, ("parameter",), "parameter")
    with FmuInstance.open(fmu, start_values=start_values) as model:
        info = model.info
        joints = life_outputs(info)
        _check_angle(info, cycle)
        names = list(cycle.inputs)
        recorded = ["input_torque", *(n for outputs in joints.values() for n in outputs)]
        rows = np.empty((len(cycle.steps), len(recorded)))
        columns = [cycle.inputs[n] for n in names]
        for i, (start, step) in enumerate(zip(cycle.times, cycle.steps)):
            model.set(**{n: float(c[i]) for n, c in zip(names, columns)})
            model.time = float(start)
            try:
                model.step(float(step))
            except StepRefusedError as refused:
                raise UsageError(f"{cycle.source}: {refused}") from None
            rows[i] = model.values(*recorded)
        ratings = model.get("rated_torque", "bearing_radius")
        history = {"time": cycle.times + cycle.steps, "part": cycle.part}
        history.update({name: rows[:, k] for k, name in enumerate(recorded)})
        return info.model_name, {"joints": joints, **history}, ratings


def life_report(
    cycle: DutyCycle | str | Path,
    fmu,
    start_values=None,
    cycle_time: float = 10.0,
    step: float = 1e-3,
    spans: int = 10,
) -> LifeReport:
    """The cycle (a `DutyCycle`, or a file `read_duty_cycle` reads with
    `cycle_time`, `step` and `spans`) run through `fmu` from `start_values`
    (parameters), and what it uses of each joint's life."""
    if not isinstance(cycle, DutyCycle):
        return life_report(read_duty_cycle(cycle, cycle_time, step, spans), fmu, start_values)
    model, history, ratings = run_cycle(fmu, cycle, start_values)
    joints = history.pop("joints")
    used = {j: float(history[life][-1]) for j, (life, _, _) in joints.items()}
    hours = cycle.seconds / 3600.0
    b10 = {j: hours / d if d > 0.0 else math.inf for j, d in used.items()}
    governing = max(used, key=lambda j: used[j])
    parts = _parts(cycle, history, joints)
    worst = max(parts, key=lambda p: p["damage"][governing])
    forces = [history[n] for _, i, o in joints.values() for n in (i, o)]
    rated_force = ratings["rated_torque"] / (2.0 * ratings["bearing_radius"])
    return LifeReport(
        model=model,
        source=cycle.source,
        kind=cycle.kind,
        cycle_seconds=cycle.seconds,
        joints=list(joints),
        life_used=used,
        b10_hours=b10,
        governing_joint=governing,
        parts=parts,
        most_damaging={
            "part": worst["label"],
            "damage": worst["damage"][governing],
            "share_of_damage": worst["share_of_damage"],
        },
        peak_torque=float(np.max(np.abs(history["input_torque"]))),
        rated_torque=ratings["rated_torque"],
        peak_bearing_force=float(max(np.max(f) for f in forces)),
        rated_bearing_force=rated_force,
        history={**history, **{f"{j} life": history[life] for j, (life, _, _) in joints.items()}},
    )


def _parts(cycle: DutyCycle, history, joints) -> list[dict]:
    """Each block or span: where it starts, how long, the damage it adds per joint."""
    parts: list[dict[str, Any]] = []
    for index, label in enumerate(cycle.labels):
        steps = np.flatnonzero(cycle.part == index)
        if len(steps) == 0:
            continue
        first, last = steps[0], steps[-1]
        damage: dict[str, float] = {}
        for joint, (life, _, _) in joints.items():
            before = history[life][first - 1] if first > 0 else 0.0
            damage[joint] = float(history[life][last] - before)
        parts.append(
            {
                "label": label,
                "start": float(cycle.times[first]),
                "seconds": math.fsum(cycle.steps[steps]),
                "damage": damage,
            }
        )
    governing = max(joints, key=lambda j: history[joints[j][0]][-1])
    total = sum(p["damage"][governing] for p in parts)
    for part in parts:
        part["share_of_damage"] = part["damage"][governing] / total if total > 0 else 0.0
    return parts


def report_text(report: LifeReport) -> str:
    """The report as a user reads it."""
    g = report.governing_joint
    torque_ratio = report.peak_torque / report.rated_torque
    lines = [
        f"{report.model}, {report.kind} {report.source}: {report.cycle_seconds:.6g} s",
        *(
            f"  {j}: life used {report.life_used[j]:.6e} per cycle; B10 "
            f"{report.b10_hours[j]:,.6g} h at this cycle's rate"
            for j in report.joints
        ),
        f"  uses most: {report.most_damaging['part']} "
        f"({100 * report.most_damaging['share_of_damage']:.1f} % of {g}'s damage)",
        f"  peak torque {report.peak_torque:.6g} N.m = {torque_ratio:.3g} x rated_torque "
        f"{report.rated_torque:g} N.m",
        f"  peak bearing force {report.peak_bearing_force:.6g} N = "
        f"{report.peak_bearing_force / report.rated_bearing_force:.3g} x the force at rated torque "
        f"{report.rated_bearing_force:.6g} N",
    ]
    return "\n".join(lines)


def default_paths(output: str | Path) -> dict[str, Path]:
    """The CSV (per part), JSON (summary) and PNG (figure) beside `output`."""
    path = Path(output)
    return {suffix: path.with_suffix(f".{suffix}") for suffix in ("csv", "json", "png")}
