"""Binds a slave class to one model folder's spec (`models/<folder>/spec.py`).

A model's pythonfmu script names its folder in `model_folder`; the spec gives
the variable table (for the build's settings), the physics object, the outputs
that stay live while an input is invalid, the FMU description and what the
messages call the model. The spec is imported relative to this package, so a
shipped copy of the package reads its own copy of the model."""

import importlib
from typing import Any


class ModelBinding:
    """Mixed in before `SlaveCore`: `__init_subclass__` reads the spec."""

    model_folder = ""
    # Written in by the build script, e.g. {"joints": N}.
    build_settings: dict = {}
    start_overrides: dict = {}
    _spec: Any = None

    def __init_subclass__(cls, **kwargs):
        if cls.model_folder:
            package = __package__.rpartition(".")[0]
            spec = importlib.import_module(f"{package}.models.{cls.model_folder}.spec").MODEL
            settings = {**spec.default_settings, **cls.build_settings}
            cls._spec, cls.build_settings = spec, settings
            cls.table = spec.table_for(settings)
            cls.live_outputs, cls.owner = spec.live_outputs, spec.owner
            cls.description, cls.watches = spec.description, spec.watches
        super().__init_subclass__(**kwargs)

    def _new_model(self):
        return self._spec.make(self.build_settings, **self.start_overrides)

    def _initialization_warnings(self):
        return self._model.warnings() if self._spec and self._spec.warns else ()
