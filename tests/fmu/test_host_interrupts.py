"""Ctrl-C in a host whose Python runs its signal handlers (FMPy's own calls, no
`FmuInstance` holding the signals) lands in the slave's Python when a call
enters it: the runtime hands the KeyboardInterrupt back to the host, says the
call was interrupted, and leaves the instance in the error state (its slave
stopped part way): in a step of the slave's do_step, with the fast path or
plain calls, and in a change of mode."""

import os
import sys
import textwrap

import pytest
from test_no_debris import _child

# A host on FMPy's own calls (no FmuInstance holding the signals), whose Python
# runs its SIGINT handler: a Ctrl-C at the 5th step, sent from the model's own
# step (in Python), lands in the slave. The host must get it back.
PLAIN_HOST = textwrap.dedent(
    """
    import os, signal, sys
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    description = read_model_description(sys.argv[1])
    fmu = FMU2Slave(guid=description.guid, unzipDirectory=extract(sys.argv[1]),
                    modelIdentifier=description.coSimulation.modelIdentifier, instanceName="i")
    if sys.argv[2] == "plain":  # a slave without the fast path: get_real and friends
        fmu.instantiate()
        fmu.freeInstance()
        core = next(m for n, m in sys.modules.items() if n.endswith(".fmi.fast_path"))
        del core.FastPath.fast_layout
    callbacks = None
    if sys.argv[3:] == ["python_logger"]:  # the host's logger in Python, as FmuInstance's
        from fmpy.fmi2 import defaultCallbacks, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
        callbacks = fmi2CallbackFunctions()
        callbacks.logger = fmi2CallbackLoggerTYPE(lambda *message: None)
        callbacks.allocateMemory = defaultCallbacks.allocateMemory
        callbacks.freeMemory = defaultCallbacks.freeMemory
    fmu.instantiate(callbacks=callbacks)
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    if sys.argv[2] == "exit_initialization_mode":  # Ctrl-C as initialization ends
        core = next(m for n, m in sys.modules.items() if n.endswith(".fmi.core"))
        ending = core.SlaveCore.exit_initialization_mode

        def interrupted_end(self):
            os.kill(os.getpid(), signal.SIGINT)
            return ending(self)

        core.SlaveCore.exit_initialization_mode = interrupted_end
        try:
            fmu.exitInitializationMode()
            print("no interrupt", flush=True)
        except KeyboardInterrupt:
            print("KeyboardInterrupt", flush=True)
        try:  # the instance stays in the error state: no step
            fmu.doStep(0.0, 1e-3)
            print("stepped", flush=True)
        except Exception as error:
            print("step:", error, flush=True)
        sys.exit(3)
    fmu.exitInitializationMode()
    model = next(m for n, m in sys.modules.items() if n.endswith(".universal_joint.model"))
    calls = []

    def interrupted(method):
        def call(self, *args):
            calls.append(1)
            if len(calls) == 5:
                os.kill(os.getpid(), signal.SIGINT)
            return method(self, *args)
        return call

    model.CardanJoint.run = interrupted(model.CardanJoint.run)  # the slave's do_step runs it
    try:
        try:
            for k in range(100):
                fmu.doStep(k * 1e-3, 1e-3)
            print("no step interrupted", flush=True)
        except Exception as error:  # FMPy raises on the step's Error
            print("step:", error, flush=True)
            total = sum(range(100000))  # the host's Python goes on
            print("no interrupt", flush=True)
            sys.exit(4)
    except KeyboardInterrupt:
        print("KeyboardInterrupt after", len(calls), "steps", flush=True)
        sys.exit(3)
    """
)


def _host(fmu_path, call: str, *options: str, **environment: str) -> tuple[int, list[str], str]:
    """PLAIN_HOST interrupted in the slave's `call`, the runtime's messages on
    stderr: (its exit status, its output lines, all it said)."""
    process = _child(
        [sys.executable, "-c", PLAIN_HOST, str(fmu_path), call, *options],
        env={**os.environ, "CARDAN_JOINT_FMU_STDERR": "1", **environment},
    )
    try:
        out, err = process.communicate(timeout=60)
    finally:
        process.kill()
    return process.returncode, out.decode().splitlines(), out.decode() + err.decode()


@pytest.mark.parametrize("calls", ["fast_path", "plain"])
def test_ctrl_c_that_lands_in_the_slave_is_handed_back_to_the_host(fmu_path, calls):
    """The runtime clears the KeyboardInterrupt the slave raised, says the step was
    interrupted (Error: the instance can only be reset or freed, its slave having
    stopped part way) and raises it again in the host's Python, once; with the
    fast path's arrays and with plain calls."""
    status, out, said = _host(fmu_path, calls, CARDAN_JOINT_FMU_PYTHON_STEP="1")
    assert status == 3, said
    assert out[-1] == "KeyboardInterrupt after 5 steps", said
    assert said.count("was interrupted by a KeyboardInterrupt") == 1, said
    assert "the slave's do_step was interrupted by a KeyboardInterrupt" in said
    assert "Traceback" not in said


def test_ctrl_c_in_the_slave_reaches_a_host_whose_logger_is_python(fmu_path):
    """The interrupt is handed back after the call's last message: raised in a
    logger written in Python (a ctypes callback, as FmuInstance's) it would be
    dropped there, and the host would go on after a failed step."""
    status, out, said = _host(fmu_path, "fast_path", "python_logger",
                              CARDAN_JOINT_FMU_PYTHON_STEP="1")  # fmt: skip
    assert status == 3, said
    assert out[-1] == "KeyboardInterrupt after 5 steps", said


def test_ctrl_c_as_initialization_ends_leaves_the_instance_in_the_error_state(fmu_path):
    """A change of mode interrupted in the slave does not enter its new mode:
    the next doStep is refused, naming the error state."""
    status, out, said = _host(fmu_path, "exit_initialization_mode")
    assert status == 3, said
    assert out[-2:] == [
        "KeyboardInterrupt",
        "step: fmi2DoStep failed with status 3 (error).",
    ], said
    assert "the slave's exit_initialization_mode was interrupted by a KeyboardInterrupt" in said
    assert "fmi2DoStep is not allowed after an error that left the slave out of step" in said
