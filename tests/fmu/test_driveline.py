"""Motor and Load FMUs: their physics, refusals and FMU behaviour (the SSP system they
make: tests/fmu/test_driveline_ssp.py)."""

import math

import numpy as np
import pytest
from conftest import refused_keeping_state

from cardan_joint.framework import Reason
from cardan_joint.host.instance import ExtractedFMU, FmuInstance
from cardan_joint.models.load.model import Load
from cardan_joint.models.motor.model import Motor


@pytest.fixture(scope="module")
def component_fmus(motor_fmu_path, load_fmu_path):
    return {"Motor": motor_fmu_path, "Load": load_fmu_path}


@pytest.fixture(scope="module")
def motor_unzipped(component_fmus):
    with ExtractedFMU(component_fmus["Motor"]) as motor:
        yield motor.directory


# --- physics ---------------------------------------------------------------


def _ode_reference(motor, load_torques, steps):
    """The motor's speed and angle by a tight numerical integration of
    J w' = T_s (1 - w / w0) - T_L, independent of the closed form."""
    from scipy.integrate import solve_ivp

    w, angle, out = motor.speed_start, motor.angle_start, []
    for load_torque, h in zip(load_torques, steps):

        def rhs(t, y, load_torque=load_torque):
            torque = motor.stall_torque * (1.0 - y[0] / motor.no_load_speed)
            return [(torque - load_torque) / motor.rotor_inertia, y[0]]

        solution = solve_ivp(rhs, (0.0, h), [w, angle], method="DOP853", rtol=1e-13, atol=1e-12)
        w, angle = solution.y[:, -1]
        out.append((w, angle))
    return out


def test_motor_steps_follow_the_exact_run_up_at_any_step_size():
    rng = np.random.default_rng(7)
    motor = Motor(
        stall_torque=80.0, no_load_speed=150.0, rotor_inertia=0.1, speed_start=5.0, angle_start=1.0
    )
    steps = rng.uniform(1e-4, 0.2, 30)
    loads = rng.uniform(-50.0, 70.0, 30)
    reference = _ode_reference(motor, loads, steps)
    for load_torque, h, (w, angle) in zip(loads, steps, reference):
        motor.load_torque = load_torque
        assert motor.step(h) is None
        assert motor.speed == pytest.approx(w, rel=1e-10, abs=1e-9)
        assert motor.angle == pytest.approx(angle, rel=1e-10, abs=1e-9)
        # The acceleration output is the ODE's right-hand side at the step's end.
        speed, acceleration, _, torque = motor.outputs()
        assert torque == pytest.approx(80.0 * (1 - speed / 150.0), rel=1e-14)
        assert acceleration == pytest.approx((torque - load_torque) / 0.1, rel=1e-12)


def test_motor_run_up_from_rest_is_the_exponential():
    motor = Motor(stall_torque=60.0, no_load_speed=100.0, rotor_inertia=0.3)
    motor.load_torque = 15.0
    tau, final = 0.3 * 100.0 / 60.0, 100.0 * (1 - 15.0 / 60.0)
    for k in range(1, 101):
        motor.step(0.01)
        t = 0.01 * k
        assert motor.speed == pytest.approx(final * (1 - math.exp(-t / tau)), rel=1e-12)
        assert motor.angle == pytest.approx(final * (t - tau * (1 - math.exp(-t / tau))), rel=1e-11)


def test_load_torque_is_inertia_drag_and_constant():
    load = Load(inertia=0.4, drag=0.2, constant_torque=-3.0)
    load.speed, load.acceleration = 12.0, -5.0
    assert load.outputs() == (0.4 * -5.0 + 0.2 * 12.0 - 3.0,)


@pytest.mark.parametrize(
    "change, words",
    [
        ({"load_torque": math.nan}, ["input load_torque = nan", "not a finite number"]),
        ({"load_torque": 2e9}, ["load_torque = 2000000000.0 N.m", "[-1000000000.0, 1000000000.0]"]),
        # Within range, but it would drive the rotor past its speed limit in this step.
        ({"load_torque": 9e8}, ["rotor speed to", "beyond the limit 100000.0 rad/s"]),
    ],
)
def test_motor_refuses_unusable_inputs_and_keeps_its_state(change, words):
    motor = Motor(stall_torque=60.0, no_load_speed=100.0, rotor_inertia=0.3)
    refused_keeping_state(motor, change, words, "load_torque")


def test_bad_step_sizes_and_parameters_are_refused():
    motor = Motor()
    assert "step size = nan s" in motor.step(math.nan).message
    assert "step size = -0.1 s" in motor.step(-0.1).message
    motor = Motor(rotor_inertia=0.0)
    refusal = motor.step(1e-3)
    assert (refusal.code, refusal.variable, refusal.value, refusal.limit) == (
        Reason.OUT_OF_RANGE,
        "rotor_inertia",
        0.0,
        1e-9,
    )
    assert "parameter rotor_inertia = 0.0 kg.m2 is outside its range" in refusal.message
    assert "input speed = inf" in Load(speed=math.inf).step(1e-3).message


# --- FMUs ------------------------------------------------------------------


@pytest.mark.parametrize("name", ["Motor", "Load"])
def test_component_fmus_pass_validation_with_units_and_dependencies(component_fmus, name):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    assert validate_fmu(str(component_fmus[name])) == []
    description = read_model_description(str(component_fmus[name]))
    variables = {v.name: v for v in description.modelVariables}
    if name == "Load":
        assert variables["drag"].declaredType is None and variables["drag"].unit == "N.m.s/rad"
        torque = description.outputs[0]
        assert {v.name for v in torque.dependencies} == {"speed", "acceleration"}
    else:
        dependencies = {
            u.variable.name: {v.name for v in u.dependencies} for u in description.outputs
        }
        assert dependencies["acceleration"] == {"load_torque"} and dependencies["speed"] == set()


def test_motor_fmu_refuses_a_nan_load_torque_and_says_why(motor_unzipped):
    messages = []
    with FmuInstance.open(motor_unzipped, name="m", messages=messages) as motor:
        motor.set(load_torque=10.0)
        motor.step(0.1)
        speed = motor.get("speed")
        motor.set(load_torque=math.nan)
        assert motor.try_step(0.1) == 3  # a refused step: fmi2Error
        assert any(
            text.startswith(
                "t = 0.1 s: input load_torque = nan N.m is not a finite "
                "number (limit 1000000000.0 N.m); step of 0.1 s refused, "
                "the motor stays at t = 0.1 s"
            )
            for _, _, text in messages
        )
        motor.set(load_torque=10.0)
        assert motor.get("speed") == speed
        # Parameters are fixed after initialization: the change is refused, not applied.
        assert motor.try_set(stall_torque=1.0) == 3  # fmi2Error
        assert any("parameter stall_torque is fixed" in text for _, _, text in messages)


def test_motor_fmu_holds_only_the_outputs_that_depend_on_an_invalid_input(motor_unzipped):
    messages = []
    with FmuInstance.open(motor_unzipped, name="m", messages=messages) as motor:
        motor.set(load_torque=10.0)
        motor.step(0.1)
        valid = motor.get_outputs()
        motor.set(load_torque=math.inf)
        assert motor.get_outputs() == valid  # acceleration held, the rest unchanged
        assert any("outputs that depend on it are held" in text for _, _, text in messages)


def test_motor_fmu_state_round_trips_through_bytes(motor_unzipped):
    with FmuInstance.open(motor_unzipped, name="m") as motor:
        motor.set(load_torque=10.0)
        motor.step(0.05)
        state = motor.deserialize_state(motor.serialize_state(motor.get_state()))
        motor.step(0.05)
        first = motor.get("speed", "angle")
        motor.set_state(state)
        motor.time = 0.05
        motor.step(0.05)
        assert motor.get("speed", "angle") == first
