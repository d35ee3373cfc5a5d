"""Regenerate every image in docs/img from the example that draws it.

    .venv/bin/python tools/gallery.py              # build the FMUs, run every example, copy
    .venv/bin/python tools/gallery.py --only seed  # the examples whose name contains "seed"

Builds the FMUs the examples need into a scratch folder, runs each example
there (its --out a scratch folder too, so results/ is left alone), copies the
images it writes into docs/img and records them in docs/img/gallery.json: for
each image, the example that drew it, a digest of the sources that decide what
it draws and a digest of the image. tests/unit/test_gallery.py recomputes both, so
an example changed without rerunning this script, or an image replaced by hand,
fails the suite. About 70 s on a 2-core machine (the seeds run their full
horizons, the design sweep its 336 cases serially, the SSP example both hosts).
"""

import argparse
import hashlib
import json
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
IMAGES = ROOT / "docs" / "img"
MANIFEST = IMAGES / "gallery.json"
PACKAGE = "fmu_src/cardan_joint"
# What every example draws with: its command line and the plot style.
COMMON = ("examples/_support.py", f"{PACKAGE}/host/plotting.py")
SEEDS = ("examples/_seed_support.py",)


@dataclass(frozen=True)
class Example:
    script: str  # examples/<script>.py
    images: tuple[str, ...]  # the PNGs it writes into its --out folder
    model: str | None = "UniversalJoint"  # the FMU it takes as --fmu (None: builds its own)
    options: tuple[str, ...] = ()
    sources: tuple[str, ...] = ()  # besides the script and COMMON

    def source_files(self) -> list[str]:
        return [f"examples/{self.script}.py", *COMMON, *self.sources]


EXAMPLES = (
    Example("demo", ("demo.png",)),
    Example("motor_load", ("motor_load.png",)),
    Example(
        "duty_cycle",
        ("duty_cycle.png",),
        sources=("examples/duty_cycle_blocks.csv", f"{PACKAGE}/host/life_files.py"),
    ),
    Example("driveshaft", ("driveshaft.png",), sources=("examples/_driveshaft_support.py",)),
    Example("propshaft_layout", ("propshaft_layout.png",), model="Propshaft"),
    Example(
        "design_sweep",
        ("design_sweep.png",),
        options=("--serial",),
        sources=tuple(f"{PACKAGE}/sweep/{m}.py" for m in ("heatmap", "spec")),
    ),
    Example(
        "driveline_ssp",
        ("driveline_ssp.png",),
        model=None,
        sources=(f"{PACKAGE}/host/driveline_system.py",),
    ),
    Example(
        "driveline_resonance",
        ("driveline_resonance.png", "driveline_resonance_orders.png"),
        model=None,
    ),
    Example(
        "seed_wikipedia",
        tuple(
            f"seed_wikipedia_{n}.png"
            for n in ("output_speed", "output_angle", "output_acceleration")
        ),
        sources=SEEDS,
    ),
    Example(
        "seed_maker",
        tuple(
            f"seed_maker_{n}.png" for n in ("output_angle", "cardan_error", "amplitude_unevenness")
        ),
        sources=SEEDS,
    ),
    Example(
        "seed_tataru", ("seed_tataru_alpha_2pi_7.png", "seed_tataru_alpha_2pi_5.png"), sources=SEEDS
    ),
    Example(
        "seed_mityushov_misyura",
        tuple(
            f"seed_mityushov_misyura_{n}.png"
            for n in ("kinematics", "quaternion", "torques", "energy")
        ),
        sources=(*SEEDS, "examples/_mityushov_support.py"),
    ),
)


def digest(paths) -> str:
    """sha256 over the files' names and bytes, in the order given."""
    hash_ = hashlib.sha256()
    for path in paths:
        hash_.update(str(path).encode() + b"\0" + (ROOT / path).read_bytes() + b"\0")
    return hash_.hexdigest()


def image_digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def entry(example: Example, image: str) -> dict:
    return {
        "example": f"examples/{example.script}.py",
        "command": " ".join(
            ["python", f"examples/{example.script}.py", *example.options, "--out", "docs/img"]
        ),
        "sources": example.source_files(),
        "sources_sha256": digest(example.source_files()),
        "image_sha256": image_digest(IMAGES / image),
    }


def _build(model: str, dest: Path) -> Path:
    command = [sys.executable, str(ROOT / "build_fmu.py"), "--dest", str(dest)]
    if model != "UniversalJoint":
        command += ["--model", model]
    subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return dest / f"{model}.fmu"


def regenerate(examples, work: Path) -> dict:
    manifest = json.loads(MANIFEST.read_text()) if MANIFEST.is_file() else {}
    fmus: dict[str, Path] = {}
    for example in examples:
        command = [sys.executable, str(ROOT / "examples" / f"{example.script}.py")]
        if example.model:
            if example.model not in fmus:
                fmus[example.model] = _build(example.model, work / "dist")
            command += ["--fmu", str(fmus[example.model])]
        out = work / example.script
        command += [*example.options, "--out", str(out)]
        print(f"gallery: {example.script} ...", flush=True)
        subprocess.run(command, cwd=work, check=True, stdout=subprocess.DEVNULL)
        for image in example.images:
            shutil.copyfile(out / image, IMAGES / image)
            manifest[image] = entry(example, image)
    return dict(sorted(manifest.items()))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="", help="the examples whose name contains this")
    args = parser.parse_args(argv)
    chosen = [e for e in EXAMPLES if args.only in e.script]
    if not chosen:
        parser.error(f"no example matches {args.only!r}: {', '.join(e.script for e in EXAMPLES)}")
    with tempfile.TemporaryDirectory(prefix="cardan_gallery_") as work:
        manifest = regenerate(chosen, Path(work))
    MANIFEST.write_text(json.dumps(manifest, indent=1) + "\n")
    print(f"gallery: {sum(len(e.images) for e in chosen)} images in {IMAGES}, {MANIFEST.name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
