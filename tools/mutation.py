"""Mutation run: is every guard proven by a test?

For each guard below, replace its text in a temporary copy of the source tree
(the working tree is never touched), run the tests that should notice, and
report whether at least one failed (the mutant is "killed").

    .venv/bin/python tools/mutation.py             # all guards, a markdown table
    .venv/bin/python tools/mutation.py --only bend # guards whose name contains "bend"
    .venv/bin/python tools/mutation.py --list      # the guards, no run

Exits non-zero if a mutant survives. tests/unit/test_mutation_list.py checks that
each target still occurs exactly once (whatever its layout: reformatting keeps it),
so a refactor cannot orphan a guard.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from guards import COPIED, MUTATIONS, ROOT, Mutation  # noqa: E402


def _copy_tree(destination: Path):
    for entry in COPIED:
        source = ROOT / entry
        if source.is_dir():
            shutil.copytree(
                source,
                destination / entry,
                ignore=shutil.ignore_patterns("__pycache__", "*.pyc", ".hypothesis"),
            )
        else:
            shutil.copy2(source, destination / entry)


def _failures(output: str):
    """The failing tests, once each, with how many of their cases failed."""
    names = re.findall(r"^(?:FAILED|ERROR) \S+?::(\w+)", output, re.MULTILINE)
    return [
        f"{name} ({names.count(name)} cases)" if names.count(name) > 1 else name
        for name in dict.fromkeys(names)
    ]


def run_mutation(tree: Path, mutation: Mutation, timeout=300):
    """(killed, failing tests, seconds) of one mutant in `tree`, restored afterwards."""
    path = tree / mutation.path
    original = path.read_text()
    try:
        path.write_text(mutation.apply(original))
    except ValueError as error:
        raise SystemExit(str(error)) from None
    env = {
        **os.environ,
        "PYTHONPATH": str(tree / "fmu_src"),
        "PYTHONDONTWRITEBYTECODE": "1",
        "CI": "1",
    }
    start = time.perf_counter()
    try:
        run = subprocess.run(
            [
                sys.executable,
                "-m",
                "pytest",
                "-q",
                "-rfE",
                "-p",
                "no:cacheprovider",
                *mutation.tests,
            ],
            cwd=tree,
            env=env,
            capture_output=True,
            text=True,
            timeout=timeout,
        )
        failing = _failures(run.stdout)
        # Exit code 1: tests failed. 0: all passed (survived). Others: collection or usage errors,
        # which would make a survivor look killed, so they stop the run.
        if run.returncode not in (0, 1):
            raise SystemExit(
                f"{mutation.guard}: pytest exited {run.returncode}\n{run.stdout[-3000:]}"
            )
        killed = run.returncode == 1
    except subprocess.TimeoutExpired:
        failing, killed = ["(timed out)"], True
    finally:
        path.write_text(original)
    return killed, failing, time.perf_counter() - start


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="", help="run the guards whose name contains this")
    parser.add_argument("--list", action="store_true", help="list the guards and exit")
    args = parser.parse_args(argv)
    chosen = [m for m in MUTATIONS if args.only in m.guard]
    if args.list:
        for m in chosen:
            print(f"{m.guard}: {m.what}  [{' '.join(m.tests)}]")
        return 0
    rows, survivors, start = [], 0, time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="mutation-") as tmp:
        tree = Path(tmp)
        _copy_tree(tree)
        for k, mutation in enumerate(chosen, 1):
            killed, failing, seconds = run_mutation(tree, mutation)
            survivors += not killed
            shown = ", ".join(f"`{name}`" for name in failing[:3])
            if len(failing) > 3:
                shown += f" (+{len(failing) - 3} more)"
            rows.append(
                f"| {mutation.guard} | {mutation.what} | {shown or '(none)'} | "
                f"{'yes' if killed else '**NO**'} |"
            )
            print(
                f"[{k}/{len(chosen)}] {mutation.guard}: {'killed' if killed else 'SURVIVED'} "
                f"({seconds:.1f} s)",
                file=sys.stderr,
            )
    print("| guard | mutation | failing test(s) | killed |\n|---|---|---|---|")
    print("\n".join(rows))
    print(
        f"\n{len(chosen) - survivors} of {len(chosen)} mutants killed "
        f"in {time.perf_counter() - start:.0f} s."
    )
    return 1 if survivors else 0


if __name__ == "__main__":
    sys.exit(main())
