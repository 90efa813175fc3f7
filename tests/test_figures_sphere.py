"""The sphere's figures: drawn headless, nothing clipped, the plotted numbers checked.

Each figure's data are read back from its artists and checked against a computation written
here: the limits' lines against Hertz, JKR and DMT in Maugis' units; the Maugis--Dugdale
curves against Maugis' own equations (his units, his ``m = c/a``) solved by a root-finder;
the pull-off markers against the table of ``docs/sphere.md``; the map's regions against
each model's radius from its load solved here; the alpha curve's ends and its markers
against the docs' table. matplotlib is needed (the ``plot`` extra, part of ``test``).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

pytest.importorskip("matplotlib")

import linecontact.figures as figs  # noqa: E402
from linecontact.closed_forms.sphere import sphere_maugis_parameter  # noqa: E402
from linecontact.figures import sphere as sf  # noqa: E402
from linecontact.figures._style import DEFAULT_SIZE, DPI, Run  # noqa: E402
from linecontact.sphere import sphere_contact_for_load  # noqa: E402

DOC = Path(__file__).resolve().parents[1] / "docs" / "sphere.md"
BUILDERS = {
    "sphere01_load_curves": sf.load_curves_figure,
    "sphere02_adhesion_map": sf.adhesion_map_figure,
    "sphere03_cos_alpha": sf.alpha_figure,
}


@pytest.fixture(scope="module")
def runs():
    """One run at the smallest size and one at the default, sharing their data sets."""
    small = Run(size=figs.MIN_SIZE)
    return small, Run(size=DEFAULT_SIZE, _cache=small._cache)


@pytest.fixture(scope="module")
def built(runs):
    cache: dict = {}

    def build(stem, size="default"):
        key = (stem, size)
        if key not in cache:
            cache[key] = BUILDERS[stem](runs[0] if size == "small" else runs[1])
            cache[key].canvas.draw()
        return cache[key]

    return build


def _table(marker: str) -> dict[float, list[str]]:
    """A table of docs/sphere.md by its first column (as in tests/test_sphere_models.py)."""
    text = DOC.read_text(encoding="utf-8")
    block = text.split(marker, 1)[1].split("\n\n", 1)[0]
    rows = [r for r in block.strip().splitlines() if r.startswith("|")][2:]
    cells = [[c.strip() for c in r.strip("|").split("|")] for r in rows]
    return {float(r[0]): r[1:] for r in cells}


def _same(printed: str, value: float) -> bool:
    """``value`` printed with ``printed``'s digits is ``printed``."""
    decimals = len(printed.split(".")[1]) if "." in printed else 0
    return abs(float(printed) - value) <= 0.5 * 10**-decimals + 1e-12


def _line(ax, label: str):
    found = [ln for ln in ax.get_lines() if ln.get_label() == label]
    assert len(found) == 1, f"no single line labelled {label!r}"
    return np.asarray(found[0].get_xdata(), float), np.asarray(found[0].get_ydata(), float)


# --------------------------------------------------------------------------------------------
# every figure


def test_the_jobs_are_the_three_figure_functions():
    assert [j.stem for j in sf.jobs()] == list(sf.STEMS) == list(BUILDERS)
    assert [j.build for j in sf.jobs()] == list(BUILDERS.values())


@pytest.mark.parametrize("stem", list(BUILDERS))
def test_each_figure_is_an_agg_figure_at_the_common_size(built, stem):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = built(stem)
    assert isinstance(fig, Figure) and isinstance(fig.canvas, FigureCanvasAgg)
    assert tuple(fig.get_size_inches()) == pytest.approx(DEFAULT_SIZE)
    assert fig.dpi == DPI and fig.canvas.get_width_height() == (1440, 810)
    ax = fig.axes[0]
    assert ax.get_xlabel() and ax.get_ylabel() and ax.get_title()
    assert ax.get_legend() is not None


@pytest.mark.parametrize("stem", list(BUILDERS))
def test_fixed_layout_clips_nothing_at_the_smallest_size(built, stem):
    fig = built(stem, "small")
    box = fig.get_tightbbox(fig.canvas.get_renderer())
    w, h = fig.get_size_inches()
    assert box.x0 >= -0.02 and box.y0 >= -0.02 and box.x1 <= w + 0.02 and box.y1 <= h + 0.02


def test_extra_figures_writes_the_sphere_files(tmp_path, monkeypatch):
    # only the sphere's jobs, on small grids: the route, not the numbers
    for mod in (figs._push, figs._history, figs._adhesion_map):
        monkeypatch.setattr(mod, "jobs", lambda: [])
    monkeypatch.setattr(sf, "ALPHA_LAMBDAS", (0.01, 1.0, 100.0))
    monkeypatch.setattr(sf, "MAP_N_LAMBDA", 6)
    monkeypatch.setattr(sf, "MAP_N_LOAD", 5)
    monkeypatch.setattr(sf, "LOAD_LAMBDAS", (1.0,))
    written = figs.extra_figures(tmp_path, formats=("png", "svg"))
    assert [p.name for p in written] == [f"{s}.{f}" for s in sf.STEMS for f in ("png", "svg")]
    for p in written:
        assert p.stat().st_size > 1000


# --------------------------------------------------------------------------------------------
# sphere01: the load curves


def test_the_limits_are_hertz_jkr_and_dmt_in_maugis_units(built):
    ax = built("sphere01_load_curves").axes[0]
    A, hertz = _line(ax, "Hertz")
    assert_allclose(hertz, A**3, rtol=1e-12, atol=1e-14)
    A, jkr = _line(ax, "JKR")
    assert_allclose(jkr, A**3 - np.sqrt(6 * A**3), rtol=1e-12, atol=1e-12)
    # the JKR line's pull-off under load control: -3/2 at A = (3/2)^(1/3), to its spacing
    k = int(np.argmin(jkr))
    assert jkr[k] == pytest.approx(-1.5, abs=1e-4)
    assert A[k] == pytest.approx(1.5 ** (1 / 3), abs=A[1] - A[0])
    A, dmt = _line(ax, "DMT")
    assert_allclose(dmt, A**3 - 2, rtol=1e-12, atol=1e-12)


def _maugis_load(lam: float, A: float) -> float:
    """Maugis (1992, Eqs 6.17, 6.18) in his units: m = c/a from the gap, then P."""
    from scipy.optimize import brentq

    def gap(m: float) -> float:
        r = math.sqrt(m * m - 1)
        t = math.atan(r)
        return lam * A * A / 2 * (r + (m * m - 2) * t) + 4 * lam * lam * A / 3 * (r * t - m + 1) - 1

    hi = 2.0
    while gap(hi) < 0:
        hi *= 2
    m = brentq(gap, 1.0, hi, xtol=1e-15, rtol=1e-15)
    r = math.sqrt(m * m - 1)
    return A**3 - lam * A * A * (r + m * m * math.atan(r))


def test_the_curves_are_maugis_equations(built):
    ax = built("sphere01_load_curves").axes[0]
    for lam in sf.LOAD_LAMBDAS:
        A, P = _line(ax, f"lambda = {lam:g}")  # the stable part, from the load minimum
        assert A[-1] == pytest.approx(sf.A_MAX, rel=1e-12)
        for i in np.linspace(0, A.size - 1, 6).astype(int):
            assert P[i] == pytest.approx(_maugis_load(lam, A[i]), abs=1e-9), (lam, A[i])


def test_the_pull_off_markers_are_the_minima_and_the_docs_table(built):
    ax = built("sphere01_load_curves").axes[0]
    table = _table("<!-- alpha-lambda table")
    markers = {
        (ln.get_marker(), ln.get_color()): (float(ln.get_xdata()[0]), float(ln.get_ydata()[0]))
        for ln in ax.get_lines()
        if ln.get_marker() in ("o", "D") and len(ln.get_xdata()) == 1
    }
    previous = -2.0
    for lam in sf.LOAD_LAMBDAS:
        A, P = _line(ax, f"lambda = {lam:g}")
        color = next(
            ln.get_color() for ln in ax.get_lines() if ln.get_label() == f"lambda = {lam:g}"
        )
        A_po, P_po = markers[("o", color)]
        _, P_pd = markers[("D", color)]
        # load control: the lowest point of the curve, where its stable part begins
        dotted = [ln for ln in ax.get_lines() if ln.get_color() == color and ln.get_ls() == ":"]
        assert len(dotted) == 1
        A_all = np.concatenate([dotted[0].get_xdata(), A])
        P_all = np.concatenate([dotted[0].get_ydata(), P])
        k = int(np.argmin(P_all))
        assert (A_po, P_po) == pytest.approx((A_all[k], P_all[k]), rel=1e-12)
        assert A[0] <= A_po * (1 + 1e-12) and A_po <= A[1]
        # between DMT's -2 and JKR's -3/2, rising with lambda
        assert previous < P_po < -1.5
        previous = P_po
        assert P_po <= P_pd < 0
        if lam in table:
            po, pd = table[lam][1], table[lam][2]
            assert _same(po, P_po) and _same(pd, P_pd), (lam, P_po, P_pd)
    assert any(lam in table for lam in sf.LOAD_LAMBDAS)


def test_sigma0_over_E_of_lambda_gives_lambda_back():
    lam = np.geomspace(1e-3, 1e3, 13)
    s = sf.sigma0_over_E_of_lambda(lam)
    assert_allclose(sphere_maugis_parameter(sf.R_OVER_H, s), lam, rtol=1e-13)


# --------------------------------------------------------------------------------------------
# sphere02: the adhesion map


def _region(ax, gid: str):
    found = [c for c in ax.collections if c.get_gid() == gid]
    assert len(found) == 1, gid
    return found[0]


def test_the_map_regions_are_each_models_radius_within_tol(built):
    ax = built("sphere02_adhesion_map").axes[0]
    # every other interior node of the grid (none on the fill's outline)
    lam = np.geomspace(*sf.MAP_LAMBDA_RANGE, sf.MAP_N_LAMBDA)[1:-1:2]
    P = np.geomspace(*sf.MAP_LOAD_RANGE, sf.MAP_N_LOAD)[1:-1:2]
    L, PP = np.meshgrid(lam, P, indexing="ij")
    s = sf.sigma0_over_E_of_lambda(L)
    unit = np.cbrt(3 * np.pi * s / (4 * sf.R_OVER_H))  # Maugis' unit of length over R
    A_md = np.asarray(sphere_contact_for_load(PP * np.pi * s, sf.R_OVER_H, s).a_over_R) / unit
    # each model's radius at the load, solved here: Hertz A^3 = P, DMT A^3 - 2 = P,
    # JKR A^3 - sqrt(6) A^(3/2) = P (the larger root in A^(3/2))
    radius = {
        "hertz": np.cbrt(PP),
        "dmt": np.cbrt(PP + 2),
        "jkr": ((math.sqrt(6) + np.sqrt(6 + 4 * PP)) / 2) ** (2 / 3),
    }
    pts = np.column_stack([L.ravel(), PP.ravel()])
    for name, A in radius.items():
        err = np.abs(A / A_md - 1).ravel()
        region = _region(ax, f"region-{name}")
        inside = np.any([p.contains_points(pts) for p in region.get_paths()], axis=0)
        clear = np.abs(err - sf.TOL) > 0.2 * sf.TOL  # not within a cell of the outline
        assert clear.mean() > 0.8
        np.testing.assert_array_equal(inside[clear], err[clear] <= sf.TOL, err_msg=name)
    # where no model is within tol: the grey region
    best = np.min([np.abs(A / A_md - 1) for A in radius.values()], axis=0).ravel()
    none = np.any([p.contains_points(pts) for p in _region(ax, "region-none").get_paths()], 0)
    clear = np.abs(best - sf.TOL) > 0.2 * sf.TOL
    np.testing.assert_array_equal(none[clear], best[clear] > sf.TOL)


def test_the_map_has_jkr_at_large_lambda_and_dmt_at_small(built):
    ax = built("sphere02_adhesion_map").axes[0]
    lam = np.geomspace(0.0125, 80, 40)
    for load in (0.02, 0.1, 1.0):
        pts = np.column_stack([lam, np.full(lam.shape, load)])
        jkr = np.any([p.contains_points(pts) for p in _region(ax, "region-jkr").get_paths()], 0)
        dmt = np.any([p.contains_points(pts) for p in _region(ax, "region-dmt").get_paths()], 0)
        assert jkr[lam > 5].all() and not jkr[lam < 1].any(), load
        assert dmt[lam < 0.05].all() and not dmt[lam > 0.3].any(), load
        assert not (jkr & dmt).any()


def test_the_map_states_its_tolerance(built):
    fig = built("sphere02_adhesion_map")
    ax = fig.axes[0]
    assert "5 %" in ax.get_title()
    assert "5 %" in ax.get_legend().get_title().get_text()
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    assert ax.get_xlim() == pytest.approx(sf.MAP_LAMBDA_RANGE)


# --------------------------------------------------------------------------------------------
# sphere03: alpha against lambda


def test_alpha_runs_from_dmt_to_jkr_and_its_markers_are_the_docs_table(built):
    ax = built("sphere03_cos_alpha").axes[0]
    x, y = _line(ax, "fitted (PCHIP in $\\log\\lambda$)")
    assert x[0] == pytest.approx(1e-3) and x[-1] == pytest.approx(1e3)
    assert 0 < y[0] < 1e-3 and 0 < 1 - y[-1] < 1e-3  # DMT's 0 and JKR's 1
    assert np.all(np.diff(y) > 0)
    lam, alpha = _line(ax, "fits: the table of\ndocs/sphere.md")
    table = _table("<!-- alpha-lambda table")
    assert sorted(table) == sorted(lam.tolist())
    for v, a in zip(lam, alpha, strict=True):
        assert _same(table[float(v)][0], a), (v, a)
    # the line passes through every fit
    lam_all = np.concatenate([lam, _line(ax, "fits beyond the table")[0]])
    alpha_all = np.concatenate([alpha, _line(ax, "fits beyond the table")[1]])
    assert_allclose(np.interp(np.log(lam_all), np.log(x), y), alpha_all, atol=2e-3)


def test_alpha_line_between_the_fits_is_near_the_fit_there(built):
    from linecontact.sphere import cos_alpha

    ax = built("sphere03_cos_alpha").axes[0]
    x, y = _line(ax, "fitted (PCHIP in $\\log\\lambda$)")
    mid = np.array([math.sqrt(0.3), math.sqrt(3.0)])  # halfway, where the line bends most
    drawn = np.interp(np.log(mid), np.log(x), y)
    assert_allclose(drawn, cos_alpha(mid), atol=0.01)


def test_the_published_conversion_is_drawn_as_published(built):
    ax = built("sphere03_cos_alpha").axes[0]
    lam, alpha = _line(ax, "$\\lambda = -0.924\\ln(1 - 1.02\\alpha)$\n(Carpick et al. 1999)")
    keep = lam < 5  # beyond, 1 - 1.02 alpha loses digits to rounding
    assert keep.sum() > 200 and lam[0] == pytest.approx(1e-3)
    assert_allclose(-0.924 * np.log(1 - 1.02 * alpha[keep]), lam[keep], rtol=1e-10)
