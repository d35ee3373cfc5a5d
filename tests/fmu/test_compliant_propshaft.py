"""CompliantPropshaft: the independent 3-D propshaft construction (tests/reference)
with the hand-written spring-damper law; the FMU of three joints."""

import math

import mpmath
import pytest
from conftest import build_fmu
from reference.propshaft import PropshaftReference

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.compliant_propshaft.model import CompliantPropshaft
from cardan_joint.models.compliant_propshaft.variables import compliant_propshaft_table
from cardan_joint.models.propshaft.refusals import PropshaftReason

D = math.radians
SIDE, TOP, PHASES = [D(2), D(-9), D(4), D(0)], [D(0), D(3), D(-5), D(1)], [0.4, -0.2]
SHAFTS, CROSS = [0.2, 0.1], (0.02, 0.03, 0.01)
SPEED, RATE, OUT_SPEED, OUT_RATE, ANGLE0 = 30.0, -4.0, 29.0, 3.0, 0.7
K, C, TWIST0 = 5e3, 3.0, 0.002


def _start_values():
    values = {f"shaft_{k}_side_angle": SIDE[k] for k in range(4)}
    values.update({f"shaft_{k}_top_angle": TOP[k] for k in range(4)})
    values.update({f"shaft_{k + 1}_yoke_phase": PHASES[k] for k in range(2)})
    values.update({f"shaft_{k + 1}_inertia": SHAFTS[k] for k in range(2)})
    values.update({f"crosspiece_inertia_{i + 1}": CROSS[i] for i in range(3)})
    return dict(
        values,
        input_angle_start=ANGLE0,
        twist_angle_start=TWIST0,
        torsional_stiffness=K,
        torsional_damping=C,
        input_speed=SPEED,
        input_acceleration=RATE,
        output_speed=OUT_SPEED,
        output_acceleration=OUT_RATE,
    )


def _expected(reference, offsets, t):
    """Outputs at t: the reference's kinematics and torque path, the spring by hand."""
    with mpmath.workdps(40):
        t_mp = mpmath.mpf(t)
        angle = ANGLE0 + t_mp * (SPEED + RATE * t_mp / 2)
        start_output = ANGLE0 + offsets[-1] - TWIST0
        output_angle = start_output + t_mp * (OUT_SPEED + OUT_RATE * t_mp / 2)
        kinematic = reference.at(angle, SPEED + RATE * t, RATE, 0.0, offsets)
        twist = kinematic["angles"][-1] - output_angle
        torque = K * twist + C * (kinematic["speeds"][-1] - (OUT_SPEED + OUT_RATE * t))
        loaded = reference.at(angle, SPEED + RATE * t, RATE, torque, offsets)
        return {
            "input_angle": float(angle),
            "output_angle": float(output_angle),
            "twist_angle": float(twist),
            "output_torque": float(torque),
            "kinematic_output_speed": float(kinematic["speeds"][-1]),
            "spring_energy": float(K * twist**2 / 2),
            "input_torque": float(loaded["input_torque"]),
        }


def test_spring_damper_on_the_3d_construction_at_every_step():
    reference = PropshaftReference(SIDE, TOP, PHASES, SHAFTS, CROSS)
    offsets = reference.start_offsets(ANGLE0)
    shaft = CompliantPropshaft(3, **_start_values())
    names = shaft.table.OUTPUTS
    for n in range(5):
        if n:
            assert shaft.step(0.04) is None
        got = dict(zip(names, shaft.outputs()))
        for name, value in _expected(reference, offsets, 0.04 * n).items():
            assert got[name] == pytest.approx(value, rel=1e-10, abs=1e-10), name


def test_layout_and_spring_parameters_are_checked():
    steep = CompliantPropshaft(2, shaft_1_side_angle=D(20), max_working_angle=D(15))
    assert steep.step(0.1).code is PropshaftReason.WORKING_ANGLE
    loose = CompliantPropshaft(2, torsional_damping=-1.0)
    assert loose.step(0.1).variable == "torsional_damping"
    assert CompliantPropshaft(4).table is compliant_propshaft_table(4)


def test_fmu_of_three_joints_steps_as_the_physics(tmp_path_factory):
    path = build_fmu(
        tmp_path_factory.mktemp("cp"), "--model", "CompliantPropshaft", "--joints", "3"
    )
    assert path.name == "CompliantPropshaft3.fmu"
    model = CompliantPropshaft(3, **_start_values())
    with FmuInstance.open(str(path), name="cp", start_values=_start_values()) as fmu:
        for k in range(3):
            fmu.time = k * 0.05
            fmu.step(0.05)
            model.step(0.05)
            fmu.set(input_speed=model.input_speed, output_speed=model.output_speed)
            assert tuple(fmu.get_outputs().values()) == pytest.approx(model.outputs(), rel=1e-15)
