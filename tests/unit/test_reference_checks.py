"""The independent references (tests/reference) checked against themselves,
physical identities and the model page's closed forms, section by section."""

import pytest
from reference.check_references import SECTIONS, Checks, section_d_multibody

# The multibody runs on a quarter of the script's horizon: the same checks, a
# quarter of the time (the full run: python tests/reference/check_references.py).
QUICK = {section_d_multibody: {"horizon": 0.25}}


@pytest.mark.parametrize("section", SECTIONS, ids=lambda s: s.__name__)
def test_reference_section(section):
    check = Checks()
    section(check, **QUICK.get(section, {}))
    assert check.worst, "the section ran no check"
    assert check.failures == []


def test_a_failed_check_is_reported():
    check = Checks()
    check("within", 1e-16, 1e-15)
    check("beyond", 2e-15, 1e-15)
    check("not a number", float("nan"), 1.0)
    assert [f.split(":")[0] for f in check.failures] == ["beyond", "not a number"]
    assert check.worst["within"] == 1e-16
