"""A Python FMI 2.0 host with the standard library only (ctypes): runs the FMU in
any Python, with or without numpy or FMPy, as a plain C host does.

    python stdlib_host.py DIR STEPS DT [name=value ...]

prints "instance NULL" when fmi2Instantiate refuses, else every variable's value
after STEPS steps as "name=repr(value)"; logger calls go to stderr as "LOG <status>: <text>".
"""

import ctypes
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

LOGGER = ctypes.CFUNCTYPE(
    None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p
)


class Callbacks(ctypes.Structure):
    _fields_ = [
        ("logger", LOGGER),
        ("allocate", ctypes.c_void_p),
        ("free", ctypes.c_void_p),
        ("step_finished", ctypes.c_void_p),
        ("environment", ctypes.c_void_p),
    ]


def log(environment, name, status, category, message):
    print(f"LOG {status}: {message.decode(errors='replace')}", file=sys.stderr)


def main(directory: Path, steps: int, dt: float, settings: list) -> None:
    description = ElementTree.parse(directory / "modelDescription.xml").getroot()
    identifier = description.find("CoSimulation").get("modelIdentifier")
    references = {
        v.get("name"): int(v.get("valueReference"))
        for v in description.iter("ScalarVariable")
        if v.find("Real") is not None
    }
    fmu = ctypes.CDLL(str(directory / "binaries" / "linux64" / f"{identifier}.so"))
    fmu.fmi2Instantiate.restype = ctypes.c_void_p
    libc = ctypes.CDLL(None)
    logger = LOGGER(log)
    callbacks = Callbacks(
        logger,
        ctypes.cast(libc.calloc, ctypes.c_void_p).value,
        ctypes.cast(libc.free, ctypes.c_void_p).value,
        None,
        None,
    )
    instance = fmu.fmi2Instantiate(
        b"stdlib_host",
        1,
        description.get("guid").encode(),
        (directory / "resources").as_uri().encode(),
        ctypes.byref(callbacks),
        0,
        0,
    )
    if not instance:
        print("instance NULL")
        return
    instance = ctypes.c_void_p(instance)
    for setting in settings:
        name, value = setting.split("=")
        vr = ctypes.c_uint(references[name])
        fmu.fmi2SetReal(instance, ctypes.byref(vr), 1, ctypes.byref(ctypes.c_double(float(value))))
    fmu.fmi2SetupExperiment(
        instance, 0, ctypes.c_double(0), ctypes.c_double(0), 0, ctypes.c_double(0)
    )
    fmu.fmi2EnterInitializationMode(instance)
    fmu.fmi2ExitInitializationMode(instance)
    for step in range(steps):
        status = fmu.fmi2DoStep(instance, ctypes.c_double(step * dt), ctypes.c_double(dt), 1)
        assert status == 0, f"fmi2DoStep returned {status} at step {step}"
    for name, vr in references.items():
        value = ctypes.c_double()
        fmu.fmi2GetReal(instance, ctypes.byref(ctypes.c_uint(vr)), 1, ctypes.byref(value))
        print(f"{name}={value.value!r}")
    fmu.fmi2Terminate(instance)
    fmu.fmi2FreeInstance(instance)


if __name__ == "__main__":
    main(Path(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4:])
