"""The inertia_load model: its table, physics and spec (spec.py)."""
