"""The watches (framework/watches.py, fmi/watching.py) in built FMUs: each
watched output past its limit is logged once, as a warning of category
logWatch naming the output, value, limit and time; the run goes on. FMI 2.0
and 3.0 alike."""

import pytest

from cardan_joint.host.instance import FmuInstance, status_of

WARNING = 1


def _watch_messages(messages):
    return [text for status, category, text in messages if category == "logWatch"]


def _run(fmu, stop_time, step=1e-3, start_values=None):
    messages: list = []
    with FmuInstance.open(fmu, start_values=start_values, messages=messages) as model:
        for _ in range(round(stop_time / step)):
            model.step(step)
        end = model.get("life_consumed", "output_torque")
    return messages, end


@pytest.mark.parametrize("fmi_version", [2, 3])
def test_compliant_joint_at_its_defaults_warns_once_of_torque_and_once_of_life(built, fmi_version):
    # The output shaft held still: the spring winds up to 200,555 N.m at 2 s.
    messages, end = _run(built("CompliantJoint", fmi_version=fmi_version), 2.0)
    watched = _watch_messages(messages)
    assert len(watched) == 2, watched
    torque, life = watched
    assert torque.startswith("input_torque = ") and "past rated_torque = 1000 N.m" in torque
    assert life.startswith("life_consumed = ") and "is past 1:" in life
    assert all(" s is past " in text and "at t = " in text for text in watched)
    assert all(s == WARNING for s, c, _ in messages if c == "logWatch")
    # The run went on to its end: the life and the torque of the whole run.
    assert end["life_consumed"] == pytest.approx(12.3, rel=1e-2)
    assert end["output_torque"] == pytest.approx(200_555, rel=1e-4)


def test_the_warning_comes_at_the_step_that_passes_the_limit(compliant_joint_fmu_path):
    messages: list = []
    with FmuInstance.open(compliant_joint_fmu_path, messages=messages) as model:
        torque = 0.0
        while abs(torque) <= 1000.0:
            assert _watch_messages(messages) == []
            model.step(1e-3)
            torque = model.get("input_torque")["input_torque"]
        (text,) = _watch_messages(messages)
        assert f"at t = {round(model.time, 12)!r} s" in text


def test_a_stated_twist_warns_once(compliant_joint_fmu_path):
    messages, _ = _run(compliant_joint_fmu_path, 0.2, start_values={"twist_angle_warning": 0.01})
    twist = [t for t in _watch_messages(messages) if t.startswith("twist_angle = ")]
    assert len(twist) == 1 and "past twist_angle_warning = 0.01 rad" in twist[0]


def test_a_state_from_before_the_warning_warns_again_one_from_after_it_does_not(
    compliant_joint_fmu_path,
):
    messages: list = []
    with FmuInstance.open(compliant_joint_fmu_path, messages=messages) as model:
        before = model.get_state()
        for _ in range(20):
            model.step(1e-3)
        after = model.get_state()
        assert len(_watch_messages(messages)) == 1
        for state, again in ((after, 0), (before, 1)):
            messages.clear()
            model.set_state(state)
            model.time = 0.02 if state is after else 0.0
            for _ in range(20):
                model.step(1e-3)
            assert len(_watch_messages(messages)) == again
        model.free_state(before)
        model.free_state(after)


def test_the_propshafts_tube_past_its_critical_speed_margin_warns_once(propshaft_fmu_path):
    # 1.4 m steel tube: first bending critical speed about 683 rad/s; 0.75 of it
    # is passed on a run-up from 400 rad/s at 2000 rad/s2.
    start = {"input_speed": 400.0, "input_acceleration": 2000.0}
    messages, _ = _propshaft_run(propshaft_fmu_path, start, 0.2)
    watched = _watch_messages(messages)
    assert len(watched) == 1 and watched[0].startswith("shaft_1_critical_speed_ratio = ")
    assert "past critical_speed_margin = 0.75" in watched[0]


def _propshaft_run(fmu, start_values, stop_time, step=1e-3):
    messages: list = []
    with FmuInstance.open(fmu, start_values=start_values, messages=messages) as model:
        for _ in range(round(stop_time / step)):
            model.step(step)
        end = model.get("shaft_1_critical_speed_ratio")
    return messages, end


@pytest.mark.parametrize("fmi_version", [2, 3])
def test_fmpys_simulate_runs_on_past_the_warnings(built, fmi_version, capfd, tmp_path):
    from fmpy import extract, simulate_fmu

    unzipped = extract(str(built("CompliantJoint", fmi_version=fmi_version)), unzipdir=tmp_path)
    capfd.readouterr()
    result = simulate_fmu(unzipped, stop_time=2.0, step_size=1e-3, output=["life_consumed"])
    assert result["time"][-1] == pytest.approx(2.0)
    assert result["life_consumed"][-1] == pytest.approx(12.3, rel=1e-2)
    # No logger turned on: FMI 2.0's runtime writes warnings to stderr, FMPy's
    # FMI 3.0 logger prints them; each once.
    text = "".join(capfd.readouterr())
    assert text.count("input_torque = ") == 1 and text.count("life_consumed = ") == 1, text


def test_a_state_with_malformed_watches_is_refused_whole(compliant_joint_fmu_path):
    import json

    messages: list = []
    with FmuInstance.open(compliant_joint_fmu_path, messages=messages) as model:
        model.step(1e-3)
        state = model.get_state()
        data = json.loads(model.serialize_state(state))
        model.free_state(state)
        data["watches_passed"] = 5
        data["model"]["lag"] = 123.0
        before = model.get("twist_angle")
        messages.clear()
        # Deserialize refuses what Set would refuse: no state is made, nothing changes.
        bad = json.dumps(data).encode()
        assert status_of(model.deserialize_state, bad) == 3
        assert any("refused the bytes" in text for _, _, text in messages)
        assert model.get("twist_angle") == before
