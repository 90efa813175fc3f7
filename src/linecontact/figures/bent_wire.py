r"""The figure of a bent wire's fit (issue 35): the profile, the fitted wire, the residuals.

One figure, :func:`bent_wire_fit`, of a :class:`~linecontact.bent_wire.BentWireFit`
(:func:`linecontact.bent_wire.fit_bent_wire`; ``linecontact fit-bent-wire --plot FILE``),
drawn with the helpers of :mod:`linecontact.figures._style`. No physics is computed here:
every number drawn is one of the fit's (turned into the wire's frame, geometry only).

Top panel
    The profile's points and the fitted wire over them (``fit.x``, ``fit.y``;
    ``fit.curve_x``, ``fit.curve_y``) in the wire's frame: each point relative to the
    fitted midpoint (``fit.midpoint``), projected on the wire's axis (``fit.axis_angle``:
    *along*, the abscissa) and on the drag's direction (``fit.drag_angle``: *across*, the
    ordinate), a rotation about the midpoint (a mirror image of the profile as imaged when
    the drag is clockwise from the axis). The midpoint sits at (0, 0), the ends lag below it
    at negative *across*, and the arrow of the drag points up from it, a fifth of the
    *across* span long. The aspect is not equal: a wire bent by 85 nm over 5 µm would look
    straight at equal scales, so the transverse scale is exaggerated, by the factor written
    in the panel (the axes' data spans per inch, along over across). Beside it, the friction
    per unit length :math:`f` in nN/µm (= mN/m) with its 95 % intervals, from the covariance
    and from the bootstrap, the position noise, the half-length, the bending stiffness, and
    the fit's note when the data do not determine :math:`f`.
Bottom panel
    Each point's signed distance to the fitted wire (``fit.residuals``, nm) against its
    foot's arc length from the midpoint (``fit.arc_length``), with the band of
    :math:`\pm 2` noises (``fit.noise``): independent noise leaves about 95 % of the points
    inside it and no long runs of one sign.

matplotlib is imported only when the figure is drawn.
"""

from __future__ import annotations

import math
import os
import textwrap

import numpy as np

from ..bent_wire.fit import BentWireFit
from ..errors import ParameterError
from ._style import DEFAULT_SIZE, Margins, Run, _colors, _new_figure, check_size
from .fit import _target, _write

__all__ = ["ARROW_FRACTION", "LENGTH_UNITS", "bent_wire_fit"]

#: The display units of the profile's lengths: unit -> its size [m].
LENGTH_UNITS = {"nm": 1e-9, "um": 1e-6, "m": 1.0}
_UNIT_TEXT = {"um": r"$\mu$m"}
#: The drag arrow's length, as a fraction of the span of the top panel's data across the
#: wire (the points' and the fitted wire's).
ARROW_FRACTION = 0.2
_MARGINS = Margins(left=0.95, right=3.35)
_NM = 1e9  # m -> nm
_F = 1e3  # N/m -> nN/um (mN/m)


def _unit(units: str) -> str:
    if not isinstance(units, str) or units not in LENGTH_UNITS:
        raise ParameterError(
            "units", f"units must be one of {', '.join(LENGTH_UNITS)}, got {units!r}"
        )
    return units


def bent_wire_fit(
    fit: BentWireFit,
    path: str | os.PathLike | None = None,
    *,
    units: str = "nm",
    size=DEFAULT_SIZE,
):
    """Draw a bent wire's fit: the profile with the fitted wire over it, and the residuals.

    Parameters
    ----------
    fit : BentWireFit
        The fit (:func:`linecontact.bent_wire.fit_bent_wire`), with its data.
    path : str or os.PathLike, optional
        The file; its extension sets the format (``.png``, ``.svg``, ``.pdf``). Written
        atomically (it appears only once complete), replacing a file of that name. Without
        it the figure is returned, not written.
    units : {"nm", "um", "m"}, default "nm"
        The unit of the profile's coordinates and of the arc length; the residuals are in
        nm whatever it is.
    size : (float, float)
        Inches, between :data:`~linecontact.figures.MIN_SIZE` and
        :data:`~linecontact.figures.MAX_SIZE`.

    Returns
    -------
    pathlib.Path or matplotlib.figure.Figure
        The file written; the figure (on the Agg canvas, no pyplot) when ``path`` is None.

    Raises
    ------
    ImportError
        If matplotlib is not installed.
    ValueError
        For an extension that names no format, a size outside the accepted range, or
        ``units`` not one of those listed (a :class:`~linecontact.errors.ParameterError`).
    """
    unit = _unit(units)
    target = None if path is None else _target(path)
    fig = _figure(fit, Run(size=check_size(size)), unit)
    if target is None:
        return fig
    return _write(fig, *target)


def _interval(ci: tuple[float, float]) -> str:
    lo, hi = ci
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return "none"
    return f"[{lo * _F:.4g}, {hi * _F:.4g}]"


def _summary(fit: BentWireFit) -> str:
    """The text beside the profile: f with its intervals, the noise, the wire."""
    f = fit.friction_per_length * _F
    name = r"mean $|f_n|$" if fit.model == "held" else "$f$"
    boot = (
        f"bootstrap ({fit.bootstrap - fit.bootstrap_failed} refits): "
        + _interval(fit.friction_per_length_bootstrap_ci95)
        if fit.bootstrap
        else "bootstrap: not drawn"
    )
    noise = "given" if fit.noise_given else "from the residuals"
    lines = [
        rf"{name} = {f:.4g} nN/$\mu$m (mN/m)",
        f"   sd {fit.friction_per_length_sd * _F:.2g} (covariance)",
        "95 % intervals [nN/$\\mu$m]:",
        "   covariance: " + _interval(fit.friction_per_length_ci95),
        "   " + boot,
        f"noise {fit.noise * _NM:.3g} nm ({noise})",
        rf"half-length $l$ = {fit.half_length * 1e6:.4g} $\mu$m",
        rf"$EI$ = {fit.bending_stiffness:.3g} N m$^2$",
        rf"group $f l^3/EI$ = {fit.friction_group:.3g}",
        f"{fit.points} points, {fit.dof} degrees of freedom",
    ]
    if fit.model == "held":
        lines[-2] = rf"group mean $|f_n| l^3/EI$ = {fit.friction_group:.3g}"
        lines.append(f"{fit.modes} curvature modes")
    if not fit.determined and fit.note:
        lines += ["", *textwrap.wrap(fit.note.replace("$", r"\$"), 46)]
    return "\n".join(lines)


def _frame(fit: BentWireFit, x, y) -> tuple[np.ndarray, np.ndarray]:
    """Points in the wire's frame [m]: along its axis and across it, towards the drag."""
    dx = np.asarray(x, float) - fit.midpoint[0]
    dy = np.asarray(y, float) - fit.midpoint[1]
    a = fit.axis_angle
    d = fit.drag_angle if math.isfinite(fit.drag_angle) else a + math.pi / 2  # held: the normal
    return dx * math.cos(a) + dy * math.sin(a), dx * math.cos(d) + dy * math.sin(d)


def _exaggeration(fig, ax) -> str:
    """The note of the transverse scale: the axes' data spans per inch, along over across."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    box = ax.get_position()
    w, h = fig.get_size_inches()
    factor = ((x1 - x0) / (box.width * w)) / ((y1 - y0) / (box.height * h))
    if factor >= 1.05:
        return f"transverse scale exaggerated \u00d7{factor:.3g}"
    if factor > 1 / 1.05:
        return "equal scales along and across"
    return f"transverse scale \u00d7{factor:.2g} the axial"


def _figure(fit: BentWireFit, run: Run, unit: str = "nm"):
    k = 1.0 / LENGTH_UNITS[unit]  # m -> display
    ut = _UNIT_TEXT.get(unit, unit)
    fig = _new_figure(run, _MARGINS)
    held = fit.model == "held"
    if held:
        gs = fig.add_gridspec(3, 1, height_ratios=(2.0, 1.0, 1.0), hspace=0.55)
    else:
        gs = fig.add_gridspec(2, 1, height_ratios=(2.2, 1.0), hspace=0.42)
    ax = fig.add_subplot(gs[0])
    ax2 = fig.add_subplot(gs[1])
    panels = [ax, ax2]
    if held:
        ax3 = fig.add_subplot(gs[2])
        panels.append(ax3)
    for a in panels:
        a.grid(True, color="0.88", linewidth=0.6)
        a.tick_params(labelsize=10)
    col_fit, col_mid = _colors(2)

    # the profile, the fitted wire, the midpoint and the drag, in the wire's frame: along its
    # axis and across it towards the drag, from the midpoint
    ax.set_title(
        "static friction holding a bent wire: its curvature modes fitted"
        if held
        else "friction from the shape of a wire dragged at its midpoint: elastica fit",
        fontsize=11,
    )
    ax.set_xlabel(rf"along the wire's axis [{ut}]", fontsize=11)
    ax.set_ylabel(
        rf"across it [{ut}]" if held else rf"across it, towards the drag [{ut}]", fontsize=11
    )
    along_p, across_p = _frame(fit, fit.x, fit.y)
    along_c, across_c = _frame(fit, fit.curve_x, fit.curve_y)
    ax.plot(
        along_p * k,
        across_p * k,
        ls="none",
        marker="o",
        ms=3,
        mfc="none",
        mec="0.3",
        mew=0.7,
        label=f"profile ({fit.points} points)",
    )
    ax.plot(
        along_c * k,
        across_c * k,
        color=col_fit,
        lw=1.8,
        label="fitted wire (modes)" if held else "fitted wire (elastica)",
    )
    ax.plot(
        [0.0],
        [0.0],
        ls="none",
        marker="D",
        ms=7,
        mfc=col_mid,
        mec="k",
        zorder=5,
        label="midpoint",
    )
    if not held:  # the drag, from the midpoint
        span = float(np.ptp(np.concatenate([across_p, across_c])))
        if not span > 0:  # a wire drawn exactly straight: the arrow as long as it is
            span = 2.0 * fit.half_length
        reach = ARROW_FRACTION * span * k
        arrow = ax.annotate(
            "",
            xy=(0.0, reach),
            xytext=(0.0, 0.0),
            arrowprops=dict(arrowstyle="-|>", color="k", lw=1.4, shrinkA=0, shrinkB=0),
        )
        arrow.set_gid("drag")
        ax.annotate(
            "drag",
            xy=(0.0, reach / 2),
            xytext=(6, 0),
            textcoords="offset points",
            ha="left",
            va="center",
            fontsize=9,
        )
        ax.update_datalim([(0.0, 0.0), (0.0, reach)])
    if held:  # a wire held in its shape is bent much: drawn as it is, at equal scales
        ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    if not held:
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        ax.set_xlim(x0, x1)  # fixed: the factor below is that of these limits
        ax.set_ylim(y0, y1)
        ax.text(
            0.5,
            0.04,
            _exaggeration(fig, ax),
            transform=ax.transAxes,
            ha="center",
            va="bottom",
            fontsize=8.5,
            color="0.25",
            bbox=dict(boxstyle="round,pad=0.25", fc="white", ec="none", alpha=0.8),
        ).set_gid("scale")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8.5, frameon=False)
    # the summary beside the profile; the held wire's, taller than its panel, beside the
    # panels below it (their legends then inside them)
    ax.text(
        1.02,
        1.0 if held else 0.0,
        _summary(fit),
        transform=(ax2 if held else ax).transAxes,
        ha="left",
        va="top" if held else "bottom",
        fontsize=8,
        bbox=dict(boxstyle="round,pad=0.4", fc="white", ec="0.6", lw=0.7),
    )

    # the residuals along the wire, with the band of +-2 noises
    s = np.asarray(fit.arc_length, float) * k
    r = np.asarray(fit.residuals, float) * _NM
    two = 2.0 * fit.noise * _NM
    ends = (-fit.half_length * k, fit.half_length * k)
    ax2.fill_between(
        ends,
        [-two, -two],
        [two, two],
        color=col_fit,
        alpha=0.18,
        lw=0,
        label=rf"$\pm 2$ noise ($\pm${two:.3g} nm)",
    )
    ax2.axhline(0.0, color="0.4", lw=0.8)
    ax2.plot(s, r, ls="none", marker="o", ms=3, mfc="k", mec="k", label="residuals")
    ax2.set_xlim(*ends)
    ax2.set_xlabel(rf"arc length from the midpoint [{ut}]", fontsize=11)
    ax2.set_ylabel("residual [nm]", fontsize=11)
    if held:
        ax2.legend(loc="upper right", fontsize=7.5, framealpha=0.8, ncols=2)
    else:
        ax2.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8.5, frameon=False)
    if held:  # the friction normal to the wire along it, with its band of +-2 sd
        sd = np.linspace(ends[0], ends[1], len(fit.normal_friction))
        fn = np.asarray(fit.normal_friction) * _F
        band = 2.0 * np.asarray(fit.normal_friction_sd) * _F
        ax3.fill_between(sd, fn - band, fn + band, color=col_fit, alpha=0.18, lw=0,
                         label=r"$\pm 2$ sd")  # fmt: skip
        ax3.plot(sd, fn, color=col_fit, lw=1.6, label=r"$f_n = EI(\kappa'' + \kappa^3/2)$")
        ax3.axhline(0.0, color="0.4", lw=0.8)
        ax3.set_xlim(*ends)
        ax3.set_xlabel(rf"arc length from the midpoint [{ut}]", fontsize=11)
        ax3.set_ylabel(r"$f_n$ [nN/$\mu$m]", fontsize=11)
        ax3.legend(loc="upper center", fontsize=7.5, framealpha=0.8, ncols=2)
    return fig
