"""Sphinx configuration of the linecontact documentation site.

Build (the README's line): ``python -m pip install '.[docs]' && python -m sphinx -W -b html
docs docs/_build/html``. The API reference is every name of ``linecontact.__all__``
(``api.rst``, written here), the command-line reference every subcommand's ``--help``
(``cli-reference.md``, written here from the parsers), the gallery ``examples/`` run at build
time (sphinx-gallery); the theory pages are the Markdown files beside this one.
"""

from __future__ import annotations

import contextlib
import io
import os
import sys

import linecontact

sys.path.insert(0, os.path.dirname(__file__))  # _gallery (the examples' command lines)

project = "linecontact"
author = "linecontact developers"
copyright = "2026, linecontact developers"
release = version = linecontact.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
]
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build", "images", "auto_examples/*.ipynb", "auto_examples/*.py"]
html_theme = "pydata_sphinx_theme"
html_title = f"linecontact {release}"
numpydoc_show_class_members = False
autosummary_generate = True
suppress_warnings = ["myst.header"]
sphinx_gallery_conf = {
    "examples_dirs": "../examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r".*\.py$",  # every example runs at build time
    "reset_argv": "_gallery.argv",  # a figure path of their own, in a temporary folder
    "abort_on_example_error": True,
    "download_all_examples": False,
    "plot_gallery": "True",
}

HERE = os.path.dirname(__file__)


def _api_page() -> None:
    """``api.rst``: every name of ``linecontact.__all__``, one generated page each."""
    names = sorted(n for n in linecontact.__all__ if not n.startswith("_"))
    lines = [
        "API reference",
        "=============",
        "",
        ".. currentmodule:: linecontact",
        "",
        "Every name in ``linecontact.__all__`` (``import linecontact as lc``).",
        "",
        ".. autosummary::",
        "   :toctree: generated",
        "",
        *(f"   {n}" for n in names),
    ]
    with open(os.path.join(HERE, "api.rst"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def _cli_page() -> None:
    """``cli-reference.md``: every subcommand's ``--help``, from the parsers."""
    from linecontact.cli import COMMANDS, main

    out = [
        "# Command-line reference",
        "",
        "Every subcommand's `--help`, as `linecontact COMMAND --help` prints it (generated from "
        "the parsers when the site is built). The conventions, outputs and the table of flags: "
        "[The command line](cli.md).",
        "",
    ]
    for name, (_, summary) in COMMANDS.items():
        text = io.StringIO()
        with contextlib.redirect_stdout(text), contextlib.suppress(SystemExit):
            main([name, "--help"])
        out += [f"## {name}", "", summary, "", "```text", text.getvalue().rstrip(), "```", ""]
    with open(os.path.join(HERE, "cli-reference.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(out))


_api_page()
_cli_page()
