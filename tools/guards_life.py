"""The mutation table's guards of the life integral the default build's step
runs (tools/guards.py, docs/life.md "Exact over each step"): its torque zeros
located and substituted, the zeros' reach on the panels' ellipses, and the
panels sized so that the verdict can pass them."""

from guards_base import Mutation

LIFE_INTEGRAL = "fmu_src/cardan_joint/physics/life_integral.py"
LIFE_ZEROS = "fmu_src/cardan_joint/physics/life_zeros.py"
LIFE_ELLIPSE = "fmu_src/cardan_joint/physics/life_ellipse.py"
LIFE_PANEL = "fmu_src/cardan_joint/physics/life_panel.py"
REACH_TESTS = ("tests/unit/test_life_bound.py", "-k", "zeros_reach or cubics_root")
ZEROS_TESTS = ("tests/unit/test_life_zeros.py",)
STEADY_CHAIN_TESTS = (
    "tests/unit/test_chain_life_search.py::test_a_steady_chain_from_a_dead_centre_takes_its_zeros_at_once_and_exactly",
)

LIFE_MUTATIONS = (
    Mutation(
        "life integral: two torque zeros an ulp apart",
        LIFE_INTEGRAL,
        "hi, zero = (middle, 1) if middle > t else (end, 0)",
        "hi, zero = middle, 1",
        ("tests/unit/test_life.py", "-k", "ulp_apart"),
    ),
    Mutation(
        "life zeros: a zero settled to its share of the starting torques",
        LIFE_ZEROS,
        "if abs(fb) <= settled:",
        "if abs(fb) <= 1e4 * settled:",
        ZEROS_TESTS,
    ),
    Mutation(
        "life zeros: the settled bracket's share",
        LIFE_ZEROS,
        "_SETTLED_BRACKET = 0.25 * SETTLED_ZERO",
        "_SETTLED_BRACKET = 0.25e-8",
        ZEROS_TESTS,
    ),
    Mutation(
        "life zeros: rounding is seen only at a step within the linear reach",
        LIFE_ZEROS,
        "abs(fb) >= abs(fa) and abs(b - a) <= rounding and first < a < last",
        "abs(fb) >= abs(fa) and first < a < last",
        ZEROS_TESTS,
    ),
    Mutation(
        "life zeros: a zero the rounding hides is not an end of its bracket",
        LIFE_ZEROS,
        "abs(fb) >= abs(fa) and abs(b - a) <= rounding and first < a < last",
        "abs(fb) >= abs(fa) and abs(b - a) <= rounding",
        ZEROS_TESTS,
    ),
    Mutation(
        "life zeros: a settled bracket's zero is not an end of it",
        LIFE_ZEROS,
        "return b if first < b < last else c",
        "return b",
        ZEROS_TESTS,
    ),
    Mutation(
        "life zeros: a torque that vanishes at a panel's end has its zero there",
        LIFE_ZEROS,
        "if abs(at_end) * abs(node - end) <= same * abs(at_node - at_end):",
        "if at_end == 0.0:",
        STEADY_CHAIN_TESTS,
    ),
    Mutation(
        "life zeros: two joints' zeros a rounding apart are one",
        LIFE_ZEROS,
        "SAME_ZERO = 1e-10",
        "SAME_ZERO = 1e-12",
        STEADY_CHAIN_TESTS,
    ),
    Mutation(
        "life integral: a zero where the panel starts substitutes it there",
        LIFE_INTEGRAL,
        "if (zero_lo | starting) != zero_lo:",
        "if False:",
        STEADY_CHAIN_TESTS,
    ),
    Mutation(
        "life ellipse: the zeros' reach solved from above its root",
        LIFE_ELLIPSE,
        "x = _spread_bound(c1, c2, c3, limit)",
        "x = 1.0",
        REACH_TESTS,
    ),
    Mutation(
        "life ellipse: the zeros' reach stops where Newton's steps no longer fall",
        LIFE_ELLIPSE,
        "if not lower < x:",
        "if False:",
        REACH_TESTS,
    ),
    Mutation(
        "life panel: the longest panel passes the check it was sized for",
        LIFE_PANEL,
        "_ROUND_TRIP = 1.0 - 1e-12",
        "_ROUND_TRIP = 1.0",
        ("tests/unit/test_life_singularities.py", "-k", "longest_length"),
    ),
)
