"""tools/mutation.py's guard list still matches the source: each mutation's
target occurs exactly once (however a formatter lays it out), and the tests it
runs exist. A refactor that moves a guard must move its mutation too (run the
script to see it killed)."""

import importlib.util
import re

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


def _orphans(m) -> list:
    """What no longer holds of mutation `m`: its target, its change, its tests."""
    try:
        if m.apply((ROOT / m.path).read_text()) == (ROOT / m.path).read_text():
            return [f"{m.guard}: the replacement changes nothing"]
    except ValueError as error:
        return [str(error)]
    files = [a.split("::")[0] for a in m.tests if a.startswith("tests/")]
    tests = set()
    for name in files:
        if not (ROOT / name).is_file():
            return [f"{m.guard}: no test module {name}"]
        tests |= set(re.findall(r"^def (test_\w+)", (ROOT / name).read_text(), re.MULTILINE))
    missing = [a for a in m.tests if "::" in a and a.split("::")[1] not in tests]
    if "-k" in m.tests:
        expression = m.tests[m.tests.index("-k") + 1]
        words = re.split(r" or | and ", expression)
        missing += [w for w in words if not any(w in test for test in tests)]
    return [f"{m.guard}: no test {name}" for name in missing]


def test_each_mutation_targets_its_guard_exactly_once_and_names_existing_tests():
    assert len(mutation.MUTATIONS) > 50
    assert [problem for m in mutation.MUTATIONS for problem in _orphans(m)] == []


def test_a_reformatted_guard_is_still_found_and_a_missing_one_is_named():
    guard = mutation.Mutation(
        "example", "x.py", "    if not abs(change, limit) <= MAX:\n", "    if False:\n", ()
    )
    wrapped = (
        "def f():\n    if not abs(\n        change,\n        limit,\n    ) <=  MAX:\n        pass\n"
    )
    assert guard.apply(wrapped) == "def f():\n    if False:\n        pass\n"
    assert guard.apply("    if not abs(change, limit) <= MAX:\n") == "    if False:\n"
    for source in ("if not abs(change) <= MAX:\n", wrapped + wrapped):
        try:
            guard.apply(source)
        except ValueError as error:
            assert "example: target found" in str(error)
        else:
            raise AssertionError("a missing or repeated target must be named")
