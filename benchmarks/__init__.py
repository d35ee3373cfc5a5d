"""Benchmarks of the project's FMUs, one module per section (step_cost,
accuracy, vectorized, growth, c_host, instructions, generated_step, long_run),
what they step (cases: each model's default build at one operating point), the
floor FMUs (floor, floor_slave), where instructions are counted (interpreters),
shared helpers (timing, workers) and the runner (runner, measure, report):

    python -m benchmarks [SECTION ...] [--models MODEL ...] [--quick]
"""
