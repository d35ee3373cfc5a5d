"""A rigid drive with a torsional spring-damper at its output, as a stepped system.

`CompliantDrive` wraps a rigid drive (the joint, the propshaft): the rigid drive
keeps the input shaft, bend and exact kinematics; between its kinematic output
and the output shaft sits a spring k with a damper c in parallel. The output
shaft's speed and acceleration are inputs (from the load side), held over a
step as polynomials, like the input shaft's; the output angle is their exact
integral. The state kept here is the lag = input angle - output angle, a small
number (the twist minus the kinematic offset), so the twist carries no error of
large angles however long the run:

    twist   = (kinematic output angle - input angle) + lag
    torque  = k twist + c (kinematic output speed - output_speed)

and the input torque is the rigid drive's with `load_torque` = that torque (its
inertia and bend-rate terms included). Same protocol as every stepped model.
"""

from operator import attrgetter

from ...framework.refusal import Refusal
from ...framework.stepped import SteppedModel, ValueChecks
from ...framework.values import MAX_INCREMENT, set_start_values, value_ranges
from ..universal_joint.model import CardanJoint
from ..universal_joint.step import LIFE_STATE
from .refusals import CompliantReason
from .step import (
    compliant_joint_step,
    spring_loaded_torque,
    spring_outputs,
    twist_change,
)
from .variables import COMPLIANT_JOINT

# The step's parameters: the table's, but the one the slave's watch alone reads.
_STEP_PARAMETERS = attrgetter(
    *(name for name in COMPLIANT_JOINT.PARAMETERS if name != "twist_angle_warning")
)
_VALID = LIFE_STATE.index("parameters_valid")
# The rigid drive's outputs the compliant one replaces with its own.
_REPLACED = ("input_angle", "output_angle", "output_speed", "output_acceleration")


def _forward(cls, names) -> None:
    """A property on `cls` for each name, reading and writing `self.rigid`'s value:
    made once per class (a propshaft's per-shaft names once per layout), so each
    access costs a property call, not a failed lookup and __getattr__."""
    for name in names:
        if name not in cls.__dict__:
            setattr(cls, name, property(attrgetter(f"rigid.{name}"), _setter(name)))


def _setter(name: str):
    def set_on_rigid(self, value) -> None:
        setattr(self.rigid, name, value)

    return set_on_rigid


class CompliantDrive(ValueChecks):
    """The spring-damper layer; a subclass names the rigid drive's kinematic offset."""

    # The spring's own inputs and parameters (the rest are the rigid drive's).
    output_speed: float
    output_acceleration: float
    twist_angle_start: float
    torsional_stiffness: float
    torsional_damping: float
    twist_angle_warning: float  # read by the slave's watches only (spec.py)

    def __init__(self, rigid, table, what: str, **values: float) -> None:
        self.rigid = rigid
        rigid_names = rigid.table.INPUTS + rigid.table.PARAMETERS
        # The rigid drive's inputs, parameters and clock live in it, read and
        # written through this object by properties made once per class.
        shared = {n for n in table.INPUTS + table.PARAMETERS if n in rigid_names} | {"time"}
        _forward(type(self), shared)
        self.table = table
        self._own_inputs = tuple(n for n in table.INPUTS if n not in shared)
        self._own_parameters = tuple(n for n in table.PARAMETERS if n not in shared)
        self._input_ranges = value_ranges(table.BY_NAME, self._own_inputs)
        self._parameter_ranges = value_ranges(table.BY_NAME, self._own_parameters)
        rigid_outputs = rigid.table.OUTPUTS
        passed = [n for n in table.OUTPUTS if n in rigid_outputs and n not in _REPLACED]
        self._passed = tuple(rigid_outputs.index(n) for n in passed)
        rigid.load_torque = 0.0  # the rigid checks see no load; outputs() sets it
        set_start_values(self, table, values, what)
        self.start(0.0)

    def _kinematics(self) -> tuple[float, float]:
        """(kinematic output angle - input angle, kinematic output speed) now."""
        raise NotImplementedError(f"{type(self).__name__} must give its kinematics")

    # --- set-up and checks ---------------------------------------------------

    def start(self, time: float) -> None:
        """Rigid drive at its start, the output shaft `twist_angle_start` behind its
        kinematic output; parameters are checked here, once."""
        self.rigid.start(time)
        self.parameter_fault = self.parameter_problem()
        valid = not self.parameter_fault and not self.rigid.input_problem()
        offset = self._kinematics()[0] if valid else 0.0
        self._lag = (self.twist_angle_start if valid else 0.0) - offset

    def parameter_problem(self) -> Refusal | None:
        return self.rigid.parameter_problem() or self._value_problem(
            self._own_parameters, self._parameter_ranges
        )

    def input_problem(self, step_size: float = 0.0) -> Refusal | None:
        return self.rigid.input_problem(step_size) or self._value_problem(
            self._own_inputs, self._input_ranges
        )

    def invalid_inputs(self) -> set:
        own = {r.variable for r in self._bad_values(self._own_inputs, self._input_ranges)}
        return self.rigid.invalid_inputs() | own

    # --- stepping ------------------------------------------------------------

    def run(self, time: float, h: float, inputs) -> "tuple | Refusal":
        """The FMU's step (`SteppedModel.run`'s contract): the drive's written
        step (`_written_step`), the definition the FMU's C runtime is generated
        from; a step it does not take goes through the checks, which name the
        refusal."""
        self.set_inputs(inputs)
        state = self.step_state()
        taken = self._written_step(time, h, state, inputs)
        if taken is None:
            return SteppedModel.run(self, time, h, inputs)  # type: ignore[arg-type]
        self.set_step_state(taken[: len(state)])
        moved = taken[len(state) : len(state) + len(inputs)]
        self.set_inputs(moved)
        self.time = time + h
        return taken[len(state) + len(inputs) :], moved

    def _written_step(self, time: float, h: float, state: tuple, inputs) -> tuple | None:
        """The step's entry (`step_state()`'s values, then the inputs...), or None."""
        raise NotImplementedError(f"{type(self).__name__} must name its step")

    def step_state(self) -> tuple:
        raise NotImplementedError(f"{type(self).__name__} must give its step state")

    def set_step_state(self, state) -> None:
        raise NotImplementedError(f"{type(self).__name__} must take its step state")

    def step(self, step_size: float) -> Refusal | None:
        """Advance by `step_size`; None, or the Refusal (then nothing has changed)."""
        problem = self.step_problem(step_size)
        if problem:
            return problem
        h, rigid = step_size, self.rigid
        speed, acceleration = self.output_speed, self.output_acceleration
        change = twist_change(h, rigid.input_speed, rigid.input_acceleration, speed, acceleration)
        if not abs(change) <= MAX_INCREMENT:
            details = {"step_size": h}
            return Refusal(
                CompliantReason.TWIST_OVERFLOW,
                "twist_angle",
                change,
                MAX_INCREMENT,
                self.time,
                "rad",
                details,
            )
        if getattr(rigid, "life", False):
            rigid.load_over_step = self._spring_over_step(speed, acceleration)
        try:
            problem = rigid.advance(h)  # its inputs and parameters were checked above
        finally:
            rigid.load_over_step = None
        if problem:
            return problem
        self._lag += change
        self.output_speed = speed + acceleration * h
        return None

    def _spring_over_step(self, speed: float, acceleration: float) -> tuple:
        """(torque_at, load): the rigid drive's life under the spring over the
        step, as the generated step takes it (the rigid drive's `load_over_step`)."""
        raise NotImplementedError(f"{type(self).__name__} must give its spring's torque")

    # --- outputs -------------------------------------------------------------

    @property
    def input_angle(self) -> float:
        return self.rigid.input_angle

    @property
    def output_angle(self) -> float:
        return self.rigid.input_angle - self._lag

    def outputs(self) -> tuple:
        """Values of the table's outputs, in order."""
        rigid = self.rigid
        spring = spring_outputs(
            rigid.input_angle, self._lag, *self._kinematics(), self.output_speed,
            self.torsional_stiffness, self.torsional_damping,
        )  # fmt: skip
        rigid.load_torque = spring[3]  # the output torque
        try:
            values = rigid.outputs()
        finally:
            rigid.load_torque = 0.0
        return (*spring, *(values[i] for i in self._passed))

    # --- saved state ---------------------------------------------------------

    def state(self) -> dict:
        values = {n: getattr(self, n) for n in self._own_inputs + self._own_parameters}
        return {**values, "lag": self._lag, "rigid": self.rigid.state()}

    def restore(self, state: dict) -> None:
        """Take a `state()`; all or nothing (a malformed state raises and changes nothing)."""
        values = {n: float(state[n]) for n in self._own_inputs + self._own_parameters}
        lag = float(state["lag"])
        self.rigid.restore(state["rigid"])
        for name, value in values.items():
            setattr(self, name, value)
        self._lag = lag
        self.parameter_fault = self.parameter_problem()


class CompliantJoint(CompliantDrive):
    """The single joint (`CardanJoint`) with the spring-damper at its output."""

    table = COMPLIANT_JOINT

    # The rigid joint's inputs and parameters, kept in `rigid` (see CompliantDrive).
    input_speed: float
    input_acceleration: float
    bend_angle: float
    bend_angle_rate: float
    bend_angle_acceleration: float
    yoke_phase: float
    input_angle_start: float
    crosspiece_inertia_1: float
    crosspiece_inertia_2: float
    crosspiece_inertia_3: float
    max_bend_angle: float
    bearing_radius: float
    rated_torque: float
    life_constant: float
    life_exponent: float
    life_min_angle: float

    def __init__(self, **values: float) -> None:
        super().__init__(CardanJoint(), COMPLIANT_JOINT, "compliant joint", **values)

    def _written_step(self, time: float, h: float, state: tuple, inputs) -> tuple | None:
        return compliant_joint_step(time, h, *state, *inputs, *_STEP_PARAMETERS(self))

    def step_state(self) -> tuple:
        """The values of `step.STATE`: the rigid joint's, with this drive's
        parameters' validity, and the lag."""
        joint = self.rigid.step_state()
        valid = self.parameter_fault is None
        return (*joint[:_VALID], valid, *joint[_VALID + 1 :], self._lag)

    def set_step_state(self, state) -> None:
        """Take a state a generated step advanced (`step_state`'s values)."""
        self.rigid.set_step_state(state[: len(LIFE_STATE)])
        self._lag = float(state[len(LIFE_STATE)])

    def _spring_over_step(self, speed: float, acceleration: float):
        """The joint's life under the spring, as the generated step takes it:
        `step.spring_loaded_torque` from the spring's start (`JointLife`'s hook)."""
        spring = (self._lag, speed, acceleration, self.torsional_stiffness, self.torsional_damping)
        return spring_loaded_torque, spring

    def _kinematics(self) -> tuple[float, float]:
        r = self.rigid.response()
        return r.cardan_error, r.output_speed
