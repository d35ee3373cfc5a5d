"""Long runs (the slow layer): the joint stepped a million revolutions stays exact;
a state rolled back after ten thousand FMU steps replays them bit for bit; the
repeated or instrumented C-host runs whose quick case is in tests/fmu (thirty
concurrent starts, the 2,000-cycle memory run of FMI 3.0, the rest of the valgrind
matrix)."""

import math
from fractions import Fraction

import numpy as np
import pytest
from test_concurrent_start import started_together
from test_damaged_resources import VALGRIND_SLOW, needs_valgrind, no_invalid_access_under_valgrind
from test_instance_memory import cycles_leave_less_than_a_kilobyte_each

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.physics import cardan_error


def test_a_million_revolutions_at_constant_speed_stay_exact():
    # 1e6 revolutions of 2 pi * 0.98 rad per step at 0.5 s: the stepped joint's
    # input and output angle against exact rational arithmetic.
    speed = 2 * math.pi * 1.96  # rad/s
    step = 0.5
    steps = 1_020_409  # a little over 1e6 revolutions
    # Without life: the angle is the subject here, and a million steps of a turn
    # each would integrate a million damage increments for nothing.
    joint = CardanJoint(False, input_speed=speed, bend_angle=0.5, yoke_phase=0.3)
    for _ in range(steps):
        assert joint.step(step) is None
    two_pi = Fraction("6.283185307179586476925286766559005768394")
    exact_input = steps * Fraction(speed) * Fraction(step)
    assert exact_input / two_pi > 1e6
    assert abs(float(exact_input - Fraction(joint.input_angle))) < 1e-8
    exact_input_float = float(exact_input)
    turns = math.floor(exact_input / two_pi)
    fraction = float(exact_input - turns * two_pi)
    expected_output = exact_input + Fraction(cardan_error(fraction + 0.3, 0.5))
    outputs = joint.outputs()
    assert abs(float(Fraction(outputs[1]) - expected_output)) < 1e-8
    assert abs(outputs[0] - exact_input_float) <= math.ulp(exact_input_float)


def test_different_fmus_started_at_once_thirty_of_thirty(
    concurrent_host, unzipped_fmu, propshaft_unzipped, fmi3_unzipped
):
    started_together(concurrent_host, (unzipped_fmu, propshaft_unzipped, fmi3_unzipped), 30)


def test_two_thousand_fmi3_cycles_leave_less_than_a_kilobyte_each(request):
    cycles_leave_less_than_a_kilobyte_each(request, 3)


@needs_valgrind
@pytest.mark.parametrize(
    "version, name, damage",
    VALGRIND_SLOW,
    ids=[f"fmi{v}-{n}-{d.__name__}" for v, n, d in VALGRIND_SLOW],
)
def test_under_valgrind_no_invalid_access_in_the_fmus_code(
    request, tmp_path, version, name, damage
):
    no_invalid_access_under_valgrind(request, tmp_path, version, name, damage)


def test_state_rollback_is_bit_for_bit_after_ten_thousand_steps(model_description, unzipped_fmu):
    rng = np.random.default_rng(3)
    inputs = [
        dict(
            input_speed=rng.uniform(5, 50),
            input_acceleration=rng.uniform(-5, 5),
            bend_angle=rng.uniform(-1, 1),
            load_torque=rng.uniform(-50, 50),
        )
        for _ in range(10_000)
    ]
    joint = FmuInstance(model_description, unzipped_fmu)

    def run():
        trace = []
        for u in inputs:
            joint.set(**u)
            joint.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1e-3)
            trace.append(tuple(joint.get_outputs().values()))
        return trace

    try:
        for _ in range(7):
            joint.step(1e-3)
        saved = joint.get_state()
        serialized = joint.serialize_state(saved)
        first = run()
        other = joint.get_state()  # a second, independent copy
        joint.set_state(saved)
        assert run() == first
        joint.set_state(other)
        assert tuple(joint.get_outputs().values()) == first[-1]
        # A serialized state restores in a fresh instance.
        fresh = FmuInstance(model_description, unzipped_fmu, name="fresh")
        try:
            state = fresh.deserialize_state(serialized)
            fresh.set_state(state)
            fresh.free_state(state)
            joint, original = fresh, joint
            assert run() == first
            joint = original
        finally:
            fresh.close()
        joint.free_state(saved)
        joint.free_state(other)
    finally:
        joint.close()
