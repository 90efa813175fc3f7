"""The monotone solution of each friction law of the tangential histories, in its own units.

Lengths over ``a``, stresses over the friction scale (``tau0``, or ``mu p0``), loads over
the full-slip load (``r = T/T_full``), slips and displacements over ``a (stress scale)/E``,
energies over ``E a^2 (stress scale/E)^2``: the closed forms of the Masing rules
(``_masing_rules.py``) and the pieces of the incremental solver (``_collocation.py``).

Each law (:data:`_Law`, one of :class:`_Constant` and :class:`_Coulomb`) has a ``name``,
its full-slip load ``T_full`` over (stress scale) a, and

* ``stick(r)``: the stick-zone half-width over a at the monotone load r = T/T_full in [0, 1];
* ``displacement(r)``: the monotone displacement D/a (datum a) over (stress scale)/E;
* ``virgin_loss(r)``: the energy dissipated by monotone loading from 0 to r, over
  E a^2 (scale/E)^2;
* ``traction(x, r)``: the monotone traction over the stress scale (x and r broadcast);
* ``slip(x, r)``: the monotone slip relative to the centre, over a (scale)/E (nan beyond
  |x| = 1);

and the collocation pieces: ``B(x)``, the slip-zone traction (times the direction),
``HB(x)``, its transform (1/pi) PV int_{-1}^{1} B(xi)/(xi - x) dxi for |x| < 1, and
``logB(x)`` = int_{-1}^{1} B(xi) ln|x - xi| dxi.
"""

from __future__ import annotations

import math
from typing import TypeAlias

import numpy as np

from ...sie import chebyshev_log_expansion
from .._core import _xlogy
from ..initiation import _init_slip_closed


def _series(x, coef_of_k, k0: int, kmax: int):
    """sum_{k = k0..kmax} coef_of_k(k) x^k (small x: the closed forms cancel there)."""
    out = np.zeros_like(x)
    p = x**k0
    for k in range(k0, kmax + 1):
        out = out + coef_of_k(k) * p
        p = p * x
    return out


class _Constant:
    """Constant friction stress ``tau0``."""

    name = "constant"
    T_full = 2.0  # full-slip load over (stress scale) a

    def stick(self, r):
        return np.sqrt(np.clip((1 - r) * (1 + r), 0.0, None))

    def displacement(self, r):
        # (4/pi) [r (1 + ln 2) - ((1 + r) ln(1 + r) - (1 - r) ln(1 - r))/2]
        r = np.asarray(r, float)
        odd = _xlogy(1 + r, 1 + r) - _xlogy(1 - r, 1 - r)
        return (4 / np.pi) * (r * (1 + math.log(2)) - odd / 2)

    def virgin_loss(self, r):
        # (8/pi) h(r), h = ((1+r) ln(1+r) + (1-r) ln(1-r))/2 - r^2/2 = sum_{k>=2} r^2k/(2k(2k-1))
        r = np.abs(np.asarray(r, float))
        small = r < 0.3
        rs = np.where(small, r, 0.0)
        h_series = _series(rs * rs, lambda k: 1.0 / (2 * k * (2 * k - 1)), 2, 18)
        h_direct = (_xlogy(1 + r, 1 + r) + _xlogy(1 - r, 1 - r)) / 2 - r * r / 2
        return (8 / np.pi) * np.where(small, h_series, h_direct)

    def traction(self, x, r):
        d = self.stick(r)
        ax = np.abs(x)
        inner = (2 / np.pi) * np.arctan2(r, np.sqrt(np.clip(d * d - x * x, 0.0, None)))
        return np.where(ax <= 1.0, np.where(ax < d, inner, 1.0), 0.0)

    def slip(self, x, r):
        d = self.stick(r)
        ax = np.abs(x)
        xs = np.clip(ax, d, 1.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            val = (4 / np.pi) * _init_slip_closed(xs, d)
        return np.where(ax > 1.0, np.nan, np.where(ax <= d, 0.0, val))

    def B(self, x):
        return np.ones_like(x)

    def HB(self, x):
        return -(2 / np.pi) * np.arctanh(x)

    def logB(self, x):
        return _xlogy(1 + x, np.abs(1 + x)) + _xlogy(1 - x, np.abs(1 - x)) - 2.0


class _Coulomb:
    """Coulomb friction on the Hertz contact (stress scale ``mu p0``)."""

    name = "coulomb"
    T_full = np.pi / 2  # full-slip load over (stress scale) a

    def stick(self, r):
        return np.sqrt(np.clip(1 - r, 0.0, None))

    def displacement(self, r):
        # Q (1/2 + ln 2) + (1 - Q) ln(1 - Q)/2
        r = np.asarray(r, float)
        return r * (0.5 + math.log(2)) + _xlogy(1 - r, 1 - r) / 2

    def virgin_loss(self, r):
        # (pi/2) h_c(Q), h_c = (1-Q) ln(1-Q)/2 + Q/2 - Q^2/4 = sum_{k>=3} Q^k/(2k(k-1))
        r = np.abs(np.asarray(r, float))
        small = r < 0.25
        rs = np.where(small, r, 0.0)
        h_series = _series(rs, lambda k: 1.0 / (2 * k * (k - 1)), 3, 30)
        h_direct = _xlogy(1 - r, 1 - r) / 2 + r / 2 - r * r / 4
        return (np.pi / 2) * np.where(small, h_series, h_direct)

    def traction(self, x, r):
        d = self.stick(r)
        xc = np.clip(x, -1.0, 1.0)
        q = np.sqrt(1 - xc * xc) - np.sqrt(np.clip(d * d - x * x, 0.0, None))
        return np.where(np.abs(x) <= 1.0, q, 0.0)

    def slip(self, x, r):
        # x^2 - d^2 (e^{-2v}/2 + v + 1/2), cosh v = |x|/d, outside the stick zone
        d = self.stick(r)
        ax = np.abs(x)
        with np.errstate(divide="ignore", invalid="ignore"):
            y = np.where(d > 0, np.clip(ax, d, 1.0) / np.where(d > 0, d, 1.0), 1.0)
        v = np.arccosh(y)
        val = ax * ax - d * d * (np.exp(-2 * v) / 2 + v + 0.5)
        return np.where(ax > 1.0, np.nan, np.where(ax <= d, 0.0, val))

    def B(self, x):
        return np.sqrt(np.clip(1 - x * x, 0.0, None))

    def HB(self, x):
        return -x

    def logB(self, x):
        c0, e = chebyshev_log_expansion(x, 2)
        return (np.pi / 2) * (e[..., 2] / 2 + c0)


#: One friction law: either strategy, each with the same attributes and methods (module docstring).
_Law: TypeAlias = _Constant | _Coulomb

_LAWS: dict[str, _Law] = {"constant": _Constant(), "coulomb": _Coulomb()}
