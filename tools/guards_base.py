"""What every part of the mutation table (tools/guards.py) shares: the
`Mutation` record and the files the guards live in and are tested by."""

import difflib
import re
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "fmu_src"))

RESTORED = "        values = {name: float(state[name]) for name in self._saved_names()}\n"
MODEL = "fmu_src/cardan_joint/models/universal_joint/model.py"
LIMITS = "fmu_src/cardan_joint/models/universal_joint/limits.py"
VALUES = "fmu_src/cardan_joint/framework/values.py"
STEPPED = "fmu_src/cardan_joint/framework/stepped.py"
WRITTEN_STEP = "fmu_src/cardan_joint/framework/written_step.py"
ROTOR_MODEL = "fmu_src/cardan_joint/framework/rotor_model.py"
SLAVE = "fmu_src/cardan_joint/fmi/slave.py"
CORE = "fmu_src/cardan_joint/fmi/core.py"
FMU_STATE = "fmu_src/cardan_joint/fmi/fmu_state.py"
REFERENCES = "fmu_src/cardan_joint/fmi/references.py"
FAST_PATH = "fmu_src/cardan_joint/fmi/fast_path.py"
WATCHES = "fmu_src/cardan_joint/framework/watches.py"
WATCHING = "fmu_src/cardan_joint/fmi/watching.py"
WATCH_TESTS = "tests/fmu/test_watched_limits.py"
WATCH_UNIT_TESTS = "tests/unit/test_watch_rows.py"
GUARDS = "tests/unit/test_guards.py"
SLAVE_GUARDS = "tests/fmu/test_slave_guards.py"
ROBUSTNESS_CALLS = "tests/fmu/test_robustness_calls.py"
HONEST = "tests/fmu/test_honest_statuses.py"
COMPLIANT = "fmu_src/cardan_joint/models/compliant_joint/model.py"
COMPLIANT_TESTS = "tests/fmu/test_compliant_joint.py"
SLAVE_ARRAYS = "tests/unit/test_slave_arrays.py"


@dataclass(frozen=True)
class Mutation:
    guard: str
    path: str
    target: str  # must occur exactly once in `path`, however it is laid out
    replacement: str
    tests: tuple  # pytest arguments: the tests expected to catch it

    @property
    def what(self):
        """The changed lines only: `removed` -> `added`."""
        diff = list(difflib.ndiff(self.target.splitlines(), self.replacement.splitlines()))
        removed = " ".join(line[2:].strip() for line in diff if line.startswith("- "))
        added = " ".join(line[2:].strip() for line in diff if line.startswith("+ "))
        return f"`{removed}` -> `{added}`" if removed else f"insert `{added}`"

    @property
    def pattern(self) -> re.Pattern:
        """The target wherever a formatter may have laid it out otherwise: any
        whitespace between its characters, and the trailing comma a formatter adds
        before a closing bracket when it wraps a call."""
        tokens = []
        for char in self.target:
            if char.isspace():
                continue
            if char in ")]}":
                tokens.append(r"(?:,\s*)?")
            tokens.append(re.escape(char))
        return re.compile(r"\s*".join(tokens))

    def apply(self, source: str) -> str:
        """`source` with the target replaced; ValueError unless it occurs exactly once."""
        found = list(self.pattern.finditer(source))
        if len(found) != 1:
            raise ValueError(f"{self.guard}: target found {len(found)} times in {self.path}")
        lead = self.target[: len(self.target) - len(self.target.lstrip())]
        trail = self.target[len(self.target.rstrip()) :]
        new = self.replacement.removeprefix(lead)
        new = new[: len(new) - len(trail)] if trail and new.endswith(trail) else new
        return source[: found[0].start()] + new + source[found[0].end() :]
