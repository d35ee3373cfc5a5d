"""A step entry whose function takes its flat arguments grouped into tuples
(`framework.grouped_entry.GroupedEntry`, docs/codegen.md "Arguments in
groups"): one definition serves every number of grouped values, its C takes
the flat arguments and gives the Python's bits, and an entry whose groups do
not fit its arguments is refused, naming the parameter."""

import inspect
import math
import random
import re

import pytest
from generated_c import CStep, mismatches

from cardan_joint.codegen import Untranslatable, generate
from cardan_joint.framework.grouped_entry import GroupedEntry

GROUPS = {
    "angle": ("turns", "fraction", "fraction_error"),
    "layout": ("joint_*_angle", "joint_*_inertia"),
    "load": "load_torque",
}


def names(joints: int) -> tuple[str, ...]:
    """Flat arguments as a model's: time, h, a state per joint, an input, parameters."""
    per_joint = (f"joint_{k}_{n}" for k in range(1, joints + 1) for n in ("angle", "inertia"))
    return ("time", "h", "turns", "fraction", "fraction_error", "valid", *per_joint,
            "load_torque", "gain", "unused_parameter")  # fmt: skip


def twice(x):
    return 2.0 * x


def grouped(time, h, angle: tuple[int, float, float], valid: bool, layout, load, gain, scale_of,
            limit) -> tuple | None:  # fmt: skip
    """A step over every joint of `layout`, with a bound function and number."""
    if not (valid and abs(load) <= limit):
        return None
    total = angle[1] + angle[2] + float(angle[0])
    for k in range(len(layout) // 2):
        total = total + scale_of(layout[2 * k]) * layout[2 * k + 1] * h
    return (total * gain, load, total - time)


BOUND = {"scale_of": twice, "limit": 100.0}


def entry(joints: int) -> GroupedEntry:
    return GroupedEntry(f"grouped_{joints}", grouped, names(joints), GROUPS, BOUND)


def draw(rng: random.Random, joints: int) -> list:
    return [rng.uniform(0, 9), rng.uniform(0, 1), rng.randint(-9, 9), rng.random(), 1e-17,
            rng.random() > 0.2, *(rng.uniform(-2, 2) for _ in range(2 * joints)),
            rng.choice([rng.uniform(-150.0, 150.0), math.nan]), rng.uniform(-3, 3)]  # fmt: skip


@pytest.mark.parametrize("joints", [2, 3])
def test_one_grouped_definition_serves_each_size_with_pythons_bits(joints, tmp_path):
    step = entry(joints)
    # It takes the flat arguments its parameters use, in order: not the parameters after them.
    assert step.arguments == names(joints)[:-1]
    assert tuple(inspect.signature(step).parameters) == step.arguments
    generated = generate(step, step.__name__)
    assert generated.arguments == step.arguments
    assert f"const long grouped_{joints}_sizes[2] = {{{len(step.arguments)}, 3}};" in (
        generated.source
    )
    c_step = CStep(generated, tmp_path)
    rng = random.Random(joints)
    differ, taken, refused = mismatches(step, c_step, [draw(rng, joints) for _ in range(500)])
    assert differ == 0
    assert taken > 100 and refused > 50, (taken, refused)


def test_a_bound_number_is_a_constant_of_the_c():
    source = generate(entry(2), "grouped").source
    assert "static const double K_limit = 100.0;" in source


def test_the_python_entry_takes_exactly_its_flat_arguments():
    step = entry(2)
    arguments = draw(random.Random(1), 2)
    with pytest.raises(TypeError, match=re.escape("grouped_2 takes 12 arguments (13 given)")):
        step(*arguments, 0.0)


@pytest.mark.parametrize(
    "groups, said",
    [
        ({**GROUPS, "load": "torque"}, "load takes 'torque', not the argument 'load_torque'"),
        ({**GROUPS, "layout": ("shaft_*",)}, "('shaft_*',), not the argument 'joint_1_angle'"),
        ({**GROUPS, "gains": ("gain",)}, "grouped has no parameter ['gains']"),
    ],
)  # fmt: skip
def test_groups_that_do_not_fit_the_arguments_are_refused_by_name(groups, said):
    with pytest.raises(TypeError, match=re.escape(said)):
        GroupedEntry("grouped", grouped, names(2), groups, BOUND)


def test_a_parameter_past_the_last_argument_is_refused():
    with pytest.raises(TypeError, match="gain takes 'gain', not the argument 'none left'"):
        GroupedEntry("grouped", grouped, names(2)[:-2], GROUPS, BOUND)


def annotated(time, h, angle: tuple[int, float]) -> tuple | None:
    if time < 0.0:
        return None
    return (angle[1],)


def test_an_annotated_group_of_another_size_is_untranslatable():
    step = GroupedEntry("annotated", annotated, names(2), {"angle": GROUPS["angle"]})
    with pytest.raises(Untranslatable, match="parameter angle must be a tuple of 3 numbers"):
        generate(step, "annotated")


def refused(time, h, angle, valid: bool) -> tuple | None:
    return [h, h]  # type: ignore[return-value]


def test_an_untranslatable_grouped_function_is_named_with_its_line():
    step = GroupedEntry("refused", refused, names(2), {"angle": GROUPS["angle"]})
    line = inspect.getsourcelines(refused)[1] + 1
    with pytest.raises(Untranslatable, match=f"`\\[h, h\\]` at .*test_codegen_entry.py:{line}"):
        generate(step, "refused")
