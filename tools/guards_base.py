"""What every part of the mutation table (tools/guards.py) shares: the
`Mutation` record and the files the guards live in and are tested by."""

import difflib
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "fmu_src"))

RESTORED = "        values = {name: float(state[name]) for name in self._saved_names()}\n"
MODEL = "fmu_src/cardan_joint/models/universal_joint/model.py"
VALUES = "fmu_src/cardan_joint/physics/values.py"
STEPPED = "fmu_src/cardan_joint/physics/stepped.py"
SLAVE = "fmu_src/cardan_joint/fmi/slave.py"
CORE = "fmu_src/cardan_joint/fmi/core.py"
FAST_STEP = "fmu_src/cardan_joint/fmi/fast_step.py"
GUARDS = "tests/test_guards.py"
SLAVE_GUARDS = "tests/test_slave_guards.py"
ROBUSTNESS_CALLS = "tests/test_robustness_calls.py"
COMPLIANT = "fmu_src/cardan_joint/models/compliant_joint/model.py"
COMPLIANT_TESTS = "tests/test_compliant_joint.py"
FAST_STEP_TESTS = "tests/test_fast_step.py"


@dataclass(frozen=True)
class Mutation:
    guard: str
    path: str
    target: str  # must occur exactly once in `path`
    replacement: str
    tests: tuple  # pytest arguments: the tests expected to catch it

    @property
    def what(self):
        """The changed lines only: `removed` -> `added`."""
        diff = list(difflib.ndiff(self.target.splitlines(), self.replacement.splitlines()))
        removed = " ".join(line[2:].strip() for line in diff if line.startswith("- "))
        added = " ".join(line[2:].strip() for line in diff if line.startswith("+ "))
        return f"`{removed}` -> `{added}`" if removed else f"insert `{added}`"
