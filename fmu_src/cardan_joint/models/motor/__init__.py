"""The motor model: its table, physics and spec (spec.py)."""
