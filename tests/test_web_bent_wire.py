"""The bent wire's page (issue 35): a profile uploaded, the friction it gives, its plots.

A profile of known friction per unit length is made here from the elastica
(:func:`linecontact.bent_wire.dragged_wire`), written as the CSV a microscope's tracing
gives, and uploaded on ``/bent-wire`` in a real headless browser (Chromium from the system,
driven by Playwright, as ``tests/test_web_pages.py``). The page's numbers are compared with
the Python API's (:func:`linecontact.bent_wire.fit_bent_wire`,
:func:`linecontact.inverse.shear_strength_from_bent_wire`) and with its own command line
run here, to the digits shown and to the JSON's; its plots with the file's points, turned
into the wire's frame here from the API's midpoint and angles (the dragged wire's transverse
scale exaggerated, by the factor its caption says). A wire held at rest by static friction
(``model="held"``) is made here too, its tangent integrated by ``solve_ivp`` from a
curvature outside the fit's modes: its mean |f_n| is the API's and the command line's, and
its plot of f_n along the wire the record's.
"""

from __future__ import annotations

import json
import re
import shlex
import urllib.error
import urllib.parse
import urllib.request
from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("starlette")
pw = pytest.importorskip("playwright.sync_api")

from linecontact.bent_wire import bending_stiffness, dragged_wire, fit_bent_wire  # noqa: E402
from linecontact.cli import main  # noqa: E402
from linecontact.inverse import shear_strength_from_bent_wire  # noqa: E402
from linecontact.materials import composite_modulus  # noqa: E402
from linecontact.presets import Material  # noqa: E402

WAIT = 60_000  # ms: the longest the page may take to answer

#: The wire of the profile: a ZnO-like wire, E = 140 GPa, R = 50 nm, 5 um long.
MODULUS, RADIUS, HALF_LENGTH = 140e9, 50e-9, 2.5e-6
#: The friction per unit length that bent it [N/m] (12 nN/um).
FRICTION = 0.012


def _profile(friction: float, points: int = 250, noise: float = 2e-9, seed: int = 7) -> str:
    """The CSV of a wire dragged at its midpoint (x_nm,y_nm, end to end), turned by 0.3 rad,
    moved off the origin and with Gaussian position noise: the elastica's nodes interpolated
    by a Chebyshev series over each half."""
    from numpy.polynomial import chebyshev as C

    EI = float(bending_stiffness(MODULUS, RADIUS))
    w = dragged_wire(friction * HALF_LENGTH**3 / EI, nodes=64)
    cx = C.chebfit(2 * w.u - 1, w.x_over_l, 64)
    cy = C.chebfit(2 * w.u - 1, w.y_over_l, 64)
    s = np.linspace(-1.0, 1.0, points)
    x = np.sign(s) * C.chebval(2 * abs(s) - 1, cx) * HALF_LENGTH
    y = C.chebval(2 * abs(s) - 1, cy) * HALF_LENGTH
    c, sn = np.cos(0.3), np.sin(0.3)
    x, y = c * x - sn * y + 1e-6, sn * x + c * y + 2e-7
    rng = np.random.default_rng(seed)
    x, y = x + noise * rng.standard_normal(points), y + noise * rng.standard_normal(points)
    rows = "".join(f"{a * 1e9:.4f},{b * 1e9:.4f}\n" for a, b in zip(x, y, strict=True))
    return "x_nm,y_nm\n" + rows


def _read(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """The profile's points [m], read here (not by the library's reader)."""
    xy = np.loadtxt(path, delimiter=",", skiprows=1)
    return xy[:, 0] * 1e-9, xy[:, 1] * 1e-9


def _fmt(v: float) -> str:
    """A number as the page writes it: 4 significant digits, no trailing zeros."""
    return f"{float(f'{v:.4g}'):g}"


@pytest.fixture(scope="module")
def bent(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("profiles") / "wire7.csv"
    path.write_text(_profile(FRICTION))
    return path


def _cli(capsys, argv: list[str]) -> dict[str, Any]:
    capsys.readouterr()
    assert main([*argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)["results"][0]


def _shown(page, key: str) -> tuple[Any, str]:
    """The headline's value of ``key``: its full value (a list for an interval) and text."""
    el = page.locator(f"#headline [data-key='{key}']").first
    raw = el.get_attribute("data-value")
    value = [float(x) for x in raw.split(",")] if "," in raw else float(raw)
    return value, el.inner_text()


def _compute(page) -> str:
    with page.expect_request(lambda r: "/api/v1/fit-bent-wire" in r.url) as req:
        page.click("#go")
    assert req.value.method == "POST"
    assert "multipart/form-data" in req.value.headers["content-type"]
    page.wait_for_selector("#headline", timeout=WAIT, state="attached")
    return page.inner_text("#answer")


def _same(got: Any, want: Any, rel: float = 1e-9) -> None:
    """Equal JSON, numbers to ``rel``: the server's workers run one BLAS thread, this
    process may run more, which moves the fits' last bits (``tests/test_web.py``)."""
    if isinstance(want, dict):
        assert got.keys() == want.keys()
        for k in want:
            _same(got[k], want[k], rel)
    elif isinstance(want, list):
        assert isinstance(got, list) and len(got) == len(want)
        for g, w in zip(got, want, strict=True):
            _same(g, w, rel)
    elif isinstance(want, float):
        assert got == pytest.approx(want, rel=rel, abs=1e-300)
    else:
        assert got == want


# ------------------------------------------------------------------------------------------
# the answer


def test_the_page_gives_the_apis_and_the_command_lines_friction_and_tau0(
    server, page, bent, capsys
):
    page.goto(f"{server}/bent-wire")
    assert page.input_value("#a-elastic") == "presets"  # the defaults: ZnO, no tau0
    assert page.input_value("#a-tau0") == "none"
    assert page.locator("#w-work_of_adhesion").is_hidden()
    page.select_option("#a-elastic", "modulus")
    page.fill("#f-modulus", "140")  # GPa
    page.select_option("#a-tau0", "presets")  # w 0.3 J/m^2, z0 0.3 nm, on SiO2
    assert page.locator("#w-substrate_material").is_visible()
    assert page.locator("#w-E2").is_hidden() and page.locator("#w-contact_modulus").is_hidden()
    page.set_input_files("#f-data", str(bent))
    text = _compute(page)

    # the Python API, on the points read here, with EI from E and R
    x, y = _read(bent)
    fit = fit_bent_wire(x, y, float(bending_stiffness(MODULUS, RADIUS)))
    sio2 = Material.from_name("SiO2")
    Ec = float(composite_modulus(MODULUS, 0.36, sio2.E, sio2.nu))
    tau = shear_strength_from_bent_wire(fit, RADIUS, MODULUS, Ec, 0.3, 3e-10)
    assert fit.friction_per_length == pytest.approx(FRICTION, rel=0.02)  # the profile's f
    assert fit.friction_per_length_ci95[0] < FRICTION < fit.friction_per_length_ci95[1]

    f, f_text = _shown(page, "friction_per_length_N_per_m")
    assert f == pytest.approx(fit.friction_per_length, rel=1e-9)
    assert f_text == f"{_fmt(f / 1e-3)} nN/µm"
    ci, ci_text = _shown(page, "friction_per_length_ci95_N_per_m")
    assert ci == pytest.approx(fit.friction_per_length_ci95, rel=1e-9)
    assert ci_text == f"{_fmt(ci[0] / 1e-3)} to {_fmt(ci[1] / 1e-3)} nN/µm"
    boot, boot_text = _shown(page, "friction_per_length_bootstrap_ci95_N_per_m")
    assert boot == pytest.approx(fit.friction_per_length_bootstrap_ci95, rel=1e-9)
    assert boot_text == f"{_fmt(boot[0] / 1e-3)} to {_fmt(boot[1] / 1e-3)} nN/µm"
    t, t_text = _shown(page, "tau0_Pa")
    assert t == pytest.approx(tau.value, rel=1e-9) and t_text == f"{_fmt(t / 1e6)} MPa"
    tci, tci_text = _shown(page, "tau0_ci95_Pa")
    assert tci == pytest.approx(tau.ci95, rel=1e-9)
    assert tci_text == f"{_fmt(tci[0] / 1e6)} to {_fmt(tci[1] / 1e6)} MPa"
    assert f"f = {f_text} (95 % interval {ci_text}; the bootstrap's, from 200 refits:" in text
    assert f"tau0 = f/(2a) = {t_text} (95 % interval {tci_text})" in text
    assert "not computed" not in text and "do not determine" not in text

    # the command line the page shows, run here on the file it names: the same numbers
    line = page.inner_text("#cli")
    assert "--data wire7.csv" in line and "--modulus 1.4e11" in line
    assert "--substrate-material SiO2" in line and "--z0 3e-10" in line
    argv = shlex.split(line)[1:]
    argv[argv.index("--data") + 1] = str(bent)
    cli = _cli(capsys, argv)
    for key, value in [
        ("friction_per_length_N_per_m", f),
        ("friction_per_length_ci95_N_per_m", ci),
        ("friction_per_length_bootstrap_ci95_N_per_m", boot),
        ("tau0_Pa", t),
        ("tau0_ci95_Pa", tci),
    ]:
        assert cli[key] == pytest.approx(value, rel=1e-9), key

    # the table: the record in SI units, its lists said by their length
    page.click("#details summary")
    cell = page.locator("#results td[data-key='x_m']")
    assert cell.inner_text() == "250 values (in the JSON and CSV)"
    assert json.loads(cell.get_attribute("data-value")) == pytest.approx(x.tolist(), rel=1e-12)
    assert "/tmp" not in page.inner_text("body")  # no server path


def _frame(fit: Any, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points in the wire's frame [m], from the fit's numbers: along its axis and across it
    (towards the drag; the held wire: the axis turned by +90 degrees), from its midpoint."""
    a = fit.axis_angle
    d = fit.drag_angle if np.isfinite(fit.drag_angle) else a + np.pi / 2
    dx, dy = x - fit.midpoint[0], y - fit.midpoint[1]
    return dx * np.cos(a) + dy * np.sin(a), dx * np.cos(d) + dy * np.sin(d)


def _dots(page, svg: str) -> np.ndarray:
    """A plot's points: their values (data-x, data-y) and where they are drawn (cx, cy)."""
    return np.array(
        page.locator(f"#{svg} circle").evaluate_all(
            "cs => cs.map((c) => [c.dataset.x, c.dataset.y, c.getAttribute('cx'), "
            "c.getAttribute('cy')].map(Number))"
        )
    )


def _polyline(page, svg: str) -> np.ndarray:
    """The screen coordinates of a plot's one line."""
    line = page.locator(f"#{svg} polyline.series")
    assert line.count() == 1
    pts = line.get_attribute("points").split()
    return np.array([[float(v) for v in q.split(",")] for q in pts])


def _scales(xy: np.ndarray) -> tuple[float, float]:
    """Pixels per unit across the screen and up it, from the points' values and places."""
    sx = np.polyfit(xy[:, 0], xy[:, 2], 1)
    sy = np.polyfit(xy[:, 1], xy[:, 3], 1)
    # the places are the values' affine images (to the screen's rounding of 1e-9 px or so)
    assert np.abs(np.polyval(sx, xy[:, 0]) - xy[:, 2]).max() < 1e-6
    assert np.abs(np.polyval(sy, xy[:, 1]) - xy[:, 3]).max() < 1e-6
    return float(sx[0]), float(sy[0])


def test_the_plots_carry_the_points_the_fitted_wire_and_the_residuals(server, page, bent):
    page.goto(f"{server}/bent-wire")
    page.set_input_files("#f-data", str(bent))
    _compute(page)
    page.wait_for_selector("#residuals-svg", timeout=WAIT, state="attached")
    x, y = _read(bent)
    fit = fit_bent_wire(x, y, float(bending_stiffness(Material.from_name("ZnO").E, RADIUS)))

    # the profile in the wire's frame (the rotation from the API's midpoint and angles), nm
    along, across = _frame(fit, x, y)
    assert np.ptp(across) < 0.05 * np.ptp(along)  # bent little: straight at equal scales
    xy = _dots(page, "plot-svg")
    assert len(xy) == len(x) + 1  # the points, then the midpoint
    np.testing.assert_allclose(xy[: len(x), 0], along * 1e9, rtol=0, atol=1e-4)
    np.testing.assert_allclose(xy[: len(x), 1], across * 1e9, rtol=0, atol=1e-4)
    assert xy[-1, 0] == 0 and xy[-1, 1] == 0  # the midpoint at the origin
    assert across[[0, -1]].max() < -10e-9  # the ends lag behind the midpoint
    # not at equal scales: a nanometre across is drawn longer than one along, by the
    # factor the caption says
    sx, sy = _scales(xy)
    assert sx > 0 and sy < 0
    factor = -sy / sx
    assert factor > 5
    caption = page.inner_text("#plot figcaption")
    said = re.search(r"The transverse scale is exaggerated ×([\d.]+)", caption)
    assert said is not None, caption
    assert float(said.group(1)) == pytest.approx(factor, rel=1e-3)
    assert "along the wire's axis [nm]" in page.locator("#plot-svg").text_content()
    assert "across it, towards the drag [nm]" in page.locator("#plot-svg").text_content()
    # the fitted wire (401 points), back from the screen to nm by the points' own scale
    screen = _polyline(page, "plot-svg")
    assert len(screen) == 401
    b = np.polyfit(xy[:, 2], xy[:, 0], 1)
    c = np.polyfit(xy[:, 3], xy[:, 1], 1)
    wire_along, wire_across = _frame(fit, fit.curve_x, fit.curve_y)
    np.testing.assert_allclose(np.polyval(b, screen[:, 0]), wire_along * 1e9, atol=0.05)
    np.testing.assert_allclose(np.polyval(c, screen[:, 1]), wire_across * 1e9, atol=0.01)

    # the residuals against the arc length, in nm, and the band of +-2 noises
    res = _dots(page, "residuals-svg")
    assert len(res) == len(x)
    np.testing.assert_allclose(res[:, 0], fit.arc_length * 1e9, rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(res[:, 1], fit.residuals * 1e9, rtol=1e-6, atol=1e-6)
    assert page.locator("#residuals-svg polygon.band").count() == 1
    caption = page.inner_text("#residuals figcaption")
    assert f"±2 noises (±{_fmt(2 * fit.noise * 1e9)} nm)" in caption
    assert page.inner_text("#normal-friction") == ""  # the held wire's f_n: not drawn
    assert page.locator("#download-svg").count() == 1  # the profile's plot downloads
    page.click("#details summary")  # the table open: no overflow at a desktop's and a phone's
    for width in (1280, 390):
        page.set_viewport_size({"width": width, "height": 900})
        over = page.evaluate("document.documentElement.scrollWidth - window.innerWidth")
        assert over <= 0, (width, over)


# ------------------------------------------------------------------------------------------
# the held wire


def _held_curvature(s: np.ndarray) -> np.ndarray:
    """l kappa(s) of the held profile: a shape the fit's modes do not contain exactly."""
    return 3.0 * np.sin(np.pi * (s + 1) / 2) ** 2 * (1 + s / 2)


def _held_profile(points: int = 250, noise: float = 3e-9, seed: int = 11) -> str:
    """The CSV of a wire held at rest in the shape of :func:`_held_curvature` (x_nm,y_nm, end
    to end, half-length 2.5 um), its tangent integrated by solve_ivp, with position noise."""
    from scipy.integrate import solve_ivp

    def rhs(s, u):
        return [_held_curvature(s), np.cos(u[0]), np.sin(u[0])]

    s = np.linspace(-1.0, 1.0, points)
    sol = solve_ivp(rhs, (-1.0, 1.0), [0.0, 0.0, 0.0], t_eval=s, rtol=1e-12, atol=1e-14)
    assert sol.success
    rng = np.random.default_rng(seed)
    x = sol.y[1] * HALF_LENGTH + noise * rng.standard_normal(points)
    y = sol.y[2] * HALF_LENGTH + noise * rng.standard_normal(points)
    rows = "".join(f"{a * 1e9:.4f},{b * 1e9:.4f}\n" for a, b in zip(x, y, strict=True))
    return "x_nm,y_nm\n" + rows


def _held_mean_friction(EI: float) -> float:
    """The held profile's mean |f_n| = EI |kappa'' + kappa^3/2| along it [N/m], kappa''
    by central differences on a fine grid (not the library's modes)."""
    s = np.linspace(-1.0, 1.0, 40001)
    k = _held_curvature(s)
    kpp = np.gradient(np.gradient(k, s), s)
    fn = EI / HALF_LENGTH**3 * (kpp + k**3 / 2)
    return float(np.trapezoid(np.abs(fn), s) / 2)


def test_the_held_model_gives_the_apis_static_friction_and_its_profile(
    server, page, tmp_path, capsys
):
    held = tmp_path / "held.csv"
    held.write_text(_held_profile())
    page.goto(f"{server}/bent-wire")
    assert page.input_value("#f-model") == "dragged"  # the default
    options = page.locator("#f-model option").all_inner_texts()
    assert options == ["dragged", "held"]
    assert "held at rest (static friction)" in page.inner_text("#w-model label")
    page.select_option("#a-elastic", "modulus")
    page.fill("#f-modulus", "140")  # GPa
    page.select_option("#f-model", "held")
    page.set_input_files("#f-data", str(held))
    text = _compute(page)
    page.wait_for_selector("#normal-friction-svg", timeout=WAIT, state="attached")

    # the Python API on the points read here
    x, y = _read(held)
    EI = float(bending_stiffness(MODULUS, RADIUS))
    fit = fit_bent_wire(x, y, EI, model="held")
    assert fit.model == "held" and fit.determined and fit.modes >= 2
    assert not np.isfinite(fit.drag_angle)
    # the profile's own mean |f_n|, by finite differences: inside the fit's interval
    lo, hi = fit.friction_per_length_ci95
    assert lo < _held_mean_friction(EI) < hi

    f, f_text = _shown(page, "friction_per_length_N_per_m")
    assert f == pytest.approx(fit.friction_per_length, rel=1e-8)
    assert f_text == f"{_fmt(f / 1e-3)} nN/µm"
    ci, ci_text = _shown(page, "friction_per_length_ci95_N_per_m")
    assert ci == pytest.approx(fit.friction_per_length_ci95, rel=1e-8)
    assert ci_text == f"{_fmt(ci[0] / 1e-3)} to {_fmt(ci[1] / 1e-3)} nN/µm"
    boot, boot_text = _shown(page, "friction_per_length_bootstrap_ci95_N_per_m")
    assert boot == pytest.approx(fit.friction_per_length_bootstrap_ci95, rel=1e-8)
    assert (
        "The static friction holding the wire, averaged along it: mean |f_n| = "
        f"{f_text} (95 % interval {ci_text}; the bootstrap's, from 200 refits: {boot_text})."
    ) in text
    assert f"Fitted to 250 points, with {fit.modes} curvature modes" in text
    g, _ = _shown(page, "friction_group")
    assert g == pytest.approx(fit.friction_group, rel=1e-8)
    assert "the friction group mean |f_n| l³/EI = " in text
    assert "tau0 = mean |f_n|/(2a) is not computed" in text

    # the command line the page shows, run here: the same numbers
    line = page.inner_text("#cli")
    assert "--model held" in line and "--data held.csv" in line
    argv = shlex.split(line)[1:]
    argv[argv.index("--data") + 1] = str(held)
    cli = _cli(capsys, argv)
    assert cli["modes"] == fit.modes and cli["drag_angle"] is None
    for key, value in [
        ("friction_per_length_N_per_m", f),
        ("friction_per_length_ci95_N_per_m", ci),
        ("friction_per_length_bootstrap_ci95_N_per_m", boot),
    ]:
        assert cli[key] == pytest.approx(value, rel=1e-8), key

    # the profile in the wire's frame (across: the axis turned by +90 degrees), at equal
    # scales: the held wire is bent much
    along, across = _frame(fit, x, y)
    xy = _dots(page, "plot-svg")
    assert len(xy) == len(x) + 1
    np.testing.assert_allclose(xy[: len(x), 0], along * 1e9, rtol=0, atol=1e-3)
    np.testing.assert_allclose(xy[: len(x), 1], across * 1e9, rtol=0, atol=1e-3)
    sx, sy = _scales(xy)
    assert sx > 0 and sy == pytest.approx(-sx, rel=1e-9)
    assert "across it [nm]" in page.locator("#plot-svg").text_content()
    assert "exaggerated" not in page.inner_text("#plot figcaption")
    assert len(_dots(page, "residuals-svg")) == len(x)

    # f_n along the wire [nN/um] against the arc length [nm]: the line is the record's
    # normal_friction (an affine image of it and of curve_arc_length on the screen), the
    # band its +-2 sd
    fn = np.asarray(cli["normal_friction_N_per_m"]) * 1e3
    sd = np.asarray(cli["normal_friction_sd_N_per_m"]) * 1e3
    s = np.asarray(cli["curve_arc_length_m"]) * 1e9
    assert len(fn) == len(sd) == len(s) == 401
    np.testing.assert_allclose(
        fn, fit.normal_friction * 1e3, rtol=1e-6, atol=1e-6 * np.abs(fn).max()
    )
    assert np.mean(np.abs(fn)) == pytest.approx(f * 1e3, rel=0.01)  # its mean |f_n|
    screen = _polyline(page, "normal-friction-svg")
    assert len(screen) == 401
    bx = np.polyfit(s, screen[:, 0], 1)
    by = np.polyfit(fn, screen[:, 1], 1)
    assert bx[0] > 0 and by[0] < 0
    assert np.abs(np.polyval(bx, s) - screen[:, 0]).max() < 1e-6
    assert np.abs(np.polyval(by, fn) - screen[:, 1]).max() < 1e-6
    # the y axis's ticks read in nN/um: each label (3 digits) is the value at its place
    ticks = page.locator("#normal-friction-svg text[text-anchor='end']").evaluate_all(
        "ts => ts.map((t) => [Number(t.getAttribute('y')), Number(t.textContent)])"
    )
    assert len(ticks) == 5
    for place, label in ticks:
        value = (place - 4 - by[1]) / by[0]
        assert label == pytest.approx(value, rel=5.01e-3, abs=1e-3 * np.ptp(fn))
    band = page.locator("#normal-friction-svg polygon.band")
    assert band.count() == 1
    edge = np.array(
        [[float(v) for v in q.split(",")] for q in band.get_attribute("points").split()]
    )
    assert len(edge) == 2 * 401
    np.testing.assert_allclose(edge[:401, 1], np.polyval(by, fn + 2 * sd), atol=1e-3)
    np.testing.assert_allclose(edge[401:, 1], np.polyval(by, (fn - 2 * sd)[::-1]), atol=1e-3)
    assert "f_n [nN/µm]" in page.locator("#normal-friction-svg").text_content()


def test_an_undetermined_friction_and_no_interface_are_said(server, page, tmp_path):
    flat = tmp_path / "flat.csv"
    flat.write_text(_profile(1e-7))  # bent within the noise
    page.goto(f"{server}/bent-wire")
    page.set_input_files("#f-data", str(flat))
    text = _compute(page)
    x, y = _read(flat)
    fit = fit_bent_wire(x, y, float(bending_stiffness(Material.from_name("ZnO").E, RADIUS)))
    assert not fit.determined
    f, _ = _shown(page, "friction_per_length_N_per_m")
    assert f == pytest.approx(fit.friction_per_length, rel=1e-9)
    assert "Beware: the data do not determine f" in page.inner_text("#bent-wire-note")
    assert "tau0 = f/(2a) is not computed" in text
    assert page.locator("#headline [data-key='tau0_Pa']").count() == 0


# ------------------------------------------------------------------------------------------
# bad input, links, the API


def test_a_file_without_units_is_refused_beside_the_upload(server, page, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n" + "".join(f"{i},{i * i % 7}\n" for i in range(20)))
    page.goto(f"{server}/bent-wire")
    page.set_input_files("#f-data", str(bad))
    with page.expect_response(lambda r: "/api/v1/fit-bent-wire" in r.url) as got:
        page.click("#go")
    assert got.value.status == 422
    page.wait_for_selector("#m-data:not(:empty)", timeout=WAIT)
    said = page.inner_text("#m-data")
    assert "'bad.csv'" in said and "no unit" in said and "x_<unit>" in said, said
    assert page.inner_text("#answer") == "" and page.inner_text("#form-error") == ""
    assert "/tmp" not in said


def test_a_link_chooses_the_alternatives_its_keys_belong_to(server, page):
    query = "modulus=1.4e11&nu1=0.36&radius=5e-8&work_of_adhesion=0.3&z0=3e-10&E2=7.2e10&nu2=0.17"
    page.goto(f"{server}/bent-wire?{query}")
    page.wait_for_selector("#m-data:not(:empty)", timeout=WAIT)  # sent, without a file
    assert page.input_value("#a-elastic") == "modulus"
    assert page.input_value("#a-tau0") == "moduli"
    assert page.input_value("#f-E2") == "72" and page.input_value("#f-z0") == "0.3"
    assert "give the profile" in page.inner_text("#m-data")
    assert page.inner_text("#form-error") == ""
    # the substrate and a composite modulus, two alternatives: named, nothing computed
    requests: list[str] = []
    page.on("request", lambda r: requests.append(r.url) if "/api/v1/" in r.url else None)
    page.goto(f"{server}/bent-wire?radius=5e-8&work_of_adhesion=0.3&z0=3e-10"
              "&substrate_material=SiO2&contact_modulus=5e10")  # fmt: skip
    page.wait_for_function("document.getElementById('form-error').textContent.length > 0")
    said = page.inner_text("#form-error")
    assert "“contact_modulus”" in said and "“substrate_material”" in said, said
    assert "takes one of them" in said
    page.wait_for_timeout(300)
    assert requests == []


def test_the_api_takes_the_profile_as_a_multipart_upload(server, bent, capsys):
    httpx = pytest.importorskip("httpx")
    form = {"radius": "5e-8", "modulus": "1.4e11", "nu1": "0.36", "work_of_adhesion": "0.3",
            "z0": "3e-10", "substrate_material": "SiO2"}  # fmt: skip
    r = httpx.post(
        f"{server}/api/v1/fit-bent-wire",
        data=form,
        files={"data": ("wire7.csv", bent.read_bytes(), "text/csv")},
        timeout=60,
    )
    assert r.status_code == 200, r.text
    doc = r.json()
    assert doc["warnings"] == [] and "/tmp" not in r.text
    argv = ["fit-bent-wire", "--data", str(bent)]
    for k, v in form.items():
        argv += ["--" + k.replace("_", "-"), v]
    want = _cli(capsys, argv)
    _same(doc["results"][0], want)
    assert len(want["curve_x_m"]) == 401 and len(want["x_m"]) == 250
    # the same file without units in its header: a 422 naming the data
    bad = httpx.post(
        f"{server}/api/v1/fit-bent-wire",
        data=form,
        files={"data": ("bad.csv", b"x,y\n1,2\n2,3\n3,5\n", "text/csv")},
        timeout=60,
    )
    assert bad.status_code == 422
    err = bad.json()["error"]
    assert err["parameter"] == "data" and re.search(r"no unit", err["message"]), err
    query = urllib.parse.urlencode(form)
    with pytest.raises(urllib.error.HTTPError) as none:  # no file at all
        urllib.request.urlopen(f"{server}/api/v1/fit-bent-wire?{query}", timeout=60)
    assert (
        none.value.code == 422 and "give the profile" in json.load(none.value)["error"]["message"]
    )
