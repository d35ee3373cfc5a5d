"""A model's build settings and FMI 3 arrays come from its folder: the build
command offers `--<setting>` for what the specs declare, the host tools split
FMI 3 arrays by the models' tables. Checked with a made-up model, so that no
generic code can be keyed to the models that exist today."""

from dataclasses import replace

import pytest

from cardan_joint.build import command
from cardan_joint.models import Model, array_rows, discover
from cardan_joint.variable_schema import _IN, _OUT, Variable, VariableTable

_ROWS = (
    Variable("gear_speed", _IN, "rad/s", "Input speed", 0.0),
    *(Variable(f"gear_torque_{i}", _OUT, "N.m", f"Tooth force {i}") for i in (1, 2)),
)


class _Table(VariableTable):
    def fmi3_variables(self):
        from cardan_joint.variable_schema import fmi3_groups

        return fmi3_groups(self.VARIABLES, ("gear_torque",))


GEARBOX = Model(
    key="Gearbox",
    description="a model no generic layer knows",
    table_for=lambda settings: _Table(_ROWS, {}),
    make=lambda settings, **values: None,
    default_settings={"stages": 1},
    setting_choices={"stages": (1, 2, 3)},
    setting_help={"stages": "number of gear stages"},
    folder="gearbox",
)


@pytest.fixture
def with_gearbox(monkeypatch):
    models = {**discover(), "Gearbox": GEARBOX}
    monkeypatch.setattr(command, "discover", lambda: models)
    return models


def test_the_build_offers_a_setting_a_spec_declares(with_gearbox, monkeypatch, capsys):
    built = {}

    def build(dest, name, start_values, model, settings, fmi_version, fmi3_arrays=False):
        built.update(model=model, settings=settings)
        return "dist/Gearbox2.fmu"

    monkeypatch.setattr(command, "build", build)
    assert command.main(["--model", "Gearbox", "--stages", "2"]) == 0
    assert built == {"model": "Gearbox", "settings": {"stages": 2}}
    with pytest.raises(SystemExit):
        command.main(["--help"])
    assert "number of gear stages (default: Gearbox 1)" in " ".join(capsys.readouterr().out.split())


def test_a_setting_is_refused_for_a_model_that_does_not_declare_it(with_gearbox, capsys):
    key = next(k for k, spec in with_gearbox.items() if "stages" not in spec.default_settings)
    with pytest.raises(SystemExit):
        command.main(["--model", key, "--stages", "2"])
    assert f"--stages does not apply to {key}" in capsys.readouterr().err


def test_variants_cover_every_choice():
    assert GEARBOX.variants() == [{"stages": 1}, {"stages": 2}, {"stages": 3}]
    assert replace(GEARBOX, setting_choices={}).variants() == [{}]


def test_fmi3_array_columns_come_from_the_models_tables(monkeypatch):
    import cardan_joint.models as models

    monkeypatch.setattr(models, "discover", lambda: {"Gearbox": GEARBOX})
    array_rows.cache_clear()
    try:
        assert array_rows() == {"gear_torque": ("gear_torque_1", "gear_torque_2")}
        three = (*_ROWS, Variable("gear_torque_3", _OUT, "N.m", "Tooth force 3"))
        other = replace(GEARBOX, key="Other", table_for=lambda s: _Table(three, {}))
        monkeypatch.setattr(models, "discover", lambda: {"Gearbox": GEARBOX, "Other": other})
        array_rows.cache_clear()
        with pytest.raises(ValueError, match="FMI 3 arrays 'gear_torque' differ"):
            array_rows()
    finally:
        array_rows.cache_clear()
