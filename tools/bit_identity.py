"""Every model's FMUs (FMI 2.0 and 3.0) of two source trees, bit for bit.

    python tools/bit_identity.py BEFORE_TREE AFTER_TREE [--steps N] [--model KEY ...]
                                 [--after-setting=--SETTING ...]

Builds each model found in AFTER_TREE with each tree's own build_fmu.py, runs
both through one long scenario in FMPy (inputs varied every step, out-of-range
and NaN inputs: refused steps and held outputs; reads after writes; an FMU state
saved, serialized and restored) and compares every status, every output's bits
and every log message. Exits 1 on the first FMU that differs. A check for
changes that must not change results (a refactoring, a faster step).

--model restricts the comparison to those models; --after-setting builds AFTER
with a build setting BEFORE lacks (e.g. `--after-setting=--no-life`: a model
with a new part, built without it), both under the model's plain name;
--common-outputs compares only the outputs BEFORE has (AFTER adds outputs, and
parameters at their defaults, and must leave the others as they were)."""

import argparse
import math
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "fmu_src"))

from cardan_joint.host.instance import ExtractedFMU  # noqa: E402
from cardan_joint.models import discover  # noqa: E402

STEP = 1e-3


def builds():
    """(build arguments, FMU path under the destination) of every FMU compared."""
    for key, spec in discover().items():
        for version in spec.fmi_versions:
            folder = "fmi3/" if version == 3 else ""
            yield ["--model", key, "--fmi-version", str(version)], f"{folder}{key}.fmu"
    yield ["--model", "Propshaft", "--joints", "3"], "Propshaft3.fmu"


def build(tree: Path, dest: Path, arguments) -> None:
    command = [sys.executable, "build_fmu.py", "--dest", str(dest), *arguments]
    subprocess.run(command, cwd=tree, check=True, capture_output=True)


def flat(values) -> bytes:
    numbers = [x for v in values for x in (v if isinstance(v, list) else [v])]
    return struct.pack(f"{len(numbers)}d", *numbers)


def scenario(fmu: Path, steps: int, only=None) -> list:
    """Everything an FMU answers over the scenario, in order (of the outputs
    `only` names, if given)."""
    log: list = []
    record: list = []
    with ExtractedFMU(fmu) as extracted:
        inputs = [v for v in extracted.model_description.modelVariables if v.causality == "input"]
        starts = {v.name: float(v.start) for v in inputs}
        with extracted.instance("bits", messages=log) as fmu_instance:
            outputs = [n for n in fmu_instance.outputs if only is None or n in only]

            def read(tag):
                record.append((tag, flat(fmu_instance.values(*outputs))))

            for k in range(steps):
                values = {
                    v.name: starts[v.name]
                    + 0.05 * max(1.0, abs(starts[v.name])) * math.sin(0.0013 * k * (i + 1))
                    for i, v in enumerate(inputs)
                }
                if k % 997 == 500:
                    values[inputs[k % len(inputs)].name] = 1e300
                if k % 1499 == 700:
                    values[inputs[(k // 3) % len(inputs)].name] = math.nan
                record.append(("set", k, fmu_instance.try_set(**values)))
                if k % 7 == 0:
                    read("after set")
                record.append(("step", k, fmu_instance.try_step(STEP), fmu_instance.time))
                read("after step")
                if k == steps // 3:
                    saved = fmu_instance.serialize_state(fmu_instance.get_state())
                if k == steps // 2:
                    fmu_instance.set_state(fmu_instance.deserialize_state(saved))
                    fmu_instance.time = (steps // 3 + 1) * STEP
                    read("after restore")
    return record + [("log", list(log))]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before", type=Path)
    parser.add_argument("after", type=Path)
    parser.add_argument("--steps", type=int, default=4000)
    parser.add_argument("--model", action="append", default=[], help="only this model")
    parser.add_argument("--after-setting", action="append", default=[], metavar="ARG")
    parser.add_argument("--common-outputs", action="store_true", help="only BEFORE's outputs")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="bit_identity_") as work:
        for arguments, name in builds():
            if args.model and arguments[1] not in args.model:
                continue
            if args.after_setting:  # one name on both sides, whatever the setting names
                arguments = [*arguments, "--name", Path(name).stem]
            answers: list = []
            only = None
            for tree, side in ((args.before, "before"), (args.after, "after")):
                dest = Path(work) / side
                extra = args.after_setting if side == "after" else []
                build(tree.resolve(), dest, [*arguments, *extra])
                answers.append(scenario(dest / name, args.steps, only))
                if args.common_outputs and only is None:
                    with ExtractedFMU(dest / name) as before:
                        described = before.model_description.modelVariables
                        only = {v.name for v in described if v.causality == "output"}
            same = answers[0] == answers[1]
            print(f"{name}: {'identical' if same else 'DIFFERENT'} ({len(answers[0])} records)")
            if not same:
                return 1
    print("every FMU identical")
    return 0


if __name__ == "__main__":
    sys.exit(main())
