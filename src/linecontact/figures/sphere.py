r"""Figures of the adhesive sphere (``docs/sphere.md``): load curves, adhesion map, COS alpha.

Drawn by :func:`linecontact.figures.extra_figures` (``linecontact figures``) with the
helpers of :mod:`linecontact.figures._style`; every number comes from
:mod:`linecontact.sphere` (the Maugis--Dugdale sphere, :func:`~linecontact.sphere.sphere_models`,
:func:`~linecontact.sphere.cos_alpha`) and :mod:`linecontact.closed_forms.sphere` (Hertz,
JKR, DMT). No physics is written here.

All three are in Maugis' units, in which the sphere depends on the Maugis parameter
:math:`\lambda` alone (``docs/sphere.md``: to 1e-13 for ``R/h`` from 10 to 1e9): the contact
radius :math:`A = a (K/\pi w R^2)^{1/3}` (``K = 4E/3``) and the load
:math:`\bar P = F/(\pi w R)`. Each :math:`\lambda` is drawn at ``R/h`` = :data:`R_OVER_H`
with ``sigma0/E`` from :math:`\lambda = 2 (9 (\sigma_0/E)^2 (R/h)/(16\pi))^{1/3}`
(:func:`sigma0_over_E_of_lambda`).

Figures and parameters
----------------------
sphere01_load_curves
    The load :math:`\bar P` against the contact radius :math:`A` (0 to :data:`A_MAX`) of
    the Maugis--Dugdale sphere for :math:`\lambda` in :data:`LOAD_LAMBDAS` (the contact
    branch of :func:`~linecontact.sphere.sphere_load_curve`; solid where stable under load
    control, dotted on its ``dF/da < 0`` part), with its limits dashed: Hertz
    :math:`\bar P = A^3`, JKR :math:`A^3 - \sqrt{6A^3}` (pull-off -3/2 under load control),
    DMT :math:`A^3 - 2`. Open circles: the pull-off under load control; open diamonds:
    under displacement control. The non-contact branch (at ``A = 0``) is not drawn.
sphere02_adhesion_map
    Johnson & Greenwood's map: over :math:`\lambda` (0.01 to 100, log; Tabor's
    :math:`\mu_T` on the top axis) and the compressive load :math:`\bar P` (0.01 to 1e4,
    log), the regions where Hertz, DMT and JKR give the Maugis--Dugdale contact radius
    within :data:`TOL` (5 %), each filled and hatched in its colour and edged by its
    ``TOL`` contour; light grey where none does (only Maugis--Dugdale); dotted, Johnson &
    Greenwood's bounds of the transition (:math:`\lambda` = 0.1 and 5). The errors are
    :func:`~linecontact.sphere.sphere_models`' ``radius_error_*`` on a
    :data:`MAP_N_LAMBDA` x :data:`MAP_N_LOAD` grid, one vectorised call.
sphere03_cos_alpha
    The Carpick--Ogletree--Salmeron transition parameter :math:`\alpha` against
    :math:`\lambda` (log), fitted by :func:`~linecontact.sphere.cos_alpha` to the library's
    own Maugis--Dugdale curves at each :math:`\lambda` of :data:`ALPHA_LAMBDAS` (markers;
    filled at the table of ``docs/sphere.md``, 0.01 to 100); the line joins them by a
    monotone cubic (PCHIP) in :math:`\log\lambda` (each fit takes ~0.4 s; halfway
    between the markers it departs from the fit there by 0.007 at most, measured at
    :math:`\lambda` = 1.7). Dashed grey:
    the published conversion :math:`\lambda = -0.924 \ln(1 - 1.02\alpha)` (Carpick et al.
    1999); dotted: DMT's 0 and JKR's 1, and Johnson & Greenwood's bounds.

References
----------
D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
J. Colloid Interface Sci. 150 (1992) 243--269. doi:10.1016/0021-9797(92)90285-T
K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic spheres",
J. Colloid Interface Sci. 192 (1997) 326--333. doi:10.1006/jcis.1997.4984
R. W. Carpick, D. F. Ogletree, M. Salmeron, "A general equation for fitting contact area
and friction vs load measurements", J. Colloid Interface Sci. 211 (1999) 395--400.
doi:10.1006/jcis.1998.6027
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..closed_forms.sphere import (
    LAMBDA_OVER_TABOR,
    sphere_dmt_load,
    sphere_hertz_load,
    sphere_jkr_load,
)
from ..sphere import cos_alpha, sphere_load_curve, sphere_models
from ..sphere.models import DMT_BELOW, JKR_ABOVE
from ._style import (
    _PO_KW,
    Job,
    Margins,
    Run,
    _colors,
    _legends,
    _map_axes,
    _mpl,
    _new_axes,
    _pct,
    side_legend,
)

__all__ = [
    "ALPHA_LAMBDAS",
    "ALPHA_TABLE_LAMBDAS",
    "A_MAX",
    "LOAD_LAMBDAS",
    "MAP_LAMBDA_RANGE",
    "MAP_LOAD_RANGE",
    "MAP_N_LAMBDA",
    "MAP_N_LOAD",
    "R_OVER_H",
    "STEMS",
    "TOL",
    "adhesion_map_figure",
    "alpha_data",
    "alpha_figure",
    "jobs",
    "load_curve_data",
    "load_curves_figure",
    "map_data",
    "sigma0_over_E_of_lambda",
]

#: ``R/h`` at which each Maugis parameter is computed (any gives the same figures).
R_OVER_H = 1e6
#: The Maugis parameters of the load curves (sphere01).
LOAD_LAMBDAS = (0.1, 0.5, 1.0, 2.0, 5.0)
#: The largest contact radius of sphere01, in Maugis' unit ``(pi w R^2/K)^(1/3)``.
A_MAX = 2.0
#: Points of each load curve's contact branch.
_LOAD_POINTS = 400
#: The tolerance of the adhesion map (sphere02): a model within it of Maugis--Dugdale.
TOL = 0.05
#: The map's Maugis parameters and loads ``F/(pi w R)`` (log grids): ends and sizes.
MAP_LAMBDA_RANGE = (0.01, 100.0)
MAP_LOAD_RANGE = (0.01, 1e4)
MAP_N_LAMBDA = 61
MAP_N_LOAD = 61
#: The Maugis parameters of the COS fits (sphere03); each fit takes ~0.4 s.
ALPHA_LAMBDAS = (1e-3, 0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 1e3)
#: Those of them that the alpha-lambda table of ``docs/sphere.md`` lists.
ALPHA_TABLE_LAMBDAS = (0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0)
#: The published conversion of Carpick, Ogletree & Salmeron (1999):
#: ``lambda = -_COS_C ln(1 - _COS_D alpha)``.
_COS_C, _COS_D = 0.924, 1.02

#: The file stems, in the order drawn.
STEMS = ("sphere01_load_curves", "sphere02_adhesion_map", "sphere03_cos_alpha")

_A_LABEL = r"contact radius $A = a\,(K/\pi w R^2)^{1/3}$"
_P_LABEL = r"load $\bar P = F/(\pi w R)$"
_HERTZ_KW = dict(color="k", ls="--", lw=1.2)
_JKR_KW = dict(color="#8e5bb0", ls=(0, (6, 3)), lw=1.3)
_DMT_KW = dict(color="#d9731a", ls=(0, (3, 2)), lw=1.3)
_PD_KW = dict(ls="none", marker="D", ms=7, mfc="none", mew=1.4)
_BOUND_KW = dict(color="0.45", ls=":", lw=1.0)
_MAP_COLORS = {"hertz": "#3b75af", "dmt": "#d9731a", "jkr": "#8e5bb0"}
_MAP_HATCHES = {"hertz": "\\\\\\", "dmt": "///", "jkr": "|||"}
_MAP_LABELS = {"hertz": "Hertz", "dmt": "DMT", "jkr": "JKR"}
_NONE_COLOR = "0.90"


def sigma0_over_E_of_lambda(maugis_parameter: ArrayLike, R_over_h: float = R_OVER_H) -> NDArray:
    r"""``sigma0/E`` whose sphere at ``R/h`` has the Maugis parameter :math:`\lambda`.

    :math:`\lambda = 2 (9 s^2 \rho/(16\pi))^{1/3}` solved for ``s``:
    :math:`s = \sqrt{(\lambda/2)^3\, 16\pi/(9\rho)}`.
    """
    lam = np.asarray(maugis_parameter, float)
    return np.sqrt((lam / 2) ** 3 * 16 * np.pi / (9 * R_over_h))


def _length_unit(s: ArrayLike) -> NDArray:
    r"""Maugis' unit of length over ``R`` at ``R/h = R_OVER_H``: :math:`(3\pi s/(4\rho))^{1/3}`."""
    return np.cbrt(3 * np.pi * np.asarray(s, float) / (4 * R_OVER_H))


def _margins_top(top: float) -> Margins:
    return Margins(left=0.85, right=2.75, top=top)


# --------------------------------------------------------------------------------------------
# sphere01: the load curves


def load_curve_data(lambdas: ArrayLike | None = None) -> list[dict]:
    """The contact branch of each Maugis--Dugdale load curve, in Maugis' units.

    One dict per Maugis parameter: ``lam``, ``A``, ``P`` (the branch), ``unstable``
    (``dF/da < 0``), and the pull-offs ``A_po``, ``P_po`` (load control) and ``A_pd``,
    ``P_pd`` (displacement control). ``lambdas``: default :data:`LOAD_LAMBDAS`.
    """
    out = []
    for lam in np.atleast_1d(np.asarray(LOAD_LAMBDAS if lambdas is None else lambdas, float)):
        s = float(sigma0_over_E_of_lambda(lam))
        unit, force = float(_length_unit(s)), np.pi * s  # a/R and F/(E h R) of Maugis' units
        c = sphere_load_curve(
            R_OVER_H, s, a_max_over_R=A_MAX * unit, num=_LOAD_POINTS, num_noncontact=0
        )
        po, pd = c.pulloff, c.pulloff_displacement
        out.append(
            dict(
                lam=float(lam),
                A=np.asarray(c.a_over_R, float) / unit,
                P=np.asarray(c.F_over_EhR, float) / force,
                unstable=~np.asarray(c.stable, bool),
                A_po=float(po.a_over_R_at_pulloff) / unit,
                P_po=float(po.F_pulloff_over_EhR) / force,
                A_pd=float(pd.a_over_R_at_pulloff) / unit,
                P_pd=float(pd.F_pulloff_over_EhR) / force,
            )
        )
    return out


def _limits(A: NDArray) -> dict[str, NDArray]:
    """Hertz, JKR and DMT in Maugis' units, from the closed forms (at ``lambda = 1``)."""
    s = float(sigma0_over_E_of_lambda(1.0))
    unit, force = float(_length_unit(s)), np.pi * s
    a = A * unit
    return {
        "hertz": np.asarray(sphere_hertz_load(a, R_OVER_H), float) / force,
        "jkr": np.asarray(sphere_jkr_load(a, R_OVER_H, s), float) / force,
        "dmt": np.asarray(sphere_dmt_load(a, R_OVER_H, s), float) / force,
    }


def load_curves_figure(run: Run | None = None):
    """sphere01: the Maugis--Dugdale load curves and their limits (a matplotlib Figure)."""
    run = Run() if run is None else run
    data = run.data(
        ("sphere", "load-curves"),
        load_curve_data,
        f"the sphere's load curves ({len(LOAD_LAMBDAS)} Maugis parameters)",
    )
    fig, ax = _new_axes(
        run,
        Margins(left=0.8, right=2.55),
        "Maugis-Dugdale sphere: load against contact radius, in Maugis' units ($K = 4E/3$)",
        _A_LABEL,
        _P_LABEL,
    )
    ax.axhline(0.0, color="0.3", lw=0.8)
    A = np.linspace(0.0, A_MAX, 601)
    lim = _limits(A)
    ax.plot(A, lim["hertz"], **_HERTZ_KW, zorder=4, label="Hertz")
    ax.plot(A, lim["jkr"], **_JKR_KW, zorder=4, label="JKR")
    ax.plot(A, lim["dmt"], **_DMT_KW, zorder=4, label="DMT")
    colors = _colors(len(data))
    for d, col in zip(data, colors, strict=True):
        unstable = d["unstable"]
        A_d, P_d = d["A"], d["P"]
        if unstable.any():
            k = int(np.flatnonzero(unstable)[-1])  # the load minimum closes the unstable part
            ax.plot(A_d[: k + 1], P_d[: k + 1], color=col, lw=1.8, ls=":")
            ax.plot(A_d[k:], P_d[k:], color=col, lw=1.8, label=f"lambda = {d['lam']:g}")
        else:  # pragma: no cover - every lambda drawn has an interior minimum
            ax.plot(A_d, P_d, color=col, lw=1.8, label=f"lambda = {d['lam']:g}")
        ax.plot(d["A_po"], d["P_po"], color=col, mec=col, **_PO_KW, zorder=6)
        ax.plot(d["A_pd"], d["P_pd"], color=col, mec=col, **_PD_KW, zorder=6)
    top = max(float(np.interp(A_MAX, d["A"], d["P"])) for d in data)
    ax.set_xlim(-0.02 * A_MAX, A_MAX)  # the markers at A = 0 whole
    ax.set_ylim(-2.3, top + 0.3)
    _legends(
        ax,
        r"Maugis' $\lambda$",
        colors,
        [f"{d['lam']:g}" for d in data],
        [
            ("Maugis-Dugdale", dict(color="0.2", lw=1.8)),
            ("unstable under load\ncontrol ($dF/da<0$)", dict(color="0.2", lw=1.6, ls=":")),
            (r"Hertz, $\bar P = A^3$", _HERTZ_KW),
            (r"JKR, $A^3 - \sqrt{6A^3}$", _JKR_KW),
            (r"DMT, $A^3 - 2$", _DMT_KW),
            ("pull-off, load control", dict(color="0.2", **_PO_KW)),
            ("pull-off, displacement\ncontrol", dict(color="0.2", **_PD_KW)),
        ],
    )
    return fig


# --------------------------------------------------------------------------------------------
# sphere02: the adhesion map


def map_data(
    n_lambda: int | None = None, n_load: int | None = None, tol: float = TOL
) -> dict[str, object]:
    """Each model's relative error in the contact radius on the map's grid.

    ``lam`` (``n_lambda``, default :data:`MAP_N_LAMBDA`) and ``P`` (``n_load``, default
    :data:`MAP_N_LOAD`; ``F/(pi w R)``) are the log grids; the errors ``hertz``, ``dmt``,
    ``jkr`` (``|radius_error|`` of :func:`~linecontact.sphere.sphere_models`) have the
    shape ``(n_lambda, n_load)``.
    """
    lam = np.geomspace(*MAP_LAMBDA_RANGE, MAP_N_LAMBDA if n_lambda is None else n_lambda)
    P = np.geomspace(*MAP_LOAD_RANGE, MAP_N_LOAD if n_load is None else n_load)
    s = sigma0_over_E_of_lambda(lam)[:, None]
    m = sphere_models(P[None, :] * np.pi * s, R_OVER_H, s)
    out: dict[str, object] = {"lam": lam, "P": P, "tol": float(tol)}
    for name in _MAP_COLORS:
        out[name] = np.abs(np.asarray(getattr(m, f"radius_error_{name}"), float))
    return out


def adhesion_map_figure(run: Run | None = None, *, tol: float = TOL):
    """sphere02: the sphere's adhesion map (a matplotlib Figure)."""
    from matplotlib import rc_context
    from matplotlib.patches import Patch

    Line2D = _mpl()[2]
    run = Run() if run is None else run
    d = run.data(("sphere", "map", tol), lambda: map_data(tol=tol), "the sphere's adhesion map")
    lam, P = d["lam"], d["P"]
    X, Y = np.meshgrid(lam, P, indexing="ij")
    fig, ax = _map_axes(
        run,
        _margins_top(0.75),
        f"adhesion map of the sphere: models within {_pct(tol)} of the Maugis-Dugdale "
        "contact radius",
        r"Maugis parameter $\lambda$",
        r"load $\bar P = F/(\pi w R)$ (compressive)",
        lam,
        P,
    )
    handles: list = []
    labels: list[str] = []
    errors = np.stack([d[name] for name in _MAP_COLORS])
    best = np.min(np.where(np.isfinite(errors), errors, np.inf), axis=0)
    if np.any(best > tol):
        none = ax.contourf(
            X, Y, np.minimum(best, 1e3), levels=[tol, 1e3], colors=[_NONE_COLOR], zorder=0.5
        )
        none.set_gid("region-none")
        handles.append(Patch(facecolor=_NONE_COLOR, edgecolor="none"))
        labels.append("none: only\nMaugis-Dugdale")
    for name, color in _MAP_COLORS.items():
        err = np.where(np.isfinite(d[name]), d[name], 1e3)
        if not np.any(err <= tol):
            continue  # no region: neither drawn nor keyed
        with rc_context({"hatch.color": color, "hatch.linewidth": 0.8}):
            region = ax.contourf(
                X,
                Y,
                err,
                levels=[-1.0, tol],
                colors=[color],
                alpha=0.25,
                hatches=[_MAP_HATCHES[name]],
                zorder=1,
            )
        region.set_gid(f"region-{name}")
        edge = ax.contour(X, Y, err, levels=[tol], colors=[color], linewidths=1.6, zorder=2)
        edge.set_gid(f"edge-{name}")
        handles.append(
            Patch(facecolor=color, alpha=0.4, hatch=_MAP_HATCHES[name], edgecolor=color, lw=0)
        )
        labels.append(_MAP_LABELS[name])
    for bound in (DMT_BELOW, JKR_ABOVE):
        ax.axvline(bound, **_BOUND_KW, zorder=3)
    handles.append(Line2D([], [], **_BOUND_KW))
    labels.append(
        f"Johnson-Greenwood:\nDMT below $\\lambda$ = {DMT_BELOW:g},\nJKR above {JKR_ABOVE:g}"
    )
    side_legend(ax, handles, labels, f"error in $a$ within {_pct(tol)}")
    c = LAMBDA_OVER_TABOR
    top = ax.secondary_xaxis("top", functions=(lambda v: v / c, lambda u: c * u))
    top.set_xlabel(r"Tabor's $\mu_T$ (matched Lennard-Jones law) $= \lambda/1.157$", fontsize=10)
    top.tick_params(labelsize=9)
    return fig


# --------------------------------------------------------------------------------------------
# sphere03: alpha against lambda


def alpha_data(lambdas: ArrayLike | None = None) -> dict[str, NDArray]:
    """``lam`` and the COS ``alpha`` fitted at each (:func:`~linecontact.sphere.cos_alpha`).

    ``lambdas``: default :data:`ALPHA_LAMBDAS`.
    """
    lam = np.asarray(ALPHA_LAMBDAS if lambdas is None else lambdas, float)
    return {"lam": lam, "alpha": np.asarray(cos_alpha(lam), float)}


def alpha_figure(run: Run | None = None):
    """sphere03: the COS alpha against the Maugis parameter (a matplotlib Figure)."""
    from scipy.interpolate import PchipInterpolator  # imported where used: a slow import

    run = Run() if run is None else run
    d = run.data(
        ("sphere", "alpha"),
        alpha_data,
        f"the COS alpha ({len(ALPHA_LAMBDAS)} fits to Maugis-Dugdale curves)",
    )
    lam, alpha = d["lam"], d["alpha"]
    fig, ax = _new_axes(
        run,
        Margins(left=0.8, right=2.75),
        "Carpick-Ogletree-Salmeron $\\alpha$ fitted to the library's Maugis-Dugdale curves",
        r"Maugis parameter $\lambda$",
        r"COS transition parameter $\alpha$",
    )
    ax.set_xscale("log")
    x = np.geomspace(lam[0], lam[-1], 400)
    line = PchipInterpolator(np.log(lam), alpha)(np.log(x))
    color = _colors(1)[0]
    ax.plot(x, line, color=color, lw=2.0, label="fitted (PCHIP in $\\log\\lambda$)")
    table = np.isin(lam, ALPHA_TABLE_LAMBDAS)
    ax.plot(
        lam[table],
        alpha[table],
        ls="none",
        marker="o",
        ms=6.5,
        color=color,
        mec="k",
        mew=0.6,
        zorder=5,
        label="fits: the table of\ndocs/sphere.md",
    )
    if np.any(~table):
        ax.plot(
            lam[~table],
            alpha[~table],
            ls="none",
            marker="o",
            ms=6.5,
            mfc="white",
            mec=color,
            mew=1.4,
            zorder=5,
            label="fits beyond the table",
        )
    published = (1 - np.exp(-x / _COS_C)) / _COS_D
    ax.plot(
        x,
        published,
        color="0.45",
        ls="--",
        lw=1.3,
        label="$\\lambda = -0.924\\ln(1 - 1.02\\alpha)$\n(Carpick et al. 1999)",
    )
    ax.axhline(0.0, color="#d9731a", ls=":", lw=1.2, label=r"DMT, $\alpha = 0$")
    ax.axhline(1.0, color="#8e5bb0", ls=":", lw=1.2, label=r"JKR, $\alpha = 1$")
    bounds = f"Johnson-Greenwood bounds\n($\\lambda$ = {DMT_BELOW:g}, {JKR_ABOVE:g})"
    ax.axvline(DMT_BELOW, **_BOUND_KW, label=bounds)
    ax.axvline(JKR_ABOVE, **_BOUND_KW, label="_" + bounds)  # one legend entry for both
    ax.set_xlim(lam[0] / 1.4, lam[-1] * 1.4)  # the end markers whole
    ax.set_ylim(-0.04, 1.06)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9, frameon=False)
    return fig


def jobs() -> list[Job]:
    """The sphere's figures (costs measured on a 2-core machine, s)."""
    return [
        Job(STEMS[0], load_curves_figure, "sphere-curves", 1.3),
        Job(STEMS[1], adhesion_map_figure, "sphere-map", 1.9),
        Job(STEMS[2], alpha_figure, "sphere-alpha", 4.2),
    ]
