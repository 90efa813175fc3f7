"""The figures of the inverse problems: the drawn data are the API's numbers; the layout clips
nothing; the format follows the extension.

matplotlib is needed (the ``plot`` extra, part of ``test``).
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

pytest.importorskip("matplotlib")

import linecontact as lc  # noqa: E402
import linecontact.figures as figs  # noqa: E402
from linecontact import inverse as inv  # noqa: E402
from linecontact.figures import fit as fit_figs  # noqa: E402
from linecontact.figures._style import Run  # noqa: E402

E = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))
W, Z0 = 0.1, 0.3e-9
RADII = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])
PNG = b"\x89PNG\r\n\x1a\n"


def _noisy_fit(**kw):
    F = inv.pull_off_force(RADII, E, W, Z0)
    F = F * (1 + 0.03 * np.random.default_rng(5).standard_normal(F.size))
    return inv.fit_pull_off(RADII, F, E, sd=0.03 * np.abs(F), bootstrap=0, **kw)


@pytest.fixture(scope="module")
def fit():
    return _noisy_fit()


@pytest.fixture(scope="module")
def fixed_fit():
    return _noisy_fit(equilibrium_spacing=Z0)


@pytest.fixture(scope="module")
def jkr_fit():
    """A fit whose data do not determine z0 (the note is drawn)."""
    R = np.array([2e-6, 4e-6, 8e-6])
    F = inv.pull_off_force(R, E, 1.0, Z0) * (1 + 0.02 * np.random.default_rng(3).standard_normal(3))
    out = inv.fit_pull_off(R, F, E, bootstrap=0)
    assert not out.identifiable
    return out


def _friction_case():
    R, tau = 100e-9, 2e7
    loads = np.array([-1.0, 0.0, 1.0, 2.0, 4.0])
    cyl = lc.Cylinder.from_modulus(R, E, work_of_adhesion=W, equilibrium_spacing=Z0)
    f = 2 * cyl.contact(load=loads).contact_half_width * tau
    f = f * (1 + 0.05 * np.random.default_rng(1).standard_normal(f.size))
    t = inv.shear_strength_from_friction(f, loads, R, E, W, Z0)
    models = {
        name: inv.shear_strength_from_friction(f, loads, R, E, W, Z0, contact=c)
        for name, c in (("JKR", "jkr"), ("DMT", "dmt"))
    }
    return loads, f, t, np.array([0.9 * t, 1.1 * t]), models


def _lines(ax, text):
    return [ln for ln in ax.get_lines() if text in str(ln.get_label())]


def _points(ax, text):
    """The data line of the error-bar container labelled with ``text``."""
    return [c.lines[0] for c in ax.containers if text in str(c.get_label())]


def _clips_nothing(fig):
    box = fig.get_tightbbox(fig.canvas.get_renderer())
    w, h = fig.get_size_inches()
    assert box.x0 >= -0.02 and box.y0 >= -0.02 and box.x1 <= w + 0.02 and box.y1 <= h + 0.02


@pytest.mark.parametrize("which", ["fit", "fixed_fit", "jkr_fit"])
def test_adhesion_fit_layout_clips_nothing(which, request):
    _clips_nothing(fit_figs._adhesion_figure(request.getfixturevalue(which), Run(figs.MIN_SIZE)))


def test_friction_fit_layout_clips_nothing():
    loads, f, t, ci, models = _friction_case()
    lo, hi = ci
    models = {**models, "Hertz": t * 1.3}
    fig = fit_figs._friction_figure(Run(figs.MIN_SIZE), loads, f, t, lo, hi, models, 0.05 * f)
    _clips_nothing(fig)


def test_the_curves_are_the_api_curves(fit):
    ax = fit_figs._adhesion_figure(fit, Run()).axes[0]
    w, z0 = fit.work_of_adhesion, fit.equilibrium_spacing
    (md,) = _lines(ax, "Maugis")
    R = md.get_xdata()
    assert R[0] == pytest.approx(0.5 * RADII[0]) and R[-1] == pytest.approx(2 * RADII[-1])
    assert_allclose(md.get_ydata(), -inv.pull_off_force(R, E, w, z0), rtol=1e-14)
    (jkr,) = _lines(ax, "JKR")
    assert_allclose(jkr.get_ydata(), -inv.jkr_pull_off_force(R, E, w), rtol=1e-14)
    (dmt,) = _lines(ax, "DMT")
    assert_allclose(dmt.get_ydata(), -inv.dmt_pull_off_force(R, w, z0), rtol=1e-14)
    assert jkr.get_linestyle() == "--" and dmt.get_linestyle() != "-"
    # the data points: |F| at the radii
    (data,) = _points(ax, "data")
    assert_allclose(data.get_xdata(), RADII)
    assert_allclose(data.get_ydata(), np.abs(fit.pull_off_force))
    (bars,) = next(c for c in ax.containers if "data" in str(c.get_label())).lines[2]
    ends = np.array([seg[:, 1] for seg in bars.get_segments()])
    assert_allclose(ends[:, 1] - ends[:, 0], 2 * fit.sd, rtol=1e-12)
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    assert "51.75 GPa" in ax.get_title()
    text = "\n".join(t.get_text() for t in ax.texts)
    assert f"{w:.4g}" in text and f"{z0 * 1e9:.4g} nm" in text


def test_the_band_holds_the_fitted_curve_and_widens_with_the_uncertainty(fit):
    R = np.geomspace(0.5 * RADII[0], 2 * RADII[-1], 50)
    lo, hi = fit_figs._band(fit, R)
    mid = np.abs(inv.pull_off_force(R, E, fit.work_of_adhesion, fit.equilibrium_spacing))
    assert np.all(lo < mid) and np.all(mid < hi)
    # about +-1.96 sd of ln w at the JKR end, where F ~ w^(2/3)... within the sampling error
    rel = (hi - lo) / (2 * 1.96 * mid)
    assert np.all(rel < 0.2) and np.all(rel > 0.001)
    # seeded: the same band again
    lo2, hi2 = fit_figs._band(fit, R)
    assert np.array_equal(lo, lo2) and np.array_equal(hi, hi2)


def test_the_unidentifiable_fit_shows_its_note(jkr_fit):
    ax = fit_figs._adhesion_figure(jkr_fit, Run()).axes[0]
    text = " ".join(" ".join(t.get_text() for t in ax.texts).split())
    assert "do not determine z0" in text


def test_the_friction_figure_draws_the_given_numbers():
    loads, f, t, ci, models = _friction_case()
    fig = fit_figs._friction_figure(Run(), loads, f, t, ci[0], ci[1], models, None)
    ax, ax2 = fig.axes
    (pts,) = _points(ax, "each point")
    assert_allclose(pts.get_xdata(), loads)
    assert_allclose(pts.get_ydata(), t * 1e-6)
    for name, vals in models.items():
        (ln,) = _lines(ax, name)
        assert_allclose(ln.get_ydata(), vals * 1e-6)
        assert ln.get_linestyle() == "--"
    mean, (lo, hi) = fit_figs.combined_shear_strength(t, ci)
    (comb,) = _lines(ax, "combined")
    assert_allclose(comb.get_ydata(), [mean * 1e-6] * 2)
    assert lo < mean < hi and min(t) < mean < max(t)
    (meas,) = _points(ax2, "measured")
    assert_allclose(meas.get_ydata(), f)


def test_combined_shear_strength_is_the_weighted_mean():
    t, (lo, hi) = fit_figs.combined_shear_strength([1.0, 3.0], [[0.0, 2.0], [2.0, 4.0]])
    # sd 1/1.96 and 1/(1.96 * ...) : weights 1 and 1, mean 2; scatter chi2 = 2 * 1.96^2
    assert t == pytest.approx(2.0)
    se = (1 / 1.96) / np.sqrt(2) * np.sqrt(2 * 1.96**2)
    assert (hi - lo) / 2 == pytest.approx(1.96 * se)


def test_files_are_written_in_the_format_of_the_extension(tmp_path, fit):
    out = fit_figs.draw_adhesion_fit(fit, tmp_path / "fit.png")
    assert out == tmp_path / "fit.png" and out.read_bytes()[:8] == PNG
    svg = fit_figs.draw_adhesion_fit(fit, str(tmp_path / "fit.svg"))
    assert b"<svg" in svg.read_bytes()[:1000]
    loads, f, t, ci, models = _friction_case()
    out = fit_figs.draw_friction_fit(loads, f, t, ci, models, tmp_path / "tau.pdf")
    assert out.read_bytes()[:5] == b"%PDF-"
    out = fit_figs.draw_friction_fit(
        loads, f, t, ci.T, models, tmp_path / "tau.png", friction_sd=0.05 * f
    )
    assert out.read_bytes()[:8] == PNG
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "fit.png",
        "fit.svg",
        "tau.pdf",
        "tau.png",
    ]  # no temporary files left


@pytest.mark.parametrize("name", ["fit.jpg", "fit", "fit.png.txt"])
def test_a_bad_extension_is_a_value_error_naming_the_path(tmp_path, fit, name):
    path = tmp_path / name
    with pytest.raises(ValueError, match="extension") as err:
        fit_figs.draw_adhesion_fit(fit, path)
    assert str(path) in str(err.value)
    loads, f, t, ci, models = _friction_case()
    with pytest.raises(ValueError, match="extension"):
        fit_figs.draw_friction_fit(loads, f, t, ci, models, path)
    assert not any(tmp_path.iterdir())


def test_arrays_of_different_lengths_are_a_value_error(tmp_path):
    loads, f, t, ci, models = _friction_case()
    with pytest.raises(ValueError, match="friction_force"):
        fit_figs.draw_friction_fit(loads, f[:-1], t, ci, models, tmp_path / "x.png")
    with pytest.raises(ValueError, match="tau0_ci95"):
        fit_figs.draw_friction_fit(loads, f, t, ci[:, :-1], models, tmp_path / "x.png")
    with pytest.raises(ValueError, match="JKR"):
        fit_figs.draw_friction_fit(loads, f, t, ci, {"JKR": models["JKR"][:2]}, tmp_path / "x.png")


def test_importing_the_module_does_not_import_matplotlib():
    import subprocess
    import sys

    code = "import sys, linecontact.figures.fit; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
