r"""The adhesion map of line contact (:mod:`linecontact.adhesion_map`), drawn.

Drawn by ``linecontact map`` (any grid, with its data file) and, on a coarse grid
(:data:`COARSE`), by :func:`linecontact.figures.push_figures` (``linecontact figures``);
every number comes from :func:`linecontact.adhesion_map.adhesion_map`.

Figure
------
adhesion_map
    Over the Maugis parameter of the matched Dugdale step (bottom axis; ``mu`` on the top
    axis) and the load above the full law's pull-off over its magnitude (both log): the
    region where each simpler model -- Hertz, the rigid cylinder, JKR, Maugis--Dugdale --
    gives the half-width of the full law's repulsive region within ``tol`` (filled and
    hatched in the model's colour), the contours of each model's error (1 %, ``tol``,
    20 %, labelled where no two labels meet), and, lightly dotted in grey, the loads where
    the full law has no repulsive region yet (the central gap above ``z0``; the error is
    not defined there). A model without a region on the map (no cell within ``tol``) is
    neither drawn nor keyed; the legend keys only what is drawn.
"""

from __future__ import annotations

import pathlib
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ..adhesion_map import (
    COARSE,
    MODELS,
    AdhesionMap,
    adhesion_map,
    default_mu,
    default_y,
    domain_mu_max,
)
from ..lennard_jones import maugis_parameter_of_mu
from ._style import DEFAULT_SIZE, Job, Margins, Run, _map_axes, _mpl, _pct, _save, side_legend

__all__ = ["COARSE", "STEM", "draw", "figure", "jobs"]

#: File stem of the figure.
STEM = "adhesion_map"
_MARGINS = Margins(left=0.85, right=2.75, top=0.75)
_LABELS = {
    "hertz": "Hertz",
    "rigid": "rigid cylinder",
    "jkr": "JKR",
    "md": "Maugis-Dugdale",
}
_COLORS = {"hertz": "#3b75af", "rigid": "#d9731a", "jkr": "#8e5bb0", "md": "#2e9a52"}
_HATCHES = {"hertz": "\\\\\\", "rigid": "///", "jkr": "|||", "md": "---"}
_OFF_SCALE = 1e3  # the error drawn where a model has no contact (its own pull-off is above)
_BAND = "0.965"  # the loads without a repulsive region: a light fill, sparsely dotted
_BAND_HATCH = "0.78"
_LABEL_SIZE = 7.0  # points, the contour labels
_LABEL_PAD = 3.0  # pixels kept free around each contour label
_LABEL_AT = (0.5, 0.3, 0.7, 0.15, 0.85)  # tried in turn: fractions of a line's length


def coarse_map(progress: Callable[[str], object] | None = None) -> AdhesionMap:
    """The map on the coarse grid :data:`COARSE`."""
    top = min(COARSE["mu_max"], domain_mu_max())
    return adhesion_map(
        default_mu(COARSE["n_mu"], COARSE["mu_min"], top),
        default_y(COARSE["n_y"], COARSE["y_max"]),
        progress=None if progress is None else (lambda msg: progress(f"adhesion map: {msg}")),
        workers=1,  # `linecontact figures` shares its figures between processes already
    )


def _levels(tol: float) -> list[float]:
    return sorted({0.01, float(tol), 0.2})


def _style(level: float, tol: float) -> str:
    """Solid at ``tol``, dotted below it, dashed above."""
    return "-" if level == tol else (":" if level < tol else "--")


def _segments(path) -> list[np.ndarray]:
    """The connected pieces of a contour path (each an (n, 2) array, n >= 2)."""
    out = []
    for piece in path.to_polygons(closed_only=False):
        if len(piece) >= 2:
            out.append(np.asarray(piece, float))
    return out


def _label_contours(ax, sets: Sequence[tuple[Any, Sequence[float]]], tol: float) -> None:
    """Label the contour sets ``(cs, levels)`` where no two labels' boxes can meet.

    Each label is kept inside a square of half-side ``r`` (half the diagonal of its
    unrotated box, plus a pad) about its centre, whatever the angle matplotlib gives it;
    a position is taken only where that square stays in the axes and off the squares
    already taken. One label at most per connected piece of line, the ``tol`` level and
    the longer pieces first, at the middle of the piece or, where that is taken, further
    along (:data:`_LABEL_AT`).
    """
    renderer = ax.figure.canvas.get_renderer()
    to_px = ax.transData
    box = ax.get_window_extent(renderer)
    taken: list[tuple[float, float, float]] = []  # centre x, y and half-side, pixels

    def half_side(text: str) -> float:
        probe = ax.text(0, 0, text, fontsize=_LABEL_SIZE)
        ext = probe.get_window_extent(renderer)
        probe.remove()
        return 0.5 * float(np.hypot(ext.width, ext.height)) + _LABEL_PAD

    for cs, shown in sets:
        positions: list[tuple[float, float]] = []
        pieces = []
        for lv, path in zip(cs.levels, cs.get_paths(), strict=True):
            if lv not in shown:
                continue
            r = half_side(_pct(lv))
            for seg in _segments(path):
                px = to_px.transform(seg)
                steps = np.hypot(*np.diff(px, axis=0).T)
                length = float(steps.sum())
                if length >= 3 * r:  # too short a piece keeps no label readably
                    pieces.append((lv, r, seg, px, np.concatenate([[0.0], np.cumsum(steps)])))
        pieces.sort(key=lambda p: (p[0] != tol, -p[4][-1]))
        for _, r, seg, px, s in pieces:
            for frac in _LABEL_AT:
                k = int(np.argmin(np.abs(s - frac * s[-1])))
                cx, cy = px[k]
                inside = box.x0 + r <= cx <= box.x1 - r and box.y0 + r <= cy <= box.y1 - r
                if inside and all(max(abs(cx - x), abs(cy - y)) > r + q for x, y, q in taken):
                    taken.append((float(cx), float(cy), r))
                    positions.append((float(seg[k, 0]), float(seg[k, 1])))
                    break
        if positions:
            ax.clabel(
                cs,
                levels=list(shown),
                fmt={lv: _pct(lv) for lv in shown},
                fontsize=_LABEL_SIZE,
                inline=True,
                manual=positions,
            )


def figure(m: AdhesionMap, run: Run):
    """The figure of the map ``m`` (a matplotlib Figure on the Agg canvas)."""
    from matplotlib import rc_context
    from matplotlib.patches import Patch

    Line2D = _mpl()[2]
    lam = np.asarray(m.maugis_parameter, float).ravel()
    y = np.asarray(m.y, float).ravel()
    if lam.size < 2 or y.size < 2:
        raise ValueError(
            f"the map needs at least two values of mu and two loads to be drawn, got "
            f"{lam.size} and {y.size}"
        )
    X, Y = np.meshgrid(lam, y, indexing="ij")
    fig, ax = _map_axes(
        run,
        _MARGINS,
        f"adhesion map of line contact: models within {_pct(m.tol)} of the Lennard-Jones "
        "law's contact half-width",
        r"Maugis parameter $\lambda$ of the matched Dugdale step",
        r"load above pull-off $(F - F_{po})/|F_{po}|$",
        lam,
        y,
    )
    handles: list = []
    labels: list[str] = []
    # the full law has no repulsive region below the onset load: no width to compare
    onset = np.asarray(m.y_onset, float).ravel()
    band_top = np.clip(onset, y[0], y[-1])
    if np.any(band_top > y[0]):
        with rc_context({"hatch.color": _BAND_HATCH, "hatch.linewidth": 0.5}):
            band = ax.fill_between(
                lam, y[0], band_top, facecolor=_BAND, edgecolor="none", hatch=".", zorder=0.5
            )
        band.set_gid("no-repulsive-region")
        handles.append(Patch(facecolor=_BAND, edgecolor=_BAND_HATCH, hatch=".", lw=0))
        labels.append("no repulsive region\n(full law's gap > $z_0$)")
    levels = _levels(m.tol)
    drawn_levels: set[float] = set()
    sets: list = []  # (contour set, its levels) whose labels are placed below
    for name in MODELS:
        if not np.any(m.agrees(name)):
            continue  # no region: neither drawn nor keyed
        err = np.asarray(m.error(name), float)
        drawn = np.where(np.isinf(err), _OFF_SCALE, err)  # NaN (no width) stays blank
        color = _COLORS[name]
        if np.any(drawn <= m.tol):
            with rc_context({"hatch.color": color, "hatch.linewidth": 0.8}):
                region = ax.contourf(
                    X,
                    Y,
                    drawn,
                    levels=[-1.0, m.tol],
                    colors=[color],
                    alpha=0.22,
                    hatches=[_HATCHES[name]],
                    zorder=1,
                )
            region.set_gid(f"region-{name}")
        finite = drawn[np.isfinite(drawn)]
        shown = [lv for lv in levels if finite.size and finite.min() < lv < finite.max()]
        if shown:
            cs = ax.contour(
                X,
                Y,
                drawn,
                levels=shown,
                colors=[color],
                linestyles=[_style(lv, m.tol) for lv in shown],
                linewidths=[1.7 if lv == m.tol else 1.0 for lv in shown],
                zorder=2,
            )
            cs.set_gid(f"error-{name}")
            sets.append((cs, shown))
            drawn_levels.update(shown)
        handles.append(
            Patch(facecolor=color, alpha=0.35, hatch=_HATCHES[name], edgecolor=color, lw=0)
        )
        labels.append(f"{_LABELS[name]}")
    _label_contours(ax, sets, m.tol)
    for lv in levels:
        if lv not in drawn_levels:
            continue
        ls = _style(lv, m.tol)
        handles.append(Line2D([], [], color="0.25", ls=ls, lw=1.7 if lv == m.tol else 1.0))
        labels.append(f"error {_pct(lv)}" + (" (tol)" if lv == m.tol else ""))
    side_legend(ax, handles, labels, f"within {_pct(m.tol)} of the full law")
    c = float(maugis_parameter_of_mu(1.0))  # lambda = c mu^(2/3)
    top = ax.secondary_xaxis(
        "top",
        functions=(lambda v: (np.maximum(v, 1e-300) / c) ** 1.5, lambda u: c * u ** (2 / 3)),
    )
    top.set_xlabel(r"$\mu = w\sqrt{R/z_0}/(E z_0)$", fontsize=10)
    top.tick_params(labelsize=9)
    return fig


def draw(
    m: AdhesionMap,
    outdir: str | pathlib.Path,
    formats: Sequence[str] = ("png",),
    size: Sequence[float] = DEFAULT_SIZE,
) -> list[pathlib.Path]:
    """Draw ``m`` into ``outdir/adhesion_map.<format>`` for each format; the paths."""
    from ._style import check_formats, check_size

    fmts = check_formats(formats)
    run = Run(size=check_size(size))
    out = pathlib.Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    return _save(figure(m, run), out, STEM, fmts)


def _coarse_figure(run: Run):
    m = run.data("adhesion-map", lambda: coarse_map(run.say), "the adhesion map (coarse grid)")
    return figure(m, run)


def jobs() -> list[Job]:
    """The adhesion map on the coarse grid."""
    return [Job(STEM, _coarse_figure, "adhesion-map", 35.0)]
