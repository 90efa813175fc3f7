"""The paper figures (Figs. 2-14) fit to print: one size for all, every legend entry drawn,
every text inside the figure and every axis label inside its axes, labels that name a
nondimensional group or a unit, and ``linecontact paper`` listing each file once, in figure
order. The data drawn are checked in test_figures.py."""

import re

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from matplotlib.collections import Collection  # noqa: E402
from matplotlib.colors import to_rgba  # noqa: E402
from matplotlib.legend import Legend  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.text import Text  # noqa: E402
from PIL import Image  # noqa: E402  (a dependency of matplotlib)

import linecontact.figures as figs  # noqa: E402
from linecontact.cli import main  # noqa: E402
from linecontact.figures import paper_figures  # noqa: E402
from linecontact.figures._style import Run  # noqa: E402

STEMS = [j.stem for j in figs._jobs()]
#: a line drawn without markers must span at least this many pixels to be seen
MIN_PIXELS = 2.0


@pytest.fixture(scope="module")
def built():
    """``built(stem)``: the figure ``stem`` at the default size, built in this process and
    drawn once (one Run, so figures of one group compute their data once)."""
    run = Run(size=figs.DEFAULT_SIZE)
    jobs = {j.stem: j for j in figs._jobs()}
    cache = {}

    def build(stem):
        if stem not in cache:
            fig = jobs[stem].build(run)
            fig.canvas.draw()
            cache[stem] = fig
        return cache[stem]

    return build


def test_the_figures_are_figs_2_to_14_in_order():
    assert [s[:5] for s in STEMS] == [f"fig{n:02d}" for n in range(2, 15)]


def test_every_png_has_the_common_size(tmp_path):
    paths = paper_figures(tmp_path)
    assert [p.stem for p in paths] == STEMS
    w, h = figs.DEFAULT_SIZE
    common = (round(w * figs.DPI), round(h * figs.DPI))
    assert common == (1440, 810)
    for p in paths:
        with Image.open(p) as im:
            assert im.size == common, p.name


# --------------------------------------------------------------------------------------------
# legends: every entry stands for something drawn


def _style(line):
    marker = line.get_marker()
    return line.get_linestyle(), "None" if marker in (None, "", " ", "none") else marker


def _display_points(line, ax):
    """The finite points of ``line`` in pixels, those inside the axes."""
    xy = np.asarray(line.get_xydata(), dtype=float).reshape(-1, 2)
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    if xy.size == 0:
        return xy
    pts = line.get_transform().transform(xy)
    box = ax.bbox
    tol = 1.0
    inside = (
        (pts[:, 0] >= box.x0 - tol)
        & (pts[:, 0] <= box.x1 + tol)
        & (pts[:, 1] >= box.y0 - tol)
        & (pts[:, 1] <= box.y1 + tol)
    )
    return pts[inside]


def _is_drawn(line, ax):
    """A visible line with data in the axes: a marker at a point, or a line some pixels long."""
    if not line.get_visible():
        return False
    ls, marker = _style(line)
    pts = _display_points(line, ax)
    if marker != "None" and len(pts) >= 1:
        return True
    if ls != "None" and len(pts) >= 2:
        return float(np.max(np.ptp(pts, axis=0))) >= MIN_PIXELS
    return False


def _legends(ax):
    found = [a for a in ax.artists if isinstance(a, Legend)]
    if ax.get_legend() is not None:
        found.append(ax.get_legend())
    return found


def _matches(handle, ax, colour_key):
    """Whether ``handle`` of a legend of ``ax`` stands for an artist drawn in ``ax``."""
    if isinstance(handle, Line2D):
        drawn = [ln for ln in ax.get_lines() if _is_drawn(ln, ax)]
        if colour_key:  # the colour key: a curve of that colour, of any style
            rgba = to_rgba(handle.get_color())
            return any(np.allclose(to_rgba(ln.get_color()), rgba) for ln in drawn)
        return any(_style(ln) == _style(handle) for ln in drawn)
    if isinstance(handle, Collection | Patch):
        return any(
            a.get_visible()
            and (
                (isinstance(a, Collection) and len(a.get_paths()) > 0)
                or (isinstance(a, Patch) and a.get_path().vertices.size > 0)
            )
            for a in list(ax.collections) + list(ax.patches)
        )
    return False  # pragma: no cover - a kind of handle the figures do not use


@pytest.mark.parametrize("stem", STEMS)
def test_every_legend_entry_is_drawn(built, stem):
    fig = built(stem)
    for ax in fig.axes:
        for legend in _legends(ax):
            colour_key = bool(legend.get_title().get_text())
            labels = [t.get_text() for t in legend.get_texts()]
            handles = legend.legend_handles
            assert len(handles) == len(labels) > 0, stem
            for handle, label in zip(handles, labels, strict=True):
                assert label.strip(), stem
                assert _matches(handle, ax, colour_key), f"{stem}: {label!r} is not drawn"


# --------------------------------------------------------------------------------------------
# texts and labels


@pytest.mark.parametrize("stem", STEMS)
def test_every_text_inside_the_figure(built, stem):
    fig = built(stem)
    renderer = fig.canvas.get_renderer()
    page = fig.bbox
    tol = 1.0  # pixels
    texts = [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
    for ax in fig.axes:  # tick labels only where a tick is drawn
        for axis in (ax.xaxis, ax.yaxis):
            lo, hi = sorted(axis.get_view_interval())
            texts = [
                t
                for t in texts
                if t not in axis.get_ticklabels()
                or lo - 1e-9 * (hi - lo) <= _tick_value(t, axis) <= hi + 1e-9 * (hi - lo)
            ]
    assert texts, stem
    for t in texts:
        box = t.get_window_extent(renderer)
        assert box.x0 >= page.x0 - tol and box.x1 <= page.x1 + tol, (stem, t.get_text(), box)
        assert box.y0 >= page.y0 - tol and box.y1 <= page.y1 + tol, (stem, t.get_text(), box)


def _tick_value(label, axis):
    x, y = label.get_position()
    return x if axis.axis_name == "x" else y


@pytest.mark.parametrize("stem", STEMS)
def test_axis_labels_fit_their_axes(built, stem):
    """A y-label no taller than its axes, an x-label no wider (so none runs the page)."""
    fig = built(stem)
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        frame = ax.get_window_extent(renderer)
        ylab = ax.yaxis.label.get_window_extent(renderer)
        assert ylab.height <= frame.height, (stem, ax.get_ylabel(), ylab.height, frame.height)
        if ax.get_xlabel():
            xlab = ax.xaxis.label.get_window_extent(renderer)
            assert xlab.width <= frame.width, (stem, ax.get_xlabel(), xlab.width, frame.width)


# a nondimensional group (a ratio in math text, such as $a/R$) or a unit in brackets
GROUP_OR_UNIT = re.compile(r"\$[^$]*/[^$]*\$|\[[^\]]+\]")


@pytest.mark.parametrize("stem", STEMS)
def test_axis_labels_name_a_group_or_a_unit(built, stem):
    fig = built(stem)
    bottom = min(ax.get_position().y0 for ax in fig.axes)
    for ax in fig.axes:
        labels = [ax.get_ylabel()]
        if ax.get_position().y0 <= bottom + 1e-9:  # the bottom axes carry the x-label
            labels.append(ax.get_xlabel())
        elif ax.get_xlabel():
            labels.append(ax.get_xlabel())
        for label in labels:
            assert label.strip(), (stem, "empty axis label")
            assert GROUP_OR_UNIT.search(label), (stem, label)


# --------------------------------------------------------------------------------------------
# the command


def test_cli_paper_lists_each_figure_once_in_order(capsys, tmp_path):
    assert main(["paper", "--outdir", str(tmp_path)]) == 0
    out, err = capsys.readouterr()
    lines = out.splitlines()
    assert lines[0] == f"wrote {len(STEMS)} files to {tmp_path}/:"
    assert lines[1:] == [f"  {tmp_path / s}.png" for s in STEMS]
    both = out + err
    assert both.count("wrote ") == 1  # the summary once, not also among the progress
    for stem in STEMS:  # each file listed once (progress names each figure once as well)
        assert out.count(f"{stem}.png") == 1, stem
        assert err.count(f"drawing {stem} ") == 1, stem
