"""The propshaft as a stepped system: what the Propshaft FMU keeps between steps.

Same contract as `models.universal_joint.model.CardanJoint` (the slave drives both): inputs
and parameters as attributes, the input angle as exact revolutions, `step`
advances exactly for inputs polynomial over the step or refuses with a message
and changes nothing, `outputs` evaluates the closed forms. The geometry is
fixed at `start`; the fluctuation search runs once, at the first output read.
"""

import math

from ...framework.refusal import Refusal
from ...framework.stepped import ShaftModel
from ...framework.values import angle_limit_problem, set_start_values, value_ranges
from ...physics.life import NO_RULE, rule_of
from ...physics.life_integral import unseen_ahead
from ...physics.revolutions import split_turns
from .chain import chain, layout_values
from .checks import angle_warnings
from .critical_speed import critical_speed, critical_speed_warnings
from .entries import STEPS
from .fluctuation import equivalent_angle, speed_ratio_fluctuation
from .geometry import HALF_PI, TWO_PI, Layout, layout
from .life import PropshaftLife
from .refusals import PropshaftReason
from .step import ahead_names, fixed_by_layout, propshaft_outputs, state_names
from .variables import propshaft_table

# Without life the outputs are computed with a rule whose values they leave out.
_NO_LIFE = (1.0, NO_RULE)
_TUBE_PARTS = ("outer_diameter", "inner_diameter", "length", "youngs_modulus", "density")


class Propshaft(PropshaftLife, ShaftModel):
    # The inputs and parameters every layout has, set from the table by __init__;
    # the per-shaft angles, phases and inertias are read by name (`getattr`).
    input_speed: float
    input_acceleration: float
    load_torque: float
    input_angle_start: float
    crosspiece_inertia_1: float
    crosspiece_inertia_2: float
    crosspiece_inertia_3: float
    max_working_angle: float
    critical_speed_margin: float
    # Every joint's bearing and life parameters (docs/life.md).
    bearing_radius: float
    rated_torque: float
    life_constant: float
    life_exponent: float
    life_min_angle: float

    def __init__(self, joints: int = 2, life: bool = True, **values: float) -> None:
        self.life = life
        self.table = table = propshaft_table(joints, life)
        self._fluctuation: tuple[Layout, float] | None = None
        self.joints = joints
        self._layout_outputs: tuple[Layout, tuple] | None = None
        set_start_values(self, table, values, f"{joints}-joint Propshaft")
        by_name = table.BY_NAME
        self._input_ranges = value_ranges(by_name, table.INPUTS)
        assert all(low == -high for _, low, high, _ in self._input_ranges), "symmetric ranges"
        self._limits = tuple((name, high) for name, _, high, _ in self._input_ranges)
        self._parameter_ranges = value_ranges(by_name, table.PARAMETERS, "max_working_angle")
        self._speed_limit = by_name["input_speed"].max
        self._sides = tuple(f"shaft_{k}_side_angle" for k in range(joints + 1))
        self._tops = tuple(f"shaft_{k}_top_angle" for k in range(joints + 1))
        self._phases = tuple(f"shaft_{k}_yoke_phase" for k in range(1, joints))
        self._inertias = tuple(f"shaft_{k}_inertia" for k in range(1, joints))
        self.start(0.0)

    # --- set-up ------------------------------------------------------------

    def start(self, time: float) -> None:
        """Put the input angle at `input_angle_start`, the clock at `time`, and fix the
        geometry (parameters are fixed from here on, as in FMI)."""
        self.time = float(time)
        self.parameter_fault = self._angle_problem()
        valid = not self.parameter_fault
        self._angle = split_turns(self.input_angle_start if valid else 0.0)
        self._life = [(0.0, 0.0)] * self.joints  # each joint's Miner's sum (total, error)
        self._ahead = unseen_ahead(range(self.joints))  # what life foresees the next step from
        if not valid:
            return
        self._inertia = tuple(getattr(self, n) for n in self._inertias)
        self._crosspiece = (
            self.crosspiece_inertia_1,
            self.crosspiece_inertia_2,
            self.crosspiece_inertia_3,
        )
        self._life_rule = rule_of(self) if self.life else _NO_LIFE[1]
        self._radius = self.bearing_radius if self.life else _NO_LIFE[0]
        self.layout = self._geometry()
        self._critical_speeds = tuple(
            critical_speed(*(getattr(self, f"shaft_{k}_{part}") for part in _TUBE_PARTS))
            for k in range(1, self.joints)
        )
        self.parameter_fault = self._working_angle_problem(self.layout)
        if self.parameter_fault:
            return
        # Shaft angles start on the branch nearest the input angle (the contract).
        _, fraction, error = self._angle
        offsets = chain(self.layout, fraction, 0.0, 0.0, angle_error=error).offsets
        self._shifts = tuple(TWO_PI * round(o / TWO_PI) for o in offsets)
        self._layout_values = layout_values(self.layout, self._inertia)
        self._trig, self._reach = fixed_by_layout(self._layout_values)

    def _angle_problem(self):
        problem = self._value_problem(self.table.PARAMETERS, self._parameter_ranges)
        if problem:
            return problem
        # Built like stepped.ValueChecks' refusals (one Refusal call per reason).
        for name in self._sides + self._tops:
            value = getattr(self, name)
            if not abs(value) < HALF_PI:
                return Refusal(
                    PropshaftReason.SHAFT_ANGLE,
                    name,
                    value,
                    math.copysign(HALF_PI, value),
                    self.time,
                    "rad",
                    kind="parameter",
                )
        return self._tube_problem() or angle_limit_problem(
            PropshaftReason.WORKING_ANGLE_GUARD,
            "max_working_angle",
            self.max_working_angle,
            self.time,
        )

    def _tube_problem(self):
        """A tube whose bore is not below its outer diameter has no wall (its
        critical speed would be a number for no shaft)."""
        for k in range(1, self.joints):
            inner = getattr(self, f"shaft_{k}_inner_diameter")
            outer = getattr(self, f"shaft_{k}_outer_diameter")
            if not inner < outer:
                return Refusal(
                    PropshaftReason.TUBE_BORE,
                    f"shaft_{k}_inner_diameter",
                    inner,
                    outer,
                    self.time,
                    "m",
                    kind="parameter",
                )
        return None

    def _geometry(self):
        return layout(
            [getattr(self, n) for n in self._sides],
            [getattr(self, n) for n in self._tops],
            [getattr(self, n) for n in self._phases],
        )

    def _working_angle_problem(self, geometry):
        guard = self.max_working_angle
        for k, beta in enumerate(geometry.working_angles, start=1):
            if not beta < guard:
                return Refusal(
                    PropshaftReason.WORKING_ANGLE,
                    f"joint_{k}_working_angle",
                    beta,
                    guard,
                    self.time,
                    "rad",
                    kind="parameter",
                )
        return None

    def parameter_problem(self):
        """Why the parameters cannot run, or None (checks the current values)."""
        return self._angle_problem() or self._working_angle_problem(self._geometry())

    # --- stepping ----------------------------------------------------------

    def run(self, time: float, h: float, inputs) -> "tuple | Refusal":
        """The FMU's step: take `inputs` (the table's order), advance `h` s from
        `time` and return the outputs and the inputs after it, or the Refusal
        of the step (then only the inputs have changed).

        The step is `step.propshaft_<N>_step`, the definition the FMU's C
        runtime is generated from; a step it does not take goes through the
        checks of the generic `run`, which name the refusal."""
        if not self.life:
            return ShaftModel.run(self, time, h, inputs)
        self.set_inputs(inputs)
        taken = STEPS[self.joints](time, h, *self.step_state(), *inputs)
        if taken is None:
            return ShaftModel.run(self, time, h, inputs)
        state = len(state_names(self.joints))
        self.set_step_state(taken[:state])
        moved = taken[state : state + len(inputs)]
        self.set_inputs(moved)
        self.time = time + h
        return taken[state + len(inputs) :], moved

    def step_state(self) -> tuple:
        """The values of `step.state_names`: what the step advances (the input
        angle, each joint's Miner's sum) and what `start` fixed, which it reads."""
        valid = self.parameter_fault is None
        fixed = (
            self._fixed()
            if valid
            else (0.0,) * (len(state_names(self.joints)) - 4 - len(self._sums_and_ahead()))
        )
        return (*self._angle, valid, *fixed, *self._sums_and_ahead())

    def _sums_and_ahead(self) -> tuple:
        """The step state's values that a step moves after the angle: each
        joint's Miner's sum (total, error), then life's `ahead`."""
        return (*(v for total_and_error in self._life for v in total_and_error), *self._ahead)

    def _fixed(self) -> tuple:
        """The step state's values `start` fixes, in `state_names`' order."""
        rule = self._life_rule
        return (
            *self._layout_values, *self._trig, *self._shifts, *self._critical_speeds,
            *self._geometry_outputs()[-2:], *self._crosspiece, self._radius, *rule, self._reach,
        )  # fmt: skip

    def set_step_state(self, state) -> None:
        """Take a state a generated step advanced (`step_state`'s values): only the
        angle, the Miner's sums and life's `ahead` move over a step, the rest
        follows the parameters."""
        turns, fraction, fraction_error = state[:3]
        self._angle = (int(turns), float(fraction), float(fraction_error))
        ahead = len(ahead_names(self.joints))
        sums = state[len(state) - ahead - 2 * self.joints : len(state) - ahead]
        self._life = [(float(sums[k]), float(sums[k + 1])) for k in range(0, len(sums), 2)]
        self._ahead = tuple(float(v) for v in state[len(state) - ahead :])

    def input_problem(self, step_size: float = 0.0):
        """Why the inputs cannot be used over the next step, or None."""
        if all(abs(getattr(self, name)) <= high for name, high in self._limits):
            return None
        return self._value_problem(self.table.INPUTS, self._input_ranges)

    # --- outputs -----------------------------------------------------------

    def kinematics(self) -> tuple[float, float]:
        """(output angle - input angle, output speed) now: what a compliant layer
        winds its spring by, without the rounding of two large angles."""
        _, fraction, error = self._angle
        state = self._chain(fraction, error)
        return state.offsets[-1] - self._shifts[-1], state.speeds[-1]

    def _chain(self, fraction, error):
        return chain(
            self.layout,
            fraction,
            self.input_speed,
            self.input_acceleration,
            self._crosspiece,
            self._inertia,
            self.load_torque,
            error,
        )

    def fluctuation(self) -> float:
        # Kept with its geometry: a restart (setup, initialization, state restore)
        # with unchanged parameters does not search again.
        if self._fluctuation is None or self._fluctuation[0] != self.layout:
            self._fluctuation = (self.layout, speed_ratio_fluctuation(self.layout))
        return self._fluctuation[1]

    def outputs(self) -> tuple:
        """Values of the table's outputs, in order (`step.propshaft_outputs`, the
        step's own); raises nothing for valid inputs and parameters."""
        joints = self.joints
        I1, I2, I3 = self._crosspiece
        values = propshaft_outputs(
            self._angle, self.input_speed, self.input_acceleration, self.load_torque,
            self._layout_values, self._trig, self._shifts, self._critical_speeds,
            self._geometry_outputs()[-2:], I1, I2, I3, self._life_rule, self._radius,
            tuple(v for total_and_error in self._life for v in total_and_error),
        )  # fmt: skip
        return values if self.life else values[: len(values) - 4 * joints]

    def _geometry_outputs(self) -> tuple:
        """Working angles, fluctuation and equivalent angle: fixed with the layout,
        so computed once per layout (`start` makes a new one), not at every step."""
        cached = self._layout_outputs
        if cached is None or cached[0] is not self.layout:
            fluctuation = self.fluctuation()
            values = (*self.layout.working_angles, fluctuation, equivalent_angle(fluctuation))
            cached = self._layout_outputs = (self.layout, values)
        return cached[1]

    def warnings(self):
        """The industry's angle checks at the current input speed (never refusals)."""
        if self.parameter_fault:
            return ()
        angles = angle_warnings(self.layout.working_angles, self.fluctuation(), self.input_speed)[0]
        # The shafts' mean speed is the input's: the critical-speed check at it.
        return angles + critical_speed_warnings(
            self._critical_speeds, self.input_speed, self.critical_speed_margin
        )
