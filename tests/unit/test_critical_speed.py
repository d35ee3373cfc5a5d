"""Issue 27 item 4: the propshaft's first bending critical speed per shaft."""

import math

import pytest

from cardan_joint.models.propshaft.model import Propshaft

TUBE = dict(outer_diameter=0.09, inner_diameter=0.084, length=1.7, youngs_modulus=2.0e11,
            density=7800.0)  # fmt: skip


def _tube_omega_c(D, d, L, E, rho):
    """Euler-Bernoulli pinned-pinned beam: (pi/L)^2 sqrt(E I / (rho A)), I and A of the
    annulus written out (not simplified to (D^2 + d^2) / 16)."""
    I = math.pi * (D**4 - d**4) / 64.0
    A = math.pi * (D**2 - d**2) / 4.0
    return (math.pi / L) ** 2 * math.sqrt(E * I / (rho * A))


def _propshaft(joints, speed, margin=0.75):
    tubes = {f"shaft_{k}_{name}": value for k in range(1, joints) for name, value in TUBE.items()}
    return Propshaft(joints, input_speed=speed, critical_speed_margin=margin, **tubes)


@pytest.mark.parametrize("joints", [2, 3, 4])
def test_the_ratio_is_each_shafts_speed_over_the_tubes_critical_speed(joints):
    shaft = _propshaft(joints, 250.0)
    out = dict(zip(shaft.table.OUTPUTS, shaft.outputs()))
    omega_c = _tube_omega_c(*TUBE.values())
    for k in range(1, joints):
        expected = abs(out[f"shaft_{k}_speed"]) / omega_c
        assert out[f"shaft_{k}_critical_speed_ratio"] == pytest.approx(expected, rel=1e-13)


@pytest.mark.parametrize("margin", [0.75, 0.6])
def test_the_warning_appears_past_the_margin_and_not_below(margin):
    omega_c = _tube_omega_c(*TUBE.values())
    below = _propshaft(3, 0.99 * margin * omega_c, margin).warnings()
    above = _propshaft(3, -1.01 * margin * omega_c, margin).warnings()
    assert not [w for w in below if "critical speed" in w]
    critical = [w for w in above if "critical speed" in w]
    assert len(critical) == 2 and "shaft 1 " in critical[0] and "shaft 2 " in critical[1]
    assert f"critical_speed_margin = {margin:g}" in critical[0]
