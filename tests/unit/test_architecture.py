"""Physics apart from plumbing, and the layers of the package.

Layers, each importing only its own and lower ones: the equations and shared data
(`physics/`, the C generator `codegen/`, `units`, `variable_schema`, `names`,
`extras`, `results`) <- the stepped-model runtime (`framework/`) <- the model folders
(`models/<name>/`: a model's table, physics and spec; one model may build on
another) <- `fmi/` (the slaves) <- `build/` <- `host/` <- the commands (`sweep/`,
`cli`, the `simulate` entry point). Checked on the source, statically.
"""

import ast
import subprocess
import sys
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "fmu_src" / "cardan_joint"
LAYERS = {"shared": 0, "framework": 1, "models": 2, "fmi": 3, "build": 4, "host": 5, "commands": 6}
TOP = {
    "physics": "shared",
    "codegen": "shared",
    "framework": "framework",
    "models": "models",
    "fmi": "fmi",
    "build": "build",
    "host": "host",
}
SHARED_MODULES = {"__init__", "units", "variable_schema", "names", "extras", "results"}


def _layer(module: str) -> str:
    """The layer of `module` (dotted, under cardan_joint; "" is the package)."""
    head = module.split(".")[0] if module else "__init__"
    if head in TOP:
        return TOP[head]
    return "shared" if head in SHARED_MODULES else "commands"


def _module(path: Path, package: Path = PACKAGE) -> str:
    parts = path.relative_to(package).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path, root: Path = PACKAGE):
    """The cardan_joint modules `path` imports (dotted, under cardan_joint)."""
    dotted = _module(path, root).split(".")
    package = [p for p in (dotted if path.name == "__init__.py" else dotted[:-1]) if p]
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            elif node.module and node.module.split(".")[0] == "cardan_joint":
                target = node.module.partition(".")[2]
            else:
                continue
            yield target
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "cardan_joint":
                    yield alias.name.partition(".")[2]


def _upward_imports(package: Path = PACKAGE) -> list:
    """One line per module of `package` (laid out as cardan_joint) that imports a
    higher layer, naming the module, its layer and what it imports."""
    found = []
    for path in sorted(package.rglob("*.py")):
        module = _module(path, package)
        own = _layer(module)
        higher = [t for t in _imports(path, package) if LAYERS[_layer(t)] > LAYERS[own]]
        if higher:
            found.append(f"{own} module {module} imports {higher}")
    return found


def test_no_module_imports_a_higher_layer():
    assert len(list(PACKAGE.rglob("*.py"))) > 50  # an empty scan would check nothing
    assert _upward_imports() == []


def test_the_layer_check_sees_an_upward_import(tmp_path):
    # The check above must be able to fail: a physics module importing a host one,
    # absolutely and relatively, or the framework (equations never lean on the
    # runtime); a model importing the framework and the physics is fine.
    (tmp_path / "physics").mkdir()
    (tmp_path / "physics" / "values.py").write_text("from cardan_joint.host import simulate\n")
    (tmp_path / "physics" / "step.py").write_text("from ..host.instance import FmuInstance\n")
    (tmp_path / "physics" / "rotor.py").write_text("from ..framework.refusal import Refusal\n")
    (tmp_path / "models").mkdir()
    (tmp_path / "models" / "load.py").write_text(
        "from ..physics import values\nfrom ..framework import stepped\n"
    )
    assert _upward_imports(tmp_path) == [
        "shared module physics.rotor imports ['framework.refusal']",
        "shared module physics.step imports ['host.instance']",
        "shared module physics.values imports ['host']",
    ]


def test_physics_and_models_import_neither_pythonfmu_nor_fmpy():
    check = (
        "import sys, cardan_joint.models as m; "
        "[spec.make(spec.default_settings).outputs() for spec in m.discover().values()]; "
        "print(sorted(m for m in sys.modules if m.split('.')[0] in "
        "('pythonfmu', 'pythonfmu3', 'fmpy', 'matplotlib', 'dask', 'libcosimpy')))"
    )
    run = subprocess.run([sys.executable, "-c", check], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "[]"


def test_every_model_folder_is_discovered():
    from cardan_joint.models import discover

    folders = {p.parent.name for p in (PACKAGE / "models").glob("*/spec.py")}
    assert {spec.folder for spec in discover().values()} == folders
    assert len(folders) >= 7
