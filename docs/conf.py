"""Sphinx configuration of the linecontact documentation site.

Build (the README's line): ``python -m pip install '.[docs]' && python -m sphinx -W -b html
docs docs/_build/html``; then ``.ci/check-site docs/_build/html`` checks its links and that
nothing is loaded from another host. Written here when the site is built: the API reference
grouped by task (``api.rst``), the command-line reference from the parsers
(``cli-reference.md``) and what ``linecontact cite`` prints (``generated/cite*.txt``). The
gallery is ``examples/`` run at build time (sphinx-gallery; ``_gallery.py`` gives each
example a figure path and shows the figure it saved). The maths is typeset by a copy of
MathJax served with the site (``_static/mathjax``, from the PyPI package
``sphinx-mathjax-offline``): no page needs the internet.
"""

from __future__ import annotations

import contextlib
import importlib.util
import io
import os
import shutil
import sys

import sphinx.ext.autosummary

import linecontact

# a summary line's "Eq. (7)" or "Fig. 6" is no sentence's end: the API tables showed "... Eq."
sphinx.ext.autosummary.WELL_KNOWN_ABBREVIATIONS += tuple(
    f"{before}{word}." for before in " (" for word in ("Eq", "Eqs", "Fig", "Figs")
)

sys.path.insert(0, os.path.dirname(__file__))  # _gallery (the examples' command lines)

import _gallery  # noqa: E402

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
html_theme_options = {
    # one row of short links at 1280 px; the rest under "More"
    "header_links_before_dropdown": 7,
    "navbar_persistent": ["search-button"],  # the search as an icon: the header stays one row
    "navigation_with_keys": False,
    "show_toc_level": 2,
}
html_static_path = ["_static"]
html_css_files = ["linecontact.css"]  # wide display equations scroll, never cut off
numpydoc_show_class_members = False
autosummary_generate = True
# a class's page: its methods in a table without signatures, then each documented in full
templates_path = ["_templates"]
# signatures of names only: the types are in each docstring's Parameters (numpydoc), not
# expanded from NumPy's typing internals into the signature
autodoc_typehints = "none"
suppress_warnings = ["myst.header"]
sphinx_gallery_conf = {
    "examples_dirs": "../examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r".*\.py$",  # every example runs at build time
    "reset_argv": "_gallery.argv",  # a figure path of their own, in a temporary folder
    "image_scrapers": ("_gallery.saved_figures",),  # the figure each example saved there
    "abort_on_example_error": True,
    "download_all_examples": False,
    "plot_gallery": "True",
    "remove_config_comments": True,
    # no page of computation times: it loads jQuery and DataTables from CDNs
    "write_computation_times": False,
}

HERE = os.path.dirname(__file__)

# MathJax 3, served with the site (never from a CDN): the component that reads TeX and writes
# HTML with its own fonts, and what it loads on demand (TeX extensions, the menu, a11y)
mathjax_path = "mathjax/tex-chtml.js"
_MATHJAX_PARTS = ("tex-chtml.js", "input", "output/chtml", "a11y", "ui", "sre", "adaptors")


def _mathjax_source() -> str:
    spec = importlib.util.find_spec("sphinx-mathjax-offline")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError(
            "the site serves its own MathJax: install the docs extra "
            "(python -m pip install '.[docs]', which brings sphinx-mathjax-offline)"
        )
    return os.path.join(list(spec.submodule_search_locations)[0], "static", "mathjax")


_MATHJAX = _mathjax_source()  # at configuration time: a missing copy stops the build at once


def _copy_mathjax(app, exc) -> None:
    if exc is not None or app.builder.format != "html":
        return
    dest = os.path.join(app.outdir, "_static", "mathjax")
    for part in _MATHJAX_PARTS:
        src, out = os.path.join(_MATHJAX, part), os.path.join(dest, part)
        if os.path.isdir(src):
            shutil.copytree(src, out, dirs_exist_ok=True)
        else:
            os.makedirs(os.path.dirname(out), exist_ok=True)
            shutil.copy2(src, out)


# The API reference by task: every public name once, in the order a user meets it
API_GROUPS: list[tuple[str, str, list[str]]] = [
    (
        "A cylinder on a substrate (SI units)",
        "The entry point: a wire, fibre or tube of radius ``R`` on a substrate, its materials "
        "and its adhesion law (a value: the Dugdale step or the Lennard-Jones law); every "
        "question below is a method of it; its cross-section a value too (round, or a "
        "polygon on its facet).",
        ["Cylinder", "Dugdale", "LennardJones", "Round", "Polygon", "Material"],
    ),
    (
        "Materials and the groups of the problem",
        "The composite modulus, the compliance constants, the adhesion's Dugdale stress and "
        "range, and the dimensionless groups that name the regime.",
        [
            "composite_modulus",
            "compliance_constants",
            "dundurs_beta",
            "adhesion_from_work",
            "kappa",
            "maugis_parameter",
        ],
    ),
    (
        "Normal contact and pull-off (nondimensional)",
        "The contact width under a load, the whole load curve and the force that pulls it off, "
        "in the paper's groups; Hertz and JKR for reference.",
        [
            "normal_contact",
            "contact_for_load",
            "equilibria",
            "load_curve",
            "non_contact",
            "pull_off",
            "zero_width_load",
            "hertz_load",
            "jkr_load",
            "NormalContact",
            "PullOff",
        ],
    ),
    (
        "A faceted wire on its facet (nondimensional)",
        "A regular polygon (a hexagonal or pentagonal wire) with rounded corners lying on a "
        "facet: its contact, its contact under a load and its pull-off, lengths over the "
        "circumradius (:doc:`faceted`); in SI units ``Cylinder(...).shaped(Polygon(...))``.",
        [
            "facet_contact",
            "facet_contact_for_load",
            "facet_pull_off",
            "facet_load_curve",
            "facet_tipping",
            "FacetContact",
            "FacetPullOff",
            "FacetLoadCurve",
            "FacetTipping",
        ],
    ),
    (
        "The sphere: an AFM tip or a colloidal probe",
        "The Maugis-Dugdale sphere in the wire's input groups, force over ``E h R``: its "
        "contact, its contact under a load, its pull-offs and load curve; which model holds, "
        "and the COS alpha fitted to its curves; the self-consistent Lennard-Jones sphere "
        "(:doc:`sphere`); the fits with intervals ((w, z0) from pull-offs, tau0 from "
        "friction, which model from a pull-off). In SI units the body "
        "``Sphere`` (forces in N), a ``Body`` as the ``Cylinder`` is.",
        [
            "Sphere",
            "Body",
            "sphere_contact",
            "sphere_contact_for_load",
            "sphere_pull_off",
            "sphere_load_curve",
            "sphere_models",
            "cos_alpha",
            "maugis_parameter_of_cos_alpha",
            "sphere_lj_pull_off",
            "sphere_lj_curve",
            "sphere_work_of_adhesion_from_pull_off",
            "sphere_shear_strength_from_friction",
            "sphere_fit_pull_off",
            "sphere_fit_shear_strength",
            "sphere_which_model",
            "SphereContact",
            "SpherePullOff",
            "SphereLoadCurve",
            "SphereModels",
            "SphereLJPullOff",
            "SphereLJCurve",
            "SphereAdhesionFit",
            "SphereShearStrengthFit",
            "SphereModelChoice",
        ],
    ),
    (
        "A wire bent by friction: the friction from its shape",
        "The wire dragged at its midpoint (the kinetic case, the elastica) and the wire held by "
        "friction normal to it (the static case); the bending stiffness of its cross-section; "
        "the friction per unit length fitted to a measured profile with its intervals, and the "
        "shear strength from it (:doc:`bent-wire`).",
        [
            "fit_bent_wire",
            "BentWireFit",
            "shear_strength_from_bent_wire",
            "bending_stiffness",
            "second_moment_of_area",
            "dragged_wire",
            "DraggedWire",
            "static_wire",
            "StaticWire",
            "normal_friction_from_curvature",
            "NormalFriction",
        ],
    ),
    (
        "Sliding and rolling",
        "Steady sliding, the initiation of sliding and steady rolling, with the nano-scale "
        "friction law (constant shear stress) or Coulomb friction.",
        [
            "sliding_contact",
            "sliding_contact_for_load",
            "sliding_pull_off",
            "sliding_initiation",
            "sliding_initiation_coulomb",
            "steady_rolling",
            "steady_rolling_coulomb",
            "SlidingContact",
            "SlidingPullOff",
        ],
    ),
    (
        "Load histories and the energy lost per cycle",
        "States along a tangential load history and the energy dissipated per cycle.",
        [
            "tangential_history",
            "tangential_history_coulomb",
            "cyclic_loss",
            "cyclic_loss_coulomb",
        ],
    ),
    (
        "A fibre pushed sideways",
        "Whether a pushed fibre stays, rolls or slides, and a tip's push.",
        ["push", "tip_push", "Push", "TipPush"],
    ),
    (
        "From measurements to properties",
        "The work of adhesion and the range from pull-off forces or contact widths, the shear "
        "strength from friction, measured data with units, and uncertainties.",
        [
            "fit_pull_off",
            "work_of_adhesion_from_pull_off",
            "work_of_adhesion_from_width",
            "shear_strength_from_friction",
            "read_measurements",
            "propagate",
        ],
    ),
    (
        "Parameter studies and files",
        "A sweep over every combination of values (Dask, xarray), its store, and any file "
        "that a subcommand writes.",
        ["sweep", "open_sweep", "read"],
    ),
    (
        "Adhesion laws",
        "The Maugis–Dugdale step and the Lennard-Jones law, one module each, with the same "
        "functions in the paper's groups.",
        ["laws"],
    ),
    (
        "Errors and warnings",
        "What the library raises and warns.",
        ["ConvergenceError", "NoEquilibriumError", "CouplingWarning", "ModelValidityWarning"],
    ),
]


def _api_page() -> None:
    """``api.rst``: every public name of ``linecontact.__all__``, by task, one page each."""
    public = {n for n in linecontact.__all__ if not n.startswith("_")}
    grouped = [n for _, _, names in API_GROUPS for n in names]
    missing, unknown = public - set(grouped), set(grouped) - public
    dupes = {n for n in grouped if grouped.count(n) > 1}
    if missing or unknown or dupes:
        raise RuntimeError(
            "docs/conf.py API_GROUPS must list every public name once: "
            f"missing {sorted(missing)}, not public {sorted(unknown)}, twice {sorted(dupes)}"
        )
    lines = [
        "API reference",
        "=============",
        "",
        ".. currentmodule:: linecontact",
        "",
        "Every public name of ``linecontact`` (``import linecontact as lc``), grouped by task. "
        "The physical quantities are in SI units on :class:`Cylinder` and in the paper's "
        "nondimensional groups in the functions (:doc:`nomenclature`).",
        "",
    ]
    for title, text, names in API_GROUPS:
        lines += [title, "-" * len(title), "", text, "", ".. autosummary::"]
        lines += ["   :toctree: generated", "   :nosignatures:", ""]
        lines += [f"   {n}" for n in names] + [""]
    with open(os.path.join(HERE, "api.rst"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


def _run_cli(*args: str) -> str:
    from linecontact.cli import main

    text = io.StringIO()
    with contextlib.redirect_stdout(text), contextlib.suppress(SystemExit):
        main(list(args))
    return text.getvalue().rstrip() + "\n"


def _cli_page() -> None:
    """``cli-reference.md``: every subcommand's ``--help``, from the parsers."""
    from linecontact.cli import COMMANDS

    out = [
        "# Command-line reference",
        "",
        "Every subcommand's `--help`, as `linecontact COMMAND --help` prints it (generated from "
        "the parsers when the site is built). The conventions, outputs and the table of flags: "
        "[The command line](cli.md).",
        "",
    ]
    for name, (_, summary) in COMMANDS.items():
        help_text = _run_cli(name, "--help").rstrip()
        out += [f"## {name}", "", summary, "", "```text", help_text, "```", ""]
    with open(os.path.join(HERE, "cli-reference.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(out))


def _cite_files() -> None:
    """``generated/cite.txt`` and ``cite.bib``: what ``linecontact cite`` prints."""
    os.makedirs(os.path.join(HERE, "generated"), exist_ok=True)
    for name, args in (("cite.txt", ("cite",)), ("cite.bib", ("cite", "--bibtex"))):
        with open(os.path.join(HERE, "generated", name), "w", encoding="utf-8") as f:
            f.write(_run_cli(*args))


_api_page()
_cli_page()
_cite_files()


def setup(app) -> None:
    """Serve MathJax with the site; the gallery's temporary folder goes when the build ends."""
    app.connect("build-finished", _copy_mathjax)
    app.connect("build-finished", _gallery.cleanup)
