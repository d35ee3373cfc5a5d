"""The complete FMU state of every slave (mixed into `core.SlaveCore`): taken as
plain JSON-able values, checked whole before any of it is applied, so that a
refused state leaves every value as it was, and refused at deserialization for
the same reasons as at set."""

import json
from collections.abc import Callable
from typing import Any


class FmuStates:
    """Needs the slave's model, its held values, `_report` and the FMI names."""

    _model: Any
    _start_time: float
    _initialized: bool
    _outputs: tuple | None
    _inputs_checked: bool
    _outputs_held: tuple
    _inputs_held: tuple
    table: Any
    owner: str
    _STATUS: Any
    _API: str
    _STATE: str
    _report: Callable[[str, Any], None]
    _fault: Callable[[str, BaseException], None]
    _new_model: Callable[[], Any]
    _watches_passed: Callable[[], Any]
    _rearm: Callable[[tuple], None]

    def _get_fmu_state(self):
        try:
            return {
                "model": self._model.state(),
                "start_time": self._start_time,
                "initialized": self._initialized,
                "outputs_held": list(self._outputs_held),
                "inputs_held": list(self._inputs_held),
                "watches_passed": self._watches_passed(),
            }
        except Exception as error:
            self._fault(f"{self._API}GetFMU{self._STATE}", error)
            return {"invalid_state": f"{self._API}GetFMU{self._STATE} failed: {error}"}

    def _checked_state(self, state) -> tuple:
        """(model state, start time, initialized, held outputs, held inputs, watches
        passed) of a state, every part but the model's own checked; raises naming what is wrong.
        Nothing is applied: a refused state must leave every value as it was."""
        if not isinstance(state, dict):
            raise ValueError("not a serialized FMU state of this project")
        if "invalid_state" in state:
            raise ValueError(state["invalid_state"])
        held_outputs = tuple(float(v) for v in state["outputs_held"])
        held_inputs = tuple(float(v) for v in state["inputs_held"])
        # Before 1.1 the model's values were kept under "joint", in another format.
        if (
            "model" not in state
            or len(held_outputs) != len(self.table.OUTPUTS)
            or len(held_inputs) != len(self.table.INPUTS)
        ):
            raise ValueError("the state is from another version of the FMU")
        start_time, initialized = float(state["start_time"]), bool(state["initialized"])
        passed = tuple(map(str, state.get("watches_passed", ())))
        return state["model"], start_time, initialized, held_outputs, held_inputs, passed

    def _set_fmu_state(self, state) -> bool:
        """Take `state`; True when it is refused: then every value is as it was,
        the outputs' cache included (the runtime keeps serving its arrays)."""
        try:
            model_state, start_time, initialized, outputs, inputs, passed = self._checked_state(
                state
            )
            self._model.restore(model_state)  # all or nothing, and the last part that can fail
        except Exception as error:
            self._report(
                f"{self._API}SetFMU{self._STATE} ignored, the {self.owner} keeps its "
                f"state: {type(error).__name__}: {error}",
                self._STATUS.error,
            )
            return True
        self._outputs = None
        self._inputs_checked = False
        try:
            self._start_time, self._initialized = start_time, initialized
            self._outputs_held, self._inputs_held = outputs, inputs
            self._rearm(passed)
        except Exception as error:
            self._fault(f"{self._API}SetFMU{self._STATE}", error)
        return False

    # A class method: pythonfmu's loaders called it on the class.
    @classmethod
    def _fmu_state_to_bytes(cls, state):
        try:
            return json.dumps(state).encode("utf-8")
        except Exception as error:
            return json.dumps({"invalid_state": f"serialization failed: {error}"}).encode()

    def _fmu_state_from_bytes(self, data):
        """The state in `data`, or None once the reason Set would refuse it is
        reported (the runtime then answers Error and hands out no state). The
        model's part is checked by restoring it into a model of its own."""
        try:
            state = json.loads(data.decode("utf-8"))
            self._new_model().restore(self._checked_state(state)[0])
            return state
        except Exception as error:
            function = "DeSerialize" if self._API == "fmi2" else "Deserialize"
            self._report(
                f"{self._API}{function}FMU{self._STATE} refused the bytes, no state was "
                f"made: {type(error).__name__}: {error}",
                self._STATUS.error,
            )
            return None
