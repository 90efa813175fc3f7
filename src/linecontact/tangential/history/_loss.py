"""Cyclic tangential loading between ``-T*`` and ``+T*``: the loss per cycle and the loop.

:func:`cyclic_loss` (constant friction stress) and :func:`cyclic_loss_coulomb` (Coulomb
friction): the closed form of the steady (Masing) loop, or the friction work of the
incremental solver over one cycle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ... import domain as _domain
from ..._validation import check_array
from ...errors import ConvergenceError
from ...results import SI, Result
from .._core import _build
from ._collocation import N_INCREMENTAL, N_MAX_INCREMENTAL, _incremental
from ._histories import _SLIDING, _STICK_SLIP, _T_LIMIT, _check_method
from ._laws import _LAWS, _Law

#: The friction work of the incremental solver differences displacements of order one over
#: the slip annulus :math:`c < |x| < a` at the peaks: its relative round-off grows like
#: :math:`\epsilon (1 - c/a)^{-3/2}` (measured: 4e-7 at :math:`1 - c/a = 5 \times 10^{-7}`, Coulomb
#: friction).
_EPS_LOSS = float(np.finfo(float).eps)

_C = TypeVar("_C", bound="_Cyclic")


@dataclass(frozen=True)
class _Cyclic(Result):
    T_amplitude_over_Ea: NDArray | float = field(metadata=SI("amplitude", "Ea", "N/m"))
    T_amplitude_over_T_full_slip: NDArray | float
    W_over_Ea2: NDArray | float = field(metadata=SI("energy_per_cycle", "Ea2", "J/m"))
    c_over_a: NDArray | float = field(metadata=SI("stick_zone_half_width", "a", "m"))
    state: NDArray | str
    method: str

    def loop(self, num: int = 101) -> dict[str, NDArray]:
        r"""The steady loop: :math:`T/(E a)`, :math:`D/a` from :math:`+T^*` down and back.

        Returns arrays of shape ``points.shape + (2 num - 1,)``: the unloading branch from
        :math:`+T^*` to :math:`-T^*` then the reloading branch back to :math:`+T^*` (``nan`` for
        sliding points). The datum of ``D`` is at depth ``a``.
        """
        if isinstance(num, bool) or not isinstance(num, (int, np.integer)) or num < 2:
            raise ValueError(f"num must be an integer >= 2, got {num!r}")
        law, scale = self._law_scale()
        r = np.asarray(self.T_amplitude_over_T_full_slip, float)[..., None]
        r = np.where(r < 1, r, np.nan)
        u = np.linspace(0.0, 1.0, num)
        down = r * (1 - 2 * u)  # +r to -r
        up = r * (2 * u[1:] - 1)  # -r to +r
        g = law.displacement
        D_peak = g(r)
        D_down = D_peak - 2 * g((r - down) / 2)
        D_up = -D_peak + 2 * g((up + r) / 2)
        T = np.concatenate([down, up], axis=-1) * (law.T_full * scale)
        D = np.concatenate([D_down, D_up], axis=-1) * scale
        return {"T_over_Ea": T, "displacement_over_a": D}

    def _law_scale(self):  # pragma: no cover - defined by the subclasses
        raise NotImplementedError


@dataclass(frozen=True)
class CyclicLoss(_Cyclic):
    r"""Cyclic tangential loading between ``-T*`` and ``+T*``, constant friction stress.

    Attributes
    ----------
    T_amplitude_over_Ea : ndarray or float
        :math:`T^*/(E a)`.
    T_amplitude_over_T_full_slip : ndarray or float
        :math:`r = T^*/(2 a \tau_0)`.
    W_over_Ea2 : ndarray or float
        Energy dissipated per cycle per unit length over :math:`E a^2` (steady loop):
        :math:`(32/\pi)(\tau_0/E)^2 h(r)`, :math:`h = [(1+r)\ln(1+r) + (1-r)\ln(1-r)
        - r^2]/2`; ``nan`` when sliding (the gross-sliding loss is not computed).
    c_over_a : ndarray or float
        Stick-zone half-width at the peaks, :math:`\sqrt{1 - r^2}` (``nan`` sliding).
    state : ndarray of str or str
        ``"stick-slip"``, or ``"sliding"`` at or above full slip (:math:`r \ge 1`).
    tau0_over_E : ndarray or float
    method : str
        ``"closed-form"`` or ``"incremental"`` (three steps of the incremental solver per
        amplitude, the loss as the friction work over the last two).
    """

    inputs: ClassVar[tuple[str, ...]] = ("tau0_over_E", "method")

    tau0_over_E: NDArray | float = 0.0

    def _law_scale(self):
        return _LAWS["constant"], np.asarray(self.tau0_over_E, float)[..., None]


@dataclass(frozen=True)
class CoulombCyclicLoss(_Cyclic):
    r"""Cyclic tangential loading of a Hertz line contact with Coulomb friction.

    As :class:`CyclicLoss` with ``T_amplitude_over_T_full_slip = T_amplitude_over_muF =
    Q = T*/(mu F)`` and :math:`W/(E a^2) = (\pi/2)\mu^2(a/R)^2
    [(1-Q)\ln(1-Q)/2 + Q/2 - Q^2/4]`, the stick zone :math:`\sqrt{1 - Q}` at the peaks.
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu", "a_over_R", "method")

    T_amplitude_over_muF: NDArray | float = 0.0
    mu: NDArray | float = 0.0
    a_over_R: NDArray | float = 0.0

    def _law_scale(self):
        return _LAWS["coulomb"], (
            np.asarray(self.mu, float) * np.asarray(self.a_over_R, float) / 2
        )[..., None]


def _loss_roundoff(law: _Law, r: float) -> float:
    r"""Relative round-off of the incremental solver's loss per cycle at the amplitude ``r``.

    :math:`\epsilon (1 - c/a)^{-3/2}` with :math:`c` the stick zone at the peaks (``_EPS_LOSS``): an
    upper bound of the measured error (Coulomb: :math:`3 \times 10^{-16} Q^{-3/2}`; constant stress:
    lower).
    """
    # 1 - c/a without cancellation: 1 - c^2 = r^2 (constant stress) or r (Coulomb)
    u = r * r if law.name == "constant" else r
    gap = u / (1.0 + math.sqrt(max(1.0 - u, 0.0)))
    return math.inf if gap <= 0 else _EPS_LOSS * gap**-1.5


def _too_small(tol: float, r: float, estimate: float, n: int) -> str:
    """The message of an amplitude too small for the incremental solver."""
    return (
        f"the incremental solver missed tol={tol:g} at the amplitude {r!r} of the full-slip "
        f"load (estimate {estimate:.2e}, n={n}): an amplitude this small needs more than "
        f"{N_MAX_INCREMENTAL} nodes; use method='closed-form'"
    )


def _amplitudes(name: str, value: ArrayLike) -> NDArray:
    """The checked amplitudes ``value`` of the load ``name``: in ``(0, _T_LIMIT]``."""
    return check_array(
        name, value, low=0.0, low_inclusive=False, high=_T_LIMIT, high_inclusive=True
    )


def _cyclic(
    cls: type[_C],
    law: _Law,
    T: NDArray,
    r: NDArray,
    scale: NDArray,
    method: str,
    n: int,
    tol: float,
    inputs: dict[str, NDArray],
) -> _C:
    """The result ``cls`` for the amplitudes ``T`` over E a, ``r`` over the full-slip load.

    ``T``, ``r``, ``scale`` (the friction stress over E) and the ``inputs`` (the result's
    other fields) broadcast to the points; W over E a^2, the stick zone and the state follow.
    """
    scalar = r.ndim == 0
    sliding = r >= 1.0
    rr = np.where(sliding, 0.0, r)
    if method == "closed-form":
        w = 4 * law.virgin_loss(rr)
    else:
        w = np.empty(r.shape)
        # refused at once: an amplitude whose slip annulus is too thin for the loss to be
        # resolved to tol (the solver would spend seconds and miss tol, or lose the loss to
        # round-off); the tolerance is checked before the solver is entered
        for i, ri in np.ndenumerate(rr):
            if not sliding[i]:
                est = _loss_roundoff(law, float(ri))
                if not est <= tol:
                    raise ConvergenceError(_too_small(tol, float(ri), est, N_MAX_INCREMENTAL))
        for i, ri in np.ndenumerate(rr):
            if sliding[i]:
                w[i] = np.nan
                continue
            m = _incremental(law, np.array([ri, -ri, ri]), n)
            bad = max(m["error_estimate"].max(), m["residual_stick"].max())
            if not bad <= tol:
                raise ConvergenceError(
                    _too_small(tol, float(ri), bad, int(m["n_collocation"].max()))
                )
            w[i] = m["loss"][1] + m["loss"][2]
    W = np.where(sliding, np.nan, scale * scale * w)
    c = np.where(sliding, np.nan, law.stick(rr))
    state = np.where(sliding, _SLIDING, _STICK_SLIP)
    loads = {"T_amplitude_over_Ea": T, "T_amplitude_over_T_full_slip": r}
    return _build(cls, method, scalar, **loads, W_over_Ea2=W, c_over_a=c, state=state, **inputs)


def cyclic_loss(
    tau0_over_E: ArrayLike,
    T_amplitude_over_Ea: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
) -> CyclicLoss:
    r"""Energy dissipated per cycle of tangential loading between ``-T*`` and ``+T*``.

    Constant friction stress ``tau0``. The loop is steady from the first cycle (Masing):
    unloading from ``+T*`` and reloading from ``-T*`` are the monotone solution for
    ``2 tau0`` under the load change, and the loop closes at ``+T*``.

    Parameters
    ----------
    tau0_over_E : array_like
        Friction stress over the composite modulus, in ``[1e-12, 1]``.
    T_amplitude_over_Ea : array_like
        Amplitude :math:`T^*/(E a)`, ``> 0``. At or above full slip (:math:`2 \tau_0/E`) the point
        is reported as ``state == "sliding"`` with ``W_over_Ea2 = nan``.
    method : {"closed-form", "incremental"}
        The closed form, or the friction work of the incremental solver over one cycle.
    n, tol
        Nodes and tolerance of the incremental solver.

    Returns
    -------
    CyclicLoss
        Inputs broadcast together; scalars in, scalars out. :meth:`CyclicLoss.loop` draws
        the loop.

    Notes
    -----
    :math:`W = \frac{32}{\pi}\frac{\tau_0^2a^2}{E}\,h(r)`, :math:`r = T^*/(2a\tau_0)`,
    :math:`h = \frac12[(1+r)\ln(1+r) + (1-r)\ln(1-r)] - \frac{r^2}{2}
    = \sum_{k\ge2} \frac{r^{2k}}{2k(2k-1)}`: :math:`W \propto T^{*4}` at small amplitude
    (Coulomb friction: :math:`T^{*3}`), and
    :math:`W \to (32/\pi)(\ln 2 - 1/2)\tau_0^2 a^2/E` at full slip.

    Examples
    --------
    >>> w = cyclic_loss(0.01, [0.0002, 0.0004])
    >>> ratio = w.W_over_Ea2[1] / w.W_over_Ea2[0]
    >>> bool(15.99 < ratio < 16.01)       # ~ 2^4 at small amplitude
    True
    >>> cyclic_loss(0.01, 0.02).state
    'sliding'
    """
    _check_method(method, n, tol)
    t0 = _domain.check("tau0_over_E", tau0_over_E)
    t0, A = np.broadcast_arrays(t0, _amplitudes("T_amplitude_over_Ea", T_amplitude_over_Ea))
    r = A / (2 * t0)
    return _cyclic(CyclicLoss, _LAWS["constant"], A, r, t0, method, n, tol, {"tau0_over_E": t0})


def cyclic_loss_coulomb(
    mu: ArrayLike,
    a_over_R: ArrayLike,
    T_amplitude_over_muF: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
) -> CoulombCyclicLoss:
    r"""Energy dissipated per cycle by a Hertz line contact with Coulomb friction.

    Mindlin--Deresiewicz for the line contact: :math:`W/(E a^2) = \frac{\pi}{2}\mu^2
    (a/R)^2\,[\frac12(1-Q)\ln(1-Q) + \frac{Q}{2} - \frac{Q^2}{4}]`, :math:`Q = T^*/(\mu F)`;
    :math:`\approx (\pi/24)\mu^2(a/R)^2 Q^3` at small amplitude, :math:`(\pi/8)\mu^2(a/R)^2`
    at full slip.

    Parameters
    ----------
    mu, a_over_R : array_like
        Coefficient of friction and Hertz half-width over the radius.
    T_amplitude_over_muF : array_like
        :math:`Q = T^*/(\mu F)`, ``> 0`` (:math:`\ge 1` slides).
    method, n, tol
        As in :func:`cyclic_loss`.

    Returns
    -------
    CoulombCyclicLoss

    Examples
    --------
    >>> w = cyclic_loss_coulomb(0.3, 0.01, [0.001, 0.002])
    >>> bool(7.99 < w.W_over_Ea2[1] / w.W_over_Ea2[0] < 8.01)   # ~ 2^3
    True
    """
    _check_method(method, n, tol)
    m = _domain.check("mu", mu)
    A = _domain.check("a_over_R", a_over_R)
    m, A, Q = np.broadcast_arrays(m, A, _amplitudes("T_amplitude_over_muF", T_amplitude_over_muF))
    T = (np.pi / 4) * m * A * Q
    inputs = dict(T_amplitude_over_muF=Q, mu=m, a_over_R=A)
    return _cyclic(CoulombCyclicLoss, _LAWS["coulomb"], T, Q, m * A / 2, method, n, tol, inputs)
