"""The load-history figures: the plotted data are the API's numbers; the layout clips nothing.

matplotlib is needed (the ``plot`` extra, part of ``test``).
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

pytest.importorskip("matplotlib")

import linecontact as lc  # noqa: E402
import linecontact.figures as figs  # noqa: E402
from linecontact.figures import history as hist_figs  # noqa: E402
from linecontact.figures._style import Run  # noqa: E402

STEMS = [j.stem for j in hist_figs.jobs()]
T0 = hist_figs.TAU0_OVER_E


@pytest.fixture(scope="module")
def built():
    run = Run(size=figs.MIN_SIZE)
    jobs = {j.stem: j for j in hist_figs.jobs()}
    cache = {}

    def build(stem):
        if stem not in cache:
            cache[stem] = jobs[stem].build(run)
        return cache[stem]

    return build


@pytest.mark.parametrize("stem", STEMS)
def test_fixed_layout_clips_nothing(built, stem):
    fig = built(stem)
    box = fig.get_tightbbox(fig.canvas.get_renderer())
    w, h = fig.get_size_inches()
    assert box.x0 >= -0.02 and box.y0 >= -0.02 and box.x1 <= w + 0.02 and box.y1 <= h + 0.02


def test_the_loops_are_the_api_loops_and_the_markers_lie_on_them(built):
    ax = built("history01_loops").axes[0]
    lines = [ln for ln in ax.get_lines() if "W/(Ea^2)" in ln.get_label()]
    assert len(lines) == 2
    loop = lc.cyclic_loss(T0, 2 * T0 * hist_figs.AMPLITUDE).loop(201)
    assert_allclose(lines[0].get_xdata(), loop["displacement_over_a"], rtol=1e-14)
    assert_allclose(lines[0].get_ydata(), loop["T_over_Ea"], rtol=1e-14)
    # the incremental markers: on the closed-form loop (the same T, the same D)
    marks = [ln for ln in ax.get_lines() if ln.get_marker() == "s" and len(ln.get_xdata())]
    h = lc.tangential_history(T0, 2 * T0 * hist_figs.AMPLITUDE * np.r_[1, -1, 1])
    Dpeak = h.displacement_over_a[0]
    assert np.isclose(np.max(marks[0].get_xdata()), Dpeak, rtol=1e-12)


def test_the_loss_lines_are_the_api_losses(built):
    ax = built("history02_loss_amplitude").axes[0]
    lines = [ln for ln in ax.get_lines() if "slope" in ln.get_label()]
    r = lines[0].get_xdata()
    assert_allclose(lines[0].get_ydata(), lc.cyclic_loss(T0, 2 * T0 * r).W_over_Ea2, rtol=1e-14)
    mu = 8 / np.pi * T0 / 0.01
    assert_allclose(
        lines[1].get_ydata(), lc.cyclic_loss_coulomb(mu, 0.01, r).W_over_Ea2, rtol=1e-14
    )
    # log-log slopes at the small end: 4 and 3
    for ln, slope in zip(lines, (4, 3), strict=True):
        x, y = ln.get_xdata()[:2], ln.get_ydata()[:2]
        assert np.log(y[1] / y[0]) / np.log(x[1] / x[0]) == pytest.approx(slope, abs=1e-3)


def test_the_traction_after_reversals_is_the_api_traction(built):
    ax = built("history03_traction_after_reversal").axes[0]
    lines = [ln for ln in ax.get_lines() if "T_{full}" in ln.get_label()]
    x = lines[0].get_xdata()
    h = lc.tangential_history(T0, 2 * T0 * np.asarray(hist_figs.HISTORY))
    for ln, q in zip(lines, h.traction(x), strict=True):
        assert_allclose(ln.get_ydata(), q / T0, rtol=1e-14, atol=1e-15)
