"""The one FMU-instance helper: lifetime, extraction, names, log sink, FMI version."""

import os
import re
from types import SimpleNamespace

import pytest

from cardan_joint.host.fmu_info import MissingFMUError
from cardan_joint.host.instance import ExtractedFMU, FmuInstance, StepRefusedError


def test_open_unzips_and_removes_its_copy_on_leaving_the_block(fmu_path):
    with FmuInstance.open(fmu_path, start_values={"input_speed": 3.0}) as joint:
        unzipped = joint.fmu.unzipDirectory
        assert os.path.isdir(unzipped)
        joint.step(0.5)
        assert joint.get("input_angle") == {"input_angle": 1.5}
    assert not os.path.exists(unzipped)
    joint.close()  # a second close does nothing


def test_a_directory_is_used_as_is_and_left_in_place(unzipped_fmu):
    with ExtractedFMU(unzipped_fmu) as fmu:
        with fmu.instance("a") as a, fmu.instance("b", start_values={"input_speed": 2.0}) as b:
            a.step(1.0)
            b.step(1.0)
            assert a.values("input_angle") == [10.0]  # the FMU's default speed
            assert b.values("input_angle") == [2.0]
    assert os.path.isdir(unzipped_fmu)


def test_close_frees_the_instance_even_when_terminate_fails(model_description, unzipped_fmu):
    joint = FmuInstance(model_description, unzipped_fmu)
    freed = []
    real_free = joint.fmu.freeInstance
    joint._cleanup[0] = lambda: (freed.append(True), real_free())

    def failing_terminate():
        raise RuntimeError("terminate failed")

    joint._cleanup[1] = failing_terminate
    with pytest.raises(RuntimeError, match="terminate failed"):
        joint.close()
    assert freed == [True]


def test_a_failed_close_does_not_replace_what_the_block_raised(model_description, unzipped_fmu):
    # Ctrl-C handed back from inside a call leaves the instance in the error
    # state, where terminate fails: the block's KeyboardInterrupt goes on,
    # the failure a note on it.
    joint = FmuInstance(model_description, unzipped_fmu)

    def failing_terminate():
        raise RuntimeError("terminate failed")

    joint._cleanup[1] = failing_terminate
    with pytest.raises(KeyboardInterrupt) as raised:
        with joint:
            raise KeyboardInterrupt
    assert raised.value.__notes__ == ["closing 'instance' then failed too: terminate failed"]
    # Nothing raised in the block: the failure is raised.
    with pytest.raises(RuntimeError, match="terminate failed"), joint:
        joint._cleanup.append(failing_terminate)


def test_an_unknown_name_is_named(model_description, unzipped_fmu):
    with FmuInstance(model_description, unzipped_fmu) as joint:
        with pytest.raises(KeyError, match="'input_sped'; did you mean input_speed"):
            joint.set(input_sped=1.0)


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_a_refused_step_raises_the_fmus_own_reason(version, request):
    """Not FMPy's bare 'fmi2DoStep failed with status 2': the FMU's logged refusal."""
    fixtures = ("model_description", "unzipped_fmu")
    if version == "3.0":
        fixtures = ("fmi3_description", "fmi3_unzipped")
    description, unzipped = map(request.getfixturevalue, fixtures)
    with FmuInstance(description, unzipped) as joint:
        joint.step(0.25)
        joint.set(bend_angle=1.5)
        with pytest.raises(StepRefusedError) as refused:
            joint.step(0.1)
        assert refused.value.status >= 2  # discard or worse, as try_step returns it
        assert joint.try_step(0.1) == refused.value.status
    text = str(refused.value)
    assert text.startswith("UniversalJoint refused the step at t = 0.25 s: ")
    for named in ("bend_angle = 1.5 rad", "max_bend_angle", "80 deg", "t = 0.25 s"):
        assert named in text


def test_a_missing_fmu_names_the_command_that_builds_it(tmp_path):
    command = f"python build_fmu.py --model Propshaft --joints 3 --dest {tmp_path}"
    with pytest.raises(MissingFMUError, match=re.escape(command)):
        FmuInstance.open(tmp_path / "Propshaft3.fmu")


def test_the_message_sink_receives_the_fmus_log(model_description, unzipped_fmu):
    messages = []
    with FmuInstance(model_description, unzipped_fmu, messages=messages) as joint:
        joint.set(bend_angle=1.5)
        assert joint.try_step(0.1) != 0
        assert joint.time == 0.0
    assert any("bend_angle" in text for _, _, text in messages)


def test_a_state_serialized_in_one_instance_restores_in_another(model_description, unzipped_fmu):
    with (
        FmuInstance(model_description, unzipped_fmu, start_values={"input_speed": 7.0}) as joint,
        FmuInstance(model_description, unzipped_fmu, name="other") as other,
    ):
        joint.step(0.3)
        state = joint.get_state()
        serialized = joint.serialize_state(state)
        joint.free_state(state)
        restored = other.deserialize_state(serialized)
        other.set_state(restored)
        other.free_state(restored)
        assert other.get_outputs() == joint.get_outputs()


def test_an_fmi_version_without_an_adapter_is_refused_by_name(unzipped_fmu):
    description = SimpleNamespace(fmiVersion="1.0", modelName="Future", modelVariables=[])
    with pytest.raises(ValueError, match=r"FMI version 1.0 of 'Future' is not supported"):
        FmuInstance(description, unzipped_fmu)
