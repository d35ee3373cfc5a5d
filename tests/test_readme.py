"""The README's commands and tables stay true."""

from pathlib import Path

from cardan_joint.variables import fmi3_array_table, markdown_table

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()
TEST_COMMAND = (
    'python3 -m venv .venv && .venv/bin/pip install -e ".[test]" && .venv/bin/python -m pytest'
)


def test_variable_table_is_generated_from_the_metadata_table():
    begin, end = "<!-- variables:begin -->\n", "<!-- variables:end -->"
    assert README.split(begin)[1].split(end)[0] == markdown_table()


def test_fmi3_array_table_is_generated_from_the_metadata_table():
    begin, end = "<!-- fmi3-arrays:begin -->\n", "<!-- fmi3-arrays:end -->"
    assert README.split(begin)[1].split(end)[0] == fmi3_array_table()


def test_ci_runs_the_readmes_test_command():
    assert f"    {TEST_COMMAND}\n" in README
    ci = (ROOT / ".ci" / "run").read_text()
    assert f"\n{TEST_COMMAND}\n" in ci


def test_propshaft_variable_table_is_generated_from_its_metadata():
    from cardan_joint.propshaft_variables import propshaft_table

    text = (ROOT / "docs" / "Propshaft" / "README.md").read_text()
    begin, end = "<!-- variables:begin -->\n", "<!-- variables:end -->"
    assert text.split(begin)[1].split(end)[0] == propshaft_table(2).markdown_table()


def test_motor_and_load_tables_are_generated_from_their_tables():
    from cardan_joint.driveline_variables import LOAD, MOTOR

    for key, table in (("motor", MOTOR), ("load", LOAD)):
        begin, end = f"<!-- {key}-variables:begin -->\n", f"<!-- {key}-variables:end -->"
        assert README.split(begin)[1].split(end)[0] == table.markdown_table()


def test_readme_states_how_many_tests_the_suite_runs(request):
    import re

    import pytest

    config = request.config
    if (
        config.args_source != pytest.Config.ArgsSource.TESTPATHS
        or config.option.keyword
        or config.option.markexpr
        or config.option.deselect
    ):
        pytest.skip("only a run of the whole suite knows its size")
    stated = int(re.search(r"installs and runs (\d+) tests", README).group(1))
    assert stated == len(request.session.items), "update the test count in the README"
