"""The FMU simulated by FMPy (simulate_fmu and the low-level FMU2Slave loop)
against the physics package stepped the same way."""

import math
from fractions import Fraction

import numpy as np
from fmpy import simulate_fmu

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.physics import cardan_error


def test_default_experiment_runs_with_plain_simulate_fmu(fmu_path, model_description):
    result = simulate_fmu(str(fmu_path))
    assert result["time"][-1] == float(model_description.defaultExperiment.stopTime)
    assert np.all(np.isfinite(result["output_speed"]))


def test_simulate_fmu_with_structured_input_arrays_matches_the_physics_package(fmu_path):
    h, n = 1e-3, 500
    t = np.arange(n + 1) * h
    signals = np.zeros(n + 1, dtype=[("time", float)] + [(name, float) for name in table.INPUTS])
    signals["time"] = t
    signals["input_acceleration"] = 40.0 * np.cos(3 * t)
    signals["input_speed"] = 12.0 + 40.0 / 3 * np.sin(3 * t)
    signals["bend_angle_acceleration"] = -0.8 * np.sin(2 * t)
    signals["bend_angle_rate"] = 0.4 * np.cos(2 * t)
    signals["bend_angle"] = 0.3 + 0.2 * np.sin(2 * t)
    signals["load_torque"] = 50 + 10 * t
    result = simulate_fmu(
        str(fmu_path),
        stop_time=n * h,
        output_interval=h,
        input=signals,
        start_values={"yoke_phase": 0.4, "crosspiece_inertia_2": 0.05},
    )
    assert len(result) == n + 1
    # FMPy records right after each doStep and sets the next inputs only then, so
    # sample k > 0 shows the inputs of step k-1 carried along their polynomials.
    joint = CardanJoint(yoke_phase=0.4, crosspiece_inertia_2=0.05)
    for k in range(n + 1):
        if k > 0:
            assert joint.step(float(result["time"][k] - result["time"][k - 1])) is None
        expected = joint.outputs() if k > 0 else None
        for name in table.INPUTS:
            setattr(joint, name, float(signals[name][k]))
        expected = expected or joint.outputs()
        for name, value in zip(table.OUTPUTS, expected):
            assert math.isclose(result[name][k], value, rel_tol=1e-12, abs_tol=1e-12), (name, k)


def test_low_level_loop_is_bit_for_bit_the_physics_package(model_description, unzipped_fmu):
    rng = np.random.default_rng(7)
    joint = FmuInstance(model_description, unzipped_fmu, start_values={"yoke_phase": 1.1})
    model = CardanJoint(yoke_phase=1.1)
    try:
        for _ in range(300):
            inputs = dict(
                input_speed=rng.uniform(-100, 100),
                input_acceleration=rng.uniform(-50, 50),
                bend_angle=rng.uniform(-1.2, 1.2),
                bend_angle_rate=rng.uniform(-0.1, 0.1),
                bend_angle_acceleration=rng.uniform(-0.1, 0.1),
                load_torque=rng.uniform(-10, 10),
            )
            joint.set(**inputs)
            for name, value in inputs.items():
                setattr(model, name, value)
            assert list(joint.get_outputs().values()) == list(model.outputs())
            h = float(rng.choice([1e-4, 1e-3, 1e-2]))
            joint.step(h)
            assert model.step(h) is None
    finally:
        joint.close()


def test_outputs_read_after_new_inputs_reflect_them(model_description, unzipped_fmu):
    joint = FmuInstance(model_description, unzipped_fmu)
    try:
        joint.step(0.01)
        before = joint.get("output_speed", "input_torque")
        joint.set(bend_angle=0.9, load_torque=100.0)
        after = joint.get("output_speed", "input_torque", "input_angle")
        model = CardanJoint(bend_angle=0.9, load_torque=100.0)
        model.step(0.01)
        model.bend_angle, model.load_torque = 0.9, 100.0
        expected = dict(zip(table.OUTPUTS, model.outputs()))
        assert after["output_speed"] == expected["output_speed"] != before["output_speed"]
        assert after["input_torque"] == expected["input_torque"] != before["input_torque"]
        assert after["input_angle"] == expected["input_angle"]
    finally:
        joint.close()


def _exact_after(speed, h, steps, phase, bend):
    two_pi = Fraction("6.283185307179586476925286766559005768394")
    gamma1 = steps * Fraction(speed) * Fraction(h)
    fraction = float(gamma1 - math.floor(gamma1 / two_pi) * two_pi)
    return gamma1, gamma1 + Fraction(cardan_error(fraction + phase, bend))


def test_a_million_revolutions_through_the_fmu_stay_within_1e_8_rad(unzipped_without_life):
    # 1e4 steps of 0.5 s at 100.3 rev/s, then 1e5 steps of 0.01 s continuing the same run.
    # The build without life: the angles are the subject, and the life integral
    # over 100 turns a step would make this a run of many minutes.
    from fmpy import read_model_description

    speed, phase, bend = 2 * math.pi * 200.6, 0.3, 0.5
    joint = FmuInstance(
        read_model_description(unzipped_without_life),
        unzipped_without_life,
        start_values=dict(input_speed=speed, bend_angle=bend, yoke_phase=phase),
    )
    try:
        for _ in range(10_000):
            joint.step(0.5)
        gamma1, gamma2 = _exact_after(speed, 0.5, 10_000, phase, bend)
        assert gamma1 / Fraction(2 * math.pi) > 1e6
        values = joint.get("input_angle", "output_angle")
        assert abs(float(Fraction(values["input_angle"]) - gamma1)) < 1e-8
        assert abs(float(Fraction(values["output_angle"]) - gamma2)) < 1e-8
        for _ in range(100_000):
            joint.step(0.01)
        exact_input = gamma1 + 100_000 * Fraction(speed) * Fraction(0.01)
        two_pi = Fraction("6.283185307179586476925286766559005768394")
        fraction = float(exact_input - math.floor(exact_input / two_pi) * two_pi)
        exact_output = exact_input + Fraction(cardan_error(fraction + phase, bend))
        values = joint.get("input_angle", "output_angle")
        assert abs(float(Fraction(values["input_angle"]) - exact_input)) < 1e-8
        assert abs(float(Fraction(values["output_angle"]) - exact_output)) < 1e-8
    finally:
        joint.close()
