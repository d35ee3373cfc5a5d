"""The Propshaft FMU (built once, as `build_fmu.py --model Propshaft` builds it),
driven through FMPy's low-level API, against the independent 3-D construction
at every communication point; its warnings, refusals and state."""

import functools
import math

import mpmath
import numpy as np
import pytest
from conftest import build_fmu, load_example
from reference.propshaft import PropshaftReference
from tolerance import assert_close

from cardan_joint.host.instance import FmuInstance

REFUSED = 3  # a refused step: fmi2Error (docs/fmi-tools.md)
D = math.radians
STEPS = 25


@pytest.fixture(scope="module")
def description(propshaft_fmu_path):
    from fmpy import read_model_description

    return read_model_description(str(propshaft_fmu_path))


def test_the_build_writes_a_valid_propshaft_fmu(propshaft_fmu_path, description):
    from fmpy.validation import validate_fmu

    assert propshaft_fmu_path.name == "Propshaft.fmu"
    assert validate_fmu(str(propshaft_fmu_path)) == []
    names = [v.name for v in description.modelVariables]
    for name in (
        "input_speed",
        "input_acceleration",
        "load_torque",
        "output_speed",
        "output_acceleration",
        "input_torque",
        "shaft_1_yoke_phase",
    ):
        assert name in names


def random_case(seed, h):
    rng = np.random.default_rng(seed)
    T = STEPS * h
    return dict(
        side=list(rng.uniform(-D(15), D(15), 3)),
        top=list(rng.uniform(-D(15), D(15), 3)),
        phase=rng.uniform(-math.pi, math.pi),
        shaft=rng.uniform(0.0, 0.3),
        cross=tuple(rng.uniform(0.0, 0.05, 3)),
        angle0=rng.uniform(-10, 10),
        speed0=rng.uniform(-1, 1) * min(300.0, 100.0 / T),
        speed_rate=rng.uniform(-1, 1) * min(100.0, 200.0 / T**2),
        load=rng.uniform(-300, 300),
    )


def start_values(case):
    values = {f"shaft_{k}_side_angle": case["side"][k] for k in range(3)}
    values.update({f"shaft_{k}_top_angle": case["top"][k] for k in range(3)})
    values.update(
        shaft_1_yoke_phase=case["phase"],
        shaft_1_inertia=case["shaft"],
        input_angle_start=case["angle0"],
        crosspiece_inertia_1=case["cross"][0],
        crosspiece_inertia_2=case["cross"][1],
        crosspiece_inertia_3=case["cross"][2],
    )
    return values


def inputs_at(case, t):
    return dict(
        input_speed=case["speed0"] + case["speed_rate"] * t,
        input_acceleration=case["speed_rate"],
        load_torque=case["load"],
    )


@functools.cache
def reference_run(seed, h):
    """The random case of `seed` and step `h`, its 3-D construction, and the
    construction's exact input angle and values at every point: computed once for
    both masters (mpmath is most of the test's time)."""
    case = random_case(seed, h)
    reference = PropshaftReference(
        case["side"], case["top"], [case["phase"]], [case["shaft"]], case["cross"]
    )
    offsets = reference.start_offsets(case["angle0"])
    points = []
    for k in range(STEPS + 1):
        t = k * h
        with mpmath.workdps(40):
            angle = case["angle0"] + t * (
                mpmath.mpf(case["speed0"]) + mpmath.mpf(case["speed_rate"]) * t / 2
            )
        u = inputs_at(case, t)
        ref = reference.at(angle, u["input_speed"], u["input_acceleration"], case["load"], offsets)
        points.append((angle, ref))
    return case, reference, reference.speed_ratio_fluctuation(samples=48), points


@pytest.mark.parametrize("seed, h", [(1, 1e-3), (2, 0.02), (3, 0.3)])
@pytest.mark.parametrize("master", ["sets inputs once", "sets inputs every step"])
def test_every_communication_point_matches_the_3d_construction(
    description, propshaft_unzipped, seed, h, master
):
    case, reference, fluctuation, points = reference_run(seed, h)
    shaft = FmuInstance(
        description, propshaft_unzipped, start_values={**start_values(case), **inputs_at(case, 0.0)}
    )
    first = None
    try:
        for k in range(STEPS + 1):
            t = k * h
            if master == "sets inputs every step":
                shaft.set(**inputs_at(case, t))
            values = shaft.get_outputs()
            angle, ref = points[k]
            u = inputs_at(case, t)
            angles = (values["input_angle"], values["shaft_1_angle"], values["output_angle"])
            exact = (angle, *ref["angles"])
            first = first or (angles, exact)
            for got, want, got0, want0 in zip(angles, exact, *first):
                # Increments since the start and the angles themselves.
                assert abs((got - got0) - float(want - want0)) < 1e-12 * (1 + abs(got - got0))
                assert abs(got - float(want)) < 1e-12 * (1 + abs(got))
            speed = abs(u["input_speed"]) + 1e-9
            acceleration = speed * speed + abs(u["input_acceleration"])
            assert_close(values["shaft_1_speed"], ref["speeds"][0], 1e-9, speed, "shaft_1_speed")
            assert_close(values["output_speed"], ref["speeds"][1], 1e-9, speed, "output_speed")
            assert_close(
                values["shaft_1_acceleration"],
                ref["accelerations"][0],
                1e-9,
                acceleration,
                "shaft_1_acceleration",
            )
            assert_close(
                values["output_acceleration"],
                ref["accelerations"][1],
                1e-9,
                acceleration,
                "output_acceleration",
            )
            torque = abs(case["load"]) + (case["shaft"] + max(case["cross"])) * acceleration
            assert_close(
                values["input_torque"], ref["input_torque"], 1e-9, torque, f"input_torque at t={t}"
            )
            assert_close(values["kinetic_energy"], ref["kinetic_energy"], 1e-9, None, "energy")
            assert_close(values["speed_ratio_fluctuation"], fluctuation, 1e-9, None, "fluctuation")
            for j, beta in enumerate(reference.working_angles(), start=1):
                assert_close(values[f"joint_{j}_working_angle"], beta, 1e-14)
            if k < STEPS:
                shaft.step(h)
    finally:
        shaft.close()


def test_warnings_are_logged_at_initialization_and_never_refuse(description, propshaft_unzipped):
    messages = []
    shaft = FmuInstance(
        description,
        propshaft_unzipped,
        messages=messages,
        start_values=dict(shaft_0_side_angle=D(6.0), shaft_2_side_angle=D(1.0), input_speed=500.0),
    )
    try:
        warnings = [m for status, _, m in messages if status == 1]
        assert any("differ by more than 1 deg" in m for m in warnings), messages
        assert any("exceeds 0.0027" in m for m in warnings), messages
        assert shaft.try_step(0.01) == 0
    finally:
        shaft.close()


def test_a_working_angle_at_the_limit_refuses_every_step_and_says_why(
    description, propshaft_unzipped
):
    messages = []
    shaft = FmuInstance(
        description,
        propshaft_unzipped,
        messages=messages,
        start_values=dict(shaft_1_side_angle=D(-20.0), max_working_angle=D(20.0)),
    )
    try:
        assert shaft.try_step(0.01) == REFUSED
        text = " ".join(m for _, _, m in messages)
        assert "joint_1_working_angle" in text and "max_working_angle" in text
        assert shaft.time == 0.0
    finally:
        shaft.close()


# Same open/step/close shape as tests/fmu/test_robustness.py's refusal tests: each
# drives its own FMU, and the shared part is FmuInstance already.
def test_a_non_finite_input_is_refused_and_loses_nothing(description, propshaft_unzipped):
    messages = []
    shaft = FmuInstance(description, propshaft_unzipped, messages=messages)
    try:
        shaft.step(0.1)
        before = shaft.get("input_angle", "output_angle")
        shaft.set(load_torque=math.nan)
        assert shaft.try_step(0.1) == REFUSED
        assert any("load_torque = nan" in m for _, _, m in messages)
        shaft.set(load_torque=1.0)
        assert shaft.get("input_angle", "output_angle") == before
        assert shaft.try_step(0.1) == 0
    finally:
        shaft.close()


def test_state_serialization_round_trip(description, propshaft_unzipped):
    shaft = FmuInstance(
        description,
        propshaft_unzipped,
        start_values=dict(shaft_2_top_angle=D(4.0), input_speed=50.0),
    )
    try:
        for _ in range(7):
            shaft.step(0.013)
        state = shaft.get_state()
        saved = shaft.serialize_state(state)
        shaft.free_state(state)
        before = shaft.get_outputs()
        shaft.step(0.5)
        restored = shaft.deserialize_state(saved)
        shaft.set_state(restored)
        shaft.free_state(restored)
        assert shaft.get_outputs() == before
    finally:
        shaft.close()


def test_joints_option_names_and_validates_the_build(tmp_path):
    from fmpy import read_model_description

    built = build_fmu(tmp_path, "--model", "Propshaft", "--joints", "3")
    names = [v.name for v in read_model_description(str(built)).modelVariables]
    assert "shaft_2_yoke_phase" in names and "joint_3_working_angle" in names


def test_the_worked_layout_example_cancels_at_the_helpers_phasing(
    propshaft_fmu_path, tmp_path, capsys
):
    module = load_example("propshaft_layout")
    module.main(["--fmu", str(propshaft_fmu_path), "--out", str(tmp_path)])
    text = capsys.readouterr().out
    assert (tmp_path / "propshaft_layout.png").stat().st_size > 10_000
    assert "Phasing 0: speed-ratio fluctuation 0.006079" in text
    assert "exceeds 0.0027" in text
    assert "Best phasing 102.704 deg: fluctuation 1.39e-05" in text


def test_the_fmu_reports_cancellation_only_at_the_right_phasing(description, propshaft_unzipped):
    from cardan_joint.models.propshaft import best_phasing, layout

    side, top = [0.0, D(-4.0), D(-1.0)], [0.0, 0.0, D(3.5)]
    geometry = layout(side, top, [0.0])
    assert abs(geometry.working_angles[0] - geometry.working_angles[1]) > 1e-3
    # Make the working angles equal: turn shaft 2 about shaft 1 onto a cone of beta_1.
    d1 = np.array(geometry.directions[1])
    d2 = np.array(geometry.directions[2])
    beta = geometry.working_angles[0]
    normal = np.cross(d1, d2) / np.linalg.norm(np.cross(d1, d2))
    d2 = d1 * math.cos(beta) + np.cross(normal, d1) * math.sin(beta)
    side[2], top[2] = math.atan(d2[2] / d2[0]), math.atan(d2[1] / d2[0])
    phases, _ = best_phasing(layout(side, top, [0.0]))
    values = {f"shaft_{k}_side_angle": side[k] for k in range(3)}
    values.update({f"shaft_{k}_top_angle": top[k] for k in range(3)})
    results = {}
    for phase in (0.0, phases[0]):
        shaft = FmuInstance(
            description, propshaft_unzipped, start_values=dict(values, shaft_1_yoke_phase=phase)
        )
        try:
            results[phase] = shaft.get("speed_ratio_fluctuation", "equivalent_angle")
        finally:
            shaft.close()
    assert results[phases[0]]["speed_ratio_fluctuation"] < 1e-12
    assert results[0.0]["speed_ratio_fluctuation"] > 1e-3
    default = FmuInstance(description, propshaft_unzipped)  # a coplanar Z layout
    try:
        assert default.get("speed_ratio_fluctuation")["speed_ratio_fluctuation"] < 1e-12
    finally:
        default.close()
