"""The gallery's side of the examples: the figure path each one gets, and the figure it saved.

Each example takes a figure path as its argument (``python examples/NAME.py fig.png``) and
saves its figure there, drawn by pyplot or by :mod:`linecontact.figures` alike. In the
gallery that path is in a temporary folder (:func:`argv`), and :func:`saved_figures` (an
image scraper) moves the file, once written, into the gallery's images: the page shows it
after the code block that saved it, and the first one is the card's thumbnail. The examples
print no path of the machine that built the site.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

from sphinx_gallery.scrapers import figure_rst

_DIR = Path(tempfile.mkdtemp(prefix="linecontact-gallery-"))


def _figure_path(src_file: str) -> Path:
    return _DIR / f"{Path(src_file).stem}.png"


def argv(sphinx_gallery_conf: object, script_vars: dict) -> list[str]:
    """``[path]``: where the example saves its figure (a temporary folder)."""
    _DIR.mkdir(exist_ok=True)  # again after a build's cleanup (a second build, in tests)
    path = _figure_path(script_vars["src_file"])
    path.unlink(missing_ok=True)
    return [str(path)]


def saved_figures(block: object, block_vars: dict, gallery_conf: dict) -> str:
    """The figure the example saved during this code block, as the gallery's image."""
    saved = _figure_path(block_vars["src_file"])
    if not saved.is_file():
        return ""
    image = Path(next(block_vars["image_path_iterator"]))
    shutil.move(saved, image)  # gone from the folder: a later block does not show it again
    return figure_rst([image], gallery_conf["src_dir"])


def cleanup(app: object, exc: object) -> None:
    """Remove the temporary folder (build-finished)."""
    shutil.rmtree(_DIR, ignore_errors=True)
