"""What a model's step takes from its parameters alone travels in its step
state, computed when the model starts, not at every step
(`propshaft.step.fixed_by_layout`, `physics.life.life_rule`): each value
against its own derivation, and computed again wherever a parameter can
change (the start that initialization makes after a parameter set, a restored
state)."""

import json
import math
import random

import pytest

from cardan_joint.models.compliant_joint.model import CompliantJoint
from cardan_joint.models.compliant_joint.step import STATE as COMPLIANT_STATE
from cardan_joint.models.compliant_propshaft.model import CompliantPropshaft
from cardan_joint.models.propshaft.chain import chain
from cardan_joint.models.propshaft.model import Propshaft
from cardan_joint.models.propshaft.step import state_names
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.step import LIFE_STATE

JOINTS = (2, 3, 4)


def named(state: tuple, joints: int) -> dict:
    """The propshaft's step state by name (a compliant one's starts with it)."""
    names = state_names(joints)
    return dict(zip(names, state[: len(names)]))


def catalogue_scale(rated_torque: float, constant: float, exponent: float) -> float:
    """1/L_h per (rad x rad/s x (N.m)^p), from L_h = K / (A n) (T_r / |T|)^p
    with A in degrees and n in rpm (docs/life.md)."""
    degrees_per_radian = 180.0 / math.pi
    rpm_per_radian_per_second = 60.0 / (2.0 * math.pi)
    return degrees_per_radian * rpm_per_radian_per_second / constant / rated_torque**exponent


def assert_constants_follow(state: dict, shaft: Propshaft) -> None:
    """The state's constants against the shaft's parameters, derived apart:
    each bend's sine and cosine; each turn Delta_k from joint k's pin to the
    next's less its cardan error, from the chain's pins and offsets; the
    singularities' reach at the largest bend (|cos psi| sin b = 1 where
    cosh(Im psi) = 1 / sin b); the life rule's scale."""
    joints = shaft.joints
    bends = shaft.layout.working_angles
    for k in range(1, joints + 1):
        assert state[f"joint_{k}_bend_sine"] == pytest.approx(math.sin(bends[k - 1]), abs=1e-15)
        assert state[f"joint_{k}_bend_cosine"] == pytest.approx(math.cos(bends[k - 1]), abs=1e-15)
    pinned = chain(shaft.layout, 0.7, 0.0, 0.0)
    phases = (0.0, *shaft.layout.phases)
    offsets = (0.0, *pinned.offsets)
    for k in range(1, joints):
        joint = shaft.layout.joints[k - 1]
        error = offsets[k] - offsets[k - 1] - phases[k - 1] - joint.twist
        turn = pinned.pins[k] - pinned.pins[k - 1] - error
        assert state[f"joint_{k}_turn_sine"] == pytest.approx(math.sin(turn), abs=1e-12)
        assert state[f"joint_{k}_turn_cosine"] == pytest.approx(math.cos(turn), abs=1e-12)
    assert (state[f"joint_{joints}_turn_sine"], state[f"joint_{joints}_turn_cosine"]) == (0.0, 1.0)
    reach = math.acosh(1.0 / max(math.sin(b) for b in bends))
    assert state["singularity_reach"] == pytest.approx(reach, rel=1e-14)
    scale = catalogue_scale(shaft.rated_torque, shaft.life_constant, shaft.life_exponent)
    assert state["life_rate_scale"] == pytest.approx(scale, rel=1e-14)


def bent(rng: random.Random, joints: int) -> dict:
    values: dict = {"max_working_angle": 0.6}
    for k in range(joints + 1):
        values[f"shaft_{k}_side_angle"] = rng.uniform(-0.2, 0.2)
        values[f"shaft_{k}_top_angle"] = rng.uniform(-0.2, 0.2)
    for k in range(1, joints):
        values[f"shaft_{k}_yoke_phase"] = rng.uniform(-4.0, 4.0)
    values["rated_torque"] = rng.uniform(10.0, 5000.0)
    values["life_constant"] = rng.uniform(1e3, 1e9)
    values["life_exponent"] = rng.uniform(1.0, 10.0)
    return values


@pytest.mark.parametrize("joints", JOINTS)
def test_the_propshafts_constants_are_its_parameters_own(joints):
    rng = random.Random(joints)
    for _ in range(5):
        shaft = Propshaft(joints, **bent(rng, joints))
        assert_constants_follow(named(shaft.step_state(), joints), shaft)


@pytest.mark.parametrize("joints", JOINTS)
def test_a_parameter_set_before_initialization_reaches_the_constants(joints):
    """Parameters set after instantiation take effect at the start that
    initialization makes: the step state then carries their constants."""
    rng = random.Random(10 + joints)
    shaft = Propshaft(joints)
    before = named(shaft.step_state(), joints)
    for name, value in bent(rng, joints).items():
        setattr(shaft, name, value)
    shaft.start(0.0)
    after = named(shaft.step_state(), joints)
    assert_constants_follow(after, shaft)
    assert after["joint_1_bend_sine"] != before["joint_1_bend_sine"]
    assert after["life_rate_scale"] != before["life_rate_scale"]


def test_a_restored_state_carries_its_own_parameters_constants():
    """A state saved with other parameters brings their constants back, to the bit."""
    rng = random.Random(3)
    saved_shaft = Propshaft(3, **bent(rng, 3))
    saved_shaft.run(0.0, 1e-3, (100.0, 0.0, 50.0))
    saved = json.loads(json.dumps(saved_shaft.state()))
    other = Propshaft(3, **bent(rng, 3))
    other.restore(saved)
    assert other.step_state() == saved_shaft.step_state()
    assert_constants_follow(named(other.step_state(), 3), other)


@pytest.mark.parametrize("joints", (2, 3))
def test_the_compliant_propshaft_carries_the_rigid_ones_constants(joints):
    rng = random.Random(20 + joints)
    drive = CompliantPropshaft(joints, **bent(rng, joints))
    state = named(drive.step_state(), joints)
    assert_constants_follow(state, drive.rigid)
    assert state == named(drive.rigid.step_state(), joints)


def test_the_joints_rule_scale_is_its_parameters_own_and_follows_them():
    joint = CardanJoint(rated_torque=250.0, life_constant=2e5, life_exponent=3.0)
    state = dict(zip(LIFE_STATE, joint.step_state()))
    assert state["life_rate_scale"] == pytest.approx(catalogue_scale(250.0, 2e5, 3.0), rel=1e-14)
    joint.rated_torque, joint.life_exponent = 4000.0, 10.0 / 3.0
    joint.start(0.0)  # as initialization does after a parameter set
    state = dict(zip(LIFE_STATE, joint.step_state()))
    assert state["life_rate_scale"] == pytest.approx(
        catalogue_scale(4000.0, 2e5, 10.0 / 3.0), rel=1e-14
    )
    saved = json.loads(json.dumps(joint.state()))
    other = CardanJoint()
    other.restore(saved)
    assert other.step_state() == joint.step_state()


def test_the_compliant_joint_carries_the_rigid_ones_scale():
    drive = CompliantJoint(rated_torque=250.0, life_constant=2e5, life_exponent=3.0)
    state = dict(zip(COMPLIANT_STATE, drive.step_state()))
    assert state["life_rate_scale"] == pytest.approx(catalogue_scale(250.0, 2e5, 3.0), rel=1e-14)


@pytest.mark.parametrize("rated_torque", [0.0, -1.0, math.nan])
def test_a_rule_out_of_its_ranges_leaves_numbers_in_the_state(rated_torque):
    """A rated torque of 0 would divide by 0 and a negative one make the
    scale complex: the parameters' fault refuses every step, and the state the
    runtime takes holds numbers."""
    for model in (CardanJoint(rated_torque=rated_torque), Propshaft(2, rated_torque=rated_torque),
                  CompliantJoint(rated_torque=rated_torque)):  # fmt: skip
        assert model.parameter_fault is not None
        assert all(type(value) in (bool, int, float) for value in model.step_state())
