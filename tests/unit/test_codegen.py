"""The generator's subset (cardan_joint.codegen, docs/codegen.md): each construct
it translates gives CPython's bits in C, and each one it cannot translate is
refused by a message quoting it with its file:line."""

import inspect
import math
import random
import re

import codegen_samples as samples
import pytest
from generated_c import CStep, bits

from cardan_joint.codegen import Untranslatable, generate


@pytest.mark.parametrize(
    "function, draw",
    [
        (samples.loops, lambda rng: (rng.uniform(-20.0, 20.0), rng.randint(-5, 30))),
        (samples.choices, lambda rng: (rng.uniform(-9.0, 9.0), rng.uniform(-9.0, 9.0))),
        (samples.quadrature, lambda rng: (rng.uniform(-9.0, 9.0), rng.uniform(-9.0, 9.0))),
        (samples.shapes, lambda rng: (rng.uniform(-9.0, 9.0), rng.uniform(-9.0, 9.0))),
        (samples.over_joints, lambda rng: (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0))),
        (
            samples.extremes,
            lambda rng: tuple(rng.choice([math.nan, 1.0, -0.0, 0.0, rng.random()]) for _ in "xy"),
        ),
    ],
    ids=lambda value: getattr(value, "__name__", ""),
)
def test_a_translated_function_gives_pythons_bits(function, draw, tmp_path):
    c_function = CStep(generate(function, function.__name__), tmp_path)
    rng = random.Random(3)
    for _ in range(2_000):
        arguments = draw(rng)
        assert bits(function(*arguments)) == bits(c_function(*arguments)), arguments


@pytest.mark.parametrize("function", samples.REFUSED, ids=lambda f: f.__name__)
def test_an_untranslatable_construct_is_named_with_its_line(function):
    construct = samples.REFUSED[function]
    lines, first = inspect.getsourcelines(function)
    line = first + next(k for k, text in enumerate(lines) if construct in text)
    with pytest.raises(Untranslatable) as raised:
        generate(function, "refused")
    message = str(raised.value)
    assert f"`{construct}" in message and f"codegen_samples.py:{line}" in message, message


def test_hypot_is_refused_with_the_formula_to_write_instead():
    with pytest.raises(Untranslatable, match="sqrt"):
        generate(samples.with_hypot, "refused")


def test_tables_of_rows_of_the_same_sizes_share_their_row_starts():
    # One load indexes both tables: the compiler sees the same start array.
    source = generate(samples.shapes, "shapes").source
    starts = re.findall(r"static const int64_t (K_\w+)\[", source)
    assert len(starts) == 1, starts
    for table in ("K_RULES", "K_RULE_WEIGHTS"):
        assert f"{table}[{starts[0]}[" in source
