"""Issue 4: rollback, serialization, reset, many instances, several builds in one process.
Rollback after ten thousand steps: tests/system/test_long_runs.py."""

import ctypes
import sys

import numpy as np
from conftest import build_fmu
from robustness_support import REFUSED, all_reals

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint


def test_a_state_serialized_into_a_larger_buffer_fills_only_its_own_bytes(
    model_description, unzipped_fmu
):
    joint = FmuInstance(model_description, unzipped_fmu)
    try:
        state = joint.get_state()
        exact = joint.serialize_state(state)
        fmu = joint.fmu
        buffer = ctypes.create_string_buffer(b"\xaa" * (len(exact) + 64), len(exact) + 64)
        status = fmu.fmi2SerializeFMUstate(fmu.component, state, buffer, len(buffer))
        assert status == 0 and buffer.raw == exact + b"\xaa" * 64
        joint.free_state(state)
    finally:
        joint.close()


def test_state_includes_the_revolution_counter(model_description, unzipped_fmu):
    joint = FmuInstance(model_description, unzipped_fmu, start_values={"input_speed": 5000.0})
    try:
        saved = joint.get_state()
        angle = joint.get("input_angle", "crosspiece_quaternion_0")
        for _ in range(10):
            joint.step(0.1)  # ~800 revolutions
        joint.set_state(saved)
        assert joint.get("input_angle", "crosspiece_quaternion_0") == angle
        joint.free_state(saved)
    finally:
        joint.close()


def test_reset_returns_to_the_start_values(model_description, unzipped_fmu):
    fresh = FmuInstance(model_description, unzipped_fmu, name="fresh")
    joint = FmuInstance(model_description, unzipped_fmu, start_values={"bend_angle": 1.0})
    try:
        for _ in range(20):
            joint.step(0.01)
        path = list(sys.path)
        joint.fmu.reset()
        assert sys.path == path  # a reset is no new instantiation of the Python slave
        assert all_reals(joint) == all_reals(fresh)
        joint.fmu.setupExperiment(startTime=0.0)
        joint.fmu.enterInitializationMode()
        joint.fmu.exitInitializationMode()
        joint.time = 0.0
        for j in (joint, fresh):
            for _ in range(20):
                j.step(0.01)
        assert all_reals(joint) == all_reals(fresh)
    finally:
        joint.close()
        fresh.close()


def test_a_hundred_instances_in_one_process_are_independent(model_description, unzipped_fmu):
    joints, models = [], []
    try:
        for k in range(100):
            start = dict(
                bend_angle=-1.2 + 0.024 * k,
                yoke_phase=0.05 * k,
                input_speed=1.0 + k,
                crosspiece_inertia_3=0.001 * k,
            )
            joints.append(
                FmuInstance(model_description, unzipped_fmu, name=f"joint{k}", start_values=start)
            )
            models.append(CardanJoint(**start))
        for step in range(30):
            for k in np.random.default_rng(step).permutation(100):  # interleaved, shuffled
                joints[k].set(load_torque=float(step * k))
                models[k].load_torque = float(step * k)
                joints[k].step(0.003)
                models[k].step(0.003)
        for joint, model in zip(joints, models):
            assert list(joint.get_outputs().values()) == list(model.outputs())
    finally:
        for joint in joints:
            joint.close()


def test_builds_with_other_names_and_defaults_coexist_in_one_process(
    tmp_path, model_description, unzipped_fmu
):
    other = build_fmu(
        tmp_path, "--name=OtherJoint", "--set", "bend_angle=0.2", "--set", "max_bend_angle=0.3"
    )
    same_name = build_fmu(tmp_path / "b", "--set", "bend_angle=0.7")
    loaded = []
    try:
        for path in (other, same_name):
            loaded.append(FmuInstance.open(path, name=path.stem))
        default = FmuInstance(model_description, unzipped_fmu, name="default")
        loaded.append(default)
        bends = [j.get("bend_angle")["bend_angle"] for j in loaded]
        assert bends == [0.2, 0.7, table.BY_NAME["bend_angle"].start]
        # Each runs its own guard: 0.35 rad is beyond OtherJoint's 0.3, within the others' 80 deg.
        loaded[0].set(bend_angle=0.35)
        assert loaded[0].try_step(0.01) == REFUSED
        loaded[1].set(bend_angle=0.35)
        assert loaded[1].try_step(0.01) == 0
    finally:
        for joint in loaded:
            joint.close()
