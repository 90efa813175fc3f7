"""The figure of a bent wire's fit (issue 35): the drawn data are the fit's numbers; the text
says f and its intervals in nN/um; the layout clips nothing; the format follows the
extension; the gallery example runs.

matplotlib is needed (the ``plot`` extra, part of ``test``).
"""

from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from numpy.polynomial import chebyshev as C
from numpy.testing import assert_allclose

pytest.importorskip("matplotlib")

import linecontact.figures as figs  # noqa: E402
from linecontact.bent_wire import dragged_wire, fit_bent_wire  # noqa: E402
from linecontact.errors import ParameterError  # noqa: E402
from linecontact.figures import bent_wire as bw_figs  # noqa: E402
from linecontact.figures._style import DEFAULT_SIZE, DPI, Run  # noqa: E402

EI = 140e9 * math.pi * (50e-9) ** 4 / 4  # a ZnO wire of 100 nm diameter [N m^2]
HALF = 2.5e-6  # m
F_TRUE = 12e-3  # N/m
PNG = b"\x89PNG\r\n\x1a\n"
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _profile(f=F_TRUE, n=120, noise=3e-9, angle=0.4, shift=(3e-6, 1e-6), seed=0):
    """``n`` points at equal arc lengths along the model wire, turned, moved, noisy [m]."""
    w = dragged_wire(f * HALF**3 / EI)
    t = 2 * w.u - 1
    cx, cy = (C.chebfit(t, v, w.nodes) for v in (w.x_over_l, w.y_over_l))
    s = np.linspace(-1.0, 1.0, n)
    x = np.sign(s) * C.chebval(2 * np.abs(s) - 1, cx) * HALF
    y = C.chebval(2 * np.abs(s) - 1, cy) * HALF
    c, sn = math.cos(angle), math.sin(angle)
    rng = np.random.default_rng(seed)
    X = c * x - sn * y + shift[0] + noise * rng.standard_normal(n)
    Y = sn * x + c * y + shift[1] + noise * rng.standard_normal(n)
    return X, Y


@pytest.fixture(scope="module")
def fit():
    return fit_bent_wire(*_profile(f=0.2), EI, bootstrap=40, seed=1)


@pytest.fixture(scope="module")
def straight():
    """A wire too little bent for its noise: the data do not determine f (the note)."""
    out = fit_bent_wire(*_profile(f=0.0, noise=5e-9), EI, bootstrap=0)
    assert not out.determined and out.note
    return out


def _line(ax, text):
    (ln,) = [ln for ln in ax.get_lines() if text in str(ln.get_label())]
    return ln


def _text(ax) -> str:
    return "\n".join(t.get_text() for t in ax.texts)


def _wire_frame(fit, x, y):
    """The points [m] in the wire's frame, written here: turned about the fitted midpoint so
    that the axis (cos, sin of axis_angle) is the first coordinate and the drag (of
    drag_angle) the second (a 2-by-2 matrix whose rows are the two directions)."""
    rows = np.array(
        [
            [np.cos(fit.axis_angle), np.sin(fit.axis_angle)],
            [np.cos(fit.drag_angle), np.sin(fit.drag_angle)],
        ]
    )
    along, across = rows @ (np.stack([x, y]) - np.array(fit.midpoint)[:, None])
    return along, across


def _scale_factor(fig, ax):
    """The axes' data spans per inch, along over across, from the drawn figure."""
    fig.canvas.draw()
    box = ax.get_window_extent()  # pixels
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    return ((x1 - x0) / box.width) / ((y1 - y0) / box.height)


def test_the_profile_panel_draws_the_fit_in_the_wires_frame(fit):
    fig = bw_figs.bent_wire_fit(fit)
    ax, ax2 = fig.axes
    pts = _line(ax, "profile")
    along, across = _wire_frame(fit, fit.x, fit.y)
    assert_allclose(pts.get_xdata(), along * 1e9, rtol=1e-12, atol=1e-9)
    assert_allclose(pts.get_ydata(), across * 1e9, rtol=1e-12, atol=1e-9)
    assert pts.get_linestyle() == "None" and "120 points" in pts.get_label()
    wire = _line(ax, "fitted wire")
    c_along, c_across = _wire_frame(fit, fit.curve_x, fit.curve_y)
    assert_allclose(wire.get_xdata(), c_along * 1e9, rtol=1e-12, atol=1e-9)
    assert_allclose(wire.get_ydata(), c_across * 1e9, rtol=1e-12, atol=1e-9)
    # a rotation: the distances to the midpoint are kept
    r = np.hypot(fit.x - fit.midpoint[0], fit.y - fit.midpoint[1])
    assert_allclose(np.hypot(pts.get_xdata(), pts.get_ydata()), r * 1e9, rtol=1e-12)
    mid = _line(ax, "midpoint")
    assert_allclose(np.r_[mid.get_xdata(), mid.get_ydata()], [0.0, 0.0], atol=0)
    # the fitted wire runs from one end to the other through the midpoint, half a length
    # each way along the axis (more than its projection: the ends lag and turn)
    assert c_along[0] < 0 < c_along[-1]
    assert max(-c_along[0], c_along[-1]) <= fit.half_length
    assert np.abs(c_across).min() * 1e9 < 1e-6 and c_across.max() * 1e9 < 1e-6
    # the ends drawn below the midpoint: they lag behind it, the wire bent by the drag
    for line in (pts, wire):
        ys = line.get_ydata()
        assert ys[0] < 0 and ys[-1] < 0
        assert ys[0] < -5 * fit.noise * 1e9 and ys[-1] < -5 * fit.noise * 1e9
    # independently of the fit's angles: the chord of the data's ends is drawn (nearly)
    # level, and the midpoint above the middle of the chord
    d_along = pts.get_xdata()[-1] - pts.get_xdata()[0]
    d_across = pts.get_ydata()[-1] - pts.get_ydata()[0]
    assert abs(d_across) / abs(d_along) < 0.01
    assert (pts.get_ydata()[0] + pts.get_ydata()[-1]) / 2 < 0
    # not at equal aspect: the bend (tens of nm over micrometres) is exaggerated, by the
    # factor written in the panel
    assert ax.get_aspect() == "auto"
    assert ax.get_xlabel() == "along the wire's axis [nm]"
    assert ax.get_ylabel() == "across it, towards the drag [nm]"
    (note,) = [t for t in ax.texts if t.get_gid() == "scale"]
    written = float(re.search(r"exaggerated \u00d7([0-9.]+)", note.get_text()).group(1))
    factor = _scale_factor(fig, ax)
    assert factor > 1.05
    assert written == pytest.approx(factor, rel=2e-3)


def test_a_typical_bend_fills_the_panel():
    # 12 mN/m on the ZnO wire: the ends lag by about 85 nm over 5 um, a wire that looks
    # straight at equal scales; in the wire's frame the bend spans most of the panel's height
    out = fit_bent_wire(*_profile(noise=2e-9), EI, bootstrap=0)
    fig = bw_figs.bent_wire_fit(out)
    ax = fig.axes[0]
    wire = _line(ax, "fitted wire")
    ys = wire.get_ydata()
    lag = -(ys[0] + ys[-1]) / 2  # nm
    assert 70 < lag < 100
    (y0, y1) = ax.get_ylim()
    assert lag / (y1 - y0) > 0.6
    factor = _scale_factor(fig, ax)
    assert factor > 10
    (note,) = [t for t in ax.texts if t.get_gid() == "scale"]
    written = re.fullmatch(r"transverse scale exaggerated \u00d7([0-9.]+)", note.get_text())
    assert float(written.group(1)) == pytest.approx(factor, rel=2e-3)


def test_the_drag_arrow_starts_at_the_midpoint_and_points_up(fit):
    ax = bw_figs.bent_wire_fit(fit).axes[0]
    (arrow,) = [t for t in ax.texts if t.get_gid() == "drag"]
    tail, head = np.array(arrow.xyann), np.array(arrow.xy)
    assert_allclose(tail, [0.0, 0.0], atol=0)
    d = head - tail
    assert d[0] == 0 and d[1] > 0  # +across: towards the drag
    # a fifth of the span across of what is drawn
    _, across = _wire_frame(fit, fit.x, fit.y)
    _, c_across = _wire_frame(fit, fit.curve_x, fit.curve_y)
    both = np.concatenate([across, c_across]) * 1e9
    assert d[1] == pytest.approx(bw_figs.ARROW_FRACTION * (both.max() - both.min()), rel=1e-9)
    # the arrow and the whole wire in view
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    assert y0 < both.min() and max(both.max(), d[1]) < y1
    along = np.concatenate(
        [_wire_frame(fit, fit.x, fit.y)[0], _wire_frame(fit, fit.curve_x, fit.curve_y)[0]]
    )
    assert x0 < along.min() * 1e9 and along.max() * 1e9 < x1
    assert "drag" in [t.get_text() for t in ax.texts]


def test_the_residual_panel_draws_the_fits_residuals_and_the_noise_band(fit):
    ax2 = bw_figs.bent_wire_fit(fit).axes[1]
    res = _line(ax2, "residuals")
    assert_allclose(res.get_xdata(), fit.arc_length * 1e9, rtol=1e-14)
    assert_allclose(res.get_ydata(), fit.residuals * 1e9, rtol=1e-14)
    # the residuals are the points' distances to the fitted wire: to their feet
    dist = np.hypot(fit.x - fit.fitted_x, fit.y - fit.fitted_y)
    assert_allclose(np.abs(res.get_ydata())[1:-1], dist[1:-1] * 1e9, rtol=1e-6, atol=1e-6)
    (band,) = [c for c in ax2.collections if "noise" in str(c.get_label())]
    ys = np.concatenate([p.vertices[:, 1] for p in band.get_paths()])
    assert_allclose([ys.min(), ys.max()], [-2 * fit.noise * 1e9, 2 * fit.noise * 1e9])
    xs = np.concatenate([p.vertices[:, 0] for p in band.get_paths()])
    assert_allclose([xs.min(), xs.max()], [-fit.half_length * 1e9, fit.half_length * 1e9])
    assert ax2.get_ylabel() == "residual [nm]" and "[nm]" in ax2.get_xlabel()
    # about 95 % of the points inside +-2 noises (120 points: 7 % to 100 % would be odd)
    inside = np.mean(np.abs(fit.residuals) <= 2 * fit.noise)
    assert 0.85 <= inside <= 1.0


def test_the_text_says_f_and_its_intervals_in_nN_per_um(fit):
    text = _text(bw_figs.bent_wire_fit(fit).axes[0])
    f = fit.friction_per_length * 1e3  # N/m -> nN/um
    assert f"$f$ = {f:.4g} nN/$\\mu$m (mN/m)" in text
    lo, hi = fit.friction_per_length_ci95
    assert f"covariance: [{lo * 1e3:.4g}, {hi * 1e3:.4g}]" in text
    b_lo, b_hi = fit.friction_per_length_bootstrap_ci95
    assert f"bootstrap (40 refits): [{b_lo * 1e3:.4g}, {b_hi * 1e3:.4g}]" in text
    assert f"noise {fit.noise * 1e9:.3g} nm (from the residuals)" in text
    # the unit conversion, against the truth: 0.2 N/m is 200 nN/um
    shown = float(re.search(r"\$f\$ = ([0-9.]+) nN", text).group(1))
    assert shown == pytest.approx(200.0, rel=0.02)
    assert "do not determine" not in text


def test_an_undetermined_fit_shows_its_note_and_no_bootstrap(straight):
    text = " ".join(_text(bw_figs.bent_wire_fit(straight).axes[0]).split())
    assert "do not determine f" in text
    assert "bootstrap: not drawn" in text


def test_the_units_are_those_asked(fit):
    fig = bw_figs.bent_wire_fit(fit, units="um")
    ax, ax2 = fig.axes
    along, _ = _wire_frame(fit, fit.x, fit.y)
    _, c_across = _wire_frame(fit, fit.curve_x, fit.curve_y)
    assert_allclose(_line(ax, "profile").get_xdata(), along * 1e6, rtol=1e-12, atol=1e-12)
    assert_allclose(_line(ax, "fitted wire").get_ydata(), c_across * 1e6, rtol=1e-12, atol=1e-12)
    assert ax.get_xlabel() == r"along the wire's axis [$\mu$m]"
    assert ax.get_ylabel() == r"across it, towards the drag [$\mu$m]"
    (arrow,) = [t for t in ax.texts if t.get_gid() == "drag"]
    span = np.ptp(np.concatenate([_wire_frame(fit, fit.x, fit.y)[1], c_across])) * 1e6
    assert arrow.xy[1] == pytest.approx(bw_figs.ARROW_FRACTION * span, rel=1e-9)
    assert_allclose(_line(ax2, "residuals").get_xdata(), fit.arc_length * 1e6, rtol=1e-14)
    # the residuals stay in nm
    assert_allclose(_line(ax2, "residuals").get_ydata(), fit.residuals * 1e9, rtol=1e-14)
    assert r"[$\mu$m]" in ax2.get_xlabel() and ax2.get_ylabel() == "residual [nm]"


@pytest.mark.parametrize("units", ["mm", "NM", "", None, ("nm",)])
def test_bad_units_are_a_parameter_error_naming_them(tmp_path, fit, units):
    with pytest.raises(ParameterError, match="units must be one of nm, um, m") as err:
        bw_figs.bent_wire_fit(fit, tmp_path / "x.png", units=units)
    assert err.value.parameter == "units"
    assert not any(tmp_path.iterdir())


def _clips_nothing(fig):
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    box = fig.get_tightbbox(r)
    w, h = fig.get_size_inches()
    assert box.x0 >= -0.02 and box.y0 >= -0.02 and box.x1 <= w + 0.02 and box.y1 <= h + 0.02
    W, H = fig.canvas.get_width_height()
    for ax in fig.axes:
        texts = [*ax.texts, ax.title, ax.xaxis.label, ax.yaxis.label]
        legend = ax.get_legend()
        texts += legend.get_texts() if legend else []
        for t in texts:
            if t.get_visible() and t.get_text().strip():
                b = t.get_window_extent(r)
                assert b.x0 >= -1 and b.y0 >= -1 and b.x1 <= W + 1 and b.y1 <= H + 1, t


@pytest.mark.parametrize("which", ["fit", "straight"])
@pytest.mark.parametrize("size", [figs.MIN_SIZE, DEFAULT_SIZE])
def test_the_layout_clips_nothing(which, size, request):
    fig = bw_figs._figure(request.getfixturevalue(which), Run(size))
    _clips_nothing(fig)


def test_a_strongly_bent_wire_in_um_clips_nothing():
    out = fit_bent_wire(*_profile(f=0.4, angle=-2.0), EI, bootstrap=0)
    fig = bw_figs.bent_wire_fit(out, units="um", size=figs.MIN_SIZE)
    _clips_nothing(fig)
    # the whole wire and the arrow are in view, in the wire's frame
    ax = fig.axes[0]
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    (arrow,) = [t for t in ax.texts if t.get_gid() == "drag"]
    along, across = _wire_frame(out, out.x, out.y)
    for px, py in [*zip(along * 1e6, across * 1e6, strict=True), arrow.xy]:
        assert x0 <= px <= x1 and y0 <= py <= y1
    # bent so far the ends lag by more than a third of the half-length: still drawn below
    # the midpoint, and the note's factor is that of the axes
    assert across[0] < -out.half_length / 3 and across[-1] < -out.half_length / 3
    (note,) = [t for t in ax.texts if t.get_gid() == "scale"]
    factor = _scale_factor(fig, ax)
    m = re.search(r"\u00d7([0-9.]+)", note.get_text())
    if m is None:
        assert note.get_text() == "equal scales along and across"
        assert abs(math.log(factor)) < math.log(1.05) + 1e-3
    elif "exaggerated" in note.get_text():
        assert float(m.group(1)) == pytest.approx(factor, rel=2e-3)
    else:
        assert float(m.group(1)) == pytest.approx(factor, rel=1e-2)


def test_the_default_size_and_every_legend_entry_drawn_with_data(fit):
    fig = bw_figs.bent_wire_fit(fit)
    assert tuple(fig.get_size_inches()) == pytest.approx(DEFAULT_SIZE) and fig.dpi == DPI
    n = 0
    for ax in fig.axes:
        drawn = {a.get_label(): a for a in [*ax.lines, *ax.collections]}
        for t in ax.get_legend().get_texts():
            n += 1
            artist = drawn[t.get_text()]
            xy = (
                artist.get_xydata()
                if hasattr(artist, "get_xydata")
                else np.concatenate([p.vertices for p in artist.get_paths()])
            )
            assert np.isfinite(xy).all() and len(xy)
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            assert "[" in label and "]" in label
    assert n == 5


def test_files_are_written_in_the_format_of_the_extension(tmp_path, fit):
    # the call of the operation's --plot FILE: positional (fit, path)
    out = bw_figs.bent_wire_fit(fit, tmp_path / "wire.png")
    assert out == tmp_path / "wire.png" and out.read_bytes()[:8] == PNG
    svg = bw_figs.bent_wire_fit(fit, str(tmp_path / "wire.svg"), units="um")
    assert svg == tmp_path / "wire.svg" and b"<svg" in svg.read_bytes()[:1000]
    assert b"linecontact" in svg.read_bytes()  # the version stamp
    # the extension's case is ignored, and the file is named by its format (as the fit
    # figures of linecontact.figures.fit name theirs): the path returned is the one written
    pdf = bw_figs.bent_wire_fit(fit, tmp_path / "wire.PDF")
    assert pdf == tmp_path / "wire.pdf" and pdf.read_bytes()[:5] == b"%PDF-"
    # no temporary files left
    assert sorted(p.name for p in tmp_path.iterdir()) == ["wire.pdf", "wire.png", "wire.svg"]


@pytest.mark.parametrize("name", ["wire.jpg", "wire", "wire.png.txt"])
def test_a_bad_extension_is_a_value_error_naming_the_path(tmp_path, fit, name):
    path = tmp_path / name
    with pytest.raises(ValueError, match="extension") as err:
        bw_figs.bent_wire_fit(fit, path)
    assert str(path) in str(err.value)
    assert not any(tmp_path.iterdir())


@pytest.mark.parametrize("module", ["linecontact.bent_wire", "linecontact.figures.bent_wire"])
def test_importing_does_not_import_matplotlib(module):
    code = f"import sys, {module}; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


@pytest.mark.skipif(not EXAMPLES.is_dir(), reason="examples/ is not beside tests/")
def test_the_gallery_example_runs_and_recovers_f(tmp_path):
    p = subprocess.run(
        [sys.executable, str(EXAMPLES / "bent_wire_fit.py"), "fig.png"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=120,
    )
    assert p.returncode == 0 and "Traceback" not in p.stderr, p.stderr
    out = p.stdout
    f = float(re.search(r"  f = ([0-9.]+) nN/um", out).group(1))
    lo, hi = (float(v) for v in re.search(r"covariance: \[([0-9.]+), ([0-9.]+)\]", out).groups())
    assert lo < f < hi and lo <= 12.0 <= hi and abs(f / 12 - 1) < 0.05
    assert "truth 12" in out and "bootstrap (200 refits)" in out
    lines = (tmp_path / "profile.csv").read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("# synthetic:") and lines[1] == "x_nm,y_nm"
    assert len(lines) == 2 + 250
    assert (tmp_path / "fig.png").read_bytes()[:8] == PNG


def test_the_held_wire_draws_its_normal_friction_with_its_band():
    """The static case: three panels, the third f_n along the wire (nN/um) and its band."""
    import matplotlib

    matplotlib.use("Agg")
    from linecontact.bent_wire import fit_bent_wire

    s = np.linspace(-1.0, 1.0, 120)
    theta = 1.5 * s**2 * (1 - s**2 / 2)  # any smooth free-free-ish bend
    x = np.concatenate([[0.0], np.cumsum(np.cos(theta[1:]) * np.diff(s))]) * 2.5e-6
    y = np.concatenate([[0.0], np.cumsum(np.sin(theta[1:]) * np.diff(s))]) * 2.5e-6
    rng = np.random.default_rng(4)
    x, y = x + 2e-9 * rng.standard_normal(s.size), y + 2e-9 * rng.standard_normal(s.size)
    fit = fit_bent_wire(x, y, 7e-19, model="held", bootstrap=0)
    fig = bw_figs.bent_wire_fit(fit)
    try:
        axes = fig.axes
        assert len(axes) == 3
        line = next(ln for ln in axes[2].get_lines() if len(ln.get_xdata()) == 401)
        assert np.allclose(line.get_ydata(), fit.normal_friction * 1e3)
        assert np.allclose(line.get_xdata(), np.linspace(-1, 1, 401) * fit.half_length * 1e9)
        assert "f_n" in axes[2].get_ylabel()
        assert not any(t.get_gid() == "drag" for t in axes[0].texts)  # no drag: at rest
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)
