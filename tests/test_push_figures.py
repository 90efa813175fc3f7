"""The pushed fibre's figures: the plotted data are the API's numbers; the layout clips nothing.

matplotlib is needed (the ``plot`` extra, part of ``test``).
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

pytest.importorskip("matplotlib")

import linecontact as lc  # noqa: E402
import linecontact.figures as figs  # noqa: E402
from linecontact.cli import main  # noqa: E402
from linecontact.figures import adhesion_map as map_figs  # noqa: E402
from linecontact.figures import history as history_figs  # noqa: E402
from linecontact.figures import push as push_figs  # noqa: E402
from linecontact.figures import sphere as sphere_figs  # noqa: E402
from linecontact.figures._style import Run  # noqa: E402


@pytest.fixture(scope="module")
def built():
    run = Run(size=figs.MIN_SIZE)
    jobs = {j.stem: j for j in push_figs.jobs()}
    cache = {}

    def build(stem):
        if stem not in cache:
            cache[stem] = jobs[stem].build(run)
        return cache[stem]

    return build


STEMS = ["push01_motion_map_hysteresis", "push02_motion_map_friction", "push03_lateral_force"]


@pytest.mark.parametrize("stem", STEMS)
def test_fixed_layout_clips_nothing(built, stem):
    fig = built(stem)
    box = fig.get_tightbbox(fig.canvas.get_renderer())
    w, h = fig.get_size_inches()
    assert box.x0 >= -0.02 and box.y0 >= -0.02 and box.x1 <= w + 0.02 and box.y1 <= h + 0.02


@pytest.mark.parametrize(("stem", "name"), [(STEMS[0], "h1_over_h2"), (STEMS[1], "tau0_over_E")])
def test_motion_maps_are_the_api_numbers(built, stem, name):
    ax = built(stem).axes[0]
    rho, r, s, tau, F = push_figs.BASE
    line = next(ln for ln in ax.get_lines() if "H^*" in ln.get_label())
    H_star, ys = line.get_xdata(), line.get_ydata()
    kw = {"h1_over_h2": r, "tau0_over_E": tau, name: ys}
    p = lc.push(rho, kw["h1_over_h2"], s, kw["tau0_over_E"], F, 1.0)
    assert_allclose(H_star, p.H_critical_over_R, rtol=1e-14)
    # the coloured regions (filled between the computed boundaries): at points between the
    # grid's heights (none on the plot's edges), the region that holds the point is the
    # API's first motion there
    fills = {
        c.get_label().removeprefix("first motion: "): c
        for c in ax.collections
        if c.get_label().startswith("first motion: ")
    }
    H = np.linspace(0.0, 2.0, 101)[:-1] + 0.01
    first = lc.push(
        rho,
        kw["h1_over_h2"][:, None] if name == "h1_over_h2" else r,
        s,
        kw["tau0_over_E"][:, None] if name == "tau0_over_E" else tau,
        F,
        H,
    ).first_motion
    Hg, Yg = np.meshgrid(H, ys)
    pts = np.column_stack([Hg.ravel(), Yg.ravel()])  # the fills' paths are in data units
    inside = {
        m: np.any([path.contains_points(pts) for path in c.get_paths()], axis=0)
        for m, c in fills.items()
    }
    # points in exactly one region (those on a boundary, within a pixel, may be in none)
    one = np.sum(list(inside.values()), axis=0) == 1
    assert one.mean() > 0.9
    drawn = np.select(list(inside.values()), list(inside), default="")
    np.testing.assert_array_equal(drawn[one], first.ravel()[one])


def test_lateral_force_rises_from_onset_to_the_steady_resistances(built):
    ax = built(STEMS[2]).axes[0]
    rho, r, s, tau, F = push_figs.BASE
    lines = {ln.get_label(): ln for ln in ax.get_lines()}
    slide = next(v for k, v in lines.items() if "slides" in k)
    roll = next(v for k, v in lines.items() if "rolls" in k)
    p = lc.push(rho, r, s, tau, F, [0.3, 1.5])
    assert p.first_motion[0] == "slide" and p.first_motion[1] == "roll"
    qs, qr = slide.get_ydata(), roll.get_ydata()
    assert qs[0] == pytest.approx(p.Q_onset_over_Eh2[0], rel=1e-9)
    assert qs[-1] == pytest.approx(p.Q_slide_over_Eh2[0], rel=1e-12)
    assert qr[0] == 0 and qr[-1] == pytest.approx(p.Q_roll_over_Eh2[1], rel=1e-12)
    assert np.all(np.diff(qs) >= 0) and np.all(np.diff(qr) >= 0)


def test_the_figures_command_writes_the_push_history_and_map_files(tmp_path, capsys, monkeypatch):
    # the adhesion map on a grid smaller still than its coarse one (its own tests are in
    # test_adhesion_map.py)
    tiny = {"n_mu": 2, "mu_min": 0.01, "mu_max": 0.02, "n_y": 5, "y_max": 1.0}
    monkeypatch.setattr(map_figs, "COARSE", tiny)
    # the sphere's figures on small grids too (their own tests: test_figures_sphere.py)
    monkeypatch.setattr(sphere_figs, "ALPHA_LAMBDAS", (0.01, 100.0))
    monkeypatch.setattr(sphere_figs, "MAP_N_LAMBDA", 4)
    monkeypatch.setattr(sphere_figs, "MAP_N_LOAD", 4)
    assert main(["figures", "--outdir", str(tmp_path)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [f"{s}.png" for s in STEMS]
        + [f"{j.stem}.png" for j in history_figs.jobs()]
        + ["adhesion_map.png"]
        + [f"{s}.png" for s in sphere_figs.STEMS]
    )
    assert main(["figures", "--outdir", str(tmp_path), "--format", "gif"]) == 2
    assert "error:" in capsys.readouterr().err
