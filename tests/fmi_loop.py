"""A minimal co-simulation master on FMPy's low-level FMU2Slave/FMU3Slave API, for tests."""

from math import prod

from fmpy.fmi2 import (FMU2Slave, defaultCallbacks, fmi2CallbackFunctions,
                       fmi2CallbackLoggerTYPE)
from fmpy.fmi3 import FMU3Slave

from cardan_joint import variables as table

_ARRAY_ROWS = {g.name: g.rows for g in table.fmi3_variables() if len(g.rows) > 1}


def logging_callbacks(sink):
    """FMI callbacks whose logger appends (status, category, message) to `sink`."""
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(
        lambda env, instance, status, category, message: sink.append(
            (status, category.decode(), message.decode())))
    callbacks.allocateMemory = defaultCallbacks.allocateMemory
    callbacks.freeMemory = defaultCallbacks.freeMemory
    return callbacks


class JointInstance:
    """One FMU instance (FMI 2.0 or 3.0) with name-based access to its Float variables."""

    def __init__(self, model_description, unzipped, name="joint", start_values=None,
                 start_time=0.0, messages=None):
        self.fmi3 = model_description.fmiVersion.startswith("3")
        self.references = {v.name: v.valueReference for v in model_description.modelVariables}
        self.sizes = {v.name: prod(int(d.start) for d in getattr(v, "dimensions", []) or [])
                      for v in model_description.modelVariables}
        self.outputs = [v.name for v in model_description.modelVariables
                        if v.causality == "output"]
        slave = FMU3Slave if self.fmi3 else FMU2Slave
        self.fmu = slave(guid=model_description.guid, unzipDirectory=unzipped,
                         modelIdentifier=model_description.coSimulation.modelIdentifier,
                         instanceName=name)
        if self.fmi3:
            # FMPy keeps the callback on the FMU object, so it outlives the instance.
            self.fmu.instantiate(logMessage=None if messages is None else (
                lambda env, status, category, message: messages.append(
                    (status, category.decode(), message.decode()))))
            self.fmu.enterInitializationMode(startTime=start_time)
        else:
            # Kept on the instance: ctypes callbacks must outlive the FMU.
            self.callbacks = None if messages is None else logging_callbacks(messages)
            self.fmu.instantiate(callbacks=self.callbacks, loggingOn=messages is not None)
            self.fmu.setupExperiment(startTime=start_time)
            self.fmu.enterInitializationMode()
        if start_values:
            self.set(**start_values)
        self.fmu.exitInitializationMode()
        self.time = start_time

    def set(self, **values):
        setter = self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal
        setter([self.references[n] for n in values], list(values.values()))

    def get(self, *names):
        """Values by name; an FMI 3 array comes as a list."""
        if not self.fmi3:
            return dict(zip(names, self.fmu.getReal([self.references[n] for n in names])))
        flat = iter(self.fmu.getFloat64([self.references[n] for n in names],
                                        sum(self.sizes[n] for n in names)))
        return {n: [next(flat) for _ in range(self.sizes[n])] if self.sizes[n] > 1
                else next(flat) for n in names}

    def get_flat_outputs(self):
        """Every output by its FMI 2 name (FMI 3 arrays split into their elements)."""
        values = {}
        for name, value in self.get_outputs().items():
            rows = _ARRAY_ROWS.get(name)
            values.update(zip((row.name for row in rows), value) if rows else [(name, value)])
        return values

    def get_outputs(self):
        return self.get(*self.outputs)

    def step(self, step_size):
        self.fmu.doStep(currentCommunicationPoint=self.time, communicationStepSize=step_size)
        self.time += step_size

    def try_step(self, step_size):
        """Step; return the FMI status (a refused step leaves the time where it was)."""
        from fmpy.fmi1 import FMICallException

        try:
            self.step(step_size)
            return 0
        except FMICallException as refusal:
            return refusal.status

    def save_state(self):
        return self.fmu.getFMUState() if self.fmi3 else self.fmu.getFMUstate()

    def restore_state(self, state):
        (self.fmu.setFMUState if self.fmi3 else self.fmu.setFMUstate)(state)

    def serialize(self, state):
        return bytes((self.fmu.serializeFMUState if self.fmi3 else self.fmu.serializeFMUstate)(state))

    def deserialize(self, data):
        return (self.fmu.deserializeFMUState if self.fmi3 else self.fmu.deSerializeFMUstate)(data)

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
