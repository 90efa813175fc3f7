"""The paper figures (Figs. 2-14): files, formats, size, layout, atomic writes, no printing,
lazy import; and the data drawn, read back from the figures' lines and compared with the API's
numbers and with the closed forms written out here. No timings."""

import math
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from numpy.testing import assert_allclose

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from matplotlib.colors import to_rgba  # noqa: E402
from matplotlib.legend import Legend  # noqa: E402
from PIL import Image  # noqa: E402  (a dependency of matplotlib)

import linecontact.figures as figs  # noqa: E402
from linecontact import (  # noqa: E402
    non_contact,
    normal_contact,
    pull_off,
    sliding_contact,
    sliding_initiation,
    sliding_pull_off,
    steady_rolling,
    zero_width_load,
)
from linecontact._version import __version__  # noqa: E402
from linecontact.figures import paper_figures  # noqa: E402
from linecontact.figures._style import Run  # noqa: E402

STEMS = (
    "fig02_load_R100",
    "fig03_load_R200",
    "fig04_zone_R100",
    "fig05_zone_R200",
    "fig06_zero_width",
    "fig07_sliding_initiation",
    "fig08_sliding_schematic",
    "fig09_zone_difference_s001",
    "fig10_zone_difference_s004",
    "fig11_moment_s001",
    "fig12_moment_s004",
    "fig13_rolling_force",
    "fig14_rolling_creep",
)
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
TAG = f"linecontact {__version__}".encode()
# two cheap figures of two groups (so that two processes draw), one of them two-panel
FEW = ("fig06_zero_width", "fig08_sliding_schematic")


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    outdir = tmp_path_factory.mktemp("figs") / "nested" / "out"  # created by paper_figures
    messages = []
    paths = paper_figures(outdir, progress=messages.append)
    return outdir, paths, messages


@pytest.fixture
def few(monkeypatch):
    """paper_figures draws only the figures FEW (the wiring is the same)."""
    jobs = [j for j in figs._jobs() if j.stem in FEW]
    # every figure of FEW must still exist: otherwise the tests below would check an empty
    # list of files against an empty list of names
    assert [j.stem for j in jobs] == list(FEW)
    monkeypatch.setattr(figs, "_jobs", lambda: jobs)
    return list(FEW)


@pytest.fixture(scope="module")
def built():
    """``built(stem)``: the figure ``stem`` at the smallest size, built in this process on
    first use (one Run, so figures of one group compute their data once)."""
    run = Run(size=figs.MIN_SIZE)
    jobs = {j.stem: j for j in figs._jobs()}
    cache = {}

    def build(stem):
        if stem not in cache:
            cache[stem] = jobs[stem].build(run)
        return cache[stem]

    return build


def png_size(path):
    with Image.open(path) as im:
        return im.size


def test_default_is_every_figure_as_png(written):
    outdir, paths, _ = written
    expected = [outdir / f"{s}.png" for s in STEMS]
    assert len(paths) == 13
    assert paths == expected
    assert sorted(p.name for p in outdir.iterdir()) == sorted(p.name for p in expected)


def test_png_files_are_png_with_the_version(written):
    _, paths, _ = written
    for p in paths:
        data = p.read_bytes()
        assert len(data) > 10_000
        assert data.startswith(PNG_SIGNATURE)
        assert TAG in data  # Creator metadata
        with Image.open(p) as im:
            assert im.info["Creator"] == TAG.decode()
            assert round(im.info["dpi"][0]) == 150
        assert png_size(p) == (1440, 810)  # every figure, the two-panel Fig. 8 too


def test_progress_instead_of_printing(written, capsys):
    _, _, messages = written
    assert messages and all(isinstance(m, str) for m in messages)
    for stem in STEMS:  # also those drawn by the second process
        assert any(stem in m for m in messages), stem
    assert messages[-1].startswith("wrote 13 files")
    out = capsys.readouterr()
    assert out.out == "" and out.err == ""


def test_every_format_and_the_size(tmp_path, few):
    paths = paper_figures(tmp_path, formats=("PNG", "svg", ".pdf", "png"), size=(12, 6))
    assert [p.name for p in paths] == [
        "fig06_zero_width.png",
        "fig06_zero_width.svg",
        "fig06_zero_width.pdf",
        "fig08_sliding_schematic.png",
        "fig08_sliding_schematic.svg",
        "fig08_sliding_schematic.pdf",
    ]
    assert all(p.parent == tmp_path for p in paths)
    for p in paths:
        data = p.read_bytes()
        assert TAG in data, p
        if p.suffix == ".png":
            assert png_size(p) == (1800, 900)
        elif p.suffix == ".svg":
            root = ET.fromstring(data)
            assert root.tag.endswith("svg")
            assert root.get("width") == "864pt"  # 12 in
        else:
            assert data.startswith(b"%PDF-") and data.rstrip().endswith(b"%%EOF")
    assert sorted(tmp_path.iterdir()) == sorted(paths)  # no temporary files left


def test_one_process_writes_the_same_files(tmp_path, few):
    one = paper_figures(tmp_path / "one", processes=1)
    two = paper_figures(tmp_path / "two", processes=2)
    names = ["fig06_zero_width.png", "fig08_sliding_schematic.png"]
    assert [p.name for p in one] == [p.name for p in two] == names
    for a, b in zip(one, two, strict=True):
        assert a.read_bytes() == b.read_bytes()


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(formats=()), "formats"),
        (dict(formats=("png", "jpg")), "unknown format 'jpg'"),
        (dict(formats="eps"), "unknown format 'eps'"),
        (dict(size=(3, 2)), "size"),
        (dict(size=(9.6, 5.0)), "size"),
        (dict(size=(9.6, float("nan"))), "size"),
        (dict(size="9.6x5.4"), "size"),
        (dict(processes=0), "processes"),
    ],
)
def test_bad_arguments_rejected_before_anything_is_written(tmp_path, kwargs, match):
    with pytest.raises(ValueError, match=match):
        paper_figures(tmp_path / "out", **kwargs)
    assert not (tmp_path / "out").exists()


def test_a_failed_write_leaves_no_partial_file(tmp_path, few, monkeypatch):
    target = tmp_path / f"{few[0]}.png"
    target.write_bytes(b"old")

    def broken(fig, fh, tag):
        fh.write(b"partial")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(figs._style, "_write_png", broken)
    with pytest.raises(OSError, match="No space left"):
        paper_figures(tmp_path, processes=1)
    assert [p.name for p in tmp_path.iterdir()] == [target.name]
    assert target.read_bytes() == b"old"


def test_a_failure_in_the_second_process_is_raised_here(tmp_path, few, monkeypatch):
    drawn_there = figs._share(figs._jobs(), 2)[1][0].stem

    def fail_there(fig, out, stem, fmts):
        if stem == drawn_there:
            raise RuntimeError("boom in the worker")
        return [out / f"{stem}.png"]

    monkeypatch.setattr(figs, "_save", fail_there)
    with pytest.raises(RuntimeError, match="boom in the worker"):
        paper_figures(tmp_path, processes=2)


def test_fixed_layout_clips_nothing(built):
    """The margins (inches) leave room for every title, label and legend at the smallest
    accepted size (so at the default size too: the fonts do not change with the size)."""
    jobs = figs._jobs()
    assert [j.stem for j in jobs] == list(STEMS)
    for job in jobs:
        fig = built(job.stem)
        renderer = fig.canvas.get_renderer()
        box = fig.get_tightbbox(renderer)  # inches
        w, h = fig.get_size_inches()
        tol = 0.02
        assert box.x0 >= -tol and box.y0 >= -tol, (job.stem, box)
        assert box.x1 <= w + tol and box.y1 <= h + tol, (job.stem, box)


def test_import_does_not_load_matplotlib():
    code = "import sys, linecontact, linecontact.figures; assert 'matplotlib' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True)


def test_missing_matplotlib_message(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(ImportError, match=r"pip install 'linecontact\[plot\]'"):
        paper_figures(tmp_path)


def test_a_worker_that_dies_is_reported(tmp_path, few, monkeypatch):
    import os

    drawn_there = figs._share(figs._jobs(), 2)[1][0].stem
    real_save = figs._save

    def die_there(fig, out, stem, fmts):
        if stem == drawn_there:
            os._exit(3)
        return real_save(fig, out, stem, fmts)

    monkeypatch.setattr(figs, "_save", die_there)
    with pytest.raises(RuntimeError, match=r"stopped without a result \(exit code 3\)"):
        paper_figures(tmp_path, processes=2)


# --------------------------------------------------------------------------------------------
# the data drawn: each figure's lines read back and compared with the API's numbers and with
# closed forms written out here. Curves are told apart as the reader tells them: the colour
# by the colour key (the legend of colours), the kind by the line style and marker.


def colour_key(ax):
    """The colour key of ``ax``: its labels and colours (RGBA), in order."""
    (key,) = [a for a in ax.artists if isinstance(a, Legend)]
    return {
        t.get_text(): to_rgba(h.get_color())
        for t, h in zip(key.get_texts(), key.legend_handles, strict=True)
    }


def kind(line):
    marker, ls = line.get_marker(), line.get_linestyle()
    if marker in (None, "None", ""):
        return {"-": "solid", ":": "dotted", "--": "dashed"}.get(ls, ls)
    if marker == "s":
        return "squares"
    if marker == "o":
        return "open" if str(line.get_markerfacecolor()) == "none" else "filled"
    return marker


def lines_of(ax, colour, *kinds):
    """The lines of ``colour`` and of one of ``kinds``, in the order drawn."""
    return [
        ln
        for ln in ax.get_lines()
        if np.allclose(to_rgba(ln.get_color()), colour) and kind(ln) in kinds
    ]


def one(ax, colour, k):
    found = lines_of(ax, colour, k)
    assert len(found) == 1, (colour, k, len(found))
    return found[0].get_xydata().T


def curve(ax, colour):
    """A closed-form curve drawn as a dotted (unstable) and a solid part: (x, y, dotted x,
    solid x), the parts joined (they share the point of the load minimum)."""
    parts = lines_of(ax, colour, "solid", "dotted")
    assert parts and [kind(p) for p in parts] in (["solid"], ["dotted", "solid"])
    xy = np.concatenate([p.get_xydata() for p in parts])
    x, i = np.unique(xy[:, 0], return_index=True)
    dotted = parts[0].get_xdata() if len(parts) == 2 else np.empty(0)
    return x, xy[i, 1], np.asarray(dotted), np.asarray(parts[-1].get_xdata())


def touching_zone(rho, s):
    """c/R of the touching non-contact state (central gap zero, a = 0), from its separation
    condition h = c^2/(2R) + 4 ln2 sigma0 c/(pi E) (docs/derivations.md Sec. 5), solved as a
    quadratic in C = c/R: C^2/2 + b C - 1/rho = 0, b = (4 ln2/pi) sigma0/E."""
    b = 4 * math.log(2) / math.pi * s
    return 2 / rho / (b + math.sqrt(b * b + 2 / rho))  # the positive root, no cancellation


def test_fig02_load_curves_are_the_api_numbers(built):
    rho = 100.0
    ax = built("fig02_load_R100").axes[0]
    key = colour_key(ax)
    assert list(key) == ["0 (Hertz)", "0.001", "0.005", "0.01", "0.02", "0.05", "0.1"]
    # Hertz (Eq. 13), dashed black: F/(Eh) = (pi/4) (a/R)^2 R/h
    (hertz,) = [ln for ln in ax.get_lines() if ln.get_color() == "k"]
    x, y = hertz.get_xydata().T
    assert x[0] == 0 and x[-1] == pytest.approx(0.1) and x.size > 500
    assert_allclose(y, math.pi / 4 * x**2 * rho, rtol=1e-13, atol=0)
    # JKR line contact for the largest sigma0/E (w = sigma0 h), dashed grey:
    # F = pi E a^2/(4R) - sqrt(2 pi E w a), over E h
    (jkr,) = [ln for ln in ax.get_lines() if ln.get_color() == "0.45"]
    x, y = jkr.get_xydata().T
    assert x.size > 500
    assert_allclose(y, math.pi / 4 * x**2 * rho - np.sqrt(2 * math.pi * 0.1 * rho * x), rtol=1e-12)

    for label, colour in key.items():
        a, F, dotted, solid = curve(ax, colour)
        assert a[0] == 0.0 and a[-1] == pytest.approx(0.1) and a.size > 600, label
        if label == "0 (Hertz)":
            assert_allclose(F, math.pi / 4 * a**2 * rho, rtol=1e-13, atol=0)
            assert not lines_of(ax, colour, "open"), "no pull-off without adhesion"
            continue
        s = float(label)
        msg = f"sigma0/E = {s}"
        # a -> 0: Eq. (14), which is -2 sigma0 c of the touching state, over E h
        assert F[0] == pytest.approx(zero_width_load(rho, s), rel=1e-14), msg
        assert F[0] == pytest.approx(-2 * s * touching_zone(rho, s) * rho, rel=1e-12), msg
        st = normal_contact(a[1:], rho, s)
        assert_allclose(F[1:], st.F_over_Eh, rtol=1e-12, atol=1e-14, err_msg=msg)
        # dotted exactly on the part that is unstable under load control (dF/da < 0); the
        # two parts meet at the load minimum
        if dotted.size > 2:
            assert not np.any(normal_contact(dotted[1:-1], rho, s).stable), msg
        assert np.all(normal_contact(solid[1:], rho, s).stable), msg
        po = pull_off(rho, s)
        assert (dotted.size > 0) == (po.a_over_R_at_minimum > 0), msg
        # the markers: the collocation of Eq. 9 at 15 widths, against the closed form
        xs, ys = one(ax, colour, "squares")
        assert_allclose(xs, np.linspace(0.1 / 15, 0.1, 15), rtol=1e-15)
        assert_allclose(ys, normal_contact(xs, rho, s).F_over_Eh, rtol=1e-10, err_msg=msg)
        # the pull-off circle: at the API's pull-off, the lowest point of the curve
        (xp,), (yp,) = one(ax, colour, "open")
        assert (xp, yp) == pytest.approx(
            (po.a_over_R_at_pulloff, po.F_pulloff_over_Eh), rel=1e-12, abs=0
        ), msg
        assert yp <= F.min() + 1e-12 * abs(F.min()), msg
    # the two that snap off at a width inside the plot (docstring: a/R ~ 0.02 and ~ 0.05)
    a_po = [one(ax, key[lab], "open")[0][0] for lab in ("0.05", "0.1")]
    assert a_po == pytest.approx([0.0201, 0.0512], rel=0.01)


def test_fig04_zone_curves_are_the_api_numbers(built):
    rho = 100.0
    ax = built("fig04_zone_R100").axes[0]
    key = colour_key(ax)
    assert len(key) == 7
    for label, colour in key.items():
        if label == "0 (Hertz)":
            continue
        s = float(label)
        a, c, _, _ = curve(ax, colour)
        assert a[0] == 0.0 and a.size > 600
        # a -> 0: the touching state's adhesive zone, by the quadratic solved here
        assert c[0] == pytest.approx(touching_zone(rho, s), rel=1e-12)
        assert c[0] == pytest.approx(non_contact(0.0, rho, s).c_over_R, rel=1e-14)
        assert_allclose(c[1:], normal_contact(a[1:], rho, s).c_over_R, rtol=1e-12)
        assert np.all(c[1:] > a[1:])  # the adhesive zone lies outside the contact
        xs, ys = one(ax, colour, "squares")
        assert_allclose(ys, normal_contact(xs, rho, s).c_over_R, rtol=1e-10)


def test_fig06_lines_are_eq14_and_the_markers_the_pull_off(built):
    ax = built("fig06_zero_width").axes[0]
    key = colour_key(ax)
    assert list(key) == ["10", "50", "100", "200", "500", "1000"]
    # the limit of Eq. 14 as sigma0/E -> inf, any R/h: -pi/(2 ln 2)
    (limit,) = [ln for ln in ax.get_lines() if kind(ln) == "dotted"]
    assert_allclose(limit.get_ydata(), -math.pi / (2 * math.log(2)), rtol=1e-15)
    s_mark = np.linspace(0.1 / 12, 0.1, 12)
    n_snap = 0
    for label, colour in key.items():
        rho = float(label)
        s, F = one(ax, colour, "solid")
        assert s[0] == 0 and s[-1] == pytest.approx(0.1) and s.size == 300
        assert F[0] == 0.0
        assert_allclose(F, zero_width_load(rho, s), rtol=1e-13, atol=0, err_msg=label)
        # Eq. 14 is -2 sigma0 c of the touching state
        C = np.array([touching_zone(rho, si) for si in s])
        assert_allclose(F, -2 * s * C * rho, rtol=1e-12, atol=0, err_msg=label)
        # markers: open where the API says zero-width, filled where it says snap-off
        so, Fo = one(ax, colour, "open")
        sf, Ff = one(ax, colour, "filled")
        assert_allclose(np.sort(np.concatenate([so, sf])), s_mark, rtol=1e-15)
        for ss, FF, mech in ((so, Fo, "zero-width"), (sf, Ff, "snap-off")):
            if ss.size:
                po = pull_off(rho, ss)
                assert list(po.mechanism) == [mech] * ss.size, label
                assert_allclose(FF, po.F_pulloff_over_Eh, rtol=1e-13, err_msg=label)
                # the pull-off force (the load minimum) is never above Eq. 14
                assert np.all(FF <= zero_width_load(rho, ss) * (1 - 1e-15)), label
                if mech == "snap-off":
                    assert np.all(FF < zero_width_load(rho, ss)), label
        n_snap += sf.size
    assert 0 < n_snap < 6 * 12  # both kinds of marker are drawn


TAU0 = ["0.0025", "0.005", "0.01", "0.02"]


def test_fig07_sliding_initiation(built):
    ax = built("fig07_sliding_initiation").axes[0]
    key = colour_key(ax)
    assert list(key) == TAU0
    for label, colour in key.items():
        t0 = float(label)
        d, T = one(ax, colour, "solid")
        assert d[0] == 0 and d[-1] == 1 and d.size == 401
        # (T4): T/(Ea) = 2 (tau0/E) sqrt(1 - (d/a)^2), full slip 2 tau0 at d = 0, 0 at d = a
        assert_allclose(T, 2 * t0 * np.sqrt(1 - d**2), rtol=1e-13, atol=1e-18, err_msg=label)
        ref = sliding_initiation(t0, d[:-1], on_failure="report")  # d = 0: full slip
        assert_allclose(T[:-1], ref.T_over_Ea, rtol=1e-12)
        dc, Tc = one(ax, colour, "squares")
        assert dc.size == 13
        assert_allclose(Tc, 2 * t0 * np.sqrt(1 - dc**2), rtol=1e-11, err_msg=label)
        # Cattaneo-Mindlin at the same full-slip load mu F = 2 a tau0: T = mu F (1 - (d/a)^2)
        dd, Td = one(ax, colour, "dashed")
        assert_allclose(Td, 2 * t0 * (1 - dd**2), rtol=1e-13, atol=1e-18, err_msg=label)


def test_fig13_fig14_steady_rolling(built):
    ax13 = built("fig13_rolling_force").axes[0]
    ax14 = built("fig14_rolling_creep").axes[0]
    assert list(colour_key(ax13)) == list(colour_key(ax14)) == TAU0
    for label, colour in colour_key(ax13).items():
        t0, msg = float(label), f"tau0/E = {label}"
        d, T = one(ax13, colour, "solid")
        assert d[0] == -1 and d[-1] == 1 and d.size > 450
        assert d[-2] == pytest.approx(1 - 1e-4)
        # (T13): T/(Ea) = (tau0/E) sqrt(2 (1 + d/a)): 0 at full stick, 2 tau0 at full slip
        assert_allclose(T, t0 * np.sqrt(2 * (1 + d)), rtol=1e-13, atol=1e-18, err_msg=msg)
        r = steady_rolling(t0, d[1:-1])
        assert_allclose(T[1:-1], r.T_over_Ea, rtol=1e-12, err_msg=msg)
        dc, Tc = one(ax13, colour, "squares")
        assert_allclose(Tc, t0 * np.sqrt(2 * (1 + dc)), rtol=1e-11, err_msg=msg)
        # Carter at mu F = 2 a tau0: T/(mu F) = 1 - ((1 - d/a)/2)^2 = (1 + d/a)(3 - d/a)/4,
        # the product keeping its digits near full stick
        dd, Td = one(ax13, colour, "dashed")
        assert_allclose(Td, 2 * t0 * (1 + dd) * (3 - dd) / 4, rtol=1e-13, atol=1e-18)

        d2, C = one(ax14, colour, "solid")
        assert d2[0] == -1 and C[0] == 0 and np.array_equal(d2[1:], d[1:-1])
        # (T14): creep/V = -(2/pi)(tau0/E) arccosh((3 + d/a)/(1 - d/a)), written with
        # arccosh(z) = 2 arcsinh(sqrt((z - 1)/2)) so that it keeps its digits near full stick
        expected = -4 / math.pi * t0 * creep_arcsinh(d2[1:])
        assert_allclose(C[1:], expected, rtol=1e-12, atol=1e-18, err_msg=msg)
        assert_allclose(C[1:], r.creep_over_V, rtol=1e-12, err_msg=msg)
        dc, Cc = one(ax14, colour, "squares")
        assert_allclose(Cc, -2 / math.pi * t0 * np.arccosh((3 + dc) / (1 - dc)), rtol=1e-10)
        assert_allclose(Cc, -4 / math.pi * t0 * creep_arcsinh(dc), rtol=1e-10)
        # Carter: creep/V = -(mu a/R)(1 + d/a)/2 with mu a/R = (8/pi) tau0/E
        dd, Cd = one(ax14, colour, "dashed")
        assert_allclose(Cd, -8 / math.pi * t0 * (1 + dd) / 2, rtol=1e-13, atol=1e-18)


def creep_arcsinh(d):
    """arccosh((3 + d)/(1 - d))/2 = arcsinh(sqrt((1 + d)/(1 - d)))."""
    return np.arcsinh(np.sqrt((1 + d) / (1 - d)))


H1_OVER_H2 = ["1", "1.5", "2", "3"]


@pytest.mark.parametrize(
    "stem, s, quantity",
    [
        ("fig09_zone_difference_s001", 0.01, "d"),
        ("fig11_moment_s001", 0.01, "M"),
        ("fig12_moment_s004", 0.04, "M"),
    ],
)
def test_fig09_to_12_sliding_curves_are_the_closed_form(built, stem, s, quantity):
    rho = 100.0
    ax = built(stem).axes[0]
    key = colour_key(ax)
    assert list(key) == H1_OVER_H2

    def value(st):
        if quantity == "d":
            return np.asarray(st.c1_over_R) - np.asarray(st.c2_over_R)
        return np.asarray(st.M_over_Eh2R)

    for label, colour in key.items():
        r, msg = float(label), f"{stem}, h1/h2 = {label}"
        a, y, dotted, solid = curve(ax, colour)
        assert a[0] == 0 and a[-1] == pytest.approx(0.1) and a.size > 350, msg
        st = sliding_contact(a[1:], rho, r, s, method="closed-form")
        assert_allclose(y[1:], value(st), rtol=1e-12, atol=1e-15, err_msg=msg)
        if r == 1:  # equal ranges: the symmetric normal contact, c1 = c2 and M = 0
            assert np.all(np.abs(y) <= 1e-12), msg
        else:  # the trailing zone is the wider one, the moment clockwise (docs/sliding.md)
            assert np.all(y > 0), msg
        # the a -> 0 end closes the line: the trend of the closed form at a/R = 1e-6
        tiny = value(sliding_contact(1e-6, rho, r, s, method="closed-form"))
        assert y[0] == pytest.approx(tiny, rel=1e-3, abs=1e-12), msg
        # dotted where the API says unstable under load control, solid where stable
        if dotted.size > 2:
            assert not np.any(sliding_contact(dotted[1:-1], rho, r, s, method="closed-form").stable)
        assert np.all(sliding_contact(solid[1:], rho, r, s, method="closed-form").stable), msg
        # collocation markers (the paper's route) against the closed form
        xs, ys = one(ax, colour, "squares")
        assert xs.size == 12
        col = sliding_contact(xs, rho, r, s, method="closed-form")
        assert_allclose(ys, value(col), rtol=1e-9, atol=1e-13, err_msg=msg)
        # the pull-off circle sits at the API's pull-off width, on the curve
        po = sliding_pull_off(rho, r, s)
        (xp,), (yp,) = one(ax, colour, "open")
        assert xp == pytest.approx(po.a_over_R_at_pulloff, rel=1e-12), msg
        at = sliding_contact(xp, rho, r, s, method="closed-form")
        assert yp == pytest.approx(value(at), rel=1e-10, abs=1e-14), msg
        if quantity == "M":
            # about the axis, dashed: M - e F = (w1 - w2) R, i.e. (sigma0/E)(h1/h2 - 1)
            (_, ym) = one(ax, colour, "dashed")
            assert_allclose(ym, s * (r - 1), rtol=1e-15, atol=0, err_msg=msg)
            e, F = np.asarray(st.e_over_R), np.asarray(st.F_over_Eh2)
            assert_allclose(y[1:] - e * F, s * (r - 1), rtol=1e-9, atol=1e-13, err_msg=msg)


def test_fig08_gap_meets_both_ranges(built):
    """The computed schematic: the gap (top panel) is zero in the contact and reaches h1 at
    -c1 and h2 at c2, the separation conditions (Eqs. 21, 22)."""
    ax1, ax2 = built("fig08_sliding_schematic").axes
    par = figs._sliding.SCHEMATIC
    st = sliding_contact(**par, method="closed-form")
    a, c1, c2 = st.a_over_R, st.c1_over_R, st.c2_over_R
    (gap,) = [ln for ln in ax1.get_lines() if ln.get_color() == "k"]
    x, g = gap.get_xydata().T
    assert x.size > 1500
    assert g[x == -c1] == pytest.approx(par["h1_over_h2"], rel=1e-9)
    assert g[x == c2] == pytest.approx(1.0, rel=1e-9)
    inside = np.abs(x) < a * (1 - 1e-9)
    assert inside.sum() > 300 and np.all(np.abs(g[inside]) < 1e-9)
    assert np.all(g[~inside] > -1e-12)  # the surfaces never overlap
    # bottom panel: the pressure drawn is the API's, -sigma0/E in the adhesive zones
    (p_line,) = [ln for ln in ax2.get_lines() if ln.get_color() == "k"]
    xp, p = p_line.get_xydata().T
    assert_allclose(p, st.pressure(xp), rtol=1e-13, atol=1e-15)
    zone = (np.abs(xp) > a * (1 + 1e-9)) & (xp > -c1 * (1 - 1e-9)) & (xp < c2 * (1 - 1e-9))
    assert zone.sum() > 100
    assert_allclose(p[zone], -par["sigma0_over_E"], rtol=1e-12)
