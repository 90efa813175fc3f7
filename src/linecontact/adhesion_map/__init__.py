r"""The adhesion map of line contact: where the simpler models agree with the full law.

Johnson & Greenwood (1997) mapped, for spheres, where Hertz, Bradley (rigid), DMT, JKR and
Maugis--Dugdale hold over the Maugis parameter and the load. Their map does not carry over to a
cylinder on a half-plane. For a sphere both ends of the pull-off are plateaus in one scale,
:math:`\pi w R` (Bradley 2, JKR 1.5), so one load axis serves every Maugis parameter. For a cylinder
the rigid end scales with :math:`w \sqrt{R/z_0}` (2.466 of it under the Lennard-Jones law,
:func:`linecontact.closed_forms.lennard_jones_rigid_pull_off`; 16 % more under the matched Dugdale
step) and the JKR end with :math:`(E w^2 R)^{1/3}` (the pull-off
:math:`-\tfrac34 (4\pi/\mu)^{1/3} w \sqrt{R/z_0}`): in either scale the other end drifts with
``mu``, and there is no universal plateau. Here the load is therefore counted from the full law's
own pull-off, in units of it. The full law is the Lennard-Jones law of Eq. (1) solved
self-consistently (:mod:`linecontact.lennard_jones`), and each simpler model is judged by the
half-width of the repulsive region (the gap below ``z0``; the contact of the models) that it gives
at the same load.

Units: the full law's own (:mod:`linecontact.lennard_jones`). Half-widths
:math:`\xi = x / \sqrt{R z_0}`, loads per unit length :math:`F / (w \sqrt{R/z_0})` (compressive
positive), the one group :math:`\mu = w \sqrt{R/z_0} / (E z_0)`, ``E`` the composite plane-strain
modulus. The models, in those units:

- Hertz: :math:`F = \frac{\pi}{4\mu} \xi^2` (:func:`hertz_half_width`);
- JKR (Chaudhury et al. 1996, :func:`linecontact.closed_forms.jkr_load`):
  :math:`F = \frac{\pi}{4\mu} \xi^2 - \sqrt{2\pi \xi / \mu}`, pull-off
  :math:`-\tfrac34 (4\pi/\mu)^{1/3}` (:func:`jkr_half_width`, :func:`jkr_load`);
- rigid: the law on a rigid cylinder (no elastic deformation),
  :func:`linecontact.closed_forms.lennard_jones_rigid_load`; the gap below ``z0`` where
  :math:`g_0 + x^2/(2R) < z_0`, :math:`\xi = \sqrt{2 (1 - g_0/z_0)}` (:func:`rigid_half_width`);
- Maugis--Dugdale: the Dugdale step with the Maugis matching (same work of adhesion and
  peak tension, :func:`linecontact.lennard_jones.mu_of_dugdale`), solved by
  :func:`linecontact.contact_for_load` (:func:`md_half_width`);
- the full law: the stable contact branch of :func:`linecontact.lennard_jones.lj_curve`,
  interpolated (:func:`lj_half_width`).

The map (:func:`adhesion_map`) is over ``mu`` -- drawn against the Maugis parameter of the matched
Dugdale step, :math:`\lambda = 1.914\, \mu^{2/3}`
(:func:`~linecontact.lennard_jones.maugis_parameter_of_mu`) -- and the load above the full law's
pull-off relative to it, :math:`y = (F - F_\text{pull-off}) / |F_\text{pull-off}|`. The error of a
model is :math:`|\xi_\text{model} - \xi| / \xi` against the full law's half-width ``xi``; a model
holds where it is at most ``tol``. What the map shows, and the accuracy of the full law's widths:
``docs/adhesion-map.md``.

The default grid spans the Maugis parameters 0.01 to 100 (:data:`MAUGIS_RANGE`), or to the end
of the solver's domain where that is sooner (:func:`default_mu`). The full law's branches, one
per ``mu`` and independent, are computed in ``workers`` processes and assembled in the order of
``mu``; with ``resume_dir`` each finished one is kept in a file of its own, so that a stopped
map, run again, computes only those still missing (:func:`adhesion_map`).
"""

from __future__ import annotations

import math
import os
import pathlib
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import closed_forms as _cf
from .._progress import progress_bar
from .._validation import check_array
from ..closed_forms import lennard_jones_rigid_load, lennard_jones_rigid_pull_off
from ..errors import ConvergenceError
from ..lennard_jones import (
    MAUGIS_MATCH_SIGMA0,
    LJContinuation,
    LJCurve,
    maugis_parameter_of_mu,
)
from ..normal import contact_for_load
from ..results import Result
from ._runs import _check_workers, _clear, _entry, _read_row, _Row, _row_key, _run, _store

__all__ = [
    "COARSE",
    "MAUGIS_RANGE",
    "MD_R_OVER_H",
    "MODELS",
    "AdhesionMap",
    "FullLawBranch",
    "adhesion_map",
    "default_mu",
    "default_y",
    "domain_mu_max",
    "full_law_branch",
    "hertz_half_width",
    "jkr_half_width",
    "jkr_load",
    "jkr_pull_off",
    "lj_half_width",
    "md_groups",
    "md_half_width",
    "rigid_central_gap",
    "rigid_half_width",
]

#: The simpler models, in the order of the fields and of the figure's legend.
MODELS = ("hertz", "rigid", "jkr", "md")
#: ``R/h`` of the Dugdale step that stands for the Maugis--Dugdale model. Its load curve in
#: the full law's units depends on ``mu`` alone (``kappa = (4 sqrt 2/pi) S^(3/2) mu``); the
#: widths at ``R/h = 1e4`` and ``1e8`` agree with these to round-off.
MD_R_OVER_H = 1e6
#: Loads above pull-off over its magnitude of the default map (ends, points).
Y_RANGE = (1e-2, 30.0)
#: Loads of the default map.
N_Y = 81
#: The Maugis parameters (of the matched Dugdale step) where the default map starts and ends;
#: it ends where the Lennard-Jones solver's domain does if that is sooner (:func:`default_mu`).
MAUGIS_RANGE = (0.01, 100.0)

#: The coarse grid of ``linecontact figures`` and ``linecontact map --quick``: ``n_mu``
#: values of ``mu`` from ``mu_min`` to ``mu_max`` (or the end of the domain, if lower: a
#: curve beyond ``mu = 1`` takes minutes), ``n_y`` loads above pull-off from 0.01 to
#: ``y_max`` pull-offs.
COARSE: dict[str, Any] = {"n_mu": 4, "mu_min": 0.01, "mu_max": 1.0, "n_y": 41, "y_max": 10.0}


def _mu_of_maugis(lam: float) -> float:
    """The inverse of :func:`~linecontact.lennard_jones.maugis_parameter_of_mu`."""
    return float((lam / float(maugis_parameter_of_mu(1.0))) ** 1.5)


#: ``mu`` where the default map starts (the Maugis parameter ``MAUGIS_RANGE[0]``, 3.8e-4) ...
MU_MIN = _mu_of_maugis(MAUGIS_RANGE[0])
#: ... and where it ends, unless the solver's domain ends sooner (``MAUGIS_RANGE[1]``, 378).
MU_MAX = _mu_of_maugis(MAUGIS_RANGE[1])
#: :func:`full_law_branch` adds a state between two whose loads above pull-off differ by more
#: than this factor (at most :data:`MAX_EXTRA_STATES` in all) ...
SPLIT_RATIO = 2.0
#: ... and about a state that the others miss by more than this when it is left out.
SPLIT_MISS = 0.01
MAX_EXTRA_STATES = 6
_RIGID_GAP_MIN = 0.01  # the domain of lennard_jones_rigid_load
_ONSET_ROUND_OFF = 1e-3  # a width at the central gap z0 below this is the onset's round-off


def domain_mu_max() -> float:
    """The largest ``mu`` of the map: the end of the Lennard-Jones solver's domain (read now)."""
    from ..domain import DOMAIN

    return DOMAIN["lj_mu"][2]


# --------------------------------------------------------------------------------------------
# the models


def hertz_half_width(F: ArrayLike, mu: ArrayLike) -> NDArray:
    r"""Hertz line contact: :math:`F = \frac{\pi}{4\mu} \xi^2`, so :math:`\xi = \sqrt{4 \mu F/\pi}`.

    0 for :math:`F \le 0`. ``F`` over :math:`w \sqrt{R/z_0}`, ``xi`` over :math:`\sqrt{R z_0}`,
    arrays broadcast. The closed form of :mod:`linecontact.closed_forms` in the paper's groups with
    :math:`h = z_0`: :math:`R/h = 1` (lengths over :math:`\sqrt{R z_0}`), :math:`\sigma_0/E = \mu`,
    :math:`F/(E h) = \mu F`.
    """
    F, mu = np.broadcast_arrays(np.asarray(F, float), np.asarray(mu, float))
    return _cf._hertz_half_width(mu * F, 1.0)


def jkr_load(xi: ArrayLike, mu: ArrayLike) -> NDArray:
    r"""JKR line contact, full law's units: :math:`F = \frac{\pi}{4\mu} \xi^2 - \sqrt{2\pi\xi/\mu}`.

    :func:`linecontact.closed_forms.jkr_load`, :math:`F = \pi E a^2/(4R) - \sqrt{2\pi E w a}`,
    with :math:`a = \xi \sqrt{R z_0}` and ``F`` over :math:`w \sqrt{R/z_0}` (as
    :func:`hertz_half_width`).
    """
    xi = np.asarray(xi, float)
    mu = np.asarray(mu, float)
    return _cf._jkr(xi, 1.0, mu) / mu


def jkr_pull_off(mu: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""The JKR pull-off :math:`-\frac34 (4\pi/\mu)^{1/3}`, width :math:`(2\mu/\pi)^{1/3}`."""
    mu = np.asarray(mu, float)
    F, xi = _cf._jkr_pull_off(1.0, mu)
    return F / mu, xi


def jkr_half_width(F: ArrayLike, mu: ArrayLike) -> NDArray:
    r"""The JKR half-width on the stable branch (``xi`` above the pull-off width) at ``F``.

    :func:`linecontact.closed_forms._jkr_half_width` (Newton in :math:`\sqrt{\xi}`) at
    :math:`\mu F`. NaN below the pull-off (no JKR contact).
    """
    F, mu = np.broadcast_arrays(np.asarray(F, float), np.asarray(mu, float))
    return _cf._jkr_half_width(mu * F, 1.0, mu)


def rigid_central_gap(F: ArrayLike) -> NDArray:
    r"""The central gap over ``z0`` of a rigid cylinder carrying ``F`` under the law.

    The inverse of :func:`linecontact.closed_forms.lennard_jones_rigid_load` on its branch of
    contact (gaps below the pull-off gap 1.100925, where the load rises as the gap closes),
    by bisection in :math:`\ln g_0` to round-off; NaN below the rigid pull-off and above the load
    at the smallest gap of that function's domain (:math:`0.01\, z_0`).
    """
    F = np.asarray(F, float)
    F_po, z_po = lennard_jones_rigid_pull_off()
    lo = np.full(F.shape, math.log(_RIGID_GAP_MIN))
    hi = np.full(F.shape, math.log(z_po))
    for _ in range(64):  # the bracket, 4.7 wide, shrinks below round-off
        mid = 0.5 * (lo + hi)
        closer = np.asarray(lennard_jones_rigid_load(np.exp(mid))) > F  # the gap is larger
        lo = np.where(closer, mid, lo)
        hi = np.where(closer, hi, mid)
    F_top = float(lennard_jones_rigid_load(_RIGID_GAP_MIN))
    return np.where((F >= F_po) & (F <= F_top), np.exp(0.5 * (lo + hi)), np.nan)


def rigid_half_width(F: ArrayLike) -> NDArray:
    r"""Rigid cylinder: :math:`\xi = \sqrt{2 (1 - g_0/z_0)}` where the central gap is below z0.

    0 where it is not, NaN below the rigid pull-off (:func:`rigid_central_gap`).
    """
    g = rigid_central_gap(F)
    return np.sqrt(2.0 * np.clip(1.0 - g, 0.0, None))


def md_groups(mu: ArrayLike, R_over_h: float = MD_R_OVER_H) -> tuple[NDArray, NDArray]:
    r""":math:`(\sigma_0/E, \sqrt{R/z_0})` of the Dugdale step matched to ``mu`` at ``R/h``.

    The inverse of :func:`linecontact.lennard_jones.mu_of_dugdale`:
    :math:`\sigma_0/E = \mu S^{3/2} / \sqrt{R/h}`, :math:`R/z_0 = (R/h)/S`,
    :math:`S = 16/(9 \sqrt 3)`.
    """
    mu = np.asarray(mu, float)
    s = mu * MAUGIS_MATCH_SIGMA0**1.5 / math.sqrt(R_over_h)
    return s, np.sqrt(np.broadcast_to(R_over_h / MAUGIS_MATCH_SIGMA0, np.shape(s)))


def md_half_width(F: ArrayLike, mu: ArrayLike, R_over_h: float = MD_R_OVER_H) -> NDArray:
    r"""Maugis--Dugdale with the Maugis matching: the contact half-width at the load ``F``.

    :func:`linecontact.contact_for_load` (the stable branch) at ``R/h``, ``sigma0/E`` of
    :func:`md_groups` and :math:`F/(E h) = F (\sigma_0/E) \sqrt{R/z_0}`;
    :math:`\xi = (a/R) \sqrt{R/z_0}`.
    NaN below the Maugis--Dugdale pull-off (no contact carries the load).
    """
    F, mu = np.broadcast_arrays(np.asarray(F, float), np.asarray(mu, float))
    s, root = md_groups(mu, R_over_h)
    r = contact_for_load(F * s * root, R_over_h, s, on_failure="report")
    return np.asarray(r.a_over_R, float) * root


# --------------------------------------------------------------------------------------------
# the full law


@dataclass(frozen=True)
class FullLawBranch:
    """The stable contact branch of the full law at one ``mu``, as sampled.

    ``F`` increasing from the pull-off; ``half_width`` and ``central_gap_over_z0`` of each
    state; the states of :func:`~linecontact.lennard_jones.lj_curve` (from the pull-off on)
    and the ones solved where its steps are widest (:func:`full_law_branch`). ``onset``
    indexes the last state without a repulsive region before the repulsive ones (0: the
    pull-off; -1: none, the repulsive region exists at pull-off already).
    """

    mu: float
    F: NDArray
    half_width: NDArray
    central_gap_over_z0: NDArray
    error_estimate: NDArray
    F_pulloff: float
    onset: int
    curve: LJCurve

    @property
    def y_onset(self) -> float:
        """The load above pull-off over its magnitude where the repulsive region appears."""
        if self.onset < 0:
            return 0.0
        return (float(self.F[self.onset]) - self.F_pulloff) / abs(self.F_pulloff)

    def points(self, drop: int | None = None) -> tuple[NDArray, NDArray, float]:
        r"""The interpolation's nodes: :math:`s = \sqrt{F - F_\text{po}}`, :math:`\xi^2`, the start.

        :math:`F_\text{po}` the pull-off. From the last state without repulsion (:math:`\xi = 0`; it
        ends the zero part) or the pull-off; ``drop`` leaves one state out (the leave-one-out
        estimate).
        """
        k = max(self.onset, 0)
        keep = np.arange(k, self.F.size)
        if drop is not None:
            keep = keep[keep != drop]
        s = np.sqrt(np.maximum(self.F[keep] - self.F_pulloff, 0.0))
        return s, self.half_width[keep] ** 2, float(self.F[k])


def full_law_branch(
    mu: float,
    F_max: float,
    *,
    split: float = SPLIT_RATIO,
    miss: float = SPLIT_MISS,
    max_extra: int = MAX_EXTRA_STATES,
) -> FullLawBranch:
    r"""The stable branch of the full law at ``mu`` up to ``F_max`` (over :math:`w \sqrt{R/z_0}`).

    :func:`~linecontact.lennard_jones.lj_curve`, from the pull-off on, and more states
    (:func:`~linecontact.lennard_jones.lj_state`) where its steps are wide:

    - where the branch starts without a repulsive region (the central gap above ``z0``), the
      state with the central gap at ``z0``: there the region appears, at the centre (the
      elastic surface is drawn up most under the centre), so its width is 0 there and
      rises as :math:`\sqrt{F - F_\text{onset}}`;
    - from there (or from the pull-off) on, the state halfway in central gap between two
      states whose loads above pull-off differ by more than the factor ``split`` (the
      widest first), then about a state whose width the others miss by more than ``miss``
      when it is left out (in the wider of its two intervals); at most ``max_extra`` of
      them. The continuation's steps are long just beyond the onset, most of all from
      :math:`\mu \approx 0.5` on, where the width rises steeply there.

    A state that does not fall between its neighbours in load (another branch) is left out.
    """
    curve = LJContinuation(mu)  # the states between the curve's points go on from its own
    c = curve.curve(F_max)
    po = c.pull_off
    on = c.central_gap_over_z0 < po.central_gap_at_pulloff
    Z = np.concatenate([[po.central_gap_at_pulloff], c.central_gap_over_z0[on]])
    F = np.concatenate([[po.F_pulloff], c.F[on]])
    H = np.concatenate([[po.half_width_at_pulloff], c.half_width[on]])
    E = np.concatenate([[po.error_estimate], c.error_estimate[on]])
    F_po = float(po.F_pulloff)
    if not np.all(np.diff(F) > 0):
        raise ConvergenceError(
            f"the stable branch of the Lennard-Jones curve at mu={mu!r} is not monotone in load"
        )

    def insert(z: float, onset: bool = False) -> bool:
        nonlocal Z, F, H, E
        st = curve.state(z)
        i = int(np.searchsorted(-Z, -z))  # Z decreases: the states about z are i - 1 and i
        if not (0 < i < Z.size and F[i - 1] < st.F < F[i]):
            return False
        # at the onset the region is a point at the centre: its width is round-off
        w = 0.0 if onset and st.half_width < _ONSET_ROUND_OFF else st.half_width
        Z, F, H, E = (
            np.insert(v, i, x) for v, x in ((Z, z), (F, st.F), (H, w), (E, st.error_estimate))
        )
        return True

    first = int(np.argmax(H > 0)) if np.any(H > 0) else F.size
    if 0 < first < F.size and Z[first - 1] > 1.0 > Z[first]:
        insert(1.0, onset=True)
    floor = Y_RANGE[0] * abs(F_po)  # loads above pull-off below the map's count as its least
    for _ in range(max_extra if np.any(H > 0) else 0):
        start = int(np.argmax(H > 0)) - 1  # the onset, or -1: a repulsive region at pull-off
        b = FullLawBranch(mu, F, H, Z, E, F_po, start, c)
        i = _widest(b, max(start, 0), split, miss, floor)
        if i is None or not insert(0.5 * (Z[i] + Z[i + 1])):
            break
    positive = H > 0
    onset = -1 if positive[0] else int(np.argmax(positive)) - 1
    if onset >= 0 and not positive[onset + 1 :].all():
        raise ConvergenceError(
            f"the repulsive region of the Lennard-Jones branch at mu={mu!r} vanishes again "
            "after it appears: the interpolation of its width does not apply"
        )
    return FullLawBranch(mu, F, H, Z, E, F_po, onset, c)


def _widest(b: FullLawBranch, start: int, split: float, miss: float, floor: float) -> int | None:
    """The interval ``[i, i + 1]`` of ``b`` to split next (:func:`full_law_branch`), or None."""
    above = np.maximum(b.F[start:] - b.F_pulloff, floor)
    if above.size < 2:
        return None
    ratio = above[1:] / above[:-1]
    j = int(np.argmax(ratio))
    if ratio[j] > split:
        return start + j
    misses = _misses(b)
    if not misses.size or misses.max() <= miss:
        return None
    j = start + 1 + int(np.argmax(misses))  # the node; its wider neighbouring interval
    s = np.sqrt(np.maximum(b.F - b.F_pulloff, 0.0))
    return j - 1 if s[j] - s[j - 1] >= s[j + 1] - s[j] else j


def lj_half_width(branch: FullLawBranch, F: ArrayLike) -> NDArray:
    r"""The full law's half-width at the loads ``F`` on ``branch``, interpolated.

    Monotone piecewise-cubic (PCHIP) interpolation of :math:`\xi^2` against
    :math:`s = \sqrt{F - F_\text{pull-off}}`: both ends are regular in that variable (at the
    pull-off the width grows like :math:`s`, at the onset of the repulsive region :math:`\xi^2`
    like :math:`F - F_\text{onset}`, under large loads :math:`\xi^2` like :math:`F`). 0 at and
    below the onset; NaN below the pull-off and beyond the last state. Against
    :func:`~linecontact.lennard_jones.lj_state` at the central gaps halfway between the
    nodes of :func:`full_law_branch` (:math:`\mu` = 0.01, 0.08, 0.28, 0.66 and 1, loads up to
    3.5 pull-offs above pull-off) the error is at most 0.2 % of the width, below 0.03 % at
    larger loads (:math:`\mu` up to 0.3, to 30 pull-offs) and below 0.04 % at :math:`\mu = 3` just
    beyond the onset; against :func:`~linecontact.lennard_jones.lj_contact_for_load`
    (``tests/test_adhesion_map.py``) below 0.3 %.
    """
    from scipy.interpolate import PchipInterpolator

    return _interpolate(branch, np.asarray(F, float), PchipInterpolator)


def _interpolate(branch: FullLawBranch, F: NDArray, pchip, drop: int | None = None) -> NDArray:
    s, q, F_start = branch.points(drop)
    p = pchip(s, q, extrapolate=False)
    with np.errstate(invalid="ignore"):
        st = np.sqrt(np.maximum(F - branch.F_pulloff, 0.0))
        xi = np.sqrt(np.maximum(p(st), 0.0))
        xi = np.where((branch.onset >= 0) & (F <= F_start), 0.0, xi)
        return np.where((F < branch.F_pulloff) | (F > branch.F[-1]), np.nan, xi)


def interpolation_error(branch: FullLawBranch) -> float:
    """Leave-one-out estimate of the interpolation's relative error of the width.

    Each repulsive state between the first and the last one is left out in turn and its
    width interpolated from the others; the largest relative miss. The nodes are then twice
    as far apart about the state left out, so this overestimates the error of
    :func:`lj_half_width` (several times, for a cubic).
    """
    misses = _misses(branch)
    return float(misses.max()) if misses.size else 0.0


def _misses(branch: FullLawBranch) -> NDArray:
    """The leave-one-out misses at the nodes ``max(onset, 0) + 1`` to ``n - 2`` (0 if none)."""
    from scipy.interpolate import PchipInterpolator

    start = max(branch.onset, 0)
    out = np.zeros(max(branch.F.size - start - 2, 0))
    for k, j in enumerate(range(start + 1, branch.F.size - 1)):
        if branch.half_width[j] > 0:
            xi = _interpolate(branch, branch.F[j : j + 1], PchipInterpolator, drop=j)[0]
            out[k] = abs(xi / branch.half_width[j] - 1.0)
    return out


# --------------------------------------------------------------------------------------------
# the map


@dataclass(frozen=True)
class AdhesionMap(Result):
    r"""Where the simpler models agree with the full law, over ``mu`` and the load.

    Units of :mod:`linecontact.lennard_jones`: loads over :math:`w \sqrt{R/z_0}`, half-widths
    over :math:`\sqrt{R z_0}`. Per-``mu`` fields have the shape ``(n_mu, 1)`` and per-load fields
    ``(n_y,)``, so that they broadcast against the cells ``(n_mu, n_y)`` (one row per
    cell in :meth:`columns`; ``mu.ravel()`` is the grid).

    Attributes
    ----------
    mu, maugis_parameter : ndarray, (n_mu, 1)
        The group of the law and the Maugis parameter of the matched Dugdale step.
    y : ndarray, (n_y,)
        Load above the full law's pull-off over its magnitude,
        :math:`(F - F_\text{pull-off}) / |F_\text{pull-off}|`.
    F : ndarray, (n_mu, n_y)
        The load (compressive positive).
    F_pulloff : ndarray, (n_mu, 1)
        The full law's pull-off force.
    y_onset : ndarray, (n_mu, 1)
        ``y`` where the full law's repulsive region appears (its central gap reaches
        ``z0``); 0 where it exists at pull-off already.
    half_width_lj, half_width_hertz, half_width_rigid, half_width_jkr, half_width_md : ndarray
        Shape ``(n_mu, n_y)``. Half-width of the repulsive region of the full law and the contact
        half-width of each model; NaN where the model has no contact carrying the load (below its
        own pull-off: JKR, Maugis--Dugdale, rigid). The full law's is 0 where it has no repulsive
        region (the central gap above ``z0``: near pull-off, below :math:`\mu \approx 1`).
    error_hertz, error_rigid, error_jkr, error_md : ndarray, (n_mu, n_y)
        :math:`|\xi_\text{model} - \xi| / \xi`; NaN where the full law has no repulsive
        region, ``inf`` where the model has no contact.
    tol : float
        A model agrees with the full law where its error is at most ``tol``.
    R_over_h_md : float
        ``R/h`` of the Dugdale step (:data:`MD_R_OVER_H`).
    lj_error_estimate : ndarray, (n_mu, 1)
        The largest estimated error of the load of the full law's states used (nested
        meshes, :class:`~linecontact.lennard_jones.LJCurve`), over :math:`w \sqrt{R/z_0}`.
    interpolation_error : ndarray, (n_mu, 1)
        Leave-one-out estimate of the relative error of ``half_width_lj`` from the
        interpolation between states (an overestimate: :func:`interpolation_error`).
    n_states : ndarray of int, (n_mu, 1)
        States of the full law interpolated between.

    Derived columns: ``repulsive`` (the full law has a repulsive region) and
    ``agrees_hertz``, ``agrees_rigid``, ``agrees_jkr``, ``agrees_md`` (error at most ``tol``).
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu", "y", "tol", "R_over_h_md")
    derived: ClassVar[tuple[str, ...]] = (
        "repulsive",
        "agrees_hertz",
        "agrees_rigid",
        "agrees_jkr",
        "agrees_md",
    )

    mu: NDArray
    maugis_parameter: NDArray
    y: NDArray
    F: NDArray
    F_pulloff: NDArray
    y_onset: NDArray
    half_width_lj: NDArray
    half_width_hertz: NDArray
    half_width_rigid: NDArray
    half_width_jkr: NDArray
    half_width_md: NDArray
    error_hertz: NDArray
    error_rigid: NDArray
    error_jkr: NDArray
    error_md: NDArray
    tol: float
    R_over_h_md: float
    lj_error_estimate: NDArray
    interpolation_error: NDArray
    n_states: NDArray

    @property
    def repulsive(self) -> NDArray:
        """The full law has a repulsive region (its half-width is positive)."""
        return np.asarray(self.half_width_lj) > 0

    def error(self, model: str) -> NDArray:
        """The error field of ``model`` (one of :data:`MODELS`)."""
        if model not in MODELS:
            raise ValueError(f"model must be one of {', '.join(MODELS)}, got {model!r}")
        return np.asarray(getattr(self, f"error_{model}"))

    def agrees(self, model: str) -> NDArray:
        """Cells where ``model`` agrees with the full law within ``tol``."""
        with np.errstate(invalid="ignore"):
            return self.error(model) <= self.tol

    @property
    def agrees_hertz(self) -> NDArray:
        """Hertz within ``tol`` of the full law."""
        return self.agrees("hertz")

    @property
    def agrees_rigid(self) -> NDArray:
        """The rigid cylinder within ``tol`` of the full law."""
        return self.agrees("rigid")

    @property
    def agrees_jkr(self) -> NDArray:
        """JKR within ``tol`` of the full law."""
        return self.agrees("jkr")

    @property
    def agrees_md(self) -> NDArray:
        """Maugis--Dugdale within ``tol`` of the full law."""
        return self.agrees("md")


def default_mu(n: int | None = None, mu_min: float = MU_MIN, mu_max: float | None = None):
    r"""The default ``mu`` grid: geometric from ``mu_min`` to ``mu_max``.

    ``mu_max`` defaults to :data:`MU_MAX` (the Maugis parameter 100) or the upper end of the
    Lennard-Jones solver's domain (:func:`domain_mu_max`, read now), whichever is lower;
    ``n`` to four per decade of the Maugis parameter (:math:`\lambda \propto \mu^{2/3}`) and one, at
    least 10 and at most 17 (17 over the Maugis parameters 0.01 to 100, 11 to :math:`\mu = 3`).
    """
    hi = min(MU_MAX, domain_mu_max()) if mu_max is None else float(mu_max)
    if n is None:
        n = int(np.clip(round(4 * (2 / 3) * math.log10(hi / mu_min)) + 1, 10, 17))
    return np.geomspace(mu_min, hi, n)


def default_y(n: int = N_Y, y_max: float = Y_RANGE[1]):
    """The default loads above pull-off over its magnitude: geometric from 0.01 to ``y_max``."""
    return np.geomspace(Y_RANGE[0], y_max, n)


def _pulloff_bound(mu: float) -> float:
    r"""An upper bound of the magnitude of the full law's pull-off at ``mu``.

    The rigid cylinder's (2.4661; elasticity lowers it) and JKR's, :math:`1.7435\, \mu^{-1/3}`.
    """
    return min(2.4661, 1.7435 * mu ** (-1.0 / 3.0))


def _check_inputs(mu, y, tol) -> tuple[NDArray, NDArray, float]:
    hi = domain_mu_max()
    mu = check_array("mu", default_mu() if mu is None else mu, high=hi, high_inclusive=True)
    y = check_array("y", default_y() if y is None else y)
    for name, v in (("mu", mu), ("y", y)):
        if v.ndim > 1:
            raise ValueError(f"{name} must be a number or a 1-D array, got shape {v.shape}")
    if isinstance(tol, (bool, np.bool_)) or not isinstance(tol, (int, float, np.number)):
        raise ValueError(f"tol must be a number in (0, 1), got {tol!r}")
    tol = float(tol)
    if not (0.0 < tol < 1.0):
        raise ValueError(f"tol must be a number in (0, 1), got {tol!r}")
    return np.unique(mu), np.unique(y), tol


def _map_row(mu: float, y: NDArray) -> _Row:
    """The full law's branch at ``mu`` to the largest load of ``y``, at the loads ``y``.

    The branch is solved to ``F_max = (max(y) + 1) * _pulloff_bound(mu)``; if that bound of
    the pull-off fails, again to 1.05 times the largest load asked for.
    """
    F_max = (float(y[-1]) + 1.0) * _pulloff_bound(mu)
    br = full_law_branch(mu, F_max)
    F = br.F_pulloff + y * abs(br.F_pulloff)
    if F[-1] > br.F[-1]:  # the bound failed: continue the curve to the loads asked for
        br = full_law_branch(mu, 1.05 * float(F[-1]))
        F = br.F_pulloff + y * abs(br.F_pulloff)
    return _Row(
        F_pulloff=float(br.F_pulloff),
        y_onset=float(br.y_onset),
        half_width=np.asarray(lj_half_width(br, F), float),
        lj_error_estimate=float(np.max(br.error_estimate)),
        interpolation_error=interpolation_error(br),
        n_states=int(br.F.size),
    )


def adhesion_map(
    mu: ArrayLike | None = None,
    y: ArrayLike | None = None,
    *,
    tol: float = 0.05,
    progress: Callable[[str], object] | bool | None = None,
    workers: int | None = None,
    resume_dir: str | os.PathLike[str] | None = None,
) -> AdhesionMap:
    r"""The adhesion map of line contact: each simpler model's error against the full law.

    Parameters
    ----------
    mu : array_like, optional
        Values of :math:`w \sqrt{R/z_0}/(E z_0)`, ``> 0`` and at most the upper end of the
        Lennard-Jones solver's domain (``linecontact.domain.DOMAIN["lj_mu"]``); sorted,
        repeats dropped. Default :func:`default_mu` (the Maugis parameters 0.01 to 100, or
        to the end of that domain if it is sooner).
    y : array_like, optional
        Loads above the full law's pull-off over its magnitude, ``> 0``; sorted, repeats
        dropped. Default :func:`default_y` (81 values from 0.01 to 30).
    tol : float, default 0.05
        A model agrees where the relative error of its half-width is at most ``tol``, in
        ``(0, 1)``.
    progress : callable or bool, optional
        A callable is called with a short message (``"7/13 curves, 12.3 s"``; ``"(3
        resumed)"`` after the count where rows came from ``resume_dir``) once before the
        first curve and after each one. ``True``: a progress bar of the curves done (those
        resumed included) on stderr (tqdm where installed, else a plain line). ``False`` or
        None (the default): nothing.
    workers : int, optional
        Processes computing the curves (one per ``mu``, each independently: the map is the
        one computed in this process, whatever ``workers``), at least 1; 1 computes them in
        this process. Default: the cores this process may run on. No more are started than
        there are curves to compute.
    resume_dir : path, optional
        A directory (created if missing) where each curve's row is kept in its own file as
        soon as it is done (written atomically: a run stopped at any moment leaves only
        whole files), keyed by ``mu``, ``y`` and the library (version and code). Rows found
        there are not computed again: a stopped run, rerun with the same arguments, goes on
        where it stopped. The map's files are removed when it is complete, and the
        directory if it is then empty.

    Returns
    -------
    AdhesionMap

    Raises
    ------
    ValueError
        If ``mu`` or ``y`` holds a non-positive or non-finite value or is not 1-D, ``mu``
        lies beyond the domain, ``tol`` is not in ``(0, 1)``, ``workers`` is not an integer
        >= 1, or ``resume_dir`` cannot be created.
    ConvergenceError
        If the Lennard-Jones solver fails.

    Notes
    -----
    Cost: one :func:`~linecontact.lennard_jones.lj_curve` per ``mu``, to
    :math:`F_\text{max} = (\max y + 1) \min(2.4661, 1.7435\, \mu^{-1/3})` (a bound of the pull-off's
    magnitude), and a few states (:func:`full_law_branch`); the models are closed forms,
    or vectorised (:func:`md_half_width`). Measured on two otherwise idle cores before the
    curves ran in parallel: the grid of 13 values of :math:`\mu` from 0.01 to 3, 81 loads to
    :math:`y = 30`, 56 s, most of it beyond :math:`\mu = 1` (the solver's meshes follow the
    contact's edge, :math:`1/\mu` long); the coarse grid of
    :mod:`linecontact.figures.adhesion_map` (4 values to :math:`\mu = 1`, 41 loads to
    :math:`y = 10`) 9 s. ``benchmarks/adhesion_map.py`` times the default map with 1 and 2 workers.
    """
    mu, y, tol = _check_inputs(mu, y, tol)
    workers = _check_workers(workers)
    store = _store(resume_dir)
    say = progress if callable(progress) else (lambda msg: None)
    t0 = time.perf_counter()
    keys = [_row_key(float(m), y) if store is not None else "" for m in mu]
    paths: list[pathlib.Path] = []
    rows: list[_Row | None] = [None] * mu.size
    if store is not None:
        paths = [_entry(store, float(m), k) for m, k in zip(mu, keys, strict=True)]
        rows = [_read_row(p, k, y.size) for p, k in zip(paths, keys, strict=True)]
    resumed = sum(r is not None for r in rows)
    count = [resumed]

    def report() -> None:
        note = f" ({resumed} resumed)" if resumed else ""
        say(f"{count[0]}/{mu.size} curves{note}, {time.perf_counter() - t0:.1f} s")

    def done(k: int, row: _Row) -> None:
        rows[k] = row
        count[0] += 1
        report()
        bar.update(1)

    tasks = [
        (k, float(mu[k]), y, str(paths[k]) if store is not None else None, keys[k])
        for k, r in enumerate(rows)
        if r is None
    ]
    report()
    show = progress is True  # a bar of the curves done, the resumed ones as its start
    with progress_bar(mu.size, "map", show, initial=resumed, unit=" curves") as bar:
        _run(tasks, min(workers, len(tasks)), done, _map_row)  # looked up now (tests replace it)
    full = [r for r in rows if r is not None]
    F_po = np.array([[r.F_pulloff] for r in full])
    F = F_po + y * np.abs(F_po)
    xi = np.array([r.half_width for r in full])
    M = mu[:, None]
    widths = {
        "hertz": hertz_half_width(F, M),
        "rigid": rigid_half_width(F),
        "jkr": jkr_half_width(F, M),
        "md": md_half_width(F, M),
    }
    errors = {}
    with np.errstate(invalid="ignore", divide="ignore"):
        for name, w in widths.items():
            e = np.abs(w - xi) / xi
            e = np.where(np.isnan(w), np.inf, e)
            errors[name] = np.where(xi > 0, e, np.nan)
    result = AdhesionMap(
        mu=M,
        maugis_parameter=np.asarray(maugis_parameter_of_mu(M)),
        y=y,
        F=F,
        F_pulloff=F_po,
        y_onset=np.array([[r.y_onset] for r in full]),
        half_width_lj=xi,
        half_width_hertz=widths["hertz"],
        half_width_rigid=widths["rigid"],
        half_width_jkr=widths["jkr"],
        half_width_md=widths["md"],
        error_hertz=errors["hertz"],
        error_rigid=errors["rigid"],
        error_jkr=errors["jkr"],
        error_md=errors["md"],
        tol=tol,
        R_over_h_md=MD_R_OVER_H,
        lj_error_estimate=np.array([[r.lj_error_estimate] for r in full]),
        interpolation_error=np.array([[r.interpolation_error] for r in full]),
        n_states=np.array([[r.n_states] for r in full]),
    )
    if store is not None:
        _clear(store, paths)
    return result
