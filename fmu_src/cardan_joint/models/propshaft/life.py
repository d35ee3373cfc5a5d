"""The propshaft's bearing loads and catalogue life, joint by joint (docs/life.md):
the single joint's rule (`physics.life`) on each joint, with that joint's input
shaft speed, torque T_k and load L_k from the chain (`chain.ChainState`).

Over a step the input shaft is polynomial, so every shaft's speed and every
joint's torque are closed forms of the time (the chain at the input angle of
that instant): each joint's damage is `life_integral.step_integral` of them,
`step.chain_damages` (the step's own). Under a load that follows the motion
(the compliant propshaft's spring, whose step runs in Python) the chain at
zero load gives the kinematics the load needs, and the chain is evaluated
once per node for all joints where their nodes coincide."""

from typing import Any

from ...framework.stepped import ShaftModel
from ...physics.life import compensated_add, rate_scale, singularity_reach
from ...physics.life_integral import step_integral
from .chain import chain
from .step import chain_damages


def _chain_torque(t, step):
    """(T_k, joint k's input shaft speed) t s into the step: `step` = (the chain
    at t, k, the input speed and acceleration at the step's start)."""
    state_at, k, speed, acceleration = step
    state = state_at(t)
    return state.torques[k], state.speeds[k - 1] if k else speed + acceleration * t


def step_damages(rule, h, chain_at, working_angles, speed, acceleration):
    """Each joint's Miner damage over a step of `h` s: `chain_at(t)` the chain
    t s into it, the input shaft at `speed` and constant `acceleration`. The
    torques share the singularities of the largest working angle."""
    states: dict = {}

    def state(t):  # the joints' panels meet at the same nodes where no event parts them
        found = states.get(t)
        if found is None:
            found = states[t] = chain_at(t)
        return found

    reach = singularity_reach(max(working_angles))
    scale = rate_scale(rule) / 3600.0
    return [
        scale * step_integral(
            _chain_torque, (state, k, speed, acceleration), h, speed, acceleration, beta,
            0.0, 0.0, rule.min_angle, rule.exponent, reach,
        )
        for k, beta in enumerate(working_angles)
    ]  # fmt: skip


def added(sums, damages):
    """Each joint's compensated Miner's sum (total, error) plus its damage."""
    return [compensated_add(total, error, d) if d else (total, error)
            for (total, error), d in zip(sums, damages)]  # fmt: skip


class PropshaftLife:
    """Each joint's bearing loads, life rate and Miner's sum (`life` on), mixed
    into `Propshaft`: its outputs, its step's damage and its saved state."""

    life: bool
    joints: int
    _life: list
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
    # Set over a step by a layer whose load follows the motion (the compliant
    # drive's spring): load(t, kinematic offset, kinematic output speed), N.m.
    load_over_step: Any = None

    def _advance(self, h: float):
        """The input shaft (`ShaftModel`), then each joint's damage over the step."""
        _, fraction, error = self._angle
        speed, acceleration = self.input_speed, self.input_acceleration
        problem = ShaftModel._advance(self, h)  # type: ignore[arg-type]
        if problem or not self.life:
            return problem

        spring = self.load_over_step
        if spring is None:  # the step's own damages (`step.chain_damages`)
            I1, I2, I3 = self._crosspiece
            damages = chain_damages(
                self._life_rule, h, fraction, error, speed, acceleration, self.load_torque,
                I1, I2, I3, self._layout_values,
            )  # fmt: skip
            self._life = added(self._life, damages)
            return None

        def chain_at(t, load):
            return chain(
                self.layout,
                fraction,
                speed + acceleration * t,
                acceleration,
                self._crosspiece,
                self._inertia,
                load,
                error + t * (speed + 0.5 * acceleration * t),
            )

        def loaded_at(t):  # the kinematics first, the spring's load from them
            free = chain_at(t, 0.0)
            offset = free.offsets[-1] - self._shifts[-1]
            return chain_at(t, spring(t, offset, free.speeds[-1]))

        damages = step_damages(
            self._life_rule, h, loaded_at, self.layout.working_angles, speed, acceleration
        )
        self._life = added(self._life, damages)
        return None

    def own_state(self) -> dict:
        state = super().own_state()  # type: ignore[misc]
        if not self.life:
            return state
        state["life_consumed"] = [total for total, _ in self._life]
        state["life_consumed_error"] = [error for _, error in self._life]
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

        def put() -> None:
            put_angle()
            self._life = list(zip(totals, errors))

        return put
