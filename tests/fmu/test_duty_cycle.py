"""examples/duty_cycle.py: its block table run through the FMU (`life_report`);
for blocks of constant torque, speed and angle the FMU's life_consumed is the
catalogue's block sum (issue 27)."""

import pytest
from conftest import load_example


@pytest.fixture(scope="module")
def example():
    return load_example("duty_cycle")


def test_constant_blocks_give_the_catalogues_block_sum(example, fmu_path):
    # Every angle at 0: the torque at the joint is the load, constant in each block,
    # and the rule takes its 3-degree floor.
    report = example.run(fmu_path, cycle=2.0, straight=True)
    assert report.life_used["joint"] == pytest.approx(
        example.block_sum(cycle=2.0, straight=True), rel=1e-9, abs=0.0
    )


def test_at_the_working_angles_the_fluctuation_raises_each_blocks_damage_as_the_mean_says(
    example, fmu_path
):
    # Blocks long enough for whole turns to dominate: each block's damage over
    # the hand method's approaches the mean of (cos b / D)^p over a turn.
    report = example.run(fmu_path, cycle=20.0)
    for name, _, _, ratio, factor in example.block_table(report, cycle=20.0):
        assert ratio == pytest.approx(factor, rel=2e-3), name
    assert report.life_used["joint"] > example.block_sum(cycle=20.0)
