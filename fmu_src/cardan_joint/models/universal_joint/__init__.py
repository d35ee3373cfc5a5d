"""The universal_joint model: its table, physics and spec (spec.py)."""
