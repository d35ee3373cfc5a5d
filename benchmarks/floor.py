"""The FMUs the benchmarks time: a model's default build and its floors, empty
pythonfmu FMUs with the same Real variables (benchmarks/floor_slave.py).

from benchmarks.floor import build_floor_fmu, build_model_fmu
fmu = build_model_fmu(dest, "Propshaft")                  # the default build
floor = build_floor_fmu(dest, "plain", model="Propshaft")  # its own empty FMU
"""

import hashlib
import json
import shutil
from collections.abc import Mapping
from pathlib import Path

from cardan_joint.fmi.native import install_loader
from cardan_joint.models import discover

from .timing import ROOT, run_checked

SLAVE = Path(__file__).with_name("floor_slave.py")
JOINT = "UniversalJoint"  # the model of the FMPy, accuracy and growth sections
# kind -> what its value access is (written into the report's footnote)
FLOORS = {
    "plain": "values through pythonfmu's own get_real/set_real",
    "bare": "values by list indexing in overridden get_real/set_real",
}


def floor_config(kind: str, model: str = JOINT, settings: Mapping | None = None) -> dict:
    if kind not in FLOORS:
        raise ValueError(f"floor kind must be one of {sorted(FLOORS)}, got {kind!r}")
    table = discover()[model].table(settings)
    variables = [(v.name, v.causality, v.variability, v.initial, v.start) for v in table.VARIABLES]
    return {"value_access": kind, "variables": variables}


def build_floor_fmu(
    dest, kind: str, loader: bool = True, model: str = JOINT, settings: Mapping | None = None
) -> Path:
    """Build the `kind` floor ("plain" or "bare") of `model` built with `settings`
    (default: its default build) into `dest`; return its path. Without `loader`,
    the FMU is pythonfmu's alone (its C++ binary, no project code).

    Each floor gets its own folder (every floor FMU is named Floor.fmu) and its
    own module name, derived from the script and its configuration.
    """
    config = json.dumps(floor_config(kind, model, settings), indent=1)
    digest = hashlib.sha256(SLAVE.read_bytes() + config.encode()).hexdigest()[:12]
    folder = Path(dest).resolve() / f"floor_{kind}{'' if loader else '_pythonfmu'}_{digest}"
    staging = folder / "staging"
    staging.mkdir(parents=True, exist_ok=True)
    script = staging / f"benchmark_floor_{kind}_{digest}.py"
    shutil.copyfile(SLAVE, script)
    (staging / "floor.json").write_text(config)
    # Its own process: pythonfmu imports the script to build it.
    run_checked(
        ["-m", "pythonfmu", "build", "-f", str(script), "-d", str(folder),
         str(staging / "floor.json")],
        cwd=staging,
    )  # fmt: skip
    # The models' builds replace pythonfmu's binary by the project's runtime:
    # with `loader`, the floor gets the same, so that a ratio measures the model alone.
    fmu = folder / "Floor.fmu"
    if loader:
        install_loader(fmu, "Floor")
    return fmu


def build_model_fmu(dest, model: str = JOINT, settings: Mapping | None = None) -> Path:
    """A fresh build of the working tree (`model` with its default settings, or
    `settings`), so that the numbers are those of this code; its path."""
    spec = discover()[model]
    chosen = {**spec.default_settings, **(settings or {})}
    options = []
    for name, value in chosen.items():
        if isinstance(value, bool):
            options.append(f"--{name}" if value else f"--no-{name}")
        else:
            options += [f"--{name}", str(value)]
    folder = Path(dest) / f"{model}_{'_'.join(map(str, chosen.values())) or 'default'}"
    run_checked([str(ROOT / "build_fmu.py"), "--model", model, "--dest", str(folder), *options],
                cwd=ROOT)  # fmt: skip
    return folder / f"{spec.default_name(chosen)}.fmu"


def unzip(fmu: Path, workdir: Path) -> str:
    """Extracted once here, so that no timing run pays for the extraction."""
    from fmpy import extract

    return str(extract(str(fmu), unzipdir=str(workdir / f"{fmu.parent.name}_{fmu.stem}")))
