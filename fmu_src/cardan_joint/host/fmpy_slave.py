"""FMPy's low-level slave of an unzipped FMU, and FMI 2.0's logging callbacks:
what `instance.FmuInstance` is built on."""

from typing import Any


def fmpy_slave(model_description, unzipped: str, name: str):
    from fmpy.fmi2 import FMU2Slave
    from fmpy.fmi3 import FMU3Slave

    fmi3 = model_description.fmiVersion.startswith("3")
    return (FMU3Slave if fmi3 else FMU2Slave)(
        guid=model_description.guid,
        unzipDirectory=unzipped,
        modelIdentifier=model_description.coSimulation.modelIdentifier,
        instanceName=name,
    )


def logging_callbacks(sink: Any) -> Any:
    """FMI 2 callbacks whose logger appends (status, category, message) to `sink`."""
    from fmpy.fmi2 import defaultCallbacks, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE

    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(
        lambda env, instance, status, category, message: sink.append(
            (status, category.decode(), message.decode())
        )
    )
    callbacks.allocateMemory = defaultCallbacks.allocateMemory
    callbacks.freeMemory = defaultCallbacks.freeMemory
    return callbacks
