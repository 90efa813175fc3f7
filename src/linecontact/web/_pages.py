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

__all__ = ["PAGES", "SI_UNIT", "UNITS", "check", "index_html", "page_html"]

#: Units a field may be given in: kind -> (unit, factor to SI), the first the default.
UNITS: dict[str, list[tuple[str, float]]] = {
    "length": [("nm", 1e-9), ("um", 1e-6), ("m", 1.0)],
    "modulus": [("GPa", 1e9), ("MPa", 1e6), ("Pa", 1.0)],
    "stress": [("MPa", 1e6), ("GPa", 1e9), ("Pa", 1.0)],
    "work": [("J/m^2", 1.0), ("mJ/m^2", 1e-3)],
    "force": [("N/m", 1.0), ("mN/m", 1e-3), ("nN/um", 1e-3)],
    "newton": [("nN", 1e-9), ("uN", 1e-6), ("N", 1.0)],
    "energy": [("J/m", 1.0), ("nJ/m", 1e-9), ("pJ/m", 1e-12)],
    "none": [("", 1.0)],
}


def _f(name: str, label: str, kind: str = "none", default: str = "", **kw: Any) -> dict[str, Any]:
    """A field of a page's form.

    Its request name, its label (the words its messages use), its kind of unit, its default
    in SI units; ``many`` (several values, comma-separated), ``unit`` (the unit first
    chosen), ``alt`` (``group:option``, or ``group:one|other``: shown when that option, or
    one of those, is chosen), ``aux`` (a field of the page's second request: the map's
    wire), ``optional``.
    """
    return {"name": name, "label": label, "kind": kind, "default": default, **kw}


#: The wire's elasticity and adhesion, each in any of its spellings (as the operations take
#: them): the presets, a composite modulus or the four E1, nu1, E2, nu2; (w, z0) or
#: (sigma0, h). A link's keys choose the alternative (``static/app.js``).
_WIRE_ALTS = {
    "elastic": {
        "label": "elasticity from",
        "options": [
            ["presets", "the materials"],
            ["modulus", "a composite modulus E"],
            ["moduli", "Young's moduli and Poisson ratios E1, nu1, E2, nu2"],
        ],
    },
    "adhesion": {
        "label": "adhesion given as",
        "options": [
            ["work", "the work of adhesion w and z0"],
            ["stress", "an adhesive stress sigma0 and its range h"],
        ],
    },
}

#: The elasticity's fields, on every page of a wire (the four moduli: ZnO's and SiO2's).
_ELASTIC = [
    _f("cylinder_material", "wire material", "material", "ZnO", alt="elastic:presets"),
    _f("substrate_material", "substrate material", "material", "SiO2", alt="elastic:presets"),
    _f("modulus", "composite modulus E", "modulus", "4.8e10", alt="elastic:modulus"),
    _f("E1", "wire's Young's modulus E1", "modulus", "1.24e11", alt="elastic:moduli"),
    _f("nu1", "wire's Poisson ratio nu1", "none", "0.36", alt="elastic:moduli"),
    _f("E2", "substrate's Young's modulus E2", "modulus", "7.2e10", alt="elastic:moduli"),
    _f("nu2", "substrate's Poisson ratio nu2", "none", "0.17", alt="elastic:moduli"),
]

_WIRE = [
    *_ELASTIC,
    _f("radius", "radius R", "length", "5e-08"),
    _f("work_of_adhesion", "work of adhesion w", "work", "0.3", alt="adhesion:work"),
    _f("z0", "equilibrium spacing z0", "length", "3e-10", alt="adhesion:work"),
    _f("sigma0", "adhesive stress sigma0", "stress", "1e9", alt="adhesion:stress"),
    _f("h", "adhesion range h", "length", "3e-10", alt="adhesion:stress"),
]

_LENGTH = _f("length", "wire length L (optional)", "length", "", unit="um", optional=True)

#: The wire's cross-section (its choices are the operation's) and a polygon's corner radius.
_SHAPE = [
    _f("cross_section", "cross-section", "choice", "round"),
    _f("corner_radius", "corner radius r_c (a polygon's; 0: sharp)", "length", "", optional=True),
]

#: A tip's fields: the wire's, its material a tip's (Si) and its radius 20 nm.
_TIP = [
    _f("cylinder_material", "tip material", "material", "Si", alt="elastic:presets"),
    *[f for f in _WIRE if f["name"] not in ("cylinder_material", "radius")],
    _f("radius", "tip radius R", "length", "2e-08"),
]


def _axis(key: str, kind: str, label: str) -> dict[str, str]:
    """A plotted quantity: its key in the answer, its kind of unit, its label."""
    return {"key": key, "kind": kind, "label": label}


def _plot(x: tuple[str, str, str], *ys: tuple[str, str, str], **kw: Any) -> dict[str, Any]:
    """A page's plot: ``x`` and each of ``ys`` as (key, kind, label).

    ``ylabel``, ``points``, ``color`` and ``legend`` as ``static/app.js`` reads them.
    """
    return {"x": _axis(*x), "ys": [_axis(*y) for y in ys], **kw}


def _page(
    title: str,
    question: str,
    command: str,
    fields: list[dict[str, Any]],
    plot: dict[str, Any] | None = None,
    *,
    alts: dict[str, Any] | None = _WIRE_ALTS,
    **kw: Any,
) -> dict[str, Any]:
    """A page: its title, the question it answers, its command, its fields and its plot.

    ``alts``, the alternatives its fields are grouped in (a wire's elasticity and adhesion
    unless said); ``fixed`` (parameters the page always sends), ``upload``,
    ``upload_label``, ``job``, ``mark``, ``figures`` as :data:`PAGES` says.
    """
    page = {"title": title, "question": question, "command": command, **kw}
    if alts is not None:
        page["alts"] = alts
    return {**page, "fields": list(fields), "plot": plot}


#: A sphere's load curve against its approach (under either law).
_SPHERE_CURVE_PLOT = _plot(("delta_m", "length", "approach delta"), ("F_N", "newton", "load F"))

#: The pages: path -> title, what it answers, command, fields, fixed parameters, plot (an
#: upload page: ``upload``, its label ``upload_label``; further figures: ``figures``).
#: The headline (the answer in words) and the Python lines of each page are written by
#: ``static/app.js``, by the page's name.
PAGES: dict[str, dict[str, Any]] = {
    "pulloff": _page(
        "Contact and pull-off of a wire",
        "How hard must the wire be pulled to come off the substrate?",
        "pulloff",
        [*_WIRE, *_SHAPE, {**_LENGTH, "default": "5e-06"}],
    ),
    "contact": _page(
        "Contact width under a load",
        "How wide is the contact under these loads?",
        "normal",
        [
            *_WIRE,
            *_SHAPE,
            _f("load", "normal loads F (comma-separated)", "force", "0,1,5,10", many=True),
        ],
        _plot(("F_N_per_m", "force", "load F"), ("a_m", "length", "contact half-width a")),
    ),
    "curve": _page(
        "The load curve",
        "How does the load change with the contact width, and where does it pull off?",
        "curve",
        [*_WIRE, *_SHAPE],
        _plot(("a_m", "length", "contact half-width a"), ("F_N_per_m", "force", "load F")),
    ),
    "push": _page(
        "A wire pushed sideways: stay, roll or slide",
        "Pushed sideways at a height H, does the wire roll or slide first, and at what push?",
        "push",
        [
            *_ELASTIC,
            _f("radius", "radius R", "length", "5e-08"),
            _f(
                "work_of_adhesion_receding",
                "receding work of adhesion w1 (opening edge)",
                "work",
                "0.6",
                alt="adhesion:works",
            ),
            _f(
                "work_of_adhesion_advancing",
                "advancing work of adhesion w2 (closing edge)",
                "work",
                "0.3",
                alt="adhesion:works",
            ),
            _f("z0", "equilibrium spacing z0", "length", "3e-10", alt="adhesion:works"),
            _f("sigma0", "adhesive stress sigma0", "stress", "1e8", alt="adhesion:ranges"),
            _f("h2", "advancing range h2", "length", "3e-10", alt="adhesion:ranges"),
            _f("h1", "receding range h1", "length", "6e-10", alt="adhesion:ranges"),
            _f("tau0", "interfacial shear strength tau0", "stress", "1e7"),
            _f(
                "height",
                "push heights H (comma-separated, 0 to 2R)",
                "length",
                "1e-08,2e-08,3e-08,4e-08,5e-08,6e-08,7e-08,8e-08,9e-08,1e-07",
                many=True,
                alt="pusher:flat",
            ),
            _f(
                "tip_height",
                "tip heights H (comma-separated, between 0 and 2R)",
                "length",
                "1e-08,2e-08,3e-08,4e-08,5e-08,6e-08,7e-08,8e-08,9e-08",
                many=True,
                alt="pusher:tip",
            ),
            _f("tip_friction", "tip friction coefficient", "none", "0.3", alt="pusher:tip"),
            _f("load", "normal load F (optional)", "force", "", optional=True),
            _f("push", "a push Q (optional): stay, roll or slide?", "force", "", optional=True),
            {**_LENGTH, "default": "5e-06"},
        ],
        _plot(
            ("H_m", "length", "push height H"),
            ("Q_roll_N_per_m", "force", "to roll, Q_roll"),
            ("Q_slide_N_per_m", "force", "to slide, Q_slide"),
            ylabel="push Q",
        ),
        alts={
            "elastic": _WIRE_ALTS["elastic"],
            "adhesion": {
                "label": "adhesion given as",
                "options": [
                    ["works", "receding and advancing works of adhesion"],
                    ["ranges", "adhesive stress and ranges (sigma0, h2, h1)"],
                ],
            },
            "pusher": {
                "label": "pushed by",
                "options": [["flat", "a flat push at heights H"], ["tip", "a tip at heights H"]],
            },
        },
    ),  # fmt: skip
    "cycle": _page(
        "Energy lost per cycle",
        "How much energy does a tangential cycle of this amplitude dissipate?",
        "cycle",
        [
            *_WIRE,
            _f("load", "normal load F", "force", "1"),
            _f("tau0", "interfacial shear strength tau0", "stress", "1e7"),
            _f(
                "tangential_amplitude",
                "amplitudes T* (comma-separated)",
                "force",
                "0.01,0.02,0.04,0.06",
                many=True,
            ),
        ],  # fmt: skip
        _plot(
            ("T_amplitude_N_per_m", "force", "amplitude T*"),
            ("W_J_per_m", "energy", "energy lost per cycle W"),
        ),
    ),
    "sphere": _page(
        "An AFM tip or a colloidal probe: pull-off",
        "How hard must a sphere (an AFM tip, a colloidal probe) be pulled to come "
        "off the substrate?",
        "pulloff",
        _TIP,
        fixed={"body": "sphere"},
    ),
    "sphere-contact": _page(
        "An AFM tip or a colloidal probe: contact radius under a load",
        "How large is the contact of a sphere under these loads?",
        "normal",
        [
            *_TIP,
            _f("force", "loads F (comma-separated)", "newton", "0,1e-9,5e-9,1e-8", many=True),
        ],
        _plot(("F_N", "newton", "load F"), ("a_m", "length", "contact radius a")),
        fixed={"body": "sphere"},
    ),
    "sphere-curve": _page(
        "An AFM tip or a colloidal probe: the load curve",
        "How does the load of a sphere change with its approach, and where does it pull off?",
        "curve",
        _TIP,
        _SPHERE_CURVE_PLOT,
        fixed={"body": "sphere"},
    ),
    "sphere-lennard-jones": _page(
        "An AFM tip or a colloidal probe under the Lennard-Jones law: pull-off",
        "How hard must a sphere be pulled off under the full Lennard-Jones law "
        "(Greenwood's self-consistent sphere, not Dugdale's step)?",
        "pulloff",
        _TIP,
        fixed={"body": "sphere", "law": "lennard-jones"},
    ),
    "sphere-lennard-jones-curve": _page(
        "An AFM tip or a colloidal probe under the Lennard-Jones law: the load curve",
        "How does the load of a sphere change with its approach under the full "
        "Lennard-Jones law, through its jump-in and pull-off?",
        "curve",
        _TIP,
        _SPHERE_CURVE_PLOT,
        fixed={"body": "sphere", "law": "lennard-jones"},
    ),
    "lennard-jones": _page(
        "The Lennard-Jones law: pull-off",
        "The pull-off under the full Lennard-Jones law (not Dugdale's step).",
        "pulloff",
        _WIRE,
        fixed={"law": "lennard-jones"},
    ),
    "fit": _page(
        "Work of adhesion from pull-off forces (CSV upload)",
        "Which work of adhesion (and range z0) explain the measured pull-offs?",
        "fit-adhesion",
        [
            _f("cylinder_material", "wire material", "material", "SiO2"),
            _f("substrate_material", "substrate material", "material", "Si"),
            _f(
                "z0",
                "equilibrium spacing z0 (optional: fixed if given)",
                "length",
                "",
                optional=True,
            ),
        ],  # fmt: skip
        _plot(("radius_m", "length", "radius R"), ("F_N_per_m", "force", "pull-off force")),
        alts=None,
        upload=True,
    ),
    "bent-wire": _page(
        "Friction from the shape of a bent wire (profile upload)",
        "Which friction per unit length f (and interfacial shear strength tau0) "
        "bent the wire dragged at its midpoint into the shape imaged, or, for a wire held at "
        "rest in its bent shape, which static friction holds it there (its mean |f_n| along "
        "the wire, and f_n along it)?",
        "fit-bent-wire",
        [
            _f(
                "model",
                "the model: dragged at its midpoint (kinetic friction) or held at rest "
                "(static friction)",
                "choice",
                "dragged",
            ),
            _f("cylinder_material", "wire material", "material", "ZnO", alt="elastic:presets"),
            _f("modulus", "wire's Young's modulus E", "modulus", "1.4e11", alt="elastic:modulus"),
            _f(
                "nu1",
                "wire's Poisson ratio nu1 (for tau0's contact)",
                "none",
                "0.36",
                alt="elastic:modulus",
                optional=True,
            ),
            _f("radius", "radius R (a polygon's circumradius)", "length", "5e-08"),
            *_SHAPE,
            _f("inner_radius", "a tube's inner radius (optional)", "length", "", optional=True),
            _f(
                "noise",
                "position noise, its sd (optional: from the residuals)",
                "length",
                "",
                optional=True,
            ),
            _f("bootstrap", "bootstrap refits (0 to 10000)", "none", "200"),
            _f(
                "work_of_adhesion",
                "work of adhesion w",
                "work",
                "0.3",
                alt="tau0:presets|moduli|composite",
            ),
            _f(
                "z0",
                "equilibrium spacing z0",
                "length",
                "3e-10",
                alt="tau0:presets|moduli|composite",
            ),
            _f("substrate_material", "substrate material", "material", "SiO2", alt="tau0:presets"),
            _f("E2", "substrate's Young's modulus E2", "modulus", "7.2e10", alt="tau0:moduli"),
            _f("nu2", "substrate's Poisson ratio nu2", "none", "0.17", alt="tau0:moduli"),
            _f(
                "contact_modulus",
                "contact's composite modulus E*",
                "modulus",
                "4.8e10",
                alt="tau0:composite",
            ),
        ],
        _plot(("x_m", "length", "x"), ("y_m", "length", "y")),
        alts={
            "elastic": {
                "label": "the wire's Young's modulus (its bending stiffness EI) from",
                "options": [["presets", "the wire's material"], ["modulus", "a modulus E"]],
            },
            "tau0": {
                "label": "tau0 = f/(2a), the contact's half-width a from",
                "options": [
                    ["none", "(none: the friction f alone)"],
                    ["presets", "w, z0 and the substrate's material"],
                    ["moduli", "w, z0 and the substrate's E2, nu2"],
                    ["composite", "w, z0 and the contact's composite modulus"],
                ],
            },
        },
        upload=True,
        upload_label="the wire's profile (CSV: x_nm,y_nm, points from end to end)",
        figures=["residuals", "normal-friction"],
    ),
    "map": _page(
        "The adhesion map (quick grid), your wire marked",
        "Which model (Hertz, rigid, JKR, Maugis-Dugdale) holds for your wire?",
        "map",
        [{**f, "aux": True} for f in _WIRE],
        _plot(
            ("maugis_parameter", "none", "Maugis parameter"),
            (
                "load_above_pulloff_over_abs_pulloff",
                "none",
                "load above pull-off / |pull-off|",
            ),
            points=True,
            color="agrees_md",
            legend="blue: Maugis-Dugdale agrees with the full law, grey: it does not",
        ),
        fixed={"quick": "true"},
        job=True,
        mark={"command": "pulloff", "key": "maugis_parameter", "label": "your wire"},
    ),
}


#: The SI unit of each kind of field (the unit its value is sent in).
SI_UNIT = {
    "length": "m",
    "modulus": "Pa",
    "stress": "Pa",
    "work": "J/m^2",
    "force": "N/m",
    "newton": "N",
    "energy": "J/m",
    "none": "",
    "material": "",
    "choice": "",
}


def check(pages: dict[str, dict[str, Any]] | None = None) -> list[str]:
    """What in the pages disagrees with the operations they call (empty: nothing).

    Each field must be a parameter of its page's operation (of the marking operation for
    the map's wire) and its kind's SI unit the unit the declaration gives it; each plotted
    key's unit, as its name states it, the one of its kind. A page that passes cannot send
    a value in a unit the operation does not take, nor label a result in another unit.
    """
    from .. import operations
    from ..output import unit_of

    problems = []
    for name, page in (PAGES if pages is None else pages).items():
        main = operations.get(page["command"])
        aux = operations.get(page["mark"]["command"]) if "mark" in page else main
        for f in page["fields"]:
            op = aux if f.get("aux") else main
            try:
                p = op.parameter(f["name"])
            except ValueError:
                problems.append(f"{name}: field {f['name']!r} is no parameter of {op.name}")
                continue
            unit = SI_UNIT.get(f["kind"])
            if unit is None or unit != p.unit:
                problems.append(
                    f"{name}: field {f['name']!r} is sent as {f['kind']} ({unit!r}), "
                    f"{op.name} takes {p.option} in {p.unit or 'no unit'!r}"
                )
        plot = page.get("plot") or {}
        for axis in [plot["x"], *plot["ys"]] if plot else []:
            stated = unit_of(axis["key"])
            unit = SI_UNIT.get(axis["kind"])
            if (stated if stated != "1" else "") != unit:
                problems.append(
                    f"{name}: plotted {axis['key']!r} is in {stated!r}, drawn as {axis['kind']}"
                )
    return problems


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


def _field(f: dict[str, Any], command: str) -> str:
    name, kind = f["name"], f["kind"]
    label = f"<label for='f-{name}'>{html.escape(f['label'])}</label>"
    if kind in ("material", "choice"):
        if kind == "choice":  # the words the operation declares
            from .. import operations

            words = operations.get(command).parameter(name).choices or ()
        else:
            words = tuple(material_names())
        opts = "".join(
            f"<option{' selected' if m == f['default'] else ''}>{html.escape(m)}</option>"
            for m in words
        )
        control = f"<select id='f-{name}' name='{name}'>{opts}</select>"
    else:
        control = (
            f"<input id='f-{name}' name='{name}' data-kind='{kind}' inputmode='decimal' "
            f"data-default='{html.escape(f['default'])}' autocomplete='off' spellcheck='false'>"
        )
        if len(UNITS[kind]) > 1:
            chosen = f.get("unit") or UNITS[kind][0][0]
            opts = "".join(
                f"<option value='{html.escape(u)}'{' selected' if u == chosen else ''}>"
                f"{html.escape(u)}</option>"
                for u, _ in UNITS[kind]
            )
            control += (
                f"<select class='unit' id='u-{name}' aria-label='unit of the "
                f"{html.escape(f['label'])}'>{opts}</select>"
            )
        elif UNITS[kind][0][0]:
            control += f"<span class='unit'>{html.escape(UNITS[kind][0][0])}</span>"
    alt = f" data-alt='{html.escape(f['alt'])}'" if f.get("alt") else ""
    return (
        f"<div class='field' id='w-{name}'{alt}>{label}<div class='control'>{control}</div>"
        f"<div class='message' id='m-{name}' role='alert'></div></div>"
    )


def _alternative(group: str, a: dict[str, Any]) -> str:
    opts = "".join(
        f"<option value='{html.escape(v)}'>{html.escape(text)}</option>" for v, text in a["options"]
    )
    return (
        f"<div class='field choice'><label for='a-{group}'>{html.escape(a['label'])}</label>"
        f"<div class='control'><select id='a-{group}' class='alt'>{opts}</select></div></div>"
    )


def _json_in_html(obj: Any) -> str:
    """JSON inside a ``<script>`` element: no ``<``, ``>`` or ``&`` that HTML would read."""
    text = json.dumps(obj)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def page_html(name: str) -> str:
    """The page ``name``: its question, its form, and empty places for the answer."""
    p = PAGES[name]
    keys = ("title", "command", "fixed", "plot", "job", "upload", "mark", "alts")
    spec = {k: p.get(k) for k in keys}
    spec["page"] = name
    spec["units"] = UNITS
    spec["fields"] = [
        {
            k: f.get(k)
            for k in ("name", "label", "kind", "default", "aux", "many", "alt", "optional")
        }
        for f in p["fields"]
    ]
    alts = "".join(_alternative(g, a) for g, a in (p.get("alts") or {}).items())
    fields = "".join(_field(f, p["command"]) for f in p["fields"])
    upload = (
        "<div class='field'><label for='f-data'>"
        f"{html.escape(p.get('upload_label', 'measurements (CSV, units in the header)'))}</label>"
        "<div class='control'><input type='file' id='f-data' name='data' accept='.csv'></div>"
        "<div class='message' id='m-data' role='alert'></div></div>"
        if p.get("upload")
        else ""
    )
    # the page's further figures (the bent wire's residuals): empty places for static/app.js
    figures = "".join(f"<figure id='{html.escape(x)}'></figure>" for x in p.get("figures", ()))
    return (
        _head(p["title"]) + f"<h1>{html.escape(p['title'])}</h1>"
        f"<p class='question'>{html.escape(p['question'])}</p>"
        f"<script type='application/json' id='spec'>{_json_in_html(spec)}</script>"
        f"<form id='form' novalidate>{alts}{fields}{upload}"
        "<div class='buttons'><button type='submit' id='go'>Compute</button>"
        "<button type='button' id='cancel' hidden>Cancel</button></div></form>"
        "<div id='status' role='status'></div><div id='form-error' class='error'></div>"
        "<section id='answer' aria-live='polite'></section>"
        f"<figure id='plot'></figure><figure id='motion'></figure>{figures}"
        "<details id='details'><summary>All values: the table, the nondimensional groups and "
        "the solver's diagnostics</summary><section id='results'></section></details>"
        "<div id='downloads'></div>"
        "<section id='equivalent'><h2>The same elsewhere</h2><pre id='cli'></pre>"
        "<pre id='py'></pre></section>"
        "</main><script src='/static/app.js'></script></body></html>"
    )
