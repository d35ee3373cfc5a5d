"""Build the project's FMUs with pythonfmu and refuse them unless FMPy validates them.

Which models exist and their start-value checks come from their folders
(`models/<name>/spec.py`, found by `models.discover`); every model's script is
written from the one template of its FMI version (`fmi/script<N>.py`). Every
build ships its own copy of the runtime part of `cardan_joint` (physics, framework,
slaves, and of the models its own folder and those its code imports) under a
name derived from a hash of that code and of the build's settings, and names the
slave module after the same hash: two different FMUs of this project loaded in
one process can then never run each other's code (Python keeps one module per
name per process). The model's page goes into the FMU's `documentation/`.
"""

import ast
import hashlib
import json
import re
import shutil
import sys
import tempfile
from importlib.util import resolve_name
from pathlib import Path

from .. import DEFAULT_MODEL
from ..models import MODELS_DIR, Model, StartValueError
from ..models import model as find_model
from ..names import UsageError
from .archive import ArchiveError, normalise

PACKAGE_DIR = Path(__file__).resolve().parent.parent
# What every FMU needs at run time: the shared layers (the equations, the
# stepped-model framework), the models' registry and the slaves; of the model
# folders, only its own and those its code imports (`_model_folders`: a model
# may build on another's), Python only. The rest of the package (host, build,
# the native loader's sources, the script templates, other models, pages and
# reference runs) runs in the host only.
RUNTIME = (
    "__init__.py",
    "names.py",
    "units.py",
    "variable_schema.py",
    "physics",
    "framework",
    "models/__init__.py",
    "fmi",
)
# Host-only parts of the runtime's folders.
_HOST_ONLY = ("native", "__pycache__")
SCRIPTS = {2: PACKAGE_DIR / "fmi" / "script2.py", 3: PACKAGE_DIR / "fmi" / "script3.py"}
FMI_VERSIONS = (2, 3)


class BuildError(RuntimeError):
    pass


class BuildUsageError(BuildError, UsageError):
    """A build asked for something it cannot build (an unknown model or start
    value, a value out of range, a bad name): the user's mistake, exit 2."""


def _python_files(path: Path) -> list:
    """`path` itself, or the Python files under the folder `path`, host-only ones left out."""
    if not path.is_dir():
        return [path]
    return sorted(
        p
        for p in path.rglob("*.py")
        if p not in SCRIPTS.values() and not set(p.relative_to(path).parts) & set(_HOST_ONLY)
    )


def _imported_folders(path: Path) -> set:
    """The model folders the module at `path` (under models/) imports."""
    parts = path.relative_to(MODELS_DIR).with_suffix("").parts
    module = ".".join((PACKAGE_DIR.name, MODELS_DIR.name, *parts))
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    prefix = f"{PACKAGE_DIR.name}.{MODELS_DIR.name}."
    named = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            named += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = resolve_name("." * node.level + (node.module or ""), package)
            named += [base, *(f"{base}.{alias.name}" for alias in node.names)]
    folders = {name[len(prefix) :].split(".")[0] for name in named if name.startswith(prefix)}
    return {folder for folder in folders if (MODELS_DIR / folder).is_dir()}


def _model_folders(folder: str) -> list:
    """`folder` and every model folder its code imports, directly or not."""
    found: set = set()
    pending = [folder]
    while pending:
        current = pending.pop()
        if current not in found:
            found.add(current)
            for path in _python_files(MODELS_DIR / current):
                pending += _imported_folders(path)
    return sorted(found)


def _runtime_files(folder: str) -> list:
    """What an FMU of the model in `folder` ships of the package."""
    shared = [path for entry in RUNTIME for path in _python_files(PACKAGE_DIR / entry)]
    own = [p for name in _model_folders(folder) for p in _python_files(MODELS_DIR / name)]
    return shared + own


def _fingerprint(
    script: Path, folder: str, model_name: str, start_values: dict, settings: dict, arrays: bool
) -> str:
    digest = hashlib.sha256()
    for path in [script, *_runtime_files(folder)]:
        digest.update(str(path.relative_to(PACKAGE_DIR)).encode())
        digest.update(path.read_bytes())
    digest.update(
        json.dumps(
            [folder, model_name, sorted(start_values.items()), sorted(settings.items()), arrays]
        ).encode()
    )
    return digest.hexdigest()[:12]


def _check_start_values(spec: Model, start_values: dict, settings: dict) -> dict:
    values = {name: float(value) for name, value in start_values.items()}
    try:
        spec.check_start_values(values, settings)
    except StartValueError as error:
        raise BuildUsageError(str(error)) from None
    return values


def _rewrite(script: str, pattern: str, replacement: str, what: str, required: bool) -> str:
    script, count = re.subn(pattern, lambda _: replacement, script, count=1, flags=re.M)
    if count != 1 and required:
        raise BuildError(f"the script template no longer has the {what} line the build rewrites")
    return script


def _stage(
    workdir: Path,
    script_template: Path,
    model_name: str,
    start_values: dict,
    settings: dict,
    fingerprint: str,
    folder: str,
    fmi3_arrays: bool = False,
) -> Path:
    package = f"cardan_joint_{fingerprint}"
    target = workdir / package
    target.mkdir()
    for source in _runtime_files(folder):
        copy = target / source.relative_to(PACKAGE_DIR)
        copy.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, copy)
    # FMI's place for the model's documentation: its page.
    (workdir / "documentation").mkdir()
    shutil.copy2(MODELS_DIR / folder / "README.md", workdir / "documentation" / "README.md")
    script = script_template.read_text().replace("from cardan_joint.", f"from {package}.")
    base = re.search(r"^class \w+\(([\w, ]+)\):", script, flags=re.M)
    if base is None:
        raise BuildError(f"{script_template} has no slave class for the build to rename")
    script = _rewrite(
        script, r"^class \w+\([\w, ]+\):", f"class {model_name}({base.group(1)}):", "class", True
    )
    script = _rewrite(
        script,
        r"^    model_folder = \"\"  # .*$",
        f"    model_folder = {folder!r}",
        "model_folder",
        True,
    )
    script = _rewrite(
        script,
        r"^    start_overrides = \{\}$",
        f"    start_overrides = {start_values!r}",
        "start_overrides",
        True,
    )
    script = _rewrite(
        script,
        r"^    build_settings = \{\}$",
        f"    build_settings = {settings!r}",
        "build_settings",
        bool(settings),
    )
    if fmi3_arrays:
        script = _rewrite(
            script, r"^    fmi3_arrays = False$", "    fmi3_arrays = True", "fmi3_arrays", True
        )
    script_path = workdir / f"{model_name.lower()}_{fingerprint}.py"
    script_path.write_text(script)
    return script_path


def _fmu_builder(fmi_version: int):
    if fmi_version == 2:
        from pythonfmu import FmuBuilder
    else:
        from pythonfmu3 import FmuBuilder
    return FmuBuilder


def build(
    dest: str | Path = "dist",
    model_name: str | None = None,
    start_values: dict | None = None,
    validate: bool = True,
    model: str = DEFAULT_MODEL,
    settings: dict | None = None,
    fmi_version: int = 2,
    fmi3_arrays: bool = False,
) -> Path:
    """Build `<dest>/<model_name>.fmu` (FMI 3: `<dest>/fmi3/<model_name>.fmu`);
    raise BuildError unless FMPy validates it. `fmi3_arrays`: FMI 3 vectors as
    Float64 arrays instead of the FMI 2.0 scalars (docs/fmi3.md says which hosts
    read which)."""
    try:
        spec = find_model(model)
    except StartValueError as error:
        raise BuildUsageError(str(error)) from None
    settings = {**spec.default_settings, **(settings or {})}
    model_name = model_name or spec.default_name(settings)
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", model_name):
        raise BuildUsageError(f"model name {model_name!r} must be a Python identifier")
    if fmi_version not in spec.fmi_versions:
        raise BuildUsageError(
            f"{model} is built for FMI {', '.join(map(str, spec.fmi_versions))} only, "
            f"not FMI {fmi_version}"
        )
    if fmi3_arrays and fmi_version != 3:
        raise BuildUsageError(f"FMI 3 arrays need FMI 3, not FMI {fmi_version}")
    script_template = SCRIPTS[fmi_version]
    start_values = _check_start_values(spec, start_values or {}, settings)
    dest = Path(dest).resolve() / ("fmi3" if fmi_version == 3 else "")
    dest.mkdir(parents=True, exist_ok=True)
    fingerprint = _fingerprint(
        script_template, spec.folder, model_name, start_values, settings, fmi3_arrays
    )
    builder = _fmu_builder(fmi_version)
    with tempfile.TemporaryDirectory(prefix="cardan_joint_build_") as workdir:
        script = _stage(
            Path(workdir),
            script_template,
            model_name,
            start_values,
            settings,
            fingerprint,
            spec.folder,
            fmi3_arrays,
        )
        package_dir = script.parent / f"cardan_joint_{fingerprint}"
        try:
            fmu = builder.build_FMU(
                script,
                dest=dest,
                project_files=[package_dir],
                documentation_folder=script.parent / "documentation",
            )
        finally:
            # pythonfmu imported the staged script and package: drop them, so a
            # second build in this process cannot pick up this one's code. (Third-
            # party modules they imported stay: numpy cannot be imported twice.)
            for name in [
                n for n in sys.modules if n.split(".")[0] in (package_dir.name, script.stem)
            ]:
                del sys.modules[name]
    fmu = Path(fmu)
    # --- native loader (issue 11): C hosts run the FMU without any set-up ---
    from ..fmi.native import NativeBuildError
    from .step_source import generated_step, install_runtime

    try:
        install_runtime(fmu, model_name, fmi_version, generated_step(spec, settings, model_name))
    except NativeBuildError as error:
        fmu.unlink()
        raise BuildError(str(error)) from None
    # --- end native loader ---
    # Last: everything that writes into the FMU has written (see archive.py).
    try:
        normalise(fmu, fmi_version)
    except ArchiveError as error:
        fmu.unlink()
        raise BuildError(str(error)) from None
    if validate:
        from fmpy.validation import validate_fmu

        problems = validate_fmu(str(fmu))
        if problems:
            fmu.unlink()
            raise BuildError("FMPy's validate_fmu rejected the FMU:\n  " + "\n  ".join(problems))
    return fmu
