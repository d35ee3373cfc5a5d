"""The mutation table's guards of what life carries from one step to the next
(tools/guards.py, docs/life.md "Exact over each step"): the step's first
panel foreseen from the last step's last plain panel only when there is one
and its zeros asked for more points than the singularities, and a restored
state's `life_ahead` checked before it is taken."""

from guards_base import Mutation

LIFE_INTEGRAL = "fmu_src/cardan_joint/physics/life_integral.py"
PROPSHAFT_LIFE = "fmu_src/cardan_joint/models/propshaft/life.py"
COUNT = ("tests/unit/test_life_march.py", "-k", "without_a_mean_torque")
RESTORED = ("tests/unit/test_propshaft_life.py", "-k", "restored or malformed")
FEWEST = ("tests/unit/test_propshaft_life.py", "-k", "fewest_points")

AHEAD_MUTATIONS = (
    Mutation(
        "life ahead: a last plain panel of the fewest points drops an earlier one",
        LIFE_INTEGRAL,
        "            elif zero == 0:\n",
        "            elif False:\n",
        ("tests/unit/test_life_march.py", "-k", "last_plain_panel_took_the_fewest"),
    ),
    Mutation(
        "life ahead: the first panel foreseen from the last step's",
        LIFE_INTEGRAL,
        "if inside or (t == 0.0 and zero == 0 and guide_lo < guide_hi <= 0.0):",
        "if inside:",
        COUNT,
    ),
    Mutation(
        "life ahead: nothing foreseen before any step",
        LIFE_INTEGRAL,
        "if inside or (t == 0.0 and zero == 0 and guide_lo < guide_hi <= 0.0):",
        "if inside or (t == 0.0 and zero == 0 and guide_hi <= 0.0):",
        RESTORED,
    ),
    Mutation(
        "life ahead: a panel of the fewest points carries nothing",
        LIFE_INTEGRAL,
        "if zero == 0 and n > least:",
        "if zero == 0:",
        FEWEST,
    ),
    Mutation(
        "life ahead: a restored state carries it",
        PROPSHAFT_LIFE,
        "            self._ahead = ahead\n",
        "            pass\n",
        RESTORED,
    ),
    Mutation(
        "life ahead: a restored state's count checked",
        PROPSHAFT_LIFE,
        "if len(ahead) != len(unseen):",
        "if False:",
        RESTORED,
    ),
    Mutation(
        "life ahead: a restored state's values finite",
        PROPSHAFT_LIFE,
        "if not all(math.isfinite(x) for x in ahead):",
        "if False:",
        RESTORED,
    ),
)
