r"""Pull-off under load control (:func:`pull_off`): the global minimum of the contact branch.

The minimum and its label (snap-off or zero-width, ``docs/derivations.md``, Sec. 4), found
per parameter point on the closed form of :mod:`linecontact.normal.contact`.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _numerics as _num
from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import (
    broadcast,
    scalar_or_array,
)
from ..closed_forms.maugis_dugdale import _at_minimum
from ..results import SI, Result, as_result
from ..sie import _in_chunks
from .contact import _ustar

#: The pull-off is called a snap-off when the contact half-width at the load minimum is at
#: least this many ranges ``h`` of the adhesive stress (``h = 0.97 z0``, about one atomic
#: spacing); a contact that shrinks below that width before it lets go peels to zero width
#: (docs/derivations.md, Sec. 4). The label only: the pull-off force is always the minimum.
SNAP_OFF_MIN_WIDTH_OVER_H = 1.0


#: ... and the pull-off is called a snap-off too when it lies more than this fraction of
#: Eq. (14) below Eq. (14), however narrow the contact it lets go from: ``"zero-width"``
#: promises a pull-off force that is Eq. (14) to within 1 % (at small ``R/h`` a contact
#: narrower than ``h`` can let go far below it, e.g. 39 % at ``R/h = 1``, ``sigma0/E = 2``).
ZERO_WIDTH_LOAD_RTOL = 1e-2


@dataclass(frozen=True)
class _PullOffBase(Result):
    """The fields that open a pull-off: its force, the state it lets go from, and how.

    Those of :class:`PullOff` and of the faceted wire's
    :class:`~linecontact.facet.FacetPullOff`, with the load at vanishing width.
    """

    F_pulloff_over_Eh: NDArray | float = field(metadata=SI("pull_off_force", "Eh", "N/m"))
    a_over_R_at_pulloff: NDArray | float = field(
        metadata=SI("contact_half_width_at_pull_off", "R", "m")
    )
    c_over_R_at_pulloff: NDArray | float
    mechanism: NDArray | str
    F_zero_width_over_Eh: NDArray | float = field(metadata=SI("zero_width_force", "Eh", "N/m"))


@dataclass(frozen=True)
class PullOff(_PullOffBase):
    """Pull-off under load control: the global minimum of the load on the contact branch.

    Attributes
    ----------
    F_pulloff_over_Eh : ndarray or float
        The pull-off force over ``E h`` (negative).
    a_over_R_at_pulloff, c_over_R_at_pulloff : ndarray or float
        Half-widths at pull-off, the state of the minimum (:math:`a = 0`, the touching state,
        when the minimum is Eq. 14 itself: no adhesion, or a width below the floating-point
        range).
    mechanism : ndarray of str or str
        ``"snap-off"``: the contact lets go from a half-width of at least the adhesion range
        ``h`` (:data:`SNAP_OFF_MIN_WIDTH_OVER_H`), or at a load more than 1 % below Eq.
        (14) (:data:`ZERO_WIDTH_LOAD_RTOL`); ``"zero-width"``: it first peels to a width
        below ``h`` and lets go at a load within 1 % of Eq. (14).
    F_zero_width_over_Eh : ndarray or float
        Eq. (14), the load at vanishing contact width.
    F_minimum_over_Eh, a_over_R_at_minimum : ndarray or float
        The minimum of the load on the contact branch and its width (equal to the pull-off
        force and width; kept under these names for existing callers).
    kappa, maugis_parameter : ndarray or float
        The group that fixes the shape of the load curve, and Baney & Hui's lambda.
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    F_minimum_over_Eh: NDArray | float
    a_over_R_at_minimum: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    kappa: NDArray | float
    maugis_parameter: NDArray | float


def _pulloff_arrays(rho: NDArray, s: NDArray, scalar: bool = False, keys=None):
    """:func:`_pulloff_flat` at arrays of any shape, or at NumPy scalars (``scalar``).

    ``keys``: the entries wanted (all by default); the arrays are computed in chunks of
    points (bounded memory for any number of them).
    """
    if scalar:
        rho0, s0 = _num._scalars(rho, s)
        return _pulloff_flat(rho0, s0, keys)
    shape = np.shape(rho)
    rho = np.asarray(rho, dtype=float).reshape(-1)
    s = np.asarray(s, dtype=float).reshape(-1)
    d = _in_chunks(functools.partial(_pulloff_flat, keys=keys), rho.size, rho, s)
    return {k: np.reshape(v, shape) for k, v in d.items()}


def _c_at_pulloff(A_min, C_min, sq, kap):
    """C/R at pull-off: ``C_min``, or the touching state's where the width is 0 (Eq. 14).

    For arrays the touching state is evaluated at those points only.
    """
    if not isinstance(A_min, np.ndarray):
        return C_min if A_min > 0 else _zero_c(sq, kap)
    touch = np.flatnonzero(~(A_min > 0))
    if touch.size == 0:
        return C_min
    C = np.array(C_min, dtype=float)
    C[touch] = _zero_c(np.broadcast_to(sq, C.shape)[touch], np.broadcast_to(kap, C.shape)[touch])
    return C


def _zero_c(sq, kap):
    """C/R of the touching state (a = 0) for group kappa; ``sq = sqrt(2 / (R/h))``."""
    return sq * 2 / (kap * _cf.LN2 + np.sqrt(kap * kap * _cf.LN2**2 + 4))


#: The two labels, indexed by ``snap`` (an array of them taken at once).
_MECHANISMS = np.array(["zero-width", "snap-off"])


def _mechanism(snap):
    """``"snap-off"`` where ``snap``, ``"zero-width"`` elsewhere (arrays or a bool)."""
    if isinstance(snap, np.ndarray):
        return _MECHANISMS.take(snap.astype(np.intp))
    return "snap-off" if snap else "zero-width"


def _pulloff_flat(rho: NDArray, s: NDArray, keys=None):
    """Pull-off at flat arrays or NumPy scalars (elementwise; see _numerics._where).

    ``keys``: the entries of the dict returned (all by default).
    """
    where = _num._where
    kap = _cf._kappa(rho, s)
    F0 = _cf._zero_width(rho, s)
    us = _ustar(kap)
    fin: NDArray | bool = np.isfinite(us)
    if isinstance(fin, np.ndarray) and fin.all():
        fin = True  # kappa > 0 everywhere (the usual batch): each where below is its value
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        uf = where(fin, us, 1.0)  # kappa = 0: no interior minimum (any finite u will do)
        abar, X, Ct, phi = _at_minimum(uf, kap)
        sq = np.sqrt(2 / rho)
        A_min = where(fin, abar * sq, 0.0)
        C_min = where(fin, X * Ct * sq, 0.0)
        F_min = where(fin, _num._minimum((np.pi / 2) * phi, F0), F0)
        # the load minimum along the branch in units of Phi = (2/pi) F/(Eh) (contact_for_load)
        phi_min = where(fin, _num._minimum(phi, F0 * (2 / np.pi)), F0 * (2 / np.pi))
    # the pull-off force is the minimum of the load, at the width of u* (however small: the
    # stability of every state is judged against it); the label says whether the contact
    # lets go from a width the continuum model resolves (at least the range h) or peels
    # below it
    snap = (F_min < F0) & (
        (A_min >= SNAP_OFF_MIN_WIDTH_OVER_H / rho) | (F0 - F_min > ZERO_WIDTH_LOAD_RTOL * abs(F0))
    )
    d = dict(
        F_pulloff_over_Eh=F_min,
        a_over_R_at_pulloff=A_min,
        c_over_R_at_pulloff=_c_at_pulloff(A_min, C_min, sq, kap),
        mechanism=_mechanism(snap),
        F_zero_width_over_Eh=F0,
        F_minimum_over_Eh=F_min,
        a_over_R_at_minimum=A_min,
        kappa=kap,
        us=us,
        phi_min=phi_min,
    )
    return d if keys is None else {k: d[k] for k in keys}


def pull_off(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> PullOff:
    r"""Pull-off force under load control, vectorised over parameter points.

    The load along the contact branch has exactly one stationary point, a minimum, for every
    :math:`\sigma_0 > 0` (``docs/derivations.md``); it is found as the root of a monotone
    function of :math:`u = \operatorname{arccosh}(c/a)`, so no grid can miss it. The
    pull-off force is that minimum. The mechanism is ``"snap-off"`` when the contact
    half-width there is at least the range ``h`` of the adhesive stress
    (:data:`SNAP_OFF_MIN_WIDTH_OVER_H`) or the force more than 1 % below Eq. (14)
    (:data:`ZERO_WIDTH_LOAD_RTOL`), ``"zero-width"`` otherwise: the contact then peels
    below the range of the surface forces and lets go at a load within 1 % of Eq. (14)
    (at most 2e-3 of it for :math:`R/h \ge 100`, 2e-5 for :math:`R/h \ge 10^4`; see
    ``docs/derivations.md``). The pull-off state is the minimum in either case, and it is
    the one the load curve marks (:func:`load_curve`, ``linecontact curve``).

    Parameters
    ----------
    R_over_h : array_like
        ``> 0``.
    sigma0_over_E : array_like
        ``>= 0`` (0: Hertz, pull-off force 0 at zero width).

    Returns
    -------
    PullOff
        (The Lennard-Jones law's: :func:`linecontact.laws.lennard_jones.pull_off`.)

    Examples
    --------
    >>> po = pull_off(100.0, 0.01)       # peels to a width far below h, at Eq. (14)
    >>> po.mechanism, po.a_over_R_at_pulloff < 1e-3 / 100
    ('zero-width', True)
    >>> abs(po.F_pulloff_over_Eh / po.F_zero_width_over_Eh - 1) < 1e-8
    True
    >>> po = pull_off(100.0, 0.2)        # lets go at a/R = 0.087, far above h/R = 0.01
    >>> po.mechanism, round(po.a_over_R_at_pulloff, 4)
    ('snap-off', 0.0869)
    """
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    scalar = scalar_or_array(rho, s)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    _cf._check_kappa(rho, s)
    d = _pulloff_arrays(rho, s, scalar, _PUBLIC_KEYS)
    # the minimum is the pull-off: the same arrays under both names (no copy per name)
    d["F_minimum_over_Eh"] = d["F_pulloff_over_Eh"]
    d["a_over_R_at_minimum"] = d["a_over_R_at_pulloff"]
    lam = _cf._maugis_parameter(rho, s)
    return as_result(PullOff, scalar, R_over_h=rho, sigma0_over_E=s, maugis_parameter=lam, **d)


#: The entries of :func:`_pulloff_flat` that :func:`pull_off` returns, but for the two it
#: names twice (joined once: a 1e7-point call holds no array it does not return).
_PUBLIC_KEYS = (
    "F_pulloff_over_Eh",
    "a_over_R_at_pulloff",
    "c_over_R_at_pulloff",
    "mechanism",
    "F_zero_width_over_Eh",
    "kappa",
)
