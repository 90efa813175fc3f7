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
    20 %, labelled), and in grey the loads where the full law has no repulsive region yet
    (the central gap above ``z0``; the error is not defined there).
"""

from __future__ import annotations

import pathlib
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ..adhesion_map import (
    MODELS,
    AdhesionMap,
    adhesion_map,
    default_mu,
    default_y,
    domain_mu_max,
)
from ..lennard_jones import maugis_parameter_of_mu
from ._style import DEFAULT_SIZE, Job, Margins, Run, _mpl, _new_axes, _save

__all__ = ["COARSE", "STEM", "draw", "figure", "jobs"]

#: File stem of the figure.
STEM = "adhesion_map"
#: The coarse grid of ``linecontact figures`` and ``linecontact map --quick``: ``n_mu``
#: values of ``mu`` from ``mu_min`` to ``mu_max`` (or the end of the domain, if lower: a
#: curve beyond ``mu = 1`` takes minutes), ``n_y`` loads above pull-off from 0.01 to
#: ``y_max`` pull-offs.
COARSE: dict[str, Any] = {"n_mu": 4, "mu_min": 0.01, "mu_max": 1.0, "n_y": 41, "y_max": 10.0}
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


def _pct(v: float) -> str:
    return f"{100 * v:g} %"


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
    fig, ax = _new_axes(
        run,
        _MARGINS,
        f"adhesion map of line contact: models within {_pct(m.tol)} of the Lennard-Jones "
        "law's contact half-width",
        r"Maugis parameter $\lambda$ of the matched Dugdale step",
        r"load above pull-off $(F - F_{po})/|F_{po}|$",
    )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(lam[0], lam[-1])
    ax.set_ylim(y[0], y[-1])
    handles: list = []
    labels: list[str] = []
    # the full law has no repulsive region below the onset load: no width to compare
    onset = np.asarray(m.y_onset, float).ravel()
    ax.fill_between(lam, y[0], np.clip(onset, y[0], y[-1]), color="0.82", lw=0, zorder=0.5)
    handles.append(Patch(facecolor="0.82", edgecolor="none"))
    labels.append("no repulsive region\n(full law's gap > $z_0$)")
    levels = _levels(m.tol)
    for name in MODELS:
        err = np.asarray(m.error(name), float)
        drawn = np.where(np.isinf(err), _OFF_SCALE, err)  # NaN (no width) stays blank
        color = _COLORS[name]
        if np.any(drawn <= m.tol):
            with rc_context({"hatch.color": color, "hatch.linewidth": 0.8}):
                ax.contourf(
                    X,
                    Y,
                    drawn,
                    levels=[-1.0, m.tol],
                    colors=[color],
                    alpha=0.22,
                    hatches=[_HATCHES[name]],
                    zorder=1,
                )
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
            ax.clabel(cs, fmt={lv: _pct(lv) for lv in shown}, fontsize=7, inline=True)
        handles.append(
            Patch(facecolor=color, alpha=0.35, hatch=_HATCHES[name], edgecolor=color, lw=0)
        )
        labels.append(f"{_LABELS[name]}")
    for lv in levels:
        ls = _style(lv, m.tol)
        handles.append(Line2D([], [], color="0.25", ls=ls, lw=1.7 if lv == m.tol else 1.0))
        labels.append(f"error {_pct(lv)}" + (" (tol)" if lv == m.tol else ""))
    ax.legend(
        handles,
        labels,
        title=f"within {_pct(m.tol)} of the full law",
        loc="upper left",
        bbox_to_anchor=(1.02, 1.0),
        fontsize=8.5,
        title_fontsize=9,
        frameon=False,
        borderaxespad=0.0,
    )
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
