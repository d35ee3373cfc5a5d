"""The seed examples (examples/seed_*.py) run, draw, and reproduce the seeds' numbers.

Each script runs once, on its quick horizon, in its own process against the
session's freshly built FMU; the four run side by side to keep the module short.
The numbers are checked in the CSVs the scripts write beside their figures,
against the seeds' printed values and formulas (restated here, not imported).
"""

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from cardan_joint import results

ROOT = Path(__file__).resolve().parents[2]
FIGURES = {
    "seed_wikipedia": [
        "seed_wikipedia_output_speed",
        "seed_wikipedia_output_angle",
        "seed_wikipedia_output_acceleration",
    ],
    "seed_maker": [
        "seed_maker_output_angle",
        "seed_maker_cardan_error",
        "seed_maker_amplitude_unevenness",
    ],
    "seed_tataru": ["seed_tataru_alpha_2pi_7", "seed_tataru_alpha_2pi_5"],
    "seed_mityushov_misyura": [
        "seed_mityushov_misyura_kinematics",
        "seed_mityushov_misyura_quaternion",
        "seed_mityushov_misyura_torques",
        "seed_mityushov_misyura_energy",
    ],
}


@pytest.fixture(scope="module")
def seed_runs(fmu_path, tmp_path_factory):
    """{script: (completed process, output folder)}, each run in a scratch working directory."""
    started = {}
    for script in FIGURES:
        folder = tmp_path_factory.mktemp(script)
        process = subprocess.Popen(
            [
                sys.executable,
                str(ROOT / "examples" / f"{script}.py"),
                "--quick",
                "--fmu",
                str(fmu_path),
                "--out",
                str(folder / "out"),
            ],
            cwd=folder,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        started[script] = (process, folder / "out")
    finished = {}
    for script, (process, out) in started.items():
        stdout, stderr = process.communicate(timeout=300)
        finished[script] = (
            subprocess.CompletedProcess(process.args, process.returncode, stdout, stderr),
            out,
        )
    return finished


def table(out: Path, name: str) -> np.ndarray:
    return results.read_csv(out / f"{name}.csv")


@pytest.mark.parametrize("script", list(FIGURES))
def test_script_writes_readable_figures(seed_runs, script):
    from matplotlib.image import imread

    completed, out = seed_runs[script]
    assert completed.returncode == 0, completed.stdout + completed.stderr
    for name in FIGURES[script]:
        png = out / f"{name}.png"
        assert png.stat().st_size > 20_000, png
        assert f"wrote {png}" in completed.stdout
        pixels = imread(png)
        assert pixels.shape[0] >= 400 and pixels.shape[1] >= 600
        # A drawn figure, not a blank canvas: plenty of pixels differ from the background.
        assert np.mean(np.any(pixels[..., :3] < 0.9, axis=-1)) > 0.02
    for csv in out.glob("*.csv"):
        assert f"wrote {csv}" in completed.stdout


def test_wikipedia_speed_angle_and_acceleration(seed_runs):
    _, out = seed_runs["seed_wikipedia"]
    speed = table(out, "seed_wikipedia_output_speed")
    beta, gamma1, w1 = speed["bend_angle_rad"], speed["input_angle_rad"], speed["input_speed_rad_s"]
    assert set(np.round(np.degrees(np.unique(beta)), 9)) == {0, 10, 20, 30, 40, 50}
    d = 1 - np.sin(beta) ** 2 * np.cos(gamma1) ** 2
    np.testing.assert_allclose(speed["output_speed_rad_s"], w1 * np.cos(beta) / d, rtol=1e-12)
    acceleration = table(out, "seed_wikipedia_output_acceleration")
    np.testing.assert_allclose(
        acceleration["output_acceleration_rad_s2"],
        -(w1**2) * np.cos(beta) * np.sin(beta) ** 2 * np.sin(2 * gamma1) / d**2,
        rtol=1e-10,
        atol=1e-13,
    )
    angle = table(out, "seed_wikipedia_output_angle")
    for b in np.unique(beta):
        rows = angle["bend_angle_rad"] == b
        g1 = angle["input_angle_rad"][rows]
        # Wikipedia's atan2 form is valid on (-pi, pi); the FMU's angle is continuous beyond.
        expected = np.unwrap(np.arctan2(np.sin(g1), np.cos(b) * np.cos(g1)))
        np.testing.assert_allclose(angle["output_angle_rad"][rows], expected, rtol=0, atol=1e-12)
        assert g1[-1] == pytest.approx(2 * math.pi)


MAKER_TABLE = [(10, 0.438, 44.8), (20, 1.782, 44.1), (30, 4.117, 42.9)]


def test_maker_maxima_and_locations(seed_runs):
    _, out = seed_runs["seed_maker"]
    maxima = table(out, "seed_maker_maxima")
    assert list(maxima["bend_angle_deg"]) == [b for b, _, _ in MAKER_TABLE]
    for row, (_, printed, at) in zip(maxima, MAKER_TABLE):
        peak = row["max_cardan_error_deg"]
        # The maker truncates 10 deg (0.43856 -> 0.438) but rounds 20 deg (1.78168 -> 1.782).
        assert printed in (math.floor(peak * 1000) / 1000, round(peak, 3))
        assert round(row["at_input_angle_deg"], 1) == at
        # The refined peak tops the samples, and the error is odd about a quarter turn.
        assert (
            row["sampled_max_cardan_error_deg"] <= peak < row["sampled_max_cardan_error_deg"] + 1e-3
        )
        assert row["sampled_min_cardan_error_deg"] == pytest.approx(
            -row["sampled_max_cardan_error_deg"], rel=1e-12
        )
    curves = table(out, "seed_maker_cardan_error")
    for (b, _printed, at), row in zip(MAKER_TABLE, maxima):
        column = curves[f"cardan_error_deg_beta{b}"]
        assert column.max() == pytest.approx(row["sampled_max_cardan_error_deg"], rel=1e-12)
        assert abs(curves["input_angle_deg"][np.argmax(column)] - at) < 0.5


def test_maker_amplitude_and_unevenness_curves(seed_runs):
    _, out = seed_runs["seed_maker"]
    sweep = table(out, "seed_maker_amplitude_unevenness")
    beta = np.radians(sweep["bend_angle_deg"])
    assert len(beta) >= 8 and beta.max() >= math.radians(45) - 1e-12
    np.testing.assert_allclose(
        sweep["unevenness"], np.tan(beta) * np.sin(beta), rtol=1e-12, atol=1e-15
    )
    closed_form = np.degrees(np.arctan((1 - np.cos(beta)) / (2 * np.sqrt(np.cos(beta)))))
    np.testing.assert_allclose(sweep["max_cardan_error_deg"], closed_form, rtol=0, atol=1e-4)
    output_angle = table(out, "seed_maker_output_angle")
    assert output_angle["input_angle_deg"][-1] == pytest.approx(360)
    for b in (30, 60):
        assert output_angle[f"output_angle_deg_beta{b}"][-1] == pytest.approx(360, abs=1e-9)


@pytest.mark.parametrize("name, alpha", [("2pi_7", 2 * math.pi / 7), ("2pi_5", 2 * math.pi / 5)])
def test_tataru_extremes_and_their_mean(seed_runs, name, alpha):
    _, out = seed_runs["seed_tataru"]
    run = table(out, f"seed_tataru_alpha_{name}")
    w1 = 10.0
    np.testing.assert_array_equal(run["input_speed_rad_s"], w1)
    assert run["time_s"][-1] == pytest.approx(1.0)
    w3, phi1 = run["output_speed_rad_s"], run["input_angle_rad"]
    w_max, w_min = w1 / math.cos(alpha), w1 * math.cos(alpha)
    assert w3.max() == pytest.approx(w_max, rel=1e-9)
    assert w3.min() == pytest.approx(w_min, rel=1e-9)
    assert (w3.max() + w3.min()) / 2 == pytest.approx(
        w1 * (1 + math.cos(alpha) ** 2) / (2 * math.cos(alpha)), rel=1e-9
    )
    # Maxima at phi1 = 0, pi, 2 pi, 3 pi; minima at pi/2, 3 pi/2, 5 pi/2 (within 10 rad).
    quarter_turns = phi1 / (math.pi / 2)
    at_max = quarter_turns[np.isclose(w3, w_max, rtol=1e-9, atol=0)]
    at_min = quarter_turns[np.isclose(w3, w_min, rtol=1e-9, atol=0)]
    np.testing.assert_allclose(at_max, [0, 2, 4, 6], atol=1e-9)
    np.testing.assert_allclose(at_min, [1, 3, 5], atol=1e-9)


PAPER_W1, PAPER_ALPHA, I0 = 0.5, math.pi / 6, 0.039


def test_paper_kinematics_and_quaternion(seed_runs):
    _, out = seed_runs["seed_mityushov_misyura"]
    k = table(out, "seed_mityushov_misyura_kinematics")
    np.testing.assert_allclose(
        k["paper_omega2_rad_s"] ** 2 + k["paper_omega3_rad_s"] ** 2, PAPER_W1**2, rtol=1e-12
    )
    np.testing.assert_allclose(
        k["fmu_omega2_rad_s"] ** 2 + k["fmu_omega3_rad_s"] ** 2, PAPER_W1**2, rtol=1e-12
    )
    theta = PAPER_W1 * k["time_s"]
    np.testing.assert_allclose(k["input_angle_rad"], theta, rtol=1e-12, atol=1e-14)
    # Roll from the quaternion: rho = atan(tan a sin psi), psi = theta + 90 deg; paper (3).
    np.testing.assert_allclose(
        k["roll_rho_rad"],
        np.arctan(math.tan(PAPER_ALPHA) * np.sin(theta + math.pi / 2)),
        rtol=0,
        atol=1e-13,
    )
    np.testing.assert_allclose(
        k["paper_roll_gamma_rad"],
        math.pi / 2 - np.arctan(math.tan(PAPER_ALPHA) * np.cos(theta)),
        rtol=0,
        atol=1e-13,
    )
    # Paper (1), integrated: the driven shaft's angle is (2) continued.
    np.testing.assert_allclose(
        k["output_angle_rad"],
        np.unwrap(np.arctan2(np.sin(theta) * math.cos(PAPER_ALPHA), np.cos(theta))),
        rtol=0,
        atol=1e-12,
    )
    q = table(out, "seed_mityushov_misyura_quaternion")
    for frame in ("fmu", "paper"):
        norm = sum(q[f"{frame}_q{i}"] ** 2 for i in range(4))
        np.testing.assert_allclose(norm, 1.0, rtol=0, atol=1e-14)
    gamma = k["paper_roll_gamma_rad"]
    paper_formula_4 = [
        np.cos(theta / 2) * np.cos(gamma / 2),
        np.cos(theta / 2) * np.sin(gamma / 2),
        np.sin(theta / 2) * np.sin(gamma / 2),
        np.sin(theta / 2) * np.cos(gamma / 2),
    ]
    for i, expected in enumerate(paper_formula_4):
        np.testing.assert_allclose(q[f"paper_q{i}"], expected, rtol=0, atol=1e-12)


def test_paper_m3_vanishes_for_i1_equal_i3_equal_half_i2(seed_runs):
    _, out = seed_runs["seed_mityushov_misyura"]
    m = table(out, "seed_mityushov_misyura_torques")
    assert np.max(np.abs(m["paper_M3_flat_cross_N_m"])) < 1e-17
    assert np.max(np.abs(m["paper_M1_flat_cross_N_m"])) > 1e-4
    assert np.max(np.abs(m["paper_M3_equal_N_m"])) > 1e-3


def test_paper_energy_distributions(seed_runs):
    _, out = seed_runs["seed_mityushov_misyura"]
    e = table(out, "seed_mityushov_misyura_energy")
    k = table(out, "seed_mityushov_misyura_kinematics")
    omega = [k[f"paper_omega{i}_rad_s"] for i in (1, 2, 3)]
    distributions = {
        "T1": (2 / 3, 2 / 3, 2 / 3),
        "T2": (1 / 3, 4 / 3, 1 / 3),
        "T3": (5 / 6, 1 / 3, 5 / 6),
        "T4": (7 / 9, 1 / 9, 10 / 9),
    }
    means = set()
    for name, fractions in distributions.items():
        assert sum(fractions) == pytest.approx(2)  # same I0 = (I1 + I2 + I3) / 2
        expected = 0.5 * sum(f * I0 * w**2 for f, w in zip(fractions, omega))
        np.testing.assert_allclose(e[f"{name}_J"], expected, rtol=1e-12)
        means.add(round(float(np.mean(e[f"{name}_J"])), 7))
    assert len(means) == 4
    # T1 has equal moments, so the axis reading cannot matter.
    np.testing.assert_allclose(e["T1_physics_md_reading_J"], e["T1_J"], rtol=1e-12)
