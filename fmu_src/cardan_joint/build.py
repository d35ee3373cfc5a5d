"""Build the UniversalJoint FMU with pythonfmu and refuse it unless FMPy validates it.

Every build ships its own copy of the runtime part of `cardan_joint` (physics,
variable table, slave) under a name derived from a hash of that code and of
the build's settings, and names the slave module after the same hash: two
different FMUs of this project loaded in one process can then never run each
other's code (Python keeps one module per name per process).
"""

import argparse
import hashlib
import json
import re
import shutil
import sys
import tempfile
from pathlib import Path

from . import variables as table

PACKAGE_DIR = Path(__file__).resolve().parent
SCRIPT = PACKAGE_DIR / "fmu" / "UniversalJoint.py"            # the pythonfmu script template
RUNTIME = ("__init__.py", "variables.py", "physics", "fmu")   # what the FMU needs at run time
_NOT_SHIPPED = shutil.ignore_patterns("__pycache__", SCRIPT.name)
DEFAULT_NAME = "UniversalJoint"


class BuildError(RuntimeError):
    pass


def _runtime_files():
    for entry in RUNTIME:
        path = PACKAGE_DIR / entry
        yield from (sorted(p for p in path.rglob("*.py") if p != SCRIPT)
                    if path.is_dir() else [path])


def _fingerprint(model_name: str, start_values: dict) -> str:
    digest = hashlib.sha256()
    for path in [SCRIPT, *_runtime_files()]:
        digest.update(str(path.relative_to(PACKAGE_DIR)).encode())
        digest.update(path.read_bytes())
    digest.update(json.dumps([model_name, sorted(start_values.items())]).encode())
    return digest.hexdigest()[:12]


def _check_start_values(start_values: dict) -> dict:
    from .physics.model import CardanJoint

    settable = set(table.INPUTS) | set(table.PARAMETERS)
    unknown = sorted(set(start_values) - settable)
    if unknown:
        raise BuildError(f"cannot set start value of {', '.join(unknown)}: "
                         f"only inputs and parameters have start values")
    values = {name: float(value) for name, value in start_values.items()}
    # An FMU whose defaults cannot run would only fail later, in someone's master.
    joint = CardanJoint(**values)
    problem = joint.parameter_problem() or joint.input_problem()
    if problem:
        raise BuildError(f"invalid start values: {problem}")
    return values


def _stage(workdir: Path, model_name: str, start_values: dict, fingerprint: str) -> Path:
    package = f"cardan_joint_{fingerprint}"
    target = workdir / package
    target.mkdir()
    for entry in RUNTIME:
        source = PACKAGE_DIR / entry
        if source.is_dir():
            shutil.copytree(source, target / entry, ignore=_NOT_SHIPPED)
        else:
            shutil.copy2(source, target / entry)
    script = SCRIPT.read_text()
    script = script.replace("from cardan_joint.", f"from {package}.")
    script, classes = re.subn(r"^class UniversalJoint\(CardanJointSlave\):",
                              f"class {model_name}(CardanJointSlave):", script, flags=re.M)
    script, overrides = re.subn(r"^    start_overrides = \{\}$",
                                f"    start_overrides = {start_values!r}", script, flags=re.M)
    if classes != 1 or overrides != 1:
        raise BuildError(f"{SCRIPT} no longer has the lines the build rewrites")
    script_path = workdir / f"universal_joint_{fingerprint}.py"
    script_path.write_text(script)
    return script_path


def build(dest="dist", model_name: str = DEFAULT_NAME, start_values: dict = None,
          validate: bool = True) -> Path:
    """Build `<dest>/<model_name>.fmu`; raise BuildError unless FMPy validates it."""
    from pythonfmu import FmuBuilder

    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", model_name):
        raise BuildError(f"model name {model_name!r} must be a Python identifier")
    start_values = _check_start_values(start_values or {})
    dest = Path(dest).resolve()
    dest.mkdir(parents=True, exist_ok=True)
    fingerprint = _fingerprint(model_name, start_values)
    with tempfile.TemporaryDirectory(prefix="cardan_joint_build_") as workdir:
        script = _stage(Path(workdir), model_name, start_values, fingerprint)
        package_dir = script.parent / f"cardan_joint_{fingerprint}"
        try:
            fmu = FmuBuilder.build_FMU(script, dest=dest, project_files=[package_dir])
        finally:
            # pythonfmu imported the staged module; drop it so a second build in
            # this process cannot pick up the first one's code.
            for name in list(sys.modules):
                if name.startswith((f"cardan_joint_{fingerprint}", script.stem)):
                    del sys.modules[name]
    fmu = Path(fmu)
    # --- native loader (issue 11): C hosts run the FMU without any set-up ---
    from .native import NativeBuildError, install_loader
    try:
        install_loader(fmu, model_name)
    except NativeBuildError as error:
        fmu.unlink()
        raise BuildError(str(error)) from None
    # --- end native loader ---
    if validate:
        from fmpy.validation import validate_fmu

        problems = validate_fmu(str(fmu))
        if problems:
            fmu.unlink()
            raise BuildError("FMPy's validate_fmu rejected the FMU:\n  " + "\n  ".join(problems))
    return fmu


def _parse_start_values(pairs):
    values = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        try:
            values[name.strip()] = float(value)
        except ValueError:
            sep = ""
        if not sep:
            raise BuildError(f"--set takes NAME=VALUE with a number, got {pair!r}")
    return values


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Build and validate the UniversalJoint FMU.")
    parser.add_argument("--dest", default="dist", help="output folder (default: dist)")
    parser.add_argument("--name", default=DEFAULT_NAME,
                        help="model name and FMU file name (default: UniversalJoint)")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="start value of an input or parameter, e.g. --set bend_angle=0.2")
    args = parser.parse_args(argv)
    try:
        fmu = build(args.dest, args.name, _parse_start_values(args.set))
    except BuildError as error:
        print(f"build_fmu: {error}", file=sys.stderr)
        return 1
    print(f"built and validated {fmu}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
