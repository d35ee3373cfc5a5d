"""The compliant_propshaft model: its table, physics and spec (spec.py)."""
