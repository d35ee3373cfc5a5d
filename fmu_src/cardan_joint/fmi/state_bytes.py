"""An FMU state as bytes: the serialized form both loaders ask the slave's class for."""

import json


class StateBytes:
    """Mixed into `core.SlaveCore`; `_API` and `_STATE` name the FMI functions."""

    _API: str
    _STATE: str

    # Class methods: both loaders call these on the class, not on an instance.
    @classmethod
    def _fmu_state_to_bytes(cls, state):
        try:
            return json.dumps(state).encode("utf-8")
        except Exception as error:
            return json.dumps({"invalid_state": f"serialization failed: {error}"}).encode()

    @classmethod
    def _fmu_state_from_bytes(cls, data):
        # Returning a marked state instead of raising: the set-state call then says why.
        try:
            state = json.loads(data.decode("utf-8"))
            if not isinstance(state, dict):
                raise ValueError("not a serialized FMU state of this project")
            return state
        except Exception as error:
            reason = f"{cls._API}DeSerializeFMU{cls._STATE} got no valid state: {error}"
            return {"invalid_state": reason}
