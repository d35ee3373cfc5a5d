"""Inputs and readers shared by the test_robustness*.py modules."""

# What a refused step returns, and the status its message is logged with
# (fmi2Error/fmi3Error: docs/fmi-tools.md).
REFUSED = 3
GOOD = dict(
    input_speed=12.0,
    input_acceleration=3.0,
    bend_angle=0.4,
    bend_angle_rate=0.05,
    bend_angle_acceleration=-0.1,
    load_torque=80.0,
)


def all_reals(joint):
    return joint.get(*joint.references)
