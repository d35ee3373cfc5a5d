"""The FMU, driven through FMPy's low-level API, against the independent
geometric reference (tests/reference/geometry.py, 40-digit mpmath) at every
communication point, for inputs polynomial in time, steps from 1e-4 s to 0.5 s,
bend angles up to the guard and any yoke phase."""

import functools
import math

import mpmath
import numpy as np
import pytest
from reference.geometry import geometric_reference
from tolerance import assert_close

from cardan_joint.host.instance import FmuInstance

GUARD = math.radians(80.0)  # the FMU's default max_bend_angle
STEPS = 40
ANGLES = {"input_angle", "output_angle", "cardan_error"}


def polynomial_case(seed, h):
    """Random inputs polynomial in time, kept below the guard and under 1e3 rad."""
    rng = np.random.default_rng(seed)
    T = STEPS * h
    bend0 = rng.uniform(-0.97, 0.97) * GUARD
    # Bend rate/acceleration scaled to the horizon, then shrunk until |bend| < guard.
    rate, acc = rng.uniform(-1, 1) * 0.5 / T, rng.uniform(-1, 1) * 0.5 / T**2
    t = np.linspace(0, T, 2001)
    while np.max(np.abs(bend0 + rate * t + 0.5 * acc * t * t)) >= 0.999 * GUARD:
        rate, acc = rate / 2, acc / 2
    return dict(
        phase=rng.uniform(-math.pi, math.pi),
        angle0=rng.uniform(-10, 10),
        speed0=rng.uniform(-1, 1) * min(60.0, 200.0 / T),
        speed_rate=rng.uniform(-1, 1) * min(30.0, 400.0 / T**2),
        bend0=bend0,
        bend_rate=rate,
        bend_acc=acc,
        inertia=tuple(rng.uniform(0.0, 0.05, 3)),
        load=rng.uniform(-200, 200),
    )


def inputs_at(case, t):
    return dict(
        input_speed=case["speed0"] + case["speed_rate"] * t,
        input_acceleration=case["speed_rate"],
        bend_angle=case["bend0"] + t * (case["bend_rate"] + 0.5 * case["bend_acc"] * t),
        bend_angle_rate=case["bend_rate"] + case["bend_acc"] * t,
        bend_angle_acceleration=case["bend_acc"],
        load_torque=case["load"],
    )


def reference_at(case, t):
    c = {k: mpmath.mpf(v) if isinstance(v, float) else v for k, v in case.items()}
    return geometric_reference(
        t,
        lambda s: c["angle0"] + s * (c["speed0"] + c["speed_rate"] * s / 2),
        lambda s: c["bend0"] + s * (c["bend_rate"] + c["bend_acc"] * s / 2),
        yoke_phase=case["phase"],
        inertia=case["inertia"],
        load_torque=case["load"],
    )


def scales(case, t):
    u = inputs_at(case, t)
    w, a, r, q = (
        u["input_speed"],
        u["input_acceleration"],
        u["bend_angle_rate"],
        u["bend_angle_acceleration"],
    )
    cos_b = math.cos(u["bend_angle"])
    speed = (abs(w) + abs(r)) / cos_b + 1e-6
    acceleration = (w * w + abs(a) + r * r + abs(q) + abs(w * r)) / cos_b**3 + 1e-6
    torque = max(case["inertia"]) * acceleration / cos_b
    return {
        "speed": speed,
        "acceleration": acceleration,
        "torque": torque,
        "reaction": abs(case["load"]) / cos_b + torque / cos_b,
        "energy": max(case["inertia"]) * speed**2,
    }


SCALE_OF = {
    "output_speed": "speed",
    "crosspiece_angular_velocity": "speed",
    "output_acceleration": "acceleration",
    "crosspiece_torque": "torque",
    "crosspiece_kinetic_energy": "energy",
    "input_torque": "reaction",
    "input_yoke_moment": "reaction",
    "output_yoke_moment": "reaction",
}


# The bearing loads and life have their own independent references (tests/unit/test_life.py).
LIFE = {"input_bearing_force", "output_bearing_force", "life_rate", "life_consumed"}


def check_point(values, case, t, ref=None):
    ref = reference_at(case, t) if ref is None else ref
    s = scales(case, t)
    for name, value in values.items():
        if name in LIFE:
            continue
        if name in ANGLES:
            assert abs(value - ref[name]) <= 1e-12 + 1e-15 * abs(ref[name]), (
                name,
                t,
                value,
                ref[name],
            )
        elif name.startswith("crosspiece_quaternion") or name == "speed_ratio":
            assert_close(value, ref[name], 1e-12, 1.0, f"{name} at t={t}")
        else:
            key = next(k for prefix, k in SCALE_OF.items() if name.startswith(prefix))
            assert_close(value, ref[name], 1e-9, s[key], f"{name} at t={t}")


@functools.cache
def case_and_references(seed, h):
    """The random case of `seed` and step `h` and its reference at every point:
    computed once for both masters (mpmath is most of the test's time)."""
    case = polynomial_case(seed * 1000 + int(round(-math.log10(h) * 10)), h)
    return case, [reference_at(case, k * h) for k in range(STEPS + 1)]


@pytest.mark.parametrize("h", [1e-4, 1e-3, 1e-2, 0.1, 0.5])
@pytest.mark.parametrize("seed", [1, 2])
@pytest.mark.parametrize("master", ["sets inputs once", "sets inputs every step"])
def test_every_communication_point_matches_the_geometric_reference(
    model_description, unzipped_fmu, h, seed, master
):
    case, references = case_and_references(seed, h)
    start = dict(
        yoke_phase=case["phase"],
        input_angle_start=case["angle0"],
        crosspiece_inertia_1=case["inertia"][0],
        crosspiece_inertia_2=case["inertia"][1],
        crosspiece_inertia_3=case["inertia"][2],
        **inputs_at(case, 0.0),
    )
    joint = FmuInstance(model_description, unzipped_fmu, start_values=start)
    try:
        for k in range(STEPS + 1):
            t = k * h
            if master == "sets inputs every step":
                joint.set(**inputs_at(case, t))
            check_point(joint.get_outputs(), case, t, references[k])
            if k < STEPS:
                joint.step(h)
        # The inputs the FMU holds followed the polynomials.
        held = joint.get("input_speed", "bend_angle", "bend_angle_rate")
        expected = inputs_at(case, STEPS * h)
        for name, value in held.items():
            assert_close(value, expected[name], 1e-12, 1.0, name)
    finally:
        joint.close()


@pytest.mark.parametrize(
    "phase, angle0", [(1e3 + 0.3, -5e3), (-1e6 - 0.7, 123.4), (1e9 + 0.1, -1e4), (-7.0, -1e12)]
)
def test_large_and_negative_phases_and_start_angles_lose_no_precision(
    model_description, unzipped_fmu, phase, angle0
):
    h = 1e-2
    case = dict(polynomial_case(77, h), phase=phase, angle0=angle0)
    start = dict(
        yoke_phase=phase,
        input_angle_start=angle0,
        crosspiece_inertia_1=case["inertia"][0],
        crosspiece_inertia_2=case["inertia"][1],
        crosspiece_inertia_3=case["inertia"][2],
        **inputs_at(case, 0.0),
    )
    joint = FmuInstance(model_description, unzipped_fmu, start_values=start)
    try:
        for k in range(11):
            values = joint.get_outputs()
            if abs(angle0) > 1e9:
                # A float start angle of 1e12 rad resolves 1e-4 rad; compare what
                # does not depend on the absolute angle's last digits.
                values = {
                    n: v for n, v in values.items() if n not in ("input_angle", "output_angle")
                }
            check_point(values, case, k * h)
            joint.step(h)
    finally:
        joint.close()
