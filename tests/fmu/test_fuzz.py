"""Property-based fuzz through FMPy's low-level API: random input sequences,
bad ones included. The process survives, a refused step changes nothing, and
every accepted step matches the physics package bit for bit."""

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint

REFUSED = 3  # a refused step: fmi2Error (docs/fmi-tools.md)
nasty = st.sampled_from(
    [
        math.nan,
        math.inf,
        -math.inf,
        1e308,
        -1e308,
        1.5707963267948966,
        1.3962634015954636,
        -1.3962634015954636,
        0.0,
        -0.0,
        5e-324,
    ]
)
values = st.one_of(st.floats(-100, 100), st.floats(-1.6, 1.6), nasty)
steps = st.one_of(st.floats(1e-5, 0.5), st.sampled_from([0.0, -1e-3, math.nan, math.inf, 1e300]))
actions = st.lists(
    st.one_of(
        st.tuples(st.just("set"), st.sampled_from(table.INPUTS), values),
        st.tuples(st.just("step"), steps),
        st.tuples(st.just("rollback")),
    ),
    min_size=1,
    max_size=40,
)


@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(actions)
def test_random_sequences_never_corrupt_the_joint(model_description, unzipped_fmu, sequence):
    joint = FmuInstance(model_description, unzipped_fmu, name="fuzz")
    mirror = CardanJoint()
    saved = joint.get_state()
    saved_mirror = mirror.state()
    try:
        for action in sequence:
            if action[0] == "set":
                _, name, value = action
                joint.set(**{name: value})
                setattr(mirror, name, value)
            elif action[0] == "rollback":
                joint.set_state(saved)
                mirror.restore(saved_mirror)
            else:
                before = joint.get("input_angle")
                problem = mirror.step(action[1])
                status = joint.try_step(action[1])
                assert status == (REFUSED if problem else 0), (status, problem)
                if problem:
                    assert joint.get("input_angle") == before
                else:
                    joint.free_state(saved)
                    saved, saved_mirror = joint.get_state(), mirror.state()
            if mirror.input_problem() is None:
                outputs = list(joint.get_outputs().values())
                assert outputs == list(mirror.outputs())
                assert all(math.isfinite(v) for v in outputs)
            assert joint.get("input_angle")["input_angle"] == mirror.input_angle
    finally:
        joint.free_state(saved)
        joint.close()
