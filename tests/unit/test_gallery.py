"""Every figure in docs/img is current: drawn by tools/gallery.py from the example
as it is now (the digest of the sources that decide what it draws), and not
changed since (the digest of the image). Rerun `python tools/gallery.py` after
changing an example or the plot style."""

import importlib.util
import json

from conftest import ROOT

spec = importlib.util.spec_from_file_location("gallery", ROOT / "tools" / "gallery.py")
gallery = importlib.util.module_from_spec(spec)
spec.loader.exec_module(gallery)

MANIFEST = json.loads(gallery.MANIFEST.read_text())


def test_every_image_in_docs_is_in_the_gallery():
    drawn = {image for example in gallery.EXAMPLES for image in example.images}
    on_disk = {path.name for path in gallery.IMAGES.glob("*.png")}
    assert on_disk == drawn, "an image no example draws, or one not drawn yet"
    assert set(MANIFEST) == drawn, "run python tools/gallery.py"


def test_each_image_was_drawn_by_its_example_as_it_is_now():
    stale = []
    for example in gallery.EXAMPLES:
        for image in example.images:
            recorded = MANIFEST[image]
            if (
                recorded["sources"] != example.source_files()
                or recorded["sources_sha256"] != gallery.digest(example.source_files())
                or recorded["image_sha256"] != gallery.image_digest(gallery.IMAGES / image)
            ):
                stale.append(image)
    assert not stale, f"redraw with python tools/gallery.py --only <example>: {stale}"


def test_the_digest_notices_a_changed_source(tmp_path, monkeypatch):
    source = tmp_path / "example.py"
    source.write_text("print(1)\n")
    monkeypatch.setattr(gallery, "ROOT", tmp_path)
    before = gallery.digest(["example.py"])
    source.write_text("print(2)\n")
    assert gallery.digest(["example.py"]) != before
