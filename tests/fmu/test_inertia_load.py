"""InertiaLoad: the exact step against an independent tight integration, its
refusals, and the FMU."""

import math

import numpy as np
import pytest
from conftest import refused_keeping_state

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.inertia_load.model import InertiaLoad
from cardan_joint.physics.rotor import exact_rotor_step


def _ode(load, torques, steps):
    """Speed and angle by DOP853 on J w' = T - c w - T0, independent of the closed form."""
    from scipy.integrate import solve_ivp

    w, angle, out = load.speed_start, load.angle_start, []
    for torque, h in zip(torques, steps):

        def rhs(t, y, torque=torque):
            return [(torque - load.drag * y[0] - load.constant_torque) / load.inertia, y[0]]

        solution = solve_ivp(rhs, (0.0, h), [w, angle], method="DOP853", rtol=1e-13, atol=1e-12)
        w, angle = solution.y[:, -1]
        out.append((w, angle))
    return out


@pytest.mark.parametrize("drag", [0.0, 1e-7, 0.3, 40.0])
def test_steps_follow_the_integrated_ode_at_any_step_size_and_drag(drag):
    rng = np.random.default_rng(11)
    load = InertiaLoad(
        inertia=0.7, drag=drag, constant_torque=4.0, speed_start=-3.0, angle_start=0.5
    )
    steps, torques = rng.uniform(1e-5, 0.3, 25), rng.uniform(-30.0, 60.0, 25)
    for torque, h, (w, angle) in zip(torques, steps, _ode(load, torques, steps)):
        load.drive_torque = torque
        assert load.step(h) is None
        assert load.speed == pytest.approx(w, rel=1e-10, abs=1e-9)
        assert load.angle == pytest.approx(angle, rel=1e-10, abs=1e-9)
        speed, acceleration, _ = load.outputs()
        assert acceleration == pytest.approx((torque - drag * speed - 4.0) / 0.7, rel=1e-12)


def test_exact_step_is_continuous_through_zero_drag():
    # The series branch (|z| <= 0.05) and the closed branch meet without a jump,
    # and zero drag is uniform acceleration.
    assert exact_rotor_step(2.0, 1.0, 0.0, 3.0, 0.5) == (3.5, 0.5 * (2.0 + 0.5 * 3.0 * 0.5))
    below, above = (exact_rotor_step(2.0, 1.0, d, 3.0, 1.0) for d in (0.05, 0.05 + 1e-15))
    assert below == pytest.approx(above, rel=1e-14)


def test_a_constant_torque_turns_the_load_backwards_from_standstill():
    load = InertiaLoad(inertia=2.0, drag=0.0, constant_torque=10.0)
    assert load.step(1.0) is None
    assert load.speed == pytest.approx(-5.0) and load.angle == pytest.approx(-2.5)


@pytest.mark.parametrize(
    "change, words",
    [
        ({"drive_torque": math.nan}, ["input drive_torque = nan", "not a finite number"]),
        ({"drive_torque": 2e9}, ["drive_torque = 2000000000.0 N.m"]),
        ({"drive_torque": 9e8}, ["load speed to", "beyond the limit 100000.0 rad/s"]),
    ],
)
def test_refuses_unusable_inputs_and_keeps_its_state(change, words):
    load = InertiaLoad(inertia=0.3)
    load.drive_torque = 50.0
    refused_keeping_state(load, change, words, "drive_torque")


def test_a_zero_inertia_is_a_parameter_fault():
    problem = InertiaLoad(inertia=0.0).step(0.1)
    assert "parameter inertia = 0.0" in problem.message


def test_fmu_validates_declares_dependencies_and_steps_as_the_physics(inertia_load_fmu_path):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    assert validate_fmu(str(inertia_load_fmu_path)) == []
    description = read_model_description(str(inertia_load_fmu_path))
    dependencies = {u.variable.name: {v.name for v in u.dependencies} for u in description.outputs}
    assert dependencies == {"speed": set(), "acceleration": {"drive_torque"}, "angle": set()}
    model = InertiaLoad(drag=0.2)
    with FmuInstance.open(
        str(inertia_load_fmu_path), name="load", start_values={"drag": 0.2}
    ) as fmu:
        for k, torque in enumerate((40.0, -5.0, 25.0)):
            fmu.set(drive_torque=torque)
            model.drive_torque = torque
            fmu.time = k * 0.1
            fmu.step(0.1)
            model.step(0.1)
            assert tuple(fmu.get_outputs().values()) == model.outputs()
