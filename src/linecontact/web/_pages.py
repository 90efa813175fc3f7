"""The pages of the calculator: one form per task, built from a short specification.

Every page is one HTML document with a form (inputs in units the user chooses, the material
presets), the results (each value in ``data-key``/``data-value`` at full precision), a plot,
downloads, and the equivalent ``linecontact`` command and Python lines. The page's state is
its query string, named as the CLI flags without dashes: a result is shared by its link.
``static/app.js`` does the rest (no script from elsewhere: the content security policy
allows only this server's).
"""

from __future__ import annotations

import html
import json
from typing import Any

from .._version import __version__
from ..presets import material_names

__all__ = ["PAGES", "UNITS", "index_html", "page_html"]

#: Units a field may be given in: kind -> (unit, factor to SI), the first the default.
UNITS: dict[str, list[tuple[str, float]]] = {
    "length": [("nm", 1e-9), ("um", 1e-6), ("m", 1.0)],
    "modulus": [("GPa", 1e9), ("MPa", 1e6), ("Pa", 1.0)],
    "stress": [("MPa", 1e6), ("GPa", 1e9), ("Pa", 1.0)],
    "work": [("J/m^2", 1.0), ("mJ/m^2", 1e-3)],
    "force": [("N/m", 1.0), ("nN/um", 1e-3)],
    "none": [("", 1.0)],
}

#: The Python line that builds the wire of a page (its fields by name).
_CYL = (
    "cyl = lc.Cylinder.from_presets({radius}, {cylinder_material!r}, {substrate_material!r}, "
    "work_of_adhesion={work_of_adhesion}, equilibrium_spacing={z0})\n"
)


def _f(name: str, label: str, kind: str = "none", default: str = "", **kw: Any) -> dict[str, Any]:
    return {"name": name, "label": label, "kind": kind, "default": default, **kw}


_WIRE = [
    _f("cylinder_material", "cylinder (wire) material", "material", "ZnO"),
    _f("substrate_material", "substrate material", "material", "SiO2"),
    _f("radius", "radius R", "length", "5e-08"),
    _f("work_of_adhesion", "work of adhesion w", "work", "0.3"),
    _f("z0", "equilibrium spacing z0", "length", "3e-10"),
]

#: The pages: path -> title, command, fields, fixed parameters, plot, Python lines.
PAGES: dict[str, dict[str, Any]] = {
    "pulloff": {
        "title": "Contact and pull-off of a wire",
        "command": "pulloff",
        "fields": [*_WIRE, _f("length", "wire length (optional)", "length", "")],
        "headline": {
            "F_pulloff_N_per_m": "pull-off force per length",
            "F_pulloff_total_N": "pull-off force on the wire",
            "a_at_pulloff_m": "contact half-width at pull-off",
            "mechanism": "mechanism",
        },
        "python": (_CYL + "print(cyl.pull_off())"),
        "plot": None,
    },
    "contact": {
        "title": "Contact width under a load",
        "command": "normal",
        "fields": [*_WIRE, _f("load", "normal loads F (comma-separated)", "force", "0,1,5,10")],
        "python": (_CYL + "print(cyl.contact(load=[{load}]))"),
        "plot": {"x": "F_N_per_m", "y": "a_m", "xlabel": "load F [N/m]", "ylabel": "a [m]"},
    },
    "curve": {
        "title": "The load curve",
        "command": "curve",
        "fields": list(_WIRE),
        "python": (_CYL + "print(cyl.load_curve())"),
        "plot": {"x": "a_m", "y": "F_N_per_m", "xlabel": "a [m]", "ylabel": "load F [N/m]"},
    },
    "push": {
        "title": "A wire pushed sideways: stay, roll or slide",
        "command": "push",
        "fields": [
            _f("cylinder_material", "cylinder (wire) material", "material", "ZnO"),
            _f("substrate_material", "substrate material", "material", "SiO2"),
            _f("radius", "radius R", "length", "5e-08"),
            _f("work_of_adhesion_advancing", "work of adhesion w", "work", "0.3"),
            _f("z0", "equilibrium spacing z0", "length", "3e-10"),
            _f("h1_over_h2", "receding over advancing range h1/h2", "none", "1"),
            _f("tau0", "interfacial shear strength tau0", "stress", "1e7"),
            _f("height", "push heights H (comma-separated)", "length", "5e-09,2.5e-08,5e-08,1e-07"),
            _f("push", "a push Q (optional): stay, roll or slide?", "force", ""),
        ],
        "motion": True,
        "python": (
            "cyl = lc.Cylinder.from_presets({radius}, {cylinder_material!r}, "
            "{substrate_material!r}, work_of_adhesion={work_of_adhesion_advancing}, "
            "equilibrium_spacing={z0})\nprint(cyl.push(friction_stress={tau0}, "
            "height=[{height}]))"
        ),
        "plot": {
            "x": "H_m",
            "y": "Q_onset_N_per_m",
            "xlabel": "push height H [m]",
            "ylabel": "push to start moving Q [N/m]",
        },
    },
    "cycle": {
        "title": "Energy lost per cycle",
        "command": "cycle",
        "fields": [
            *_WIRE,
            _f("load", "normal load F", "force", "1"),
            _f("tau0", "interfacial shear strength tau0", "stress", "1e7"),
            _f("tangential_amplitude", "amplitudes T*", "force", "0.01,0.02,0.04,0.06"),
        ],
        "python": (
            _CYL + "print(cyl.cyclic_loss(normal_load={load}, "
            "friction_stress={tau0}, amplitude=[{tangential_amplitude}]))"
        ),
        "plot": {
            "x": "T_amplitude_N_per_m",
            "y": "W_J_per_m",
            "xlabel": "amplitude T* [N/m]",
            "ylabel": "energy lost per cycle W [J/m]",
        },
    },
    "lennard-jones": {
        "title": "The Lennard-Jones law: pull-off",
        "command": "pulloff",
        "fixed": {"law": "lennard-jones"},
        "fields": list(_WIRE),
        "headline": {
            "F_pulloff_N_per_m": "pull-off force per length",
            "mu": "Tabor-like parameter mu of the law",
            "method": "method",
        },
        "python": (_CYL + "print(cyl.lennard_jones_pull_off())"),
        "plot": None,
    },
    "fit": {
        "title": "Work of adhesion from pull-off forces (CSV upload)",
        "command": "fit-adhesion",
        "upload": True,
        "fields": [
            _f("cylinder_material", "cylinder (wire) material", "material", "SiO2"),
            _f("substrate_material", "substrate material", "material", "Si"),
        ],
        "python": "fit = lc.fit_pull_off(...)  # see examples/fit_pull_off.py",
        "plot": None,
    },
    "map": {
        "title": "The adhesion map (quick grid), your wire marked",
        "command": "map",
        "fixed": {"quick": "true"},
        "job": True,
        "fields": [{**f, "aux": True} for f in _WIRE],
        "python": "from linecontact.adhesion_map import adhesion_map",
        "plot": {
            "x": "maugis_parameter",
            "y": "load_above_pulloff_over_abs_pulloff",
            "xlabel": "Maugis parameter",
            "ylabel": "load above pull-off / |pull-off|",
            "points": True,
            "color": "agrees_md",
        },
        "mark": {"command": "pulloff", "key": "maugis_parameter", "label": "your wire"},
    },
}


def _head(title: str) -> str:
    return (
        "<!doctype html><html lang='en'><head><meta charset='utf-8'>"
        "<meta name='viewport' content='width=device-width, initial-scale=1'>"
        f"<title>{html.escape(title)} - linecontact</title>"
        "<link rel='stylesheet' href='/static/app.css'></head><body>"
        "<header><a href='/'>linecontact</a> "
        f"<span class='version'>{__version__}</span></header><main>"
    )


def index_html(note: str = "") -> str:
    """The index: one link per page."""
    items = "".join(
        f"<li><a href='/{name}'>{html.escape(p['title'])}</a></li>" for name, p in PAGES.items()
    )
    msg = f"<p class='error'>{html.escape(note)}</p>" if note else ""
    return (
        _head("calculator") + f"<h1>linecontact calculator</h1>{msg}<ul class='pages'>{items}</ul>"
        "<p>HTTP API: <code>/api/v1/&lt;command&gt;</code> (the JSON of "
        "<code>linecontact &lt;command&gt; --json</code>); <a href='/api/v1/openapi.json'>"
        "OpenAPI</a>.</p></main></body></html>"
    )


def _field(f: dict[str, Any]) -> str:
    name, kind = f["name"], f["kind"]
    label = f"<label for='f-{name}'>{html.escape(f['label'])}</label>"
    if kind == "material":
        opts = "".join(
            f"<option{' selected' if m == f['default'] else ''}>{html.escape(m)}</option>"
            for m in material_names()
        )
        control = f"<select id='f-{name}' name='{name}'>{opts}</select>"
    else:
        control = (
            f"<input id='f-{name}' name='{name}' data-kind='{kind}' data-default="
            f"'{html.escape(f['default'])}' autocomplete='off'>"
        )
        if len(UNITS[kind]) > 1:
            opts = "".join(
                f"<option value='{factor!r}'>{html.escape(u)}</option>" for u, factor in UNITS[kind]
            )
            control += (
                f"<select class='unit' id='u-{name}' aria-label='unit of {name}'>{opts}</select>"
            )
    return (
        f"<div class='field'>{label}<div class='control'>{control}</div>"
        f"<div class='message' id='m-{name}' role='alert'></div></div>"
    )


def _json_in_html(obj: Any) -> str:
    """JSON inside a ``<script>`` element: no ``<``, ``>`` or ``&`` that HTML would read."""
    text = json.dumps(obj)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def page_html(name: str) -> str:
    """The page ``name``: its form, and empty places for the results."""
    p = PAGES[name]
    keys = ("command", "fixed", "plot", "python", "job", "upload", "mark", "motion", "headline")
    spec = {k: p.get(k) for k in keys}
    spec["fields"] = [
        {k: f.get(k) for k in ("name", "kind", "default", "aux")} for f in p["fields"]
    ]
    fields = "".join(_field(f) for f in p["fields"])
    upload = (
        "<div class='field'><label for='f-data'>measurements (CSV, units in the header)</label>"
        "<div class='control'><input type='file' id='f-data' name='data' accept='.csv'></div>"
        "<div class='message' id='m-data' role='alert'></div></div>"
        if p.get("upload")
        else ""
    )
    return (
        _head(p["title"]) + f"<h1>{html.escape(p['title'])}</h1>"
        f"<script type='application/json' id='spec'>{_json_in_html(spec)}</script>"
        f"<form id='form' novalidate>{fields}{upload}"
        "<div class='buttons'><button type='submit' id='go'>Compute</button>"
        "<button type='button' id='cancel' hidden>Cancel</button></div></form>"
        "<div id='status' role='status'></div><div id='form-error' class='error'></div>"
        "<section id='results'></section><figure id='plot'></figure><figure id='motion'></figure>"
        "<div id='downloads'></div>"
        "<section id='equivalent'><h2>The same elsewhere</h2><pre id='cli'></pre>"
        "<pre id='py'></pre></section>"
        "</main><script src='/static/app.js'></script></body></html>"
    )
