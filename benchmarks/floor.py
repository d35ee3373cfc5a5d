"""The FMUs the benchmarks time: floor FMUs (benchmarks/floor_slave.py) and the joint.

from benchmarks.floor import build_floor_fmu
fmu = build_floor_fmu(dest, "plain")       # or "bare"
"""

import hashlib
import json
import shutil
from pathlib import Path

from cardan_joint.fmi.native import install_loader

# The runtime's joint and its floors: the joint built without life (docs/life.md).
from cardan_joint.models.universal_joint.variables import WITHOUT_LIFE as table

from .timing import ROOT, run_checked

SLAVE = Path(__file__).with_name("floor_slave.py")
# kind -> what its value access is (written into the report's footnote)
FLOORS = {
    "plain": "values through pythonfmu's own get_real/set_real",
    "bare": "values by list indexing in overridden get_real/set_real",
}


def floor_config(kind: str, table=table) -> dict:
    """The floor's configuration: `table`'s Real variables (default: the joint's)."""
    if kind not in FLOORS:
        raise ValueError(f"floor kind must be one of {sorted(FLOORS)}, got {kind!r}")
    variables = [(v.name, v.causality, v.variability, v.initial, v.start) for v in table.VARIABLES]
    return {"value_access": kind, "variables": variables}


def build_floor_fmu(dest, kind: str, loader: bool = True, table=table) -> Path:
    """Build the `kind` floor FMU into `dest` ("plain" or "bare"); return its path.
    Without `loader`, the FMU is pythonfmu's alone (its C++ binary, no project code).
    `table`: the model whose Real variables it has (default: the joint's).

    Each kind gets its own folder (both FMUs are named Floor.fmu) and its own
    module name, derived from the script and its configuration.
    """
    config = json.dumps(floor_config(kind, table), indent=1)
    digest = hashlib.sha256(SLAVE.read_bytes() + config.encode()).hexdigest()[:12]
    folder = Path(dest).resolve() / f"floor_{kind}{'' if loader else '_pythonfmu'}"
    staging = folder / "staging"
    staging.mkdir(parents=True, exist_ok=True)
    script = staging / f"benchmark_floor_{kind}_{digest}.py"
    shutil.copyfile(SLAVE, script)
    (staging / "floor.json").write_text(config)
    # Its own process: pythonfmu imports the script to build it.
    run_checked(
        [
            "-m",
            "pythonfmu",
            "build",
            "-f",
            str(script),
            "-d",
            str(folder),
            str(staging / "floor.json"),
        ],
        cwd=staging,
    )
    # The joint's build replaces pythonfmu's binary by the project's runtime:
    # the floor gets the same, so that the ratio measures the joint alone.
    fmu = folder / "Floor.fmu"
    if loader:
        install_loader(fmu, "Floor")
    return fmu


def build_joint_fmu(dest, life: bool = True) -> Path:
    """A fresh build of the working tree, so that the numbers are those of this code
    (`life` off: the same joint without bearing loads and life, docs/life.md)."""
    extra = [] if life else ["--no-life"]
    run_checked([str(ROOT / "build_fmu.py"), "--dest", str(dest), *extra], cwd=ROOT)
    return Path(dest) / ("UniversalJoint.fmu" if life else "UniversalJointNoLife.fmu")


def unzip(fmu: Path, workdir: Path) -> str:
    """Extracted once here, so that no timing run pays for the extraction."""
    from fmpy import extract

    return str(extract(str(fmu), unzipdir=str(workdir / f"{fmu.parent.name}_{fmu.stem}")))
