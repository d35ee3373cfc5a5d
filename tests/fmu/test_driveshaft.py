"""The two-joint driveshaft example: cancellation through co-simulation."""

import math

import pytest
from conftest import load_example

from cardan_joint.host.instance import ExtractedFMU


@pytest.fixture(scope="module")
def driveshaft():
    return load_example("driveshaft")


@pytest.fixture(scope="module")
def fmu(driveshaft, unzipped_fmu):
    with ExtractedFMU(unzipped_fmu) as extracted:
        yield extracted


BEND = math.radians(30)
SPEED = 10.0


def residual(driveshaft, fmu, **options):
    run = driveshaft.cosimulate(fmu, BEND, SPEED, revolutions=1, **options)
    return driveshaft.fluctuation(run["output_speed"], SPEED)


def test_z_arrangement_at_1_ms_cancels_five_orders_below_a_single_joint(driveshaft, fmu):
    single = math.tan(BEND) * math.sin(BEND)
    z = residual(driveshaft, fmu, step=1e-3, arrangement="Z")
    assert single / z >= 1e5
    # The residual is the O(h^2) angle error of joint 2's integration, as predicted.
    assert z == pytest.approx(driveshaft.predicted_hold_fluctuation(BEND, SPEED, 1e-3), rel=0.05)


def test_w_arrangement_cancels_identically(driveshaft, fmu):
    z = driveshaft.cosimulate(fmu, BEND, SPEED, 1e-3, 1, "Z")
    w = driveshaft.cosimulate(fmu, BEND, SPEED, 1e-3, 1, "W")
    assert (z["output_speed"] == w["output_speed"]).all()


def test_hold_coupling_is_second_order_and_lead_first(driveshaft, fmu):
    for coupling, order in (("hold", 2.0), ("lead", 1.0)):
        coarse = residual(driveshaft, fmu, step=1e-2, coupling=coupling)
        fine = residual(driveshaft, fmu, step=1e-3, coupling=coupling)
        assert math.log10(coarse / fine) == pytest.approx(order, abs=0.1)


def test_angle_matching_coupling_is_exact_to_rounding(driveshaft, fmu):
    assert residual(driveshaft, fmu, step=1e-2, coupling="angle") < 1e-13


def test_run_up_cancels_too(driveshaft, fmu):
    # The identity gamma3 = gamma1 holds at any speed history, so a ramp
    # cancels as well as constant speed: same O(h^2) residual.
    run = driveshaft.cosimulate(fmu, BEND, SPEED, 1e-3, 1, input_acceleration=20.0)
    slip = (run["output_speed"] - run["input_speed"]) / run["input_speed"]
    assert abs(slip).max() < 1e-5
    assert abs(run["intermediate_speed"] / run["input_speed"] - 1).max() > 0.1


def test_phase_error_follows_the_closed_form_composition(driveshaft, fmu):
    error = math.radians(2)
    cosimulated = residual(driveshaft, fmu, step=1e-3, phase_error=error)
    assert cosimulated == pytest.approx(driveshaft.exact_fluctuation(BEND, error), rel=1e-3)
