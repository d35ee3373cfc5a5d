"""Benchmarks of the UniversalJoint FMU and its physics package, one module per
measurement (step_cost, accuracy, vectorized, growth), the floor FMUs (floor,
floor_slave), shared timing helpers (timing) and the runner (runner):

    python -m benchmarks [--quick]
"""
