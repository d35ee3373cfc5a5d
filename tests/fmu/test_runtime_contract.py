"""Issue 24 items 4 and 5 and issue 26's batch set, FMI 2.0 and 3.0: a step-mode
state set into an instance that was never initialized puts it in step mode with
that state; a refused step ends an fmusim-style loop and FMPy's simulate_fmu as a
failure naming variable, value, limit and time, and a master that corrects its
input goes on bit for bit; a batch set with a fixed parameter sets the rest."""

import subprocess

import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave

from cardan_joint.host.instance import FmuInstance

STEPS, H = 100, 1e-3
INPUTS = {"input_speed": 20.0, "bend_angle": 0.3, "load_torque": 4.0}
FIXTURES = {2: ("fmu_path", "unzipped_fmu", "c_host"), 3: ("fmi3_path", "fmi3_unzipped", "c_host3")}


def opened(request, version):
    path, unzipped = (request.getfixturevalue(name) for name in FIXTURES[version][:2])
    return read_model_description(str(path)), unzipped


class Raw:
    """FMPy's low-level slave of either version, and the joint's scalar outputs."""

    def __init__(self, description, unzipped, name):
        self.fmi3 = description.fmiVersion.startswith("3")
        kind = FMU3Slave if self.fmi3 else FMU2Slave
        self.fmu = kind(
            guid=description.guid,
            unzipDirectory=unzipped,
            modelIdentifier=description.coSimulation.modelIdentifier,
            instanceName=name,
        )
        self.vr = {v.name: v.valueReference for v in description.modelVariables}
        self.outputs = [
            v.valueReference
            for v in description.modelVariables
            if v.causality == "output" and not getattr(v, "dimensions", None)
        ]
        self.fmu.instantiate()

    def initialize(self):
        if not self.fmi3:
            self.fmu.setupExperiment(startTime=0.0)
        self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()

    def run(self, start, steps):
        rows = []
        for k in range(start, start + steps):
            refs = [self.vr[name] for name in INPUTS]
            values = [value + 1e-3 * k for value in INPUTS.values()]
            (self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal)(refs, values)
            self.fmu.doStep(currentCommunicationPoint=k * H, communicationStepSize=H)
            get = self.fmu.getFloat64 if self.fmi3 else self.fmu.getReal
            rows.append(tuple(get(self.outputs)))
        return rows

    def serialized_state(self):
        if self.fmi3:
            return self.fmu.serializeFMUState(self.fmu.getFMUState())
        return self.fmu.serializeFMUstate(self.fmu.getFMUstate())

    def restore(self, data):
        if self.fmi3:
            self.fmu.setFMUState(self.fmu.deserializeFMUState(data))
        else:
            self.fmu.setFMUstate(self.fmu.deSerializeFMUstate(data))


@pytest.mark.parametrize("version", [2, 3])
def test_a_step_mode_state_set_into_a_fresh_instance_steps_on(request, version):
    description, unzipped = opened(request, version)
    original = Raw(description, unzipped, "original")
    original.initialize()
    original.run(0, STEPS)
    data = original.serialized_state()
    continued = original.run(STEPS, STEPS)
    original.fmu.terminate()
    original.fmu.freeInstance()

    fresh = Raw(description, unzipped, "fresh")  # instantiated, never initialized
    fresh.restore(data)
    assert fresh.run(STEPS, STEPS) == continued  # bit for bit
    # In step mode with the state's parameters: a fixed one is refused, terminate is legal.
    set_real = fresh.fmu.setFloat64 if fresh.fmi3 else fresh.fmu.setReal
    with pytest.raises(FMICallException):
        set_real([fresh.vr["max_bend_angle"]], [0.5])
    fresh.fmu.terminate()
    fresh.fmu.freeInstance()


@pytest.mark.parametrize("version", [2, 3])
def test_a_refused_step_fails_an_fmusim_style_loop_and_a_corrected_input_goes_on(request, version):
    _, unzipped = opened(request, version)
    host = request.getfixturevalue(FIXTURES[version][2])
    run = subprocess.run(
        [str(host), "refusal", str(unzipped), "bend_angle", "2.0"],
        env={"PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    assert "fmusim: failed at t = 0.05 with status 3" in run.stdout, run.stdout
    # The failure names variable, value, limit and time.
    assert "t = 0.05 s: input bend_angle = 2.0 rad" in run.stdout
    assert "max_bend_angle" in run.stdout
    # Logged at the status returned: `fmusim --log-level error` shows it.
    assert "LOG 3 logStatusError: t = 0.05 s: input bend_angle = 2.0 rad" in run.stderr
    assert "continued: identical" in run.stdout


@pytest.mark.parametrize("version", [2, 3])
def test_fmpy_simulate_fmu_raises_on_a_refused_step(request, version):
    path = request.getfixturevalue(FIXTURES[version][0])
    with pytest.raises(Exception, match="Error|error|3"):
        simulate_fmu(
            str(path), stop_time=0.01, output_interval=1e-3, start_values={"bend_angle": 2.0}
        )


@pytest.mark.parametrize("version", [2, 3])
def test_a_batch_set_with_a_fixed_parameter_sets_the_other_values(request, version):
    description, unzipped = opened(request, version)
    messages = []
    joint = FmuInstance(description, unzipped, messages=messages)
    try:
        refs = [joint.references["yoke_phase"], joint.references["load_torque"]]
        set_values = joint.fmu.setFloat64 if joint.fmi3 else joint.fmu.setReal
        get_values = joint.fmu.getFloat64 if joint.fmi3 else joint.fmu.getReal
        before = get_values(refs)[0]
        with pytest.raises(FMICallException):
            set_values(refs, [0.7, 33.0])
        assert get_values(refs) == [before, 33.0]
        text = messages[-1][2]
        assert "yoke_phase is fixed" in text and "other" in text, messages
    finally:
        joint.close()


def test_libcosim_fails_a_refused_run(fmu_path):
    from cardan_joint.host.cosim import run_libcosim

    with pytest.raises(RuntimeError, match="stepping failed"):
        run_libcosim(fmu_path, 0.01, 1e-3, {"bend_angle": 2.0}, ["output_angle"])
