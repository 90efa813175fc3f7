"""The calculator's pages as a colleague uses them (issue 31): in a real headless browser.

Each page is typed into, its units switched after typing, its answer read in words, its
warnings read on the page and in the API's JSON, its Python lines run and compared with the
API's numbers, and its width checked at a desktop and a phone width. Chromium from the
system, driven by Playwright (as ``tests/test_web.py``); every wait is bounded.
"""

from __future__ import annotations

import json
import os
import re
import shlex
import subprocess
import sys
import urllib.error
import urllib.parse
import urllib.request
import warnings
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("starlette")
pw = pytest.importorskip("playwright.sync_api")

from linecontact.cli import main  # noqa: E402

#: The README's push case, as the page's link (SI units, named as the flags).
README_PUSH = (
    "radius=5e-08&modulus=4.8e10&sigma0=1e8&h2=3e-10&h1=6e-10&tau0=1e6&height=2.5e-08,1e-07"
)
README_ARGV = [
    "push", "--radius", "50e-9", "--modulus", "48e9", "--sigma0", "1e8", "--h2", "0.3e-9",
    "--h1", "0.6e-9", "--tau0", "1e6", "--height", "25e-9", "100e-9",
]  # fmt: skip

WAIT = 60_000  # ms: the longest a page may take to answer (the map: a job of ~10 s)


def _api(server: str, command: str, query: str) -> dict[str, Any]:
    with urllib.request.urlopen(f"{server}/api/v1/{command}?{query}", timeout=60) as r:
        return json.load(r)


def _query(url: str) -> dict[str, list[str]]:
    return urllib.parse.parse_qs(urllib.parse.urlsplit(url).query)


def _answer(page) -> str:
    page.wait_for_selector("#headline", timeout=WAIT, state="attached")
    return page.inner_text("#answer")


def _compute(page, command: str = "") -> tuple[str, str]:
    """Click Compute; the API request the page sent (of ``command``) and its answer's text."""
    with page.expect_request(
        lambda r: f"/api/v1/{command}" in r.url and "/jobs/id/" not in r.url
    ) as req:
        page.click("#go")
    return req.value.url, _answer(page)


def _fits_both_widths(page) -> None:
    """No horizontal overflow at 1280 and 390 px, the table open (screenshots taken)."""
    if not page.locator("#details").evaluate("d => d.open"):
        page.click("#details summary")
    for width in (1280, 390):
        page.set_viewport_size({"width": width, "height": 900})
        over = page.evaluate("document.documentElement.scrollWidth - window.innerWidth")
        assert over <= 0, (page.url, width, over)
        assert page.screenshot(full_page=True)[:4] == b"\x89PNG"


def _run_python(code: str, names: list[str]) -> dict[str, Any]:
    """Run the page's Python lines in a fresh interpreter; the values of ``names`` as JSON."""
    pairs = ", ".join(f"{n!r}: {n}" for n in names)
    show = (
        "\nimport json as _j, numpy as _np\n"
        f"print('@@' + _j.dumps({{{pairs}}}, default=lambda o: _np.asarray(o).tolist()))"
    )
    p = subprocess.run(
        [sys.executable, "-W", "ignore", "-c", code + show],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout.split("@@")[-1])


# ------------------------------------------------------------------------------------------
# the unit applies to the number as typed


def test_typing_then_choosing_the_unit_computes_with_the_number_typed(server, page):
    page.goto(f"{server}/pulloff")
    page.fill("#f-length", "5")
    page.select_option("#u-length", "um")
    assert page.input_value("#f-length") == "5"  # the number stays as typed
    page.select_option("#u-radius", "um")
    assert page.input_value("#f-radius") == "50"
    page.select_option("#u-radius", "nm")
    url, text = _compute(page)
    sent = _query(url)
    assert float(sent["length"][0]) == pytest.approx(5e-6, rel=1e-15)
    assert float(sent["radius"][0]) == pytest.approx(5e-8, rel=1e-15)
    api = _api(server, "pulloff", urllib.parse.urlsplit(url).query)["results"][0]
    total = float(page.get_attribute("#headline [data-key='F_pulloff_total_N']", "data-value"))
    assert total == api["F_pulloff_total_N"]
    assert total == pytest.approx(api["F_pulloff_N_per_m"] * 5e-6, rel=1e-12)
    assert "on 5 um" in text and "µN" in text  # the total on the wire as typed
    assert "u.length=um" in page.url  # the link keeps the unit chosen
    page.goto(page.url)  # opened again: the same numbers, the same units
    _answer(page)
    assert page.input_value("#f-length") == "5" and page.input_value("#u-length") == "um"


def test_the_answer_leads_and_the_table_waits_behind_its_toggle(server, page):
    page.goto(f"{server}/pulloff")
    _compute(page)
    order = page.evaluate(
        "['answer', 'details'].map((id) => document.getElementById(id).getBoundingClientRect().top)"
    )
    assert order[0] < order[1]
    assert not page.locator("#details").evaluate("d => d.open")
    assert not page.locator("#results table").is_visible()  # groups and diagnostics: hidden
    page.click("#details summary")
    assert page.locator("#results table").is_visible()
    headers = page.locator("#results th").all_inner_texts()
    assert headers[0].endswith("[N/m]") or headers[0].endswith("[m]")  # SI values first
    for cell in page.locator("#results td[data-key]").all()[:8]:  # 5 digits shown, all kept
        shown, value = cell.inner_text(), cell.get_attribute("data-value")
        if re.fullmatch(r"-?[\d.]+(e-?\d+)?", shown) and value not in ("null", None):
            assert len(shown.replace("-", "").replace(".", "").split("e")[0].lstrip("0")) <= 5
            assert float(shown) == pytest.approx(float(value), rel=1e-4)


# ------------------------------------------------------------------------------------------
# a link's keys: every one taken, or named (issue 32)

#: The link of issue 32: a modulus, which the page offered no field for (it showed the
#: default ZnO on SiO2, -9.3568 N/m, while the API answered -10.3503 N/m).
SHARED = "radius=50e-9&modulus=1.2e11&work_of_adhesion=0.3&z0=3e-10"


def test_a_shared_link_with_a_modulus_shows_the_apis_number(server, page, capsys):
    page.goto(f"{server}/pulloff?{SHARED}")
    text = _answer(page)
    api = _api(server, "pulloff", SHARED)["results"][0]
    shown = float(page.get_attribute("#headline [data-key='F_pulloff_N_per_m']", "data-value"))
    assert shown == api["F_pulloff_N_per_m"]
    assert page.input_value("#a-elastic") == "modulus"  # the link's alternative chosen
    assert (
        page.locator("#w-modulus").is_visible() and page.locator("#w-cylinder_material").is_hidden()
    )
    assert f"{api['F_pulloff_N_per_m']:.4g}" in text.replace("−", "-")  # -10.35, in words
    # the page's Python lines and its command line give the same number
    ran = _run_python(page.inner_text("#py"), ["result.pull_off_force"])
    assert ran["result.pull_off_force"] == pytest.approx(api["F_pulloff_N_per_m"], rel=1e-12)
    cli = page.inner_text("#cli")
    assert "--modulus 1.2e11" in cli and "--cylinder-material" not in cli
    capsys.readouterr()
    main([*shlex.split(cli)[1:], "--json"])
    out = json.loads(capsys.readouterr().out)["results"][0]
    assert out["F_pulloff_N_per_m"] == api["F_pulloff_N_per_m"]


#: A hexagonal wire with 5 nm corners, as a link (issue 33): the page, its Python lines,
#: its command line and the API give one number.
FACETED = (
    "radius=5e-08&modulus=5e10&work_of_adhesion=0.1&z0=3e-10&cross_section=hexagon"
    "&corner_radius=5e-09"
)


def test_a_faceted_wire_on_the_pulloff_page(server, page, capsys):
    page.goto(f"{server}/pulloff?{FACETED}")
    _answer(page)
    api = _api(server, "pulloff", FACETED)["results"][0]
    shown = float(page.get_attribute("#headline [data-key='F_pulloff_N_per_m']", "data-value"))
    assert shown == api["F_pulloff_N_per_m"]
    assert page.input_value("#f-cross_section") == "hexagon"
    assert page.input_value("#f-corner_radius") == "5"  # shown in nm
    ran = _run_python(page.inner_text("#py"), ["result.pull_off_force"])
    assert ran["result.pull_off_force"] == pytest.approx(api["F_pulloff_N_per_m"], rel=1e-12)
    cli = page.inner_text("#cli")
    assert "--cross-section hexagon" in cli and "--corner-radius 5e-9" in cli
    capsys.readouterr()
    main([*shlex.split(cli)[1:], "--json"])
    out = json.loads(capsys.readouterr().out)["results"][0]
    assert out["F_pulloff_N_per_m"] == api["F_pulloff_N_per_m"]
    # chosen on the form: a pentagon, its corner in nm; the round wire sends no shape
    page.select_option("#f-cross_section", "pentagon")
    page.fill("#f-corner_radius", "2")
    url, _ = _compute(page)
    assert _query(url)["cross_section"] == ["pentagon"]
    assert float(_query(url)["corner_radius"][0]) == pytest.approx(2e-9)
    page.goto(f"{server}/pulloff")
    url, _ = _compute(page)
    assert "cross_section" not in _query(url) and "cross-section" not in page.inner_text("#cli")
    # a corner radius for a round wire: refused beside its field, in its words
    page.fill("#f-corner_radius", "2")
    page.click("#go")
    page.wait_for_selector("#m-corner_radius.error", timeout=WAIT)
    assert "polygon" in page.inner_text("#m-corner_radius")


#: ZnO's and SiO2's Young's moduli and Poisson ratios, as the four keys of a link.
FOUR = "E1=1.24e11&nu1=0.36&E2=7.2e10&nu2=0.17"


def test_a_link_with_the_four_moduli_chooses_them(server, page):
    query = f"radius=50e-9&{FOUR}&work_of_adhesion=0.3&z0=3e-10"
    page.goto(f"{server}/pulloff?{query}")
    _answer(page)
    assert page.input_value("#a-elastic") == "moduli"
    assert page.locator("#w-E1").is_visible() and page.locator("#w-modulus").is_hidden()
    assert page.input_value("#f-E1") == "124" and page.input_value("#u-E1") == "GPa"
    api = _api(server, "pulloff", query)["results"][0]
    shown = float(page.get_attribute("#headline [data-key='F_pulloff_N_per_m']", "data-value"))
    assert shown == api["F_pulloff_N_per_m"]
    # the presets' own moduli: the default page's number
    presets = (
        "radius=50e-9&cylinder_material=ZnO&substrate_material=SiO2&work_of_adhesion=0.3&z0=3e-10"
    )
    same = _api(server, "pulloff", presets)["results"][0]["F_pulloff_N_per_m"]
    assert shown == pytest.approx(same, rel=1e-12)
    code = page.inner_text("#py")
    assert "lc.Cylinder.from_materials(5e-8, 1.24e11, 0.36, 7.2e10, 0.17," in code
    ran = _run_python(code, ["result.pull_off_force"])
    assert ran["result.pull_off_force"] == pytest.approx(api["F_pulloff_N_per_m"], rel=1e-12)


def test_the_adhesion_as_a_stress_and_its_range(server, page):
    page.goto(f"{server}/pulloff")
    page.select_option("#a-adhesion", "stress")
    assert page.locator("#w-sigma0").is_visible() and page.locator("#w-z0").is_hidden()
    page.fill("#f-sigma0", "500")
    page.select_option("#u-sigma0", "MPa")
    page.fill("#f-h", "0.5")
    page.select_option("#u-h", "nm")
    url, _ = _compute(page)
    sent = _query(url)
    assert float(sent["sigma0"][0]) == pytest.approx(5e8) and float(sent["h"][0]) == 5e-10
    assert "work_of_adhesion" not in sent and "z0" not in sent
    api = _api(server, "pulloff", urllib.parse.urlsplit(url).query)["results"][0]
    ran = _run_python(page.inner_text("#py"), ["result.pull_off_force"])
    assert ran["result.pull_off_force"] == pytest.approx(api["F_pulloff_N_per_m"], rel=1e-12)


@pytest.mark.parametrize("name", ["pulloff", "contact", "curve"])
def test_a_wire_pages_defaults_are_the_presets_and_w_z0(server, page, name):
    page.goto(f"{server}/{name}")
    assert page.input_value("#a-elastic") == "presets"
    assert page.input_value("#a-adhesion") == "work"
    for hidden in ("modulus", "E1", "nu2", "sigma0", "h"):
        assert page.locator(f"#w-{hidden}").is_hidden()
    url, _ = _compute(page)
    sent = _query(url)
    assert sent["cylinder_material"] == ["ZnO"] and sent["substrate_material"] == ["SiO2"]
    assert sent["work_of_adhesion"] == ["0.3"] and sent["z0"] == ["3e-10"]
    assert not {"modulus", "E1", "nu1", "E2", "nu2", "sigma0", "h"} & set(sent)
    assert page.inner_text("#form-error") == ""


def _no_request(server: str, page, link: str) -> str:
    """Open ``link``: the message above the form, once no request to the API was sent."""
    requests: list[str] = []
    page.on("request", lambda r: requests.append(r.url) if "/api/v1/" in r.url else None)
    page.goto(f"{server}/{link}")
    page.wait_for_function("document.getElementById('form-error').textContent.length > 0")
    page.wait_for_timeout(500)
    assert requests == [] and page.inner_text("#answer") == ""
    return page.inner_text("#form-error")


@pytest.mark.parametrize(
    ("name", "command"),
    [("pulloff", "pulloff"), ("contact", "normal"), ("curve", "curve"), ("push", "push")],
)
def test_a_link_with_a_key_the_page_does_not_take_names_it_and_computes_nothing(
    server, page, name, command
):
    said = _no_request(server, page, f"{name}?radius=50e-9&modulus=1.2e11&colour=blue")
    assert "“colour”" in said and "does not take" in said and "422" in said
    assert "“radius”" not in said and "“modulus”" not in said
    # the API says the same of it
    with pytest.raises(urllib.error.HTTPError) as exc:
        _api(server, command, "radius=50e-9&modulus=1.2e11&colour=blue")
    assert exc.value.code == 422
    # the form changed and Compute pressed: the page asks for what it shows
    page.fill("#f-radius", "60")
    with page.expect_request(lambda r: f"/api/v1/{command}?" in r.url) as req:
        page.click("#go")
    assert "colour" not in req.value.url and "radius=6e-8" in req.value.url


def test_a_link_with_two_alternatives_names_both_and_computes_nothing(server, page):
    query = "radius=50e-9&modulus=1.2e11&cylinder_material=ZnO&work_of_adhesion=0.3&z0=3e-10"
    said = _no_request(server, page, f"pulloff?{query}")
    assert "“modulus”" in said and "“cylinder_material”" in said and "takes one" in said
    with pytest.raises(urllib.error.HTTPError) as exc:  # the API refuses the pair
        _api(server, "pulloff", query)
    assert exc.value.code == 422


# ------------------------------------------------------------------------------------------
# warnings: on the page and in the API's JSON


def test_a_radius_in_metres_is_warned_on_the_page_and_in_the_apis_json(server, page):
    page.goto(f"{server}/pulloff")
    page.fill("#f-radius", "40")
    page.select_option("#u-radius", "m")
    page.fill("#f-work_of_adhesion", "100")
    url, text = _compute(page)
    assert _query(url)["radius"] == ["40"]
    beside = page.inner_text("#m-radius")
    assert "radius R = 40 m" in beside and "is the radius in m?" in beside
    assert "work of adhesion w = 100 J/m^2" in page.inner_text("#m-work_of_adhesion")
    listed = page.inner_text("#warnings")
    assert "radius R = 40 m" in listed and "--radius" not in listed
    doc = _api(server, "pulloff", urllib.parse.urlsplit(url).query)
    assert any(w.startswith("--radius = 40 m is above") for w in doc["warnings"])
    assert any("--work-of-adhesion = 100 J/m^2" in w for w in doc["warnings"])
    # the command line says the same (its warnings on stderr)
    p = subprocess.run(
        [sys.executable, "-m", "linecontact", "pulloff", "--radius", "40", "--work-of-adhesion",
         "100", "--z0", "3e-10", "--cylinder-material", "ZnO", "--substrate-material", "SiO2"],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    for w in doc["warnings"]:
        assert w.split(" (linecontact takes SI units")[0] in p.stderr


# ------------------------------------------------------------------------------------------
# bad input: beside the field, in its words and unit, nothing computed


@pytest.mark.parametrize(
    ("typed", "words"),
    [
        ("0,3", "decimal comma: write 0.3"),
        ("40 nm", "choose nm in the list"),
        ("40nm", "choose nm in the list"),
        ("4O", "is not a number"),
        ("40 furlongs", "is not a number"),
        ("40 40", "takes one value, got 2"),
        ("1e999", "too large"),
    ],
)
def test_bad_input_is_named_beside_its_field_and_nothing_is_computed(server, page, typed, words):
    page.goto(f"{server}/pulloff")
    sent: list[str] = []
    page.on("request", lambda r: sent.append(r.url) if "/api/" in r.url else None)
    page.fill("#f-radius", typed)
    page.click("#go")
    page.wait_for_selector("#m-radius.error", timeout=5_000)
    message = page.inner_text("#m-radius")
    assert words in message, message
    assert "--" not in message
    page.wait_for_timeout(300)
    assert sent == []  # nothing computed with a number the user did not mean
    assert page.inner_text("#py") == ""  # no Python lines with the bad value in them
    assert page.inner_text("#answer") == ""


def test_an_error_from_the_server_is_in_the_fields_words_and_unit(server, page):
    page.goto(f"{server}/pulloff")
    page.fill("#f-radius", "-3")
    page.select_option("#u-radius", "um")
    page.click("#go")
    page.wait_for_selector("#m-radius.error", timeout=WAIT)
    message = page.inner_text("#m-radius")
    assert "radius R" in message and "you typed -3 um" in message and "--" not in message
    page.fill("#f-radius", "50")
    page.select_option("#u-radius", "nm")
    page.fill("#f-z0", "100")
    page.select_option("#u-z0", "um")  # the ratio R/z0 outside the solvers' domain
    page.click("#go")
    page.wait_for_selector("#m-z0.error", timeout=WAIT)  # the field it asks about
    message = page.inner_text("#m-z0")
    assert "equilibrium spacing z0" in message and "--" not in message
    assert "you typed 100 um" in message
    compile(page.inner_text("#py") or "pass", "<page>", "exec")  # never invalid Python


@pytest.mark.parametrize(
    ("field", "typed", "words"),
    [
        ("work_of_adhesion_advancing", "0.9",
         "The advancing work of adhesion w2 must be <= the receding work of adhesion w1"),
        ("height", "10, 200", "must be in [0, 100 nm] (2R), got 200 nm"),
        ("tau0", "-1", "got -1 MPa"),
        ("radius", "", "the radius R (in nm)"),
    ],
)  # fmt: skip
def test_the_push_pages_errors_are_in_its_fields_words(server, page, field, typed, words):
    page.goto(f"{server}/push")
    page.fill(f"#f-{field}", typed)
    page.click("#go")
    page.wait_for_selector(f"#m-{field}.error", timeout=WAIT)
    message = page.inner_text(f"#m-{field}")
    assert words in message and "--" not in message, message
    assert page.inner_text("#answer") == ""


# ------------------------------------------------------------------------------------------
# the push page


def test_the_push_page_answers_the_readme_case(server, page, capsys):
    page.goto(f"{server}/push?{README_PUSH}")
    text = _answer(page)
    assert page.input_value("#a-elastic") == "modulus"
    assert page.input_value("#a-adhesion") == "ranges"
    capsys.readouterr()
    main([*README_ARGV, "--json"])
    cli = json.loads(capsys.readouterr().out)["results"]
    assert [r["first_motion"] for r in cli] == ["slide", "roll+slide"]
    assert "at H = 25 nm: it slides first at 0.03268 N/m" in text
    assert "at H = 100 nm: it rolls and slips at once at 0.015 N/m" in text
    assert "rolls first above H* = 45.9 nm" in text
    heads = page.locator("#headline [data-key='Q_slide_N_per_m']").first
    assert float(heads.get_attribute("data-value")) == cli[0]["Q_slide_N_per_m"]
    assert page.inner_text("#cli").startswith("linecontact push --modulus 4.8e10 --radius 5e-8")
    ran = _run_python(
        page.inner_text("#py"),
        ["list(result.first_motion)", "result.rolling_resistance", "result.sliding_resistance"],
    )
    assert ran["list(result.first_motion)"] == ["slide", "roll+slide"]
    assert ran["result.rolling_resistance"] == pytest.approx([r["Q_roll_N_per_m"] for r in cli])
    assert ran["result.sliding_resistance"] == pytest.approx([r["Q_slide_N_per_m"] for r in cli])
    # the plot: Q_roll and Q_slide against H, in nm and N/m
    assert page.locator("#plot-svg polyline.series").count() == 2
    assert "push height H [nm]" in page.text_content("#plot-svg")


def _push_numbers(server: str, url: str, code: str) -> None:
    """The page's Python lines give the API's resistances for the request the page sent."""
    api = _api(server, "push", urllib.parse.urlsplit(url).query)["results"]
    ran = _run_python(
        code,
        ["list(result.first_motion)", "result.rolling_resistance", "result.sliding_resistance"],
    )
    assert ran["list(result.first_motion)"] == [r["first_motion"] for r in api]
    assert ran["result.rolling_resistance"] == pytest.approx([r["Q_roll_N_per_m"] for r in api])
    assert ran["result.sliding_resistance"] == pytest.approx([r["Q_slide_N_per_m"] for r in api])


def test_the_push_page_takes_the_works_of_adhesion_and_a_tip(server, page):
    page.goto(f"{server}/push")
    url, text = _compute(page)  # its defaults: the two works of adhesion, a flat push
    sent = _query(url)
    assert sent["work_of_adhesion_receding"] == ["0.6"]
    assert sent["work_of_adhesion_advancing"] == ["0.3"]
    assert "rolls first" in text and "slides first" in text and "on 5 um" in text
    _push_numbers(server, url, page.inner_text("#py"))
    # the motion map's own push requests finish first: none is taken for the next Compute's
    page.wait_for_selector("#motion-svg", timeout=WAIT, state="attached")
    # changed inputs: a tip with friction, in um, the advancing work in mJ/m^2
    page.select_option("#a-pusher", "tip")
    assert page.locator("#w-height").is_hidden() and page.locator("#w-tip_height").is_visible()
    page.fill("#f-tip_height", "0.02, 0.06")
    page.select_option("#u-tip_height", "um")
    page.fill("#f-tip_friction", "0.3")
    page.fill("#f-work_of_adhesion_advancing", "200")
    page.select_option("#u-work_of_adhesion_advancing", "mJ/m^2")
    url, text = _compute(page, "push?")
    sent = _query(url)
    assert [float(x) for x in sent["tip_height"][0].split(",")] == pytest.approx([2e-8, 6e-8])
    assert sent["tip_friction"] == ["0.3"] and "height" not in sent
    assert float(sent["work_of_adhesion_advancing"][0]) == pytest.approx(0.2)
    assert "at H = 0.02 um" in text
    _push_numbers(server, url, page.inner_text("#py"))
    page.wait_for_selector("#plot-svg polyline[stroke-dasharray='6 4']", timeout=WAIT)
    assert "a flat push" in page.inner_text("#plot figcaption")  # the tip's effect
    # a push given: its state in words
    page.fill("#f-push", "0.3")
    _, text = _compute(page)
    assert "under the push given it is at" in text


# ------------------------------------------------------------------------------------------
# the other pages: their Python lines, with the defaults and with changed inputs


@pytest.mark.parametrize(
    ("name", "fill", "command", "pairs"),
    [
        ("pulloff", {}, "pulloff", [("result.pull_off_force", "F_pulloff_N_per_m")]),
        (
            "pulloff",
            {"radius": ("80", "nm"), "work_of_adhesion": ("200", "mJ/m^2")},
            "pulloff",
            [("result.pull_off_force", "F_pulloff_N_per_m")],
        ),
        ("contact", {}, "normal", [("result.contact_half_width", "a_m")]),
        (
            "contact",
            {"load": ("2, 4", "N/m"), "radius": ("0.1", "um")},
            "normal",
            [("result.contact_half_width", "a_m")],
        ),
        ("cycle", {}, "cycle", [("result.energy_per_cycle", "W_J_per_m")]),
        (
            "curve",
            {},
            "curve",
            [("result.load", "F_N_per_m"), ("result.contact_half_width", "a_m")],
        ),
        ("lennard-jones", {}, "pulloff", [("result.pull_off_force", "F_pulloff_N_per_m")]),
        ("sphere", {}, "pulloff", [("result.pull_off_force", "F_pulloff_N")]),
        ("sphere-contact", {}, "normal", [("result.contact_radius", "a_m")]),
        (
            "sphere-contact",
            {"force": ("2, 20", "nN"), "radius": ("0.1", "um")},
            "normal",
            [("result.contact_radius", "a_m"), ("result.approach", "delta_m")],
        ),
        ("sphere-curve", {}, "curve", [("result.load", "F_N"), ("result.approach", "delta_m")]),
        ("sphere-lennard-jones", {}, "pulloff", [("result.pull_off_force", "F_pulloff_N")]),
        (
            "sphere-lennard-jones-curve",
            {"radius": ("50", "nm")},
            "curve",
            [("result.load", "F_N"), ("result.central_gap", "central_gap_m")],
        ),
        (
            "sphere",
            {"radius": ("1", "um"), "work_of_adhesion": ("50", "mJ/m^2")},
            "pulloff",
            [("result.pull_off_force", "F_pulloff_N")],
        ),
    ],
)
def test_a_pages_python_lines_give_the_apis_numbers(server, page, name, fill, command, pairs):
    page.goto(f"{server}/{name}")
    for field, (value, unit) in fill.items():
        page.fill(f"#f-{field}", value)
        page.select_option(f"#u-{field}", unit)
    url, _ = _compute(page)
    api = _api(server, command, urllib.parse.urlsplit(url).query)["results"]
    code = page.inner_text("#py")
    ran = _run_python(code, [p for p, _ in pairs])
    for py, key in pairs:
        want = [r[key] for r in api] if len(api) > 1 or isinstance(ran[py], list) else api[0][key]
        # the Lennard-Jones solver's last bits move with the BLAS threads (tests/test_web.py)
        rel = 1e-6 if "lennard-jones" in name else 1e-9
        assert ran[py] == pytest.approx(want, rel=rel), (py, key)


def test_the_lennard_jones_sphere_pages_say_the_answer_in_words(server, page):
    page.goto(f"{server}/sphere-lennard-jones")
    url, text = _compute(page, "pulloff")
    assert "Under the Lennard-Jones law it comes off at a pull of" in text
    assert "Tabor's parameter" in text and "self-consistent method" in text
    rec = _api(server, "pulloff", urllib.parse.urlsplit(url).query)["results"][0]
    shown = page.locator("#headline [data-key=F_pulloff_N]").first.get_attribute("data-value")
    assert float(shown) == pytest.approx(rec["F_pulloff_N"], rel=1e-6)
    assert rec["F_pulloff_N"] < 0 and rec["method"] == "self-consistent"
    link = "cylinder_material=Si&substrate_material=SiO2&radius=1e-04&work_of_adhesion=0.1&z0=3e-10"
    page.goto(f"{server}/sphere-lennard-jones-curve?{link}")
    _, text = _compute(page, "curve")
    assert "and jumps in at" in text  # S-shaped: a 100 um probe, Tabor's parameter 2.4
    page.wait_for_selector("#plot-svg", timeout=WAIT, state="attached")


# ------------------------------------------------------------------------------------------
# the fit page and the map page


def test_the_fit_page_plots_the_data_the_fit_and_its_band_and_fixes_z0(server, page, tmp_path):
    data = tmp_path / "my pulloffs.csv"
    data.write_text("radius_nm,pull_off_force_N_per_m\n20,-2.9\n50,-4.6\n100,-6.4\n")
    page.goto(f"{server}/fit")
    page.set_input_files("#f-data", str(data))
    page.fill("#f-z0", "0.3")
    with page.expect_request(lambda r: "/api/v1/fit-adhesion" in r.url) as req:
        page.click("#go")
    text = _answer(page)
    assert req.value.method == "POST"
    assert "--z0 3e-10" in page.inner_text("#cli")  # 0.3 nm, sent in SI units
    fixed = page.get_attribute("#results dd[data-key='z0_fixed']", "data-value")
    assert fixed == "true"  # the server fitted with z0 fixed
    assert "with z0 fixed at 0.3 nm" in text and "95 % interval" in text
    assert "[" not in text  # no raw JSON lists
    page.wait_for_selector("#plot-svg polygon.band", timeout=WAIT)
    assert page.locator("#plot-svg circle").count() == 3  # the data
    assert page.locator("#plot-svg polyline.series").count() == 1  # the fit
    whole = page.inner_text("body")
    page.click("#details summary")
    whole += page.inner_text("#results")
    assert "/tmp" not in whole and "linecontact-web" not in whole and "upload-" not in whole
    assert "my pulloffs.csv" in page.inner_text("#cli")
    w = float(page.get_attribute("#headline [data-key='work_of_adhesion']", "data-value"))
    ran = _run_python(page.inner_text("#py"), ["result.work_of_adhesion"])
    assert ran["result.work_of_adhesion"] == pytest.approx(w, rel=1e-6)
    _fits_both_widths(page)


def test_the_map_page_leads_with_your_wire_and_plots_before_its_table(server, page):
    page.goto(f"{server}/map")
    page.fill("#f-radius", "0.1")
    page.select_option("#u-radius", "um")
    page.click("#go")
    page.wait_for_selector("#plot-svg", timeout=120_000)
    text = _answer(page)
    api = _api(server, "pulloff", "cylinder_material=ZnO&substrate_material=SiO2&radius=1e-7"
               "&work_of_adhesion=0.3&z0=3e-10")["results"][0]  # fmt: skip
    assert float(page.get_attribute("#mark-value", "data-value")) == api["maugis_parameter"]
    assert text.startswith("Your wire: Maugis parameter")
    assert "On the map's column nearest your wire" in text
    top = page.evaluate(
        "['answer', 'plot', 'details'].map((id) => document.getElementById(id)"
        ".getBoundingClientRect().top)"
    )
    assert top[0] < top[1] < top[2]  # the answer, the plot, then the 164 rows
    ran = _run_python(page.inner_text("#py"), ["cyl.maugis_parameter"])
    assert ran["cyl.maugis_parameter"] == pytest.approx(api["maugis_parameter"], rel=1e-12)
    _fits_both_widths(page)


# ------------------------------------------------------------------------------------------
# widths


LINKS = {
    "pulloff": "cylinder_material=ZnO&substrate_material=SiO2&radius=5e-08&work_of_adhesion=0.3"
    "&z0=3e-10&length=5e-06&u.length=um",
    "contact": "cylinder_material=ZnO&substrate_material=SiO2&radius=5e-08&work_of_adhesion=0.3"
    "&z0=3e-10&load=0,1,5,10",
    "push": README_PUSH,
    "cycle": "cylinder_material=ZnO&substrate_material=SiO2&radius=5e-08&work_of_adhesion=0.3"
    "&z0=3e-10&load=1&tau0=1e7&tangential_amplitude=0.01,0.02",
    "curve": "cylinder_material=ZnO&substrate_material=SiO2&radius=5e-08&work_of_adhesion=0.3"
    "&z0=3e-10",
    "lennard-jones": "cylinder_material=ZnO&substrate_material=SiO2&radius=5e-08"
    "&work_of_adhesion=0.3&z0=3e-10",
    "sphere-lennard-jones-curve": "cylinder_material=Si&substrate_material=SiO2&radius=2e-07"
    "&work_of_adhesion=0.1&z0=3e-10",
}  # and the fit and the map pages, in their own tests (_fits_both_widths)


@pytest.mark.parametrize("width", [1280, 390])
def test_answered_pages_fit_desktop_and_phone_widths(server, browser, width):
    pg = browser.new_page(viewport={"width": width, "height": 900})
    where = os.environ.get("LINECONTACT_SCREENSHOTS")  # a folder to keep them in
    out = Path(where) if where else None
    try:
        for name, query in LINKS.items():
            pg.goto(f"{server}/{name}?{query}")
            _answer(pg)
            pg.wait_for_selector("#plot-svg, #regime", timeout=WAIT, state="attached")
            if name == "push":
                pg.wait_for_selector("#motion-svg", timeout=WAIT)
            pg.click("#details summary")  # the table too: it scrolls in its own box
            over = pg.evaluate("document.documentElement.scrollWidth - window.innerWidth")
            assert over <= 0, (name, width, over)
            shot = pg.screenshot(full_page=True)
            assert shot[:8] == b"\x89PNG\r\n\x1a\n"
            if out is not None:
                out.mkdir(parents=True, exist_ok=True)
                (out / f"web-{name}-{width}.png").write_bytes(shot)
    finally:
        pg.close()


def test_the_apis_warnings_go_last_and_are_a_list_even_when_empty():
    """The API's ``warnings``: a list of strings, after the command's own keys (the contract)."""
    from linecontact.web._app import _with_warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert json.loads(_with_warnings('{"results": []}\n', []))["warnings"] == []
        doc = json.loads(_with_warnings('{"a": 1, "results": [{"x": 2}]}', ["said"]))
    assert list(doc) == ["a", "results", "warnings"] and doc["warnings"] == ["said"]


@pytest.mark.parametrize(
    ("value", "words"),
    [("0,3", "a decimal comma? write 0.3"), ("40 nm", "the number alone (40), in SI units")],
)
def test_the_api_says_why_one_value_came_as_two(server, value, words):
    query = urllib.parse.urlencode({"radius": value, "R_over_h": "1"})
    with pytest.raises(urllib.error.HTTPError) as got:
        urllib.request.urlopen(f"{server}/api/v1/pulloff?{query}", timeout=60)
    assert got.value.code == 422
    err = json.load(got.value)["error"]
    assert err["parameter"] == "radius" and words in err["message"], err
