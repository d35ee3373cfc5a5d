"""The chain at a life node (`chain.node_forward`): one trigonometric call
for the whole chain, against the direct chain (`chain_forward`) and the
direct sine and cosine; the crosspiece's motion at a constant bend against
the kernel's part."""

import math

import numpy as np
import pytest

from cardan_joint.models.propshaft.chain import (
    CHAIN_FIELDS,
    bend_trig,
    chain_forward,
    node_forward,
    node_trig,
    pin_turned,
)
from cardan_joint.physics.response import crosspiece_motion, pose_of, steady_crosspiece_motion

LIMIT = math.radians(15.0)


def test_the_motion_at_a_constant_bend_is_the_kernels_to_the_bit():
    # Its terms in the bend's rate and acceleration are exact zeros, left
    # out: the rest, in the same order, rounds alike (== takes -0.0 for 0.0),
    # at zero speeds and accelerations and at the pin's quarter turns too.
    rng = np.random.default_rng(11)
    for _ in range(20000):
        psi = rng.choice(
            [rng.uniform(-20.0, 20.0), 0.0, math.pi / 2, math.pi * rng.integers(-4, 4)]
        )
        beta = rng.choice([rng.uniform(-1.4, 1.4), 0.0])
        w = rng.choice([rng.uniform(-1e3, 1e3), 0.0, -0.0])
        a = rng.choice([rng.uniform(-1e4, 1e4), 0.0, -0.0])
        pose = pose_of(math, float(psi), math.sin(beta), math.cos(beta))[2:]
        assert steady_crosspiece_motion(*pose, w, a) == crosspiece_motion(*pose, w, a, 0.0, 0.0)


def test_a_life_nodes_chain_is_the_direct_one_to_a_few_ulps():
    # node_forward takes each pin angle after the first by the addition
    # formulas (the offsets add each error's atan, as chain_forward does);
    # chain_forward takes every pin's sine and cosine and every error's atan
    # directly. They differ by no more than chain_forward itself when its
    # input angle moves by a few ulps (scales: 1 for the angles, the speed,
    # the acceleration and the torque's scale).
    rng = np.random.default_rng(12)
    worst = 0.0
    for _ in range(3000):
        joints = int(rng.integers(2, 5))
        values = []
        for k in range(joints):
            first = k == 0
            phase = 0.0 if first else rng.uniform(-3.0, 3.0)
            inertia = 0.0 if first else rng.uniform(0.0, 1.0)
            values += [rng.uniform(0.0, LIMIT), rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0),
                       phase, inertia]  # fmt: skip
        layout_ = tuple(float(v) for v in values)
        angle, w, a = (
            rng.uniform(0.0, 2.0 * math.pi),
            rng.uniform(-1e3, 1e3),
            rng.uniform(-1e4, 1e4),
        )
        I1, I2, I3 = (float(x) for x in rng.uniform(0.0, 0.01, 3))
        direct = chain_forward(
            math, angle, 1e-17, w, a, layout_, bend_trig(math, layout_), I1, I2, I3
        )
        nodes = node_forward(angle, 1e-17, w, a, layout_, node_trig(layout_), I1, I2, I3)
        assert len(nodes) == len(direct)
        motion = abs(a) + w * w
        scales = (1.0, abs(w), motion, 1.0, 0.01 * motion, 1.0)
        for i in range(len(direct) - 1):
            error = abs(nodes[i] - direct[i]) / scales[i % CHAIN_FIELDS]
            worst = max(worst, error)
        assert nodes[-1] == pytest.approx(direct[-1], rel=1e-13)
    assert worst < 2e-14


def test_a_pin_turned_by_the_addition_formulas_is_the_direct_one():
    # pin_turned against math.sin and math.cos of psi + Delta + atan(tangent).
    rng = np.random.default_rng(13)
    for _ in range(5000):
        psi, turn = rng.uniform(-7.0, 7.0), rng.uniform(-7.0, 7.0)
        tangent = rng.uniform(-0.3, 0.3)
        got = pin_turned(math.sin(psi), math.cos(psi), math.sin(turn), math.cos(turn), tangent)
        angle = psi + turn + math.atan(tangent)
        assert got == pytest.approx((math.sin(angle), math.cos(angle)), abs=4e-15)


def test_a_life_nodes_offsets_keep_their_branch_at_every_working_angle_accepted():
    # Up to the 90 deg the model accepts below, a joint's cardan error nears
    # 90 deg itself and the errors of joints in phase add up past it: each
    # offset must still be the direct chain's, not a half turn off (one atan of
    # the errors' tangents' sum was, or a division by zero). The scale grows
    # with 1 / cos(bend) per joint, so the angles are compared to 1e-6 rad.
    rng = np.random.default_rng(14)
    for _ in range(2000):
        joints = int(rng.integers(2, 5))
        values = []
        for k in range(joints):
            first = k == 0
            phase = 0.0 if first else float(rng.choice([0.0, math.pi / 4, rng.uniform(-3.0, 3.0)]))
            inertia = 0.0 if first else rng.uniform(0.0, 1.0)
            values += [rng.uniform(math.radians(60.0), math.radians(89.0)), 0.0, 0.0, phase,
                       inertia]  # fmt: skip
        layout_ = tuple(float(v) for v in values)
        angle = rng.uniform(0.0, 2.0 * math.pi)
        direct = chain_forward(
            math, angle, 0.0, 100.0, 0.0, layout_, bend_trig(math, layout_), 0.0, 0.0, 0.0
        )
        nodes = node_forward(angle, 0.0, 100.0, 0.0, layout_, node_trig(layout_), 0.0, 0.0, 0.0)
        for k in range(joints):
            for field in (0, 3):  # the offset o_k and the pin angle psi_k
                at = CHAIN_FIELDS * k + field
                assert abs(nodes[at] - direct[at]) < 1e-6, (k, field, nodes[at], direct[at])
