"""The propshaft physics refuses bad values by name; its build refuses bad starts."""

import math

import pytest

from cardan_joint.models.propshaft import (
    Propshaft,
)

D = math.radians
LIMIT = D(15.0)


def test_refusals_name_variable_value_and_limit():
    steep = Propshaft(2, shaft_1_side_angle=D(20), max_working_angle=D(15))
    assert "joint_1_working_angle" in str(steep.parameter_fault)
    assert "max_working_angle" in str(steep.parameter_fault)
    assert "refused" not in str(steep.parameter_fault) and steep.step(0.1) == steep.parameter_fault
    assert steep.time == 0.0
    vertical = Propshaft(2, shaft_0_side_angle=math.pi / 2)
    assert "shaft_0_side_angle" in str(vertical.parameter_fault)
    guard = Propshaft(2, max_working_angle=math.pi / 2)
    assert "max_working_angle" in str(guard.parameter_fault)
    ok = Propshaft(2)
    ok.input_speed = math.nan
    assert "input_speed = nan" in str(ok.step(0.1)) and ok.time == 0.0
    ok.input_speed = 2e5
    assert "outside its range" in str(ok.step(0.1))
    assert ok.invalid_inputs() == {"input_speed"}
    ok.input_speed, ok.input_acceleration = 9e4, 1e8
    assert "overflows" in str(ok.step(1.0)) and ok.time == 0.0


def test_warnings_never_refuse():
    shaft = Propshaft(2, shaft_0_side_angle=D(6), shaft_2_side_angle=D(1), input_speed=500.0)
    assert shaft.parameter_fault is None and len(shaft.warnings()) >= 2
    assert shaft.step(0.01) is None


def test_state_round_trip():
    shaft = Propshaft(3, shaft_2_top_angle=D(3), input_speed=30.0)
    shaft.step(0.37)
    saved = shaft.state()
    before = shaft.outputs()
    shaft.step(1.0)
    shaft.restore(saved)
    assert shaft.outputs() == before


def test_bad_steps_and_unknown_names_are_refused():
    shaft = Propshaft(2)
    for h in (0.0, -0.1, math.nan):
        assert "step size" in str(shaft.step(h)) and shaft.time == 0.0
    with pytest.raises(TypeError, match="bend_angle"):
        Propshaft(2, bend_angle=0.1)


@pytest.mark.parametrize(
    "settings, values, words",
    [
        ({"joints": 5}, {}, ["--joints 5", "2, 3, 4"]),
        ({"joints": 2}, {"shaft_2_yoke_phase": 0.1}, ["shaft_2_yoke_phase", "2-joint"]),
        (
            {"joints": 3},
            {"shaft_1_side_angle": 0.6},
            ["joint_1_working_angle", "max_working_angle"],
        ),
        ({"joints": 2}, {"input_speed": math.inf}, ["input_speed = inf"]),
    ],
)
def test_the_build_refuses_propshaft_start_values_that_cannot_run(settings, values, words):
    from cardan_joint.models import StartValueError, model

    with pytest.raises(StartValueError) as refusal:
        model("Propshaft").check_start_values(values, settings)
    for word in words:
        assert word in str(refusal.value)


def test_joints_applies_to_the_propshaft_only(capsys):
    from cardan_joint.build import main

    with pytest.raises(SystemExit):
        main(["--joints", "3"])
    assert "--joints does not apply to UniversalJoint" in capsys.readouterr().err


@pytest.mark.parametrize("joints, shaft", [(2, 1), (3, 2)])
@pytest.mark.parametrize("bore", [0.0762, 0.08])
def test_a_tube_without_a_wall_is_refused_by_name(joints, shaft, bore):
    # Outer diameter 0.0762 m by default: a bore as wide or wider leaves no wall.
    tube = Propshaft(joints, **{f"shaft_{shaft}_inner_diameter": bore})
    fault = tube.parameter_fault
    assert fault is not None and fault.variable == f"shaft_{shaft}_inner_diameter"
    assert fault.value == bore and fault.limit == 0.0762 and fault.unit == "m"
    text = str(fault)
    assert f"parameter shaft_{shaft}_inner_diameter = {bore} m" in text and "0.0762" in text
    assert type(fault).from_message(fault.message) == fault
    assert tube.step(0.01) == fault and tube.time == 0.0
    assert Propshaft(joints, **{f"shaft_{shaft}_inner_diameter": 0.0761}).parameter_fault is None
