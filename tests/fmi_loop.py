"""A minimal co-simulation master on FMPy's low-level FMU2Slave API, for tests."""

from fmpy.fmi2 import (FMU2Slave, defaultCallbacks, fmi2CallbackFunctions,
                       fmi2CallbackLoggerTYPE)


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
    """One FMU instance with name-based access to its Real variables."""

    def __init__(self, model_description, unzipped, name="joint", start_values=None,
                 start_time=0.0, messages=None):
        self.references = {v.name: v.valueReference for v in model_description.modelVariables}
        self.outputs = [v.name for v in model_description.modelVariables
                        if v.causality == "output"]
        self.fmu = FMU2Slave(guid=model_description.guid, unzipDirectory=unzipped,
                             modelIdentifier=model_description.coSimulation.modelIdentifier,
                             instanceName=name)
        # Kept on the instance: ctypes callbacks must outlive the FMU.
        self.callbacks = None if messages is None else logging_callbacks(messages)
        self.fmu.instantiate(callbacks=self.callbacks, loggingOn=messages is not None)
        self.fmu.setupExperiment(startTime=start_time)
        self.fmu.enterInitializationMode()
        if start_values:
            self.set(**start_values)
        self.init_status = self._status_of(self.fmu.exitInitializationMode)
        self.time = start_time

    @staticmethod
    def _status_of(call, *args, **kwargs):
        """The FMI status of a call FMPy raises on (fmi2Discard or worse)."""
        from fmpy.fmi1 import FMICallException

        try:
            call(*args, **kwargs)
            return 0
        except FMICallException as refusal:
            return refusal.status

    def set(self, **values):
        self.fmu.setReal([self.references[n] for n in values], list(values.values()))

    def get(self, *names):
        return dict(zip(names, self.fmu.getReal([self.references[n] for n in names])))

    def get_outputs(self):
        return self.get(*self.outputs)

    def step(self, step_size):
        self.fmu.doStep(currentCommunicationPoint=self.time, communicationStepSize=step_size)
        self.time += step_size

    def try_step(self, step_size):
        """Step; return the FMI status (a refused step leaves the time where it was)."""
        return self._status_of(self.step, step_size)

    def try_set(self, **values):
        """Set; return the FMI status (fmi2Error for a call FMI does not allow)."""
        return self._status_of(self.set, **values)

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
