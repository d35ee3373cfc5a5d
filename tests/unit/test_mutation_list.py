"""tools/mutation.py's guard list still matches the source: each mutation's
target text occurs exactly once, and the tests it runs exist. A refactor that
moves a guard must move its mutation too (run the script to see it killed)."""

import importlib.util
import re

import pytest
from conftest import ROOT

spec = importlib.util.spec_from_file_location("mutation", ROOT / "tools" / "mutation.py")
mutation = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mutation)


def test_every_guard_of_the_issue_has_mutations():
    names = " ".join(m.guard for m in mutation.MUTATIONS)
    for guard in (
        "finite",
        "range",
        "bend peak inside the step (fast path)",
        "bend peak inside the step (slow path)",
        "step size",
        "overflow",
        "restore",
        "state",
        "initialization",
        "after initialization",
        "unknown reference",
    ):
        assert guard in names, guard


@pytest.mark.parametrize("m", mutation.MUTATIONS, ids=lambda m: m.guard)
def test_each_mutation_targets_its_guard_exactly_once(m):
    source = (ROOT / m.path).read_text()
    assert source.count(m.target) == 1, m.target
    assert source.replace(m.target, m.replacement) != source
    files = [a.split("::")[0] for a in m.tests if a.startswith("tests/")]
    tests = set()
    for name in files:
        tests |= set(re.findall(r"^def (test_\w+)", (ROOT / name).read_text(), re.MULTILINE))
    for argument in m.tests:
        if "::" in argument:
            assert argument.split("::")[1] in tests, argument
    if "-k" in m.tests:
        expression = m.tests[m.tests.index("-k") + 1]
        for word in re.split(r" or | and ", expression):
            assert any(word in test for test in tests), word
