"""The guards the mutation run disables (tools/mutation.py): for each, the
text that is the guard in its file, what replaces it, and the tests that must
notice. tests/unit/test_mutation_list.py checks that each target text occurs exactly
once, so a refactor cannot orphan a guard."""

# The parts are top-level modules of tools/, as this one is (tools/mutation.py
# puts tools/ on the path).
from guards_ahead import AHEAD_MUTATIONS
from guards_base import ROOT, Mutation
from guards_generated import GENERATED_MUTATIONS
from guards_life import LIFE_MUTATIONS
from guards_plumbing import PLUMBING_MUTATIONS
from guards_runtime import RUNTIME_MUTATIONS
from guards_step import STEP_MUTATIONS
from guards_values import VALUE_MUTATIONS

COPIED = ("fmu_src", "tests", "build_fmu.py", "pyproject.toml", "README.md")
MUTATIONS = (
    *VALUE_MUTATIONS,
    *STEP_MUTATIONS,
    *PLUMBING_MUTATIONS,
    *GENERATED_MUTATIONS,
    *LIFE_MUTATIONS,
    *RUNTIME_MUTATIONS,
    *AHEAD_MUTATIONS,
)

__all__ = ["COPIED", "MUTATIONS", "ROOT", "Mutation"]
