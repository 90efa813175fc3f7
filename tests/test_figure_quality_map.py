"""The adhesion map figure fit to print: its size, its legend, its contour labels, its text.

On the grid of ``linecontact map --quick`` with a stand-in for the full law's curves (the
half-width ``sqrt(y)`` from an onset at ``y = 0.15``: milliseconds, not the minutes of the
real curves), where, as on the real quick map, Hertz holds nowhere; and on the same map
with Hertz given a region.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

pytest.importorskip("matplotlib")

import linecontact.adhesion_map as am  # noqa: E402
from linecontact.adhesion_map import MODELS  # noqa: E402
from linecontact.figures import adhesion_map as map_figs  # noqa: E402
from linecontact.figures._style import DEFAULT_SIZE, DPI, Run  # noqa: E402

NAMES = {"hertz": "Hertz", "rigid": "rigid cylinder", "jkr": "JKR", "md": "Maugis-Dugdale"}


@pytest.fixture(scope="module")
def quick():
    def fake_row(mu, y):
        return am._Row(-2.0, 0.15, np.sqrt(np.asarray(y, float)), 1e-9, 1e-4, 20)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(am, "_map_row", fake_row)
        g = map_figs.COARSE
        mu = am.default_mu(g["n_mu"], g["mu_min"], g["mu_max"])
        return am.adhesion_map(mu, am.default_y(g["n_y"], g["y_max"]), workers=1)


@pytest.fixture(scope="module")
def with_hertz(quick):
    """The quick map with Hertz holding at the three highest loads of every ``mu``."""
    err = np.array(quick.error_hertz, float, copy=True)
    err[:, -3:] = 0.01
    return dataclasses.replace(quick, error_hertz=err)


def _drawn(m):
    fig = map_figs.figure(m, Run())
    fig.canvas.draw()
    return fig, fig.axes[0], fig.canvas.get_renderer()


def _by_gid(ax, gid):
    return [a for a in ax.get_children() if a.get_gid() == gid]


def _has_paths(artist) -> bool:
    return any(len(p.vertices) > 0 for p in artist.get_paths())


def test_hertz_has_no_region_on_the_quick_map(quick):
    assert not np.any(quick.agrees("hertz"))
    assert any(np.any(quick.agrees(name)) for name in MODELS if name != "hertz")


def test_the_figure_is_the_common_size(quick):
    fig, _, _ = _drawn(quick)
    assert tuple(fig.get_size_inches()) == pytest.approx(DEFAULT_SIZE)
    assert fig.canvas.get_width_height() == (1440, 810)
    assert (round(DEFAULT_SIZE[0] * DPI), round(DEFAULT_SIZE[1] * DPI)) == (1440, 810)


@pytest.mark.parametrize("case", ["quick", "with_hertz"])
def test_every_legend_entry_has_data_in_the_axes(request, case):
    m = request.getfixturevalue(case)
    _, ax, _ = _drawn(m)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    for name, label in NAMES.items():
        has_cells = bool(np.any(m.agrees(name)))
        assert (label in labels) == has_cells, (name, labels)
        regions = _by_gid(ax, f"region-{name}")
        assert bool(regions) == has_cells
        if has_cells:
            assert _has_paths(regions[0])
    assert ("Hertz" in labels) == (case == "with_hertz")
    for label in labels:
        if label.startswith("no repulsive region"):
            (band,) = _by_gid(ax, "no-repulsive-region")
            assert _has_paths(band)
            assert np.any(np.asarray(m.y_onset, float) > m.y.ravel()[0])
        elif label.startswith("error "):
            level = float(label.split()[1]) / 100
            found = False
            for name in MODELS:
                for cs in _by_gid(ax, f"error-{name}"):
                    for lv, path in zip(cs.levels, cs.get_paths(), strict=True):
                        v = path.vertices
                        if lv == pytest.approx(level) and len(v) and np.isfinite(v).all():
                            found = True
            assert found, label
        else:
            assert label in NAMES.values(), label


@pytest.mark.parametrize("case", ["quick", "with_hertz"])
def test_no_two_contour_labels_meet(request, case):
    _, ax, renderer = _drawn(request.getfixturevalue(case))
    texts = [t for t in ax.texts if t.get_text().endswith("%")]
    assert len(texts) >= 3
    boxes = [t.get_window_extent(renderer) for t in texts]
    for i, a in enumerate(boxes):
        for j in range(i):
            assert not a.overlaps(boxes[j]), (texts[i].get_text(), texts[j].get_text())


@pytest.mark.parametrize("case", ["quick", "with_hertz"])
def test_no_text_leaves_the_figure(request, case):
    fig, _, renderer = _drawn(request.getfixturevalue(case))
    width, height = fig.canvas.get_width_height()
    from matplotlib.text import Text

    ax = fig.axes[0]
    axes = [ax, *ax.child_axes]  # the top axis of mu
    ticks = {id(t) for a in axes for t in [*a.get_xticklabels(), *a.get_yticklabels()]}
    boxes = [
        (t.get_text(), t.get_window_extent(renderer))
        for t in fig.findobj(Text)
        if t.get_visible() and t.get_text() and id(t) not in ticks
    ]
    # the tick labels drawn (those of ticks within the limits) with their axis
    for a in axes:
        for axis in (a.xaxis, a.yaxis):
            box = axis.get_tightbbox(renderer)
            if box is not None:  # None: nothing of it is drawn
                boxes.append((f"{axis.axis_name} axis", box))
    assert len(boxes) > 10
    for text, box in boxes:
        assert box.x0 >= -0.5 and box.y0 >= -0.5, text
        assert box.x1 <= width + 0.5 and box.y1 <= height + 0.5, text
