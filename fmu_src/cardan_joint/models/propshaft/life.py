"""The propshaft's bearing loads and catalogue life, joint by joint (docs/life.md):
the single joint's rule (`physics.life`) on each joint, with that joint's input
shaft speed, torque T_k and load L_k from the chain (`chain.ChainState`).

Over a step the input shaft is polynomial, so every shaft's speed and every
joint's torque are closed forms of the time (the chain at the input angle of
that instant): each joint's damage is `life_integral.step_integral` of them,
`step.chain_damages` (the step's own), under a held load or one that follows
the motion (the compliant propshaft's spring: `load_over_step`)."""

import math
from typing import Any

from ...framework.stepped import ShaftModel
from ...physics.life_integral import unseen_ahead
from .step import chain_damages, chain_torque, sums_added


class PropshaftLife:
    """Each joint's bearing loads, life rate and Miner's sum (`life` on), mixed
    into `Propshaft`: its outputs, its step's damage and its saved state."""

    life: bool
    joints: int
    _life: list
    _ahead: tuple
    _life_rule: Any
    _crosspiece: tuple
    _inertia: tuple
    layout: Any
    _angle: Any
    parameter_fault: Any
    bearing_radius: float
    input_speed: float
    input_acceleration: float
    load_torque: float
    _shifts: tuple
    _layout_values: tuple
    _trig: tuple
    _reach: float
    # Set over a step by a layer whose load follows the motion (the compliant
    # propshaft's spring): (torque_at, load), `step.chain_damages`'s.
    load_over_step: Any = None

    def _advance(self, h: float):
        """The input shaft (`ShaftModel`), then each joint's damage over the step."""
        _, fraction, error = self._angle
        speed, acceleration = self.input_speed, self.input_acceleration
        problem = ShaftModel._advance(self, h)  # type: ignore[arg-type]
        if problem or not self.life:
            return problem

        # A load that follows the motion (`load_over_step`) or the held one.
        torque_at, load = self.load_over_step or (chain_torque, (self.load_torque,))
        damages = chain_damages(
            self._life_rule, h, torque_at, fraction, error, speed, acceleration,
            self._crosspiece, load, self._layout_values, self._trig, self._reach, self._ahead,
        )  # fmt: skip
        sums = sums_added(tuple(v for pair in self._life for v in pair), damages[: self.joints])
        self._life = [(sums[2 * k], sums[2 * k + 1]) for k in range(self.joints)]
        self._ahead = damages[self.joints :]
        return None

    def own_state(self) -> dict:
        state = super().own_state()  # type: ignore[misc]
        if not self.life:
            return state
        state["life_consumed"] = [total for total, _ in self._life]
        state["life_consumed_error"] = [error for _, error in self._life]
        state["life_ahead"] = list(self._ahead)
        return state

    def own_state_from(self, state: dict):
        put_angle = super().own_state_from(state)  # type: ignore[misc]
        if not self.life:
            return put_angle
        totals = [float(x) for x in state["life_consumed"]]
        errors = [float(x) for x in state["life_consumed_error"]]
        if not len(totals) == len(errors) == self.joints:
            raise ValueError(
                f"life_consumed: {len(totals)} joints in the state, {self.joints} here"
            )
        # What life foresees the next step from: a state saved before it was
        # kept foresees nothing (`unseen_ahead`).
        unseen = unseen_ahead(range(self.joints))
        ahead = tuple(float(x) for x in state.get("life_ahead", unseen))
        if len(ahead) != len(unseen):
            raise ValueError(f"life_ahead: {len(ahead)} values in the state, {len(unseen)} here")
        if not all(math.isfinite(x) for x in ahead):
            raise ValueError(f"life_ahead: {list(ahead)} in the state, finite values only")

        def put() -> None:
            put_angle()
            self._life = list(zip(totals, errors))
            self._ahead = ahead

        return put
