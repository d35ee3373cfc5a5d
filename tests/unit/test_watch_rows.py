"""The watches as data (framework/watches.py): compiled against a variable
table, armed from the parameters, each output warned of once; and every
model's rows name what its table has."""

import math
from types import SimpleNamespace

import pytest

from cardan_joint.framework.watches import Watch, arm, compile_watches, passed
from cardan_joint.models import discover
from cardan_joint.models.propshaft.variables import propshaft_table

ROWS = (
    Watch("input_torque", "rated_torque", "past the rating"),
    Watch("joint_*_life_consumed", 1.0, "life used up"),
    Watch("input_torque", "no_such_parameter", "never compiled"),
)


def test_a_glob_names_every_joints_output_and_a_missing_limit_watches_nothing():
    watched = compile_watches(ROWS, propshaft_table(3))
    assert [w.name for w in watched] == [
        "input_torque",
        "joint_1_life_consumed",
        "joint_2_life_consumed",
        "joint_3_life_consumed",
    ]
    outputs = propshaft_table(3).OUTPUTS
    assert all(outputs[w.slot] == w.name for w in watched)


def _armed(rated=1000.0, fired=()):
    table = propshaft_table(2)
    watched = compile_watches(ROWS, table)
    return table, arm(watched, SimpleNamespace(rated_torque=rated), fired)


def _outputs(table, **values):
    return tuple(values.get(name, 0.0) for name in table.OUTPUTS)


def test_each_output_past_its_limit_is_warned_of_once_by_magnitude():
    table, armed = _armed()
    armed, messages = passed(armed, _outputs(table, input_torque=-999.0), 0.1)
    assert messages == [] and len(armed.watches) == 3
    armed, messages = passed(armed, _outputs(table, input_torque=-1500.0), 0.2)
    assert messages == [
        "input_torque = -1500 N.m at t = 0.2 s is past rated_torque = 1000 N.m: past the "
        "rating (warned once; the run goes on)"
    ]
    armed, messages = passed(armed, _outputs(table, input_torque=-2000.0), 0.3)
    assert messages == [] and len(armed.watches) == 2
    armed, messages = passed(armed, _outputs(table, joint_2_life_consumed=1.5), 0.4)
    assert messages == [
        "joint_2_life_consumed = 1.5 at t = 0.4 s is past 1: life used up (warned once; "
        "the run goes on)"
    ]
    assert [w.name for w in armed.watches] == ["joint_1_life_consumed"]
    armed, messages = passed(armed, _outputs(table, joint_1_life_consumed=2.0), 0.5)
    assert armed == () and len(messages) == 1
    assert passed(armed, _outputs(table, joint_1_life_consumed=3.0), 0.6) == ((), [])


def test_a_limit_is_read_when_armed_and_a_passed_watch_stays_quiet():
    table, armed = _armed(rated=2000.0, fired=("joint_1_life_consumed",))
    assert [w.name for w in armed.watches] == ["input_torque", "joint_2_life_consumed"]
    assert [limit for _, limit in armed.checks] == [2000.0, 1.0]
    assert (
        passed(armed, _outputs(table, input_torque=1500.0, joint_1_life_consumed=9.0), 1.0)[1] == []
    )


def test_a_nan_limit_watches_nothing_and_a_nan_value_passes_nothing():
    table, armed = _armed(rated=math.nan)
    assert [w.name for w in armed.watches] == ["joint_1_life_consumed", "joint_2_life_consumed"]
    assert passed(armed, _outputs(table, joint_1_life_consumed=math.nan), 0.0)[1] == []


@pytest.mark.parametrize("key", sorted(discover()))
def test_every_models_watch_rows_name_its_outputs_and_limits(key):
    spec = discover()[key]
    for watch in spec.watches:
        found = [
            w
            for settings in spec.variants()
            for w in compile_watches((watch,), spec.table(settings))
        ]
        assert found, f"{key}: {watch} names no output and limit of any build"


def test_the_limit_a_step_in_c_compares_is_the_smallest_armed_of_each_output():
    """Two watches of one output, the tighter one first or last: a step in C
    hands over to the slave at the first limit passed, whichever row says it."""
    from cardan_joint.fmi.watching import Watching

    table = propshaft_table(2)
    slot = table.OUTPUTS.index("input_torque")
    for rows in (
        ROWS[:1] + (Watch("input_torque", 5000.0, "wide"),),
        (Watch("input_torque", 5000.0, "wide"),) + ROWS[:1],
    ):
        watching = Watching()
        watching.table = table
        watching._armed = arm(compile_watches(rows, table), SimpleNamespace(rated_torque=1000.0))
        limits = watching._watch_limits()
        assert limits[slot] == 1000.0
        assert all(limit == math.inf for k, limit in enumerate(limits) if k != slot)
