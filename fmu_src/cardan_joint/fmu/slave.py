"""The pythonfmu slave: maps FMI variables onto `physics.CardanJoint`.

No equation lives here. What does live here is the FMI plumbing that pythonfmu
0.7.0 gets wrong for a robust component: any Python exception reaching its C
layer becomes fmi2Fatal, so every method it calls catches everything; a
refused step returns False (fmi2Discard) with the joint untouched; the
complete state (including the revolution counter) is saved for
fmi2GetFMUstate; and every problem is also written to stderr, because
pythonfmu drops log messages unless debug logging is on.
"""

import math
from operator import attrgetter

from pythonfmu.enums import Fmi2Status

from .. import variables as table
from ..physics.model import CardanJoint
from .base import TableSlave

_KNOWN = table.INPUTS + table.PARAMETERS
_NAMES = _KNOWN + table.OUTPUTS
_FIRST_OUTPUT = len(_KNOWN)
assert tuple(v.name for v in table.VARIABLES) == _NAMES, \
    "the slave's value references assume inputs, then parameters, then outputs"
assert table.OUTPUTS[0] == "input_angle", "held outputs keep the first one, the state, live"
_INPUT_REFERENCES = range(len(table.INPUTS))
_NAN_OUTPUTS = (math.nan,) * len(table.OUTPUTS)
_OUTPUT_DEPENDENCIES = tuple(frozenset(table.BY_NAME[n].depends_on) for n in table.OUTPUTS)
_inputs_of = attrgetter(*table.INPUTS)
# What FMPy and most masters pass every step: all inputs, all outputs, in order.
_ALL_INPUTS = list(_INPUT_REFERENCES)
_ALL_OUTPUTS = list(range(_FIRST_OUTPUT, len(_NAMES)))


class CardanJointSlave(TableSlave):
    table = table
    description = ("Exact Cardan (Hooke) universal joint: output shaft motion, crosspiece "
                   "orientation and dynamics, input torque and secondary couples")
    # Start values that differ from the table's, written in by the build script.
    start_overrides: dict = {}

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._joint = CardanJoint(**self.start_overrides)
        self._start_time = 0.0
        self._initialized = False
        self._outputs = None            # cached outputs; None = recompute on next read
        self._inputs_checked = False
        self._outputs_held, self._inputs_held = _NAN_OUTPUTS, _inputs_of(self._joint)
        if not (self._joint.parameter_fault or self._joint.input_problem()):
            self._outputs_held = self._joint.outputs()
        for name in _NAMES:
            self._register(table.BY_NAME[name])

    # --- life cycle ----------------------------------------------------------

    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        try:
            self._start_time = float(start_time)
            self._restart()
        except Exception as error:
            self._fault("setup_experiment", error)

    def _restart(self):
        """Re-apply the start time and parameters (before initialization ends)."""
        self._joint.start(self._start_time)
        self._outputs = None
        self._inputs_checked = False

    def exit_initialization_mode(self):
        try:
            self._restart()
            self._initialized = True
            problem = self._joint.parameter_fault
            if problem:
                self._report(f"{problem}; every step will be refused until it is fixed",
                             Fmi2Status.error)
        except Exception as error:
            self._fault("exit_initialization_mode", error)

    def do_step(self, current_time, step_size):
        try:
            joint = self._joint
            time = joint.time
            joint.time = current_time
            problem = joint.step(step_size)
            if problem:
                joint.time = time
                self._report(f"t = {current_time!r} s: {problem}; step of {step_size!r} s "
                             f"refused, the joint stays at t = {current_time!r} s",
                             Fmi2Status.discard)
                return False
            self._outputs = None
            self._inputs_checked = True
            return True
        except Exception as error:
            self._fault("do_step", error)
            return False

    # --- values --------------------------------------------------------------

    def _current_outputs(self):
        joint = self._joint
        if not self._inputs_checked:
            problem = joint.parameter_fault or joint.input_problem()
            if problem:
                self._report(f"t = {joint.time!r} s: {problem}; outputs that depend on it "
                             f"are held at the last valid inputs", Fmi2Status.warning)
                return self._held_outputs(joint)
            self._inputs_checked = True
        self._outputs = self._outputs_held = joint.outputs()
        self._inputs_held = _inputs_of(joint)
        return self._outputs

    def _held_outputs(self, joint):
        """Outputs with invalid inputs: each output that depends on an invalid input
        keeps its last valid value, the others (and the input angle, the state)
        follow the valid inputs, as the declared dependencies promise."""
        live = (joint.input_angle,) + self._outputs_held[1:]
        if joint.parameter_fault:
            return live
        invalid = joint.invalid_inputs()
        current = _inputs_of(joint)
        try:
            for name, held in zip(table.INPUTS, self._inputs_held):
                if name in invalid:
                    setattr(joint, name, held)
            fresh = joint.outputs()
        finally:
            for name, value in zip(table.INPUTS, current):
                setattr(joint, name, value)
        return tuple(live[i] if dependencies & invalid else fresh[i]
                     for i, dependencies in enumerate(_OUTPUT_DEPENDENCIES))

    def get_real(self, vrs):
        try:
            outputs = self._outputs or self._current_outputs()
            if vrs == _ALL_OUTPUTS:
                return list(outputs)
            joint = self._joint
            return [outputs[vr - _FIRST_OUTPUT] if vr >= _FIRST_OUTPUT
                    else getattr(joint, _KNOWN[vr]) for vr in vrs]
        except Exception as error:
            return self._get_real_failed(vrs, error, len(_NAMES))

    def set_real(self, vrs, values):
        try:
            joint = self._joint
            if vrs == _ALL_INPUTS:
                for name, value in zip(table.INPUTS, values):
                    setattr(joint, name, float(value))
                self._outputs = None
                self._inputs_checked = False
                return
            parameters_changed = False
            for vr, value in zip(vrs, values):
                if self._write_permitted(vr, self._name_of(vr), value, len(table.INPUTS),
                                         _FIRST_OUTPUT):
                    setattr(joint, _KNOWN[vr], float(value))
                    parameters_changed = parameters_changed or vr not in _INPUT_REFERENCES
            if parameters_changed:
                self._restart()        # outputs in initialization mode see them at once
            self._outputs = None
            self._inputs_checked = False
        except Exception as error:
            self._fault("set_real", error)

    @staticmethod
    def _name_of(vr):
        return _NAMES[vr] if 0 <= vr < len(_NAMES) else f"value reference {vr}"

    # --- FMU state -----------------------------------------------------------

    _state_owner = "joint"

    def _state_parts(self):
        return {"joint": self._joint.state(), "outputs_held": list(self._outputs_held),
                "inputs_held": list(self._inputs_held)}

    def _restore_parts(self, state):
        held_outputs = tuple(float(v) for v in state["outputs_held"])
        held_inputs = tuple(float(v) for v in state["inputs_held"])
        if len(held_outputs) != len(table.OUTPUTS) or len(held_inputs) != len(table.INPUTS):
            raise ValueError("the state is from another version of the FMU")
        self._joint.restore(state["joint"])           # all or nothing
        self._outputs_held, self._inputs_held = held_outputs, held_inputs

    def _state_restored(self):
        self._outputs = None
        self._inputs_checked = False
