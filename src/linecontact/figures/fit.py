r"""Figures of the inverse problems (``docs/inverse.md``): the pull-off fit, the friction fit.

Two figures, each written to one file (the format follows the extension: ``.png``,
``.svg`` or ``.pdf``), drawn with the helpers of :mod:`linecontact.figures._style`; every
curve comes from :mod:`linecontact.inverse`.

:func:`draw_adhesion_fit`
    The pull-off force magnitude ``|F|`` against the radius, log-log, in the units given
    (SI by default, or those of the measurements file; plain-number tick labels): the data
    with their standard uncertainties, the fitted Maugis--Dugdale curve
    (:func:`~linecontact.inverse.pull_off_force` at the fitted ``w``, ``z0``) from half the
    smallest radius to twice the largest, its 95 % band (the fit's covariance of
    ``(ln w, ln z0)`` propagated to the curve by :data:`BAND_SAMPLES` seeded samples), and
    for comparison the JKR (:func:`~linecontact.inverse.jkr_pull_off_force`, fitted ``w``)
    and the rigid/DMT (:func:`~linecontact.inverse.dmt_pull_off_force`, fitted ``w`` and
    ``z0``) limits, dashed. The fitted values and their 95 % intervals in a box (and the
    fit's note when the data do not determine ``z0``).
:func:`draw_friction_fit`
    The shear strength ``tau0`` of each data point against the normal load, with its 95 %
    interval; the combined ``tau0`` (the weighted mean, :func:`combined_shear_strength`) as
    a line with its 95 % band; the ``tau0`` the simple contact models would give, dashed;
    below, the friction force itself against the load.

matplotlib is imported only when a figure is drawn.
"""

from __future__ import annotations

import math
import os
import pathlib
import textwrap
from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..inverse import AdhesionFit, dmt_pull_off_force, jkr_pull_off_force, pull_off_force
from ._style import (
    DEFAULT_SIZE,
    FORMATS,
    Margins,
    Run,
    _colors,
    _new_axes,
    _new_figure,
    _save,
    check_size,
)

__all__ = [
    "BAND_SAMPLES",
    "BAND_SEED",
    "FORCE_UNITS",
    "LENGTH_UNITS",
    "combined_shear_strength",
    "csv_units",
    "draw_adhesion_fit",
    "draw_friction_fit",
]

#: Samples of ``(ln w, ln z0)`` drawn for the 95 % band of the fitted curve, and their seed.
BAND_SAMPLES = 400
BAND_SEED = 0
#: Points of the drawn curves.
_N_CURVE = 200
_MARGINS = Margins(left=0.95, right=3.3)
_FRICTION_MARGINS = Margins(left=1.05, right=2.9)
#: The data points of both figures: black-edged circles, black error bars with caps.
_DATA_KW = dict(ls="none", marker="o", mec="k", ecolor="k", capsize=3)
# the bounds of the fit's parameters (linecontact.inverse.fit_pull_off): the band's samples
# are kept inside them
_LN_W = (math.log(1e-8), math.log(1e3))
_LN_Z0 = (math.log(1e-12), math.log(1e-7))


def _target(path: str | os.PathLike) -> tuple[pathlib.Path, str]:
    """The output path and its format, from the extension."""
    p = pathlib.Path(path)
    fmt = p.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise ValueError(
            f"cannot tell the format of {str(path)!r} from its extension: use one of "
            + ", ".join(f".{f}" for f in FORMATS)
        )
    return p, fmt


def _write(fig, path: pathlib.Path, fmt: str) -> pathlib.Path:
    outdir = path.parent if str(path.parent) else pathlib.Path(".")
    return _save(fig, outdir, path.name[: -len(path.suffix)], (fmt,))[0]


def _band(fit: AdhesionFit, radius: NDArray) -> tuple[NDArray, NDArray] | None:
    """The 2.5 % and 97.5 % percentiles of ``|F|`` on ``radius`` (None without a covariance).

    ``(ln w, ln z0)`` drawn from the normal distribution of the fit's covariance in the log
    parameters (``cov_ij / (p_i p_j)``; ``ln w`` alone for a fixed range), seeded.
    """
    w, z0, E = fit.work_of_adhesion, fit.equilibrium_spacing, fit.modulus
    p = np.array([w, z0])
    n = 1 if fit.fixed_spacing else 2
    cov_log = np.asarray(fit.covariance, float)[:n, :n] / np.outer(p[:n], p[:n])
    if not np.all(np.isfinite(cov_log)):
        return None
    rng = np.random.default_rng(BAND_SEED)
    draw = rng.multivariate_normal(np.log(p[:n]), cov_log, BAND_SAMPLES, method="eigh")
    ln_w = np.clip(draw[:, 0], *_LN_W)
    ln_z = np.full(BAND_SAMPLES, math.log(z0)) if n == 1 else np.clip(draw[:, 1], *_LN_Z0)
    try:
        F = pull_off_force(radius[None, :], E, np.exp(ln_w)[:, None], np.exp(ln_z)[:, None])
    except ValueError:  # a sample outside the solvers' domain
        return None
    lo, hi = np.nanpercentile(np.abs(F), [2.5, 97.5], axis=0)
    return lo, hi


def _fmt_interval(lo: float, hi: float, scale: float = 1.0) -> str:
    return f"[{lo * scale:.3g}, {hi * scale:.3g}]"


#: The display units of the pull-off figure: unit -> factor to SI (as the CSV reader's).
LENGTH_UNITS = {"m": 1.0, "nm": 1e-9, "um": 1e-6}
FORCE_UNITS = {"N/m": 1.0, "nN/um": 1e-3, "uN/m": 1e-6}
_UNIT_TEXT = {"um": r"$\mu$m", "nN/um": r"nN/$\mu$m", "uN/m": r"$\mu$N/m"}
# the CSV header's unit suffixes (linecontact.measurements) -> display units; forces given
# as totals (N, nN) are read per unit length in N/m
_CSV_FORCE = {"N_per_m": "N/m", "nN_per_um": "nN/um", "uN_per_m": "uN/m", "N": "N/m", "nN": "N/m"}


def csv_units(path: str | os.PathLike) -> tuple[str, str]:
    """The units of a pull-off CSV file's header as display units ``(length, force)``.

    ``radius_nm`` gives ``"nm"``, ``pull_off_force_nN_per_um`` ``"nN/um"``; a unit not
    found (or forces given as totals, read per unit length) gives the SI unit. Only the
    header is read: the file itself is checked by :func:`linecontact.read_measurements`.
    """
    length, force = "m", "N/m"
    try:
        with open(path, encoding="utf-8-sig") as fh:
            lines = (ln for ln in fh if ln.strip() and not ln.lstrip().startswith("#"))
            header = next(lines, "")
    except (OSError, UnicodeDecodeError):
        return length, force
    for col in (c.strip() for c in header.split(",")):
        if col.startswith("radius_") and col[7:] in LENGTH_UNITS:
            length = col[7:]
        elif col.startswith("pull_off_force_") and col[15:] in _CSV_FORCE:
            force = _CSV_FORCE[col[15:]]
    return length, force


def _units(units) -> tuple[str, str]:
    """``units`` as a checked ``(length, force)`` pair; a path: the units of that CSV."""
    if isinstance(units, str | os.PathLike):
        return csv_units(units)
    try:
        length, force = units
    except (TypeError, ValueError):
        raise ValueError(f"units must be (length unit, force unit), got {units!r}") from None
    if length not in LENGTH_UNITS or force not in FORCE_UNITS:
        raise ValueError(
            f"units {units!r}: the length in one of {', '.join(LENGTH_UNITS)}, the force in "
            f"one of {', '.join(FORCE_UNITS)}"
        )
    return length, force


def _plain_log_ticks(axis, lo: float, hi: float) -> None:
    """Plain-number labels (2, 5, 20; no ``2x10^0``) on a log axis spanning ``lo..hi``.

    Labelled ticks at 1 per decade over wide spans, at 1, 2, 5 over a few decades and at
    every integer multiple within a decade or so; the other ticks unlabelled.
    """
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    decades = math.log10(hi / lo) if lo > 0 and hi > lo else 1.0
    subs: tuple[float, ...] = (1.0,)
    if decades <= 0.9:
        subs = tuple(float(k) for k in range(1, 10))
    elif decades <= 3.2:
        subs = (1.0, 2.0, 5.0)
    axis.set_major_locator(LogLocator(base=10.0, subs=subs))
    axis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:.6g}"))
    axis.set_minor_formatter(NullFormatter())


def draw_adhesion_fit(
    fit: AdhesionFit,
    path: str | os.PathLike,
    *,
    size=DEFAULT_SIZE,
    units: tuple[str, str] | str | os.PathLike = ("m", "N/m"),
) -> pathlib.Path:
    """Draw a pull-off fit (:func:`linecontact.inverse.fit_pull_off`) into one file.

    Parameters
    ----------
    fit : AdhesionFit
        The fit, with its data.
    path : str or os.PathLike
        The file; its extension sets the format (``.png``, ``.svg``, ``.pdf``). Written
        atomically (it appears only once complete), replacing a file of that name.
    size : (float, float)
        Inches, between :data:`~linecontact.figures.MIN_SIZE` and
        :data:`~linecontact.figures.MAX_SIZE`.
    units : (str, str) or path
        The axes' units ``(length, force)``: the length in one of :data:`LENGTH_UNITS`
        (``"m"``, ``"nm"``, ``"um"``), the force per length in one of :data:`FORCE_UNITS`
        (``"N/m"``, ``"nN/um"``, ``"uN/m"``); SI by default. A path: the measurements CSV
        file the fit came from, whose header's units are used (:func:`csv_units`).

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For an extension that names no format, a size outside the accepted range or units
        not listed.
    """
    target, fmt = _target(path)
    fig = _adhesion_figure(fit, Run(size=check_size(size)), _units(units))
    return _write(fig, target, fmt)


def _adhesion_figure(fit: AdhesionFit, run: Run, units: tuple[str, str] = ("m", "N/m")):
    length, force = units
    kx, ky = 1.0 / LENGTH_UNITS[length], 1.0 / FORCE_UNITS[force]  # SI -> display
    R = np.asarray(fit.radius, float)
    F = np.abs(np.asarray(fit.pull_off_force, float))
    sd = np.asarray(fit.sd, float)
    w, z0, E = fit.work_of_adhesion, fit.equilibrium_spacing, fit.modulus
    fig, ax = _new_axes(
        run,
        _MARGINS,
        f"pull-off force against radius: Maugis–Dugdale fit (composite modulus "
        f"$E$ = {E / 1e9:.4g} GPa)",
        rf"radius $R$ [{_UNIT_TEXT.get(length, length)}]",
        rf"pull-off force magnitude $|F_{{po}}|$ [{_UNIT_TEXT.get(force, force)}]",
    )
    col_md, col_jkr, col_dmt = _colors(3)
    Rc = np.geomspace(0.5 * R.min(), 2.0 * R.max(), _N_CURVE)
    band = _band(fit, Rc)
    if band is not None:
        ax.fill_between(
            Rc * kx,
            band[0] * ky,
            band[1] * ky,
            color=col_md,
            alpha=0.22,
            lw=0,
            label="95 % band of the fit",
        )
    ax.plot(
        Rc * kx,
        np.abs(pull_off_force(Rc, E, w, z0)) * ky,
        color=col_md,
        lw=2,
        label="Maugis–Dugdale, fitted",
    )
    ax.plot(
        Rc * kx,
        np.abs(jkr_pull_off_force(Rc, E, w)) * ky,
        color=col_jkr,
        lw=1.4,
        ls="--",
        label=r"JKR ($\propto R^{1/3}$), fitted $w$",
    )
    ax.plot(
        Rc * kx,
        np.abs(dmt_pull_off_force(Rc, w, z0)) * ky,
        color=col_dmt,
        lw=1.4,
        ls=(0, (6, 2, 1, 2)),
        label=r"rigid/DMT ($\propto R^{1/2}$), fitted $w$, $z_0$",
    )
    have_sd = np.isfinite(sd)
    ax.errorbar(
        R * kx,
        F * ky,
        yerr=np.where(have_sd, sd, 0.0) * ky if have_sd.any() else None,
        **_DATA_KW,
        ms=6,
        mfc="white",
        mew=1.3,
        elinewidth=1.1,
        zorder=5,
        label="data" + (r" $\pm$ sd" if have_sd.any() else ""),
    )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(Rc[0] * kx, Rc[-1] * kx)
    # plain numbers (2, 5, 20), never 2x10^0; unlabelled minor ticks (they collided on x)
    _plain_log_ticks(ax.xaxis, *ax.get_xlim())
    _plain_log_ticks(ax.yaxis, *ax.get_ylim())
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8.5, frameon=False)
    lines = [
        rf"$w$ = {w:.4g} J/m$^2$ (sd {fit.work_of_adhesion_sd:.2g})",
        "   95 %: " + _fmt_interval(*fit.work_of_adhesion_ci95) + " J/m$^2$",
    ]
    if fit.fixed_spacing:
        lines.append(rf"$z_0$ = {z0 * 1e9:.4g} nm (fixed)")
    else:
        lines += [
            rf"$z_0$ = {z0 * 1e9:.4g} nm (sd {fit.equilibrium_spacing_sd * 1e9:.2g})",
            "   95 %: " + _fmt_interval(*fit.equilibrium_spacing_ci95, 1e9) + " nm",
            f"correlation of $w$, $z_0$: {fit.correlation:.3f}",
        ]
    lines.append(rf"$\chi^2$ = {fit.chi2:.3g}, {fit.dof} degrees of freedom")
    if not fit.identifiable and fit.note:
        lines += ["", *textwrap.wrap(fit.note.replace("$", r"\$"), 46)]
    ax.text(
        1.02,
        0.0,
        "\n".join(lines),
        transform=ax.transAxes,
        ha="left",
        va="bottom",
        fontsize=8,
        bbox=dict(boxstyle="round,pad=0.4", fc="white", ec="0.6", lw=0.7),
    )
    return fig


# --------------------------------------------------------------------------------------------
# friction


def _vector(name: str, value: ArrayLike, n: int | None) -> NDArray:
    arr = np.asarray(value, float)
    if arr.ndim != 1 or (n is not None and arr.size != n):
        raise ValueError(
            f"{name} must be a 1-D array"
            + (f" of {n} values (one per data point)" if n is not None else "")
            + f", got shape {arr.shape}"
        )
    return arr


def _intervals(tau0_ci95: ArrayLike, n: int) -> tuple[NDArray, NDArray]:
    """``(lo, hi)`` of per-point intervals given as two arrays (shape (2, n)) or as pairs."""
    ci = np.asarray(tau0_ci95, float)
    if ci.shape == (2, n):
        return ci[0], ci[1]
    if ci.shape == (n, 2):
        return ci[:, 0], ci[:, 1]
    raise ValueError(
        f"tau0_ci95 must be (lo, hi), two 1-D arrays of {n} values, got shape {ci.shape}"
    )


def combined_shear_strength(
    tau0: ArrayLike, tau0_ci95: ArrayLike
) -> tuple[float, tuple[float, float]]:
    """The combined ``tau0`` of several points and its 95 % interval, as drawn.

    The inverse-variance weighted mean of the points' ``tau0``, with the standard
    uncertainty of each point ``(hi - lo) / (2 x 1.96)`` from its 95 % interval; the
    standard uncertainty of the mean ``1/sqrt(sum 1/sd_i^2)`` is widened by the Birge ratio
    ``sqrt(chi2/(n - 1))`` when the points scatter more than their intervals say; the
    interval is the mean ``+- 1.96`` of it. Points without a finite positive interval
    weigh equally (the plain mean and its standard error).

    Examples
    --------
    >>> t, (lo, hi) = combined_shear_strength([1e7, 1e7], ([0.9e7, 0.9e7], [1.1e7, 1.1e7]))
    >>> round(t), round(lo), round(hi)  # 1e7 +- 1.96 (1e6/1.96)/sqrt(2)
    (10000000, 9292893, 10707107)
    """
    tau = _vector("tau0", tau0, None)
    lo, hi = _intervals(tau0_ci95, tau.size)
    sd = (hi - lo) / (2 * 1.96)
    good = np.isfinite(sd) & (sd > 0)
    if tau.size == 0:
        raise ValueError("tau0 has no values")
    if good.all():
        wt = 1.0 / sd**2
        mean = float(np.sum(wt * tau) / np.sum(wt))
        se = 1.0 / math.sqrt(float(np.sum(wt)))
        if tau.size > 1:
            birge = float(np.sum(wt * (tau - mean) ** 2)) / (tau.size - 1)
            se *= math.sqrt(max(1.0, birge))
    else:
        mean = float(np.mean(tau))
        se = float(np.std(tau, ddof=1) / math.sqrt(tau.size)) if tau.size > 1 else math.nan
    return mean, (mean - 1.96 * se, mean + 1.96 * se)


def draw_friction_fit(
    normal_load: ArrayLike,
    friction_force: ArrayLike,
    tau0: ArrayLike,
    tau0_ci95: ArrayLike,
    models: Mapping[str, ArrayLike],
    path: str | os.PathLike,
    *,
    friction_sd: ArrayLike | None = None,
    combined: tuple[float, tuple[float, float]] | None = None,
    size=DEFAULT_SIZE,
) -> pathlib.Path:
    """Draw the shear strength from friction forces at several normal loads into one file.

    Parameters
    ----------
    normal_load, friction_force : array_like, 1-D
        The data [N/m], one value per point.
    tau0 : array_like, 1-D
        The shear strength of each point [Pa]
        (:func:`linecontact.inverse.shear_strength_from_friction`).
    tau0_ci95 : array_like
        The 95 % interval of each point's ``tau0`` [Pa]: ``(lo, hi)``, two 1-D arrays (an
        array of ``(lo, hi)`` pairs is read too).
    models : mapping of str to array_like
        The ``tau0`` the simple contact models give at each point, by name (for example
        ``{"JKR": ..., "DMT": ..., "Hertz": ...}``), drawn dashed.
    path : str or os.PathLike
        The file; its extension sets the format (``.png``, ``.svg``, ``.pdf``), written
        atomically.
    friction_sd : array_like, optional
        Standard uncertainties of the friction forces [N/m], error bars of the lower panel.
    combined : (float, (float, float)), optional
        The combined ``tau0`` and its 95 % interval to draw (as ``linecontact fit-friction``
        prints them); by default :func:`combined_shear_strength` of the points.
    size : (float, float)
        Inches, as for :func:`draw_adhesion_fit`.

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For an extension that names no format, arrays of different lengths, or a size
        outside the accepted range.
    """
    target, fmt = _target(path)
    F = _vector("normal_load", normal_load, None)
    n = F.size
    f = _vector("friction_force", friction_force, n)
    tau = _vector("tau0", tau0, n)
    lo, hi = _intervals(tau0_ci95, n)
    mods = {str(k): _vector(f"models[{k!r}]", v, n) for k, v in models.items()}
    fsd = None if friction_sd is None else _vector("friction_sd", friction_sd, n)
    run = Run(size=check_size(size))
    fig = _friction_figure(run, F, f, tau, lo, hi, mods, fsd, combined)
    return _write(fig, target, fmt)


def _friction_figure(run: Run, F, f, tau, lo, hi, mods, fsd, combined=None):
    fig = _new_figure(run, _FRICTION_MARGINS)
    gs = fig.add_gridspec(2, 1, height_ratios=(2.3, 1.0), hspace=0.08)
    ax = fig.add_subplot(gs[0])
    ax2 = fig.add_subplot(gs[1], sharex=ax)
    for a in (ax, ax2):
        a.grid(True, color="0.88", linewidth=0.6)
        a.tick_params(labelsize=10)
    ax.tick_params(labelbottom=False)
    ax.set_title("interfacial shear strength from friction at several normal loads", fontsize=11)
    ax.set_ylabel(r"shear strength $\tau_0$ [MPa]", fontsize=12)
    ax2.set_ylabel(r"friction $f$ [N/m]", fontsize=11)
    ax2.set_xlabel(r"normal load $F$ [N/m]", fontsize=12)
    mpa = 1e-6
    order = np.argsort(F, kind="stable")
    if combined is None:
        combined = combined_shear_strength(tau, np.array([lo, hi]))
    mean, (c_lo, c_hi) = combined
    if math.isfinite(c_lo) and math.isfinite(c_hi):
        ax.axhspan(c_lo * mpa, c_hi * mpa, color="0.5", alpha=0.18, lw=0)
    ax.axhline(
        mean * mpa,
        color="0.25",
        lw=1.6,
        label=rf"combined $\tau_0$ = {mean * mpa:.4g} MPa"
        + (
            f"\n  95 %: [{c_lo * mpa:.4g}, {c_hi * mpa:.4g}]"
            if math.isfinite(c_lo) and math.isfinite(c_hi)
            else ""
        ),
    )
    cols = _colors(max(len(mods), 1) + 1)[1:]
    markers = ("^", "v", "D", "s", "P", "X")
    for (name, t), col, mk in zip(mods.items(), cols, markers * 4, strict=False):
        ax.plot(
            F[order],
            t[order] * mpa,
            color=col,
            ls="--",
            lw=1.2,
            marker=mk,
            ms=5,
            mfc="white",
            label=rf"{name} contact",
        )
    yerr = np.array([tau - lo, hi - tau]) * mpa
    ax.errorbar(
        F,
        tau * mpa,
        yerr=np.where(np.isfinite(yerr), np.clip(yerr, 0, None), 0.0),
        **_DATA_KW,
        ms=6,
        mfc="k",
        elinewidth=1.1,
        zorder=5,
        label="Maugis–Dugdale, each point\n(95 % interval)",
    )
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8.5, frameon=False)
    ax2.errorbar(
        F,
        f,
        yerr=None if fsd is None else np.where(np.isfinite(fsd), fsd, 0.0),
        **_DATA_KW,
        ms=5,
        mfc="white",
        label="measured" + ("" if fsd is None else r" $\pm$ sd"),
    )
    ax2.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8.5, frameon=False)
    return fig
