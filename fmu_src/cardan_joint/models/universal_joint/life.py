"""The joint's bearing loads and catalogue life (build setting `life`,
docs/life.md): Miner's sum as the joint's own state, the damage of each step and
the four life outputs, mixed into `CardanJoint`."""

import math
from collections.abc import Callable
from typing import Any

from ...physics.life import (
    NO_RULE,
    compensated_add,
    life_outputs,
    rule_of,
    step_damage,
    step_damage_loaded,
)
from ...physics.response import JointResponse

_TORQUES = tuple(
    JointResponse._fields.index(name)
    for name in ("input_torque", "input_yoke_moment", "output_yoke_moment")
)


class JointLife:
    """Life on or off (`life`); the joint's angle state comes from `ShaftModel`."""

    life: bool
    # Bearing and life parameters (the table's rows with life on).
    bearing_radius: float
    rated_torque: float
    life_constant: float
    life_exponent: float
    life_min_angle: float
    # Set over a step by a layer whose load follows the motion (the compliant
    # joint's spring): (torque_at, load), `life.step_damage_loaded`'s.
    load_over_step: tuple[Callable, tuple] | None = None

    def _start_life(self) -> None:
        """The rule from the parameters (fixed until the next start), no damage yet."""
        if self.life:
            # Out of their ranges, the parameters may give the rule's scale no
            # number (a rated torque of 0 divides by 0): no step runs then.
            fault = self.parameter_fault  # type: ignore[attr-defined] # the joint's, set first
            self._life_rule = NO_RULE if fault else rule_of(self)
            self.life_consumed = self.life_consumed_error = 0.0

    # The hooks below run with life on only: the joint checks `life` at each call
    # (a call costs a few hundred instructions a step).

    def _life_start(self) -> tuple[Any, ...]:
        """What the damage of the next step starts from (`life.step_damage`), taken
        before the step."""
        angle, phase = self._angle, self._phase  # type: ignore[attr-defined]
        joint: Any = self
        return (
            angle[1] + (phase[1] + (angle[2] + phase[2])),  # psi, as `response`'s
            joint.bend_angle,
            joint.input_speed,
            joint.input_acceleration,
            joint.bend_angle_rate,
            joint.bend_angle_acceleration,
            (joint.crosspiece_inertia_1, joint.crosspiece_inertia_2, joint.crosspiece_inertia_3),
            joint.load_torque,
        )

    def _add_damage(self, h: float, start: tuple[Any, ...]) -> None:
        """Miner's sum plus the step's damage from `start`, compensated."""
        load = self.load_over_step
        if load is None:
            damage = step_damage(self._life_rule, h, *start)
        else:
            # The held load gives way to the moving one.
            psi, bend, speed, acceleration, rate, bend_acceleration, inertia, _ = start
            torque_at, spring = load
            damage = step_damage_loaded(
                self._life_rule, h, psi, bend, speed, acceleration, rate, bend_acceleration,
                inertia, torque_at, spring,
            )  # fmt: skip
        if damage:
            self.life_consumed, self.life_consumed_error = compensated_add(
                self.life_consumed, self.life_consumed_error, damage
            )

    def _with_life(self, values: tuple, r: tuple, load, speed, beta) -> tuple:
        """`values` (the joint's outputs) and the four life outputs from the
        kernel's tuple `r`."""
        if self.parameter_fault:  # type: ignore[attr-defined] # no load or life then
            return values + (math.nan, math.nan, math.nan, self.life_consumed)
        torque, input_moment, output_moment = (r[i] for i in _TORQUES)
        return values + life_outputs(
            self._life_rule,
            self.bearing_radius,
            self.life_consumed + self.life_consumed_error,
            torque,
            input_moment,
            output_moment,
            load,
            speed,
            beta,
        )

    # The model's own state: the shaft's angle and, with life on, Miner's sum.

    def own_state(self) -> dict:
        state = super().own_state()  # type: ignore[misc]
        if self.life:
            state["life_consumed"] = self.life_consumed
            state["life_consumed_error"] = self.life_consumed_error
        return state

    def own_state_from(self, state: dict) -> Callable[[], None]:
        put_angle = super().own_state_from(state)  # type: ignore[misc]
        if not self.life:
            return put_angle
        consumed = float(state["life_consumed"])
        error = float(state["life_consumed_error"])

        def put() -> None:
            put_angle()
            self.life_consumed, self.life_consumed_error = consumed, error

        return put
