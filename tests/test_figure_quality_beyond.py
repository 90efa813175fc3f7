"""The figures fit to print: common size, legends of drawn data, text inside, labelled axes.

For the pushed fibre's figures, the load-history figures and the pull-off fit figure: the
default size is the common 1440 x 810 px; every legend entry names an artist drawn with
data; no text leaves the figure; every axis label is non-empty and has its unit (or is a
ratio of quantities). Then the defects of the issue "figures fit to print": the motion map's
key lists only the regions drawn, its regions follow the computed boundaries; the fit
figure's tick labels are plain numbers, its axes in the units given.

matplotlib is needed (the ``plot`` extra, part of ``test``).
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

pytest.importorskip("matplotlib")

import linecontact as lc  # noqa: E402
from linecontact import inverse as inv  # noqa: E402
from linecontact.figures import fit as fit_figs  # noqa: E402
from linecontact.figures import history as hist_figs  # noqa: E402
from linecontact.figures import push as push_figs  # noqa: E402
from linecontact.figures._style import DEFAULT_SIZE, DPI, Run  # noqa: E402

E = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))
W, Z0 = 0.1, 0.3e-9
# radii spanning less than a decade: the fit figure's axes span less than two
RADII = np.array([40e-9, 60e-9, 90e-9, 130e-9])

JOBS = {j.stem: j for j in [*push_figs.jobs(), *hist_figs.jobs()]}
STEMS = [*JOBS, "fit_adhesion_nm"]


@pytest.fixture(scope="module")
def fit():
    F = inv.pull_off_force(RADII, E, W, Z0)
    F = F * (1 + 0.02 * np.random.default_rng(7).standard_normal(F.size))
    return inv.fit_pull_off(RADII, F, E, sd=0.02 * np.abs(F), bootstrap=0)


@pytest.fixture(scope="module")
def built(fit):
    run = Run()  # the default size
    cache: dict = {}

    def build(stem):
        if stem not in cache:
            if stem == "fit_adhesion_nm":
                cache[stem] = fit_figs._adhesion_figure(fit, run, ("nm", "nN/um"))
            else:
                cache[stem] = JOBS[stem].build(run)
            cache[stem].canvas.draw()
        return cache[stem]

    return build


def _has_data(artist) -> bool:
    """The artist is drawn with at least one finite data point (a line, a fill, a patch)."""
    if hasattr(artist, "get_xydata"):  # Line2D
        xy = np.asarray(artist.get_xydata(), float)
        return bool(xy.size) and bool(np.any(np.all(np.isfinite(xy), axis=-1)))
    if hasattr(artist, "get_paths"):  # collections: fills, meshes
        return any(
            len(p.vertices) and np.any(np.all(np.isfinite(p.vertices), axis=-1))
            for p in artist.get_paths()
        )
    if hasattr(artist, "get_path"):  # patches
        return bool(len(artist.get_path().vertices))
    if hasattr(artist, "lines"):  # an errorbar container: its data line
        return _has_data(artist.lines[0])
    return False


def _legend_entries(ax) -> list[str]:
    legends = [a for a in ax.get_children() if type(a).__name__ == "Legend"]
    return [t.get_text() for lg in legends for t in lg.get_texts()]


def _labelled(ax) -> dict[str, list]:
    out: dict[str, list] = {}
    for a in [*ax.lines, *ax.collections, *ax.patches, *ax.containers]:
        if hasattr(a, "lines") or a.get_visible():
            out.setdefault(a.get_label(), []).append(a)
    return out


@pytest.mark.parametrize("stem", STEMS)
def test_the_default_size_is_the_common_size(built, stem):
    fig = built(stem)
    assert tuple(fig.get_size_inches()) == pytest.approx(DEFAULT_SIZE)
    assert fig.dpi == DPI
    assert fig.canvas.get_width_height() == (1440, 810)


@pytest.mark.parametrize("stem", STEMS)
def test_every_legend_entry_is_an_artist_drawn_with_data(built, stem):
    fig = built(stem)
    n = 0
    for ax in fig.axes:
        drawn = _labelled(ax)
        for label in _legend_entries(ax):
            n += 1
            assert label in drawn, f"{stem}: legend entry {label!r} names no artist"
            assert any(_has_data(a) for a in drawn[label]), f"{stem}: {label!r} has no data"
    assert n > 0


def _texts(fig):
    """The visible, non-empty texts that are drawn (tick labels only of ticks in view)."""
    for ax in fig.axes:
        for axis, (lo, hi) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
            lo, hi = min(lo, hi), max(lo, hi)
            for loc, t in zip(axis.get_majorticklocs(), axis.get_majorticklabels(), strict=False):
                if lo <= loc <= hi:
                    yield t
            yield axis.label
        yield from (ax.title, ax._left_title, ax._right_title, *ax.texts)
        for lg in (a for a in ax.get_children() if type(a).__name__ == "Legend"):
            yield from lg.get_texts()
    yield from fig.texts


@pytest.mark.parametrize("stem", STEMS)
def test_no_text_exceeds_the_figure(built, stem):
    fig = built(stem)
    r = fig.canvas.get_renderer()
    W_px, H_px = fig.canvas.get_width_height()
    for t in _texts(fig):
        if not (t.get_visible() and t.get_text().strip()):
            continue
        b = t.get_window_extent(r)
        assert b.x0 >= -1 and b.y0 >= -1 and b.x1 <= W_px + 1 and b.y1 <= H_px + 1, (
            f"{stem}: {t.get_text()!r} at {b.bounds} leaves the {W_px} x {H_px} figure"
        )


@pytest.mark.parametrize("stem", STEMS)
def test_the_axis_labels_are_given_with_their_units(built, stem):
    for ax in built(stem).axes:
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            assert label.strip(), f"{stem}: an axis without a label"
            # a unit in brackets, or a ratio of quantities (the unit cancels)
            assert "[" in label or "/" in label, f"{stem}: {label!r} has no unit"


def test_the_motion_map_lists_only_the_regions_drawn(built):
    rho, r, s, tau, F = push_figs.BASE
    H = np.linspace(0.0, 2.0, 101)
    for stem, name, ys in (
        ("push01_motion_map_hysteresis", "h1_over_h2", np.linspace(1.0, 4.0, 61)),
        ("push02_motion_map_friction", "tau0_over_E", np.geomspace(1e-6, 1e-2, 61)),
    ):
        kw = {"h1_over_h2": r, "tau0_over_E": tau, name: ys[:, None]}
        first = lc.push(rho, kw["h1_over_h2"], s, kw["tau0_over_E"], F, H).first_motion
        present = {f"first motion: {m}" for m in np.unique(first)}
        entries = {e for e in _legend_entries(built(stem).axes[0]) if e.startswith("first")}
        assert entries == present, stem
    # the hysteresis map has no roll+slide region, the friction map has one
    assert not any("roll+slide" in e for e in _legend_entries(built(STEMS[0]).axes[0]))
    assert any("roll+slide" in e for e in _legend_entries(built(STEMS[1]).axes[0]))


def test_the_motion_map_regions_follow_the_computed_boundaries(built):
    """The region boundaries are the API's H* and the shear limit, not cell edges."""
    rho, r, s, tau, F = push_figs.BASE
    ax = built("push02_motion_map_friction").axes[0]
    ys = np.geomspace(1e-6, 1e-2, 61)
    p = lc.push(rho, r, s, ys, F, 1.5)
    star = next(ln for ln in ax.get_lines() if "H^*" in ln.get_label())
    assert_allclose(star.get_xdata(), p.H_critical_over_R, rtol=1e-14)
    # the roll / roll+slide boundary: where |S_roll| = dw (H - R)/H reaches 2 a_slide tau0
    limit = next(ln for ln in ax.get_lines() if "S_{roll}" in ln.get_label())
    H_hold = np.asarray(limit.get_xdata(), float)
    shown = np.isfinite(H_hold)
    assert shown.any()
    q = lc.push(rho, r, s, ys[shown], F, H_hold[shown])
    assert_allclose(np.abs(q.S_roll_over_Eh2), q.friction_over_Eh2, rtol=1e-9)
    # just either side of it: roll below, roll+slide above (the API's first motion)
    below = lc.push(rho, r, s, ys[shown], F, H_hold[shown] * (1 - 1e-6)).first_motion
    above = lc.push(rho, r, s, ys[shown], F, H_hold[shown] * (1 + 1e-6)).first_motion
    assert set(below) == {"roll"} and set(above) == {"roll+slide"}


def test_the_lateral_force_is_drawn_against_a_length_labelled_honestly(built):
    ax = built("push03_lateral_force").axes[0]
    label = ax.get_xlabel()
    assert "stretch" in label and "h_2" in label and "not the tip" in label
    rho, r, s, tau, F = push_figs.BASE
    slide = next(ln for ln in ax.get_lines() if "slides" in ln.get_label())
    x = np.asarray(slide.get_xdata())
    assert x[0] == 0 and x[-2] == pytest.approx(r - 1.0)  # (h1 - h2)/h2 at full stretch


def test_the_fit_figure_has_plain_tick_labels_and_the_units_given(built, fit):
    ax = built("fit_adhesion_nm").axes[0]
    labels = [t.get_text() for t in _texts(built("fit_adhesion_nm")) if t in _ticks(ax)]
    assert labels
    for text in labels:
        assert "$" not in text and "10^" not in text and "times" not in text, text
        float(text)  # a plain number
    assert "[nm]" in ax.get_xlabel()
    assert "nN/" in ax.get_ylabel() and "m]" in ax.get_ylabel()
    # the numbers are the fit's, in those units
    md = next(ln for ln in ax.get_lines() if ln.get_label() == "Maugis–Dugdale, fitted")
    R = np.asarray(md.get_xdata()) * 1e-9
    F_si = inv.pull_off_force(R, E, fit.work_of_adhesion, fit.equilibrium_spacing)
    assert_allclose(md.get_ydata(), np.abs(F_si) * 1e3, rtol=1e-12)


def _ticks(ax):
    return {*ax.xaxis.get_majorticklabels(), *ax.yaxis.get_majorticklabels()}


def test_the_fit_figure_takes_the_units_of_the_csv_file(tmp_path, fit):
    csv = tmp_path / "pulloff.csv"
    csv.write_text("# pull-offs\nradius_nm,pull_off_force_nN_per_um,sd\n40,-1.0,0.1\n")
    assert fit_figs.csv_units(csv) == ("nm", "nN/um")
    assert fit_figs.csv_units(tmp_path / "missing.csv") == ("m", "N/m")
    out = fit_figs.draw_adhesion_fit(fit, tmp_path / "fit.png", units=csv)
    assert out.exists()
    with pytest.raises(ValueError, match="units"):
        fit_figs.draw_adhesion_fit(fit, tmp_path / "bad.png", units=("mm", "N/m"))
