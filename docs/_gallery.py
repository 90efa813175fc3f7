"""The command line each example gets in the gallery: one figure path, in a temporary folder."""

from __future__ import annotations

import os
import tempfile

_DIR = tempfile.mkdtemp(prefix="linecontact-gallery-")


def argv(sphinx_gallery_conf: object, script_vars: dict) -> list[str]:
    """``[path]``: where the example saves its figure (the gallery shows the open figure)."""
    name = os.path.splitext(os.path.basename(script_vars["src_file"]))[0]
    return [os.path.join(_DIR, f"{name}.png")]
