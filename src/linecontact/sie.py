r"""Gauss--Chebyshev quadrature and collocation for Cauchy singular integral equations.

This module knows no physics. It solves the dominant equation

.. math::

    \frac{1}{\pi}\,\mathrm{PV}\!\int_{\alpha}^{\beta} \frac{\phi(t)}{t - x}\,dt = f(x),
    \qquad \alpha < x < \beta,

by the method of Erdogan, Gupta & Cook (1973) for the three classes of solution:

``BoundedSolver``
    :math:`\phi = \sqrt{1-\tau^2}\,g(\tau)`, bounded at both ends. ``n`` nodes
    :math:`\tau_i = \cos(i\pi/(n+1))` and ``n + 1`` collocation points
    :math:`x_k = \cos((2k-1)\pi/(2n+2))`: one equation too many, which is the
    consistency condition :math:`\int f/\sqrt{1-x^2} = 0`. For odd (symmetric) problems it
    holds by itself (the middle equation, at :math:`x = 0`, is dropped); for the others an
    extra unknown multiplying a given right-hand side is determined by it.
``EndBoundedSolver``
    :math:`\phi = \sqrt{(1-\tau)/(1+\tau)}\,g(\tau)`, bounded at one end (either), ``n``
    equations in ``n`` unknowns.
``UnboundedSolver``
    :math:`\phi = g(\tau)/\sqrt{1-\tau^2}`, unbounded at both ends, with the side condition
    :math:`\int \phi = C`.

In every case :math:`\tau = (2t - \alpha - \beta)/(\beta - \alpha)` maps the interval onto
``[-1, 1]``; the equation keeps its form and :math:`\phi` its values under the map. The
bounded solver works in the Chebyshev basis: :math:`g = \sum_j b_j U_j` and
:math:`\frac{1}{\pi}\int_{-1}^{1}\sqrt{1-t^2}\,U_j(t)/(t-x)\,dt = -T_{j+1}(x)`, so the
collocation system is inverted exactly by the discrete orthogonality of :math:`T_j` at the
zeros of :math:`T_{n+1}` (the solution is identical to that of the collocation matrix of
Erdogan, Gupta & Cook; the tests check it).

Linear functionals of the solution are evaluated exactly for polynomial ``g`` of degree
``< n``: the resultant :math:`\int\phi`, the first moment :math:`\int t\phi`, and the
logarithmic moments :math:`\int \phi(t)\ln|y - t|\,dt` for any real ``y`` (inside, at an
end point, or outside the interval) by product integration, so that a logarithmic kernel
that is singular at an end point does not spoil convergence.

All solvers take right-hand sides with arbitrary leading (batch) dimensions: the last axis
runs over the collocation points.

References
----------
F. Erdogan, G. D. Gupta, T. S. Cook, "Numerical solution of singular integral equations",
in *Methods of Analysis and Solutions of Crack Problems*, G. C. Sih (ed.), Noordhoff (1973),
368--425. doi:10.1007/978-94-017-2260-5_7
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "SIZES",
    "BoundedSolution",
    "BoundedSolver",
    "EndBoundedSolver",
    "UnboundedSolver",
    "bounded_rule",
    "chebyshev_log_expansion",
    "dct2",
    "log_end_moments",
]

#: The ladder of collocation sizes that adaptive solvers climb (each step about 1.5x).
SIZES = (
    16,
    24,
    32,
    48,
    64,
    96,
    128,
    192,
    256,
    384,
    512,
    768,
    1024,
    1536,
    2048,
    3072,
    4096,
    6144,
    8192,
)


_DCT_FROM = 48  # from this size on the bounded solve uses the fast cosine transform

#: The collocation solvers of the problems work on batches of at most about this many
#: (point, node) pairs at a time, so that their memory does not grow with the number of
#: points (~30 arrays of this size are alive at once: ~60 MB).
_CHUNK_ELEMENTS = 1 << 18


def _chunks(size: int, n: int) -> list[slice]:
    """Slices of ``range(size)`` of at most ``_CHUNK_ELEMENTS // (n + 1)`` points (>= 1)."""
    step = max(1, _CHUNK_ELEMENTS // (n + 1))
    return [slice(i, min(i + step, size)) for i in range(0, size, step)]


def _in_chunks(kernel, size: int, *args):
    """``kernel(*args)`` on the chunks of :func:`_chunks` ``(size, 0)`` of the points, joined.

    For the closed forms, whose kernels hold a few hundred bytes per point while they work:
    chunk by chunk their memory does not grow with the number of points, and their arrays
    stay in cache. The arguments that are arrays of shape ``(size,)`` are cut into chunks,
    the others passed whole; the kernel returns an array, a tuple or a dict of arrays of
    its chunk's length, and so does this function, for all the points (a single chunk is
    the kernel's own call). The points are independent, so the values are the kernel's.
    """
    parts = _chunks(size, 0)
    if len(parts) <= 1:
        return kernel(*args)
    joined: dict = {}
    kind: type = dict
    for c in parts:
        out = kernel(*(a[c] if np.shape(a) == (size,) else a for a in args))
        if not isinstance(out, dict):
            kind = tuple if isinstance(out, tuple) else np.ndarray
            out = dict(enumerate(out)) if isinstance(out, tuple) else {0: out}
        for k, v in out.items():
            if k not in joined:
                joined[k] = np.empty(size, dtype=np.asarray(v).dtype)
            joined[k][c] = v
    if kind is dict:
        return joined
    return tuple(joined.values()) if kind is not np.ndarray else joined[0]


def _linalg():
    """``scipy.linalg``, imported on first use (not with the package, to keep it light)."""
    import scipy.linalg

    return scipy.linalg


def _check_n(n: int, minimum: int = 1, name: str = "n") -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {n!r}")
    return int(n)


def _check_interval(interval: tuple[float, float]) -> tuple[float, float]:
    try:
        lo, hi = (float(v) for v in interval)
    except (TypeError, ValueError):  # not a pair of real numbers
        raise ValueError(
            f"interval must be a pair (lo, hi) of real numbers, got {interval!r}"
        ) from None
    if not (np.isfinite(lo) and np.isfinite(hi) and hi > lo):
        raise ValueError(f"interval must be finite with lo < hi, got {interval!r}")
    return lo, hi


def _check_rhs(name: str, f: ArrayLike, m: int, what: str) -> NDArray:
    """``f`` as a float array with ``m`` values on its last axis (``what`` says why)."""
    arr = np.asarray(f, dtype=float)
    if arr.ndim == 0 or arr.shape[-1] != m:
        got = "a scalar" if arr.ndim == 0 else arr.shape[-1]
        raise ValueError(f"{name} must have {what} = {m} values on its last axis, got {got}")
    return arr


def dct2(x: ArrayLike) -> NDArray[np.float64]:
    r"""The type-II discrete cosine transform along the last axis, by one complex FFT.

    :math:`y_k = 2\sum_{j=0}^{N-1} x_j\cos(\pi k(2j+1)/(2N))`, ``scipy.fft.dct(x, type=2)``
    (Makhoul's reordering: even entries forward, odd ones backward, then a phase shift). It
    uses ``numpy.fft`` so that the collocation needs no SciPy import (0.3--0.4 s).

    Examples
    --------
    >>> import numpy as np
    >>> x = np.array([1.0, 2.0, 3.0])
    >>> k, j = np.arange(3)[:, None], np.arange(3)[None, :]
    >>> bool(np.allclose(dct2(x), 2 * (x * np.cos(np.pi * k * (2 * j + 1) / 6)).sum(axis=1)))
    True
    """
    x = np.asarray(x, dtype=float)
    N = x.shape[-1]
    v = np.concatenate([x[..., ::2], x[..., 1::2][..., ::-1]], axis=-1)
    V = np.fft.fft(v, axis=-1)
    phase = np.exp(-0.5j * np.pi * np.arange(N) / N)
    return 2.0 * (V * phase).real


def bounded_rule(n: int) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    r"""Nodes, weights and collocation points of the bounded Gauss--Chebyshev rule.

    Parameters
    ----------
    n : int
        Number of nodes, ``n >= 1``.

    Returns
    -------
    nodes : ndarray, shape (n,)
        :math:`\tau_i = \cos(i\pi/(n+1))`, the zeros of :math:`U_n`, decreasing.
    weights : ndarray, shape (n,)
        :math:`W_i = \pi(1-\tau_i^2)/(n+1)`; :math:`\sum_i W_i g(\tau_i)` equals
        :math:`\int_{-1}^{1}\sqrt{1-\tau^2}\,g(\tau)\,d\tau` for polynomials ``g`` of degree
        :math:`\le 2n - 1`.
    collocation : ndarray, shape (n + 1,)
        :math:`x_k = \cos((2k-1)\pi/(2n+2))`, the zeros of :math:`T_{n+1}`.
    """
    n = _check_n(n)
    i = np.arange(1, n + 1)
    nodes = np.cos(i * np.pi / (n + 1))
    weights = np.pi * np.sin(i * np.pi / (n + 1)) ** 2 / (n + 1)
    k = np.arange(1, n + 2)
    collocation = np.cos((2 * k - 1) * np.pi / (2 * (n + 1)))
    return nodes, weights, collocation


def chebyshev_log_expansion(y: ArrayLike, kmax: int) -> tuple[NDArray, NDArray]:
    r"""Chebyshev expansion of :math:`\ln|y - t|` in ``t`` on ``[-1, 1]``.

    .. math::  \ln|y - t| = c_0(y) - 2\sum_{k\ge1} \frac{e_k(y)}{k} T_k(t)

    with :math:`c_0 = v - \ln 2`, :math:`e_k = \operatorname{sign}(y)^k e^{-kv}` and
    :math:`|y| = \cosh v` outside the interval, and :math:`c_0 = -\ln 2`,
    :math:`e_k = T_k(y)` inside it (:math:`|y| \le 1`).

    Parameters
    ----------
    y : array_like
        Real points, any shape.
    kmax : int
        Highest index ``k`` returned.

    Returns
    -------
    c0 : ndarray, shape y.shape
    e : ndarray, shape y.shape + (kmax + 1,)
        ``e[..., k]`` for ``k = 0..kmax`` (``e[..., 0] = 1``).
    """
    kmax = _check_n(kmax, 0, "kmax")
    y = np.asarray(y, dtype=float)
    k = np.arange(kmax + 1)
    ay = np.abs(y)
    outside = ay > 1.0
    v = np.arccosh(np.where(outside, ay, 1.0))
    c0 = v - np.log(2.0)
    theta = np.arccos(np.clip(y, -1.0, 1.0))
    e_in = np.cos(k * theta[..., None])
    sgn = np.where(y < 0, -1.0, 1.0)[..., None] ** k
    e_out = sgn * np.exp(-k * v[..., None])
    e = np.where(outside[..., None], e_out, e_in)
    return c0, e


@dataclass(frozen=True)
class BoundedSolution:
    r"""Solution of the bounded problem, on ``[-1, 1]`` after the map.

    Attributes
    ----------
    coefficients : ndarray, shape (..., n)
        :math:`b_j` in :math:`g = \sum_j b_j U_j`.
    values : ndarray, shape (..., n)
        ``g`` at the nodes.
    consistency : ndarray, shape (...)
        The residual of the consistency condition, ``mean_k f(x_k)`` (zero for a solvable
        right-hand side; the component of ``f`` the bounded solution cannot match).
    extra : ndarray or None, shape (...)
        The extra unknown fixed by the consistency condition, when one was asked for.
    """

    coefficients: NDArray[np.float64]
    values: NDArray[np.float64] | None
    consistency: NDArray[np.float64]
    extra: NDArray[np.float64] | None = None


class _Mapped:
    """A rule on ``[-1, 1]`` mapped onto the interval: its nodes, collocation points, weights.

    The base of the solvers: each sets ``n``, ``interval`` and the rule's ``nodes_unit``,
    ``collocation_unit`` and ``weights_unit`` on ``[-1, 1]``.
    """

    n: int
    interval: tuple[float, float]
    nodes_unit: NDArray[np.float64]
    collocation_unit: NDArray[np.float64]
    weights_unit: NDArray[np.float64]

    def _on(self, n: int, interval: tuple[float, float], n_min: int = 1) -> None:
        """Check and keep ``n`` and ``interval``, with the interval's half-length and middle."""
        self.n = _check_n(n, n_min)
        self.interval = _check_interval(interval)
        self._half = 0.5 * (self.interval[1] - self.interval[0])
        self._mid = 0.5 * (self.interval[1] + self.interval[0])

    @property
    def nodes(self) -> NDArray[np.float64]:
        """Quadrature nodes on the interval."""
        return self._mid + self._half * self.nodes_unit

    @property
    def collocation(self) -> NDArray[np.float64]:
        """Collocation points on the interval (``n + 1``, ``n`` or ``n - 1``: the solver's)."""
        return self._mid + self._half * self.collocation_unit

    @property
    def weights(self) -> NDArray[np.float64]:
        r"""Weights for :math:`\int_\alpha^\beta \phi\,h\,dt \approx \sum_i W_i g_i h(t_i)`."""
        return self._half * self.weights_unit


class BoundedSolver(_Mapped):
    r"""Collocation solver for solutions bounded at both ends.

    Parameters
    ----------
    n : int
        Number of nodes (unknowns), ``n >= 1``.
    interval : tuple of float, optional
        ``(alpha, beta)``, default ``(-1, 1)``.

    Notes
    -----
    With :math:`x_k` the zeros of :math:`T_{n+1}`, the collocation equations
    :math:`-\sum_{j<n} b_j T_{j+1}(x_k) = f(x_k)` are solved by
    :math:`b_j = -\frac{2}{n+1}\sum_k f(x_k)T_{j+1}(x_k)`; the remaining component,
    :math:`\frac{1}{n+1}\sum_k f(x_k)`, is the discrete consistency condition.

    Examples
    --------
    The Hertz-like pair :math:`\phi = \sqrt{1-t^2}` , :math:`f = -x`:

    >>> import numpy as np
    >>> s = BoundedSolver(4)
    >>> sol = s.solve(-s.collocation)
    >>> bool(np.allclose(sol.values, 1.0))
    True
    >>> round(float(s.resultant(sol)), 14)  # pi/2
    1.5707963267949
    """

    def __init__(self, n: int, interval: tuple[float, float] = (-1.0, 1.0)) -> None:
        self._on(n, interval)
        self.nodes_unit, self.weights_unit, self.collocation_unit = bounded_rule(self.n)

    @property
    def _coef_from_f(self) -> NDArray:
        """(n+1, n) matrix with b = f @ C (built on first use: large n solve by the DCT)."""
        return _bounded_operators(self.n)[0]

    @property
    def _values_from_coef(self) -> NDArray:
        """(n, n) matrix with g = b @ V (built on first use)."""
        return _bounded_operators(self.n)[1]

    def solve(
        self, f: ArrayLike, extra: ArrayLike | None = None, *, values: bool = True
    ) -> BoundedSolution:
        r"""Solve for the bounded solution.

        Parameters
        ----------
        f : array_like, shape (..., n + 1)
            Right-hand side at :attr:`collocation`.
        extra : array_like, shape (..., n + 1), optional
            A second right-hand side :math:`f_1`; the equation solved is then
            :math:`\ldots = f + \lambda f_1` with the unknown :math:`\lambda` fixed by the
            consistency condition (the non-symmetric case).
        values : bool
            Also return ``g`` at the nodes (``values`` is None otherwise; the linear
            functionals need only the coefficients).

        Returns
        -------
        BoundedSolution
        """
        rhs = _check_rhs("f", f, self.n + 1, "n + 1")
        lam = None
        if extra is not None:
            f1 = _check_rhs("extra", extra, self.n + 1, "n + 1")
            s1 = f1.mean(axis=-1)
            if np.any(s1 == 0):
                raise ValueError(
                    "extra must have a non-zero mean over the collocation points: "
                    "the consistency condition fixes its multiplier through it"
                )
            with np.errstate(divide="ignore", invalid="ignore"):
                lam = -rhs.mean(axis=-1) / s1
            rhs = rhs + lam[..., None] * f1
        if self.n >= _DCT_FROM:
            # b_j = -(2/(n+1)) sum_k f_k T_{j+1}(x_k) is a type-II DCT of f
            b = -dct2(rhs)[..., 1:] / (self.n + 1)
        else:
            b = rhs @ self._coef_from_f
        g = b @ self._values_from_coef if values else None
        return BoundedSolution(b, g, rhs.mean(axis=-1), lam)

    # --- linear functionals (on the interval, with the map's Jacobian) ---------------------
    def resultant(self, sol: BoundedSolution) -> NDArray[np.float64]:
        r""":math:`\int_\alpha^\beta \phi(t)\,dt`."""
        return self._half * (np.pi / 2) * sol.coefficients[..., 0]

    def first_moment(self, sol: BoundedSolution) -> NDArray[np.float64]:
        r""":math:`\int_\alpha^\beta t\,\phi(t)\,dt`."""
        b = sol.coefficients
        b1 = b[..., 1] if self.n > 1 else np.zeros_like(b[..., 0])
        return self._half * (self._mid * (np.pi / 2) * b[..., 0] + self._half * (np.pi / 4) * b1)

    def log_moment(self, sol: BoundedSolution, y: ArrayLike) -> NDArray[np.float64]:
        r""":math:`\int_\alpha^\beta \phi(t)\ln|y - t|\,dt`, exact for polynomial ``g``.

        ``y`` may lie inside the interval, at an end point or outside it; it broadcasts
        against the batch shape of ``sol``.
        """
        y_unit = (np.asarray(y, dtype=float) - self._mid) / self._half
        mu = _log_moment_vector(y_unit, self.n)
        b = sol.coefficients
        val = np.sum(b * mu, axis=-1)
        return self._half * (val + np.log(self._half) * (np.pi / 2) * b[..., 0])

    def log_moment_derivative(self, sol: BoundedSolution, y: ArrayLike) -> NDArray[np.float64]:
        r"""Derivative of :meth:`log_moment` in ``v`` for ``y = mid + half cosh(v)``.

        For ``y`` at or right of the interval's right end, at fixed ``sol``:
        :math:`\partial_v \int \phi(t)\ln(y - t)\,dt` (useful in Newton iterations on the
        end of a zone that begins at the interval's end).
        """
        y_unit = (np.asarray(y, dtype=float) - self._mid) / self._half
        dmu = _log_moment_vector_dv(y_unit, self.n)
        return self._half * np.sum(sol.coefficients * dmu, axis=-1)

    def evaluate(self, sol: BoundedSolution, t: ArrayLike) -> NDArray[np.float64]:
        r""":math:`\phi(t) = \sqrt{1-\tau^2}\sum_j b_j U_j(\tau)`, zero outside the interval.

        ``t`` has shape ``(..., m)`` broadcasting against the batch shape of ``sol`` plus
        one trailing axis.
        """
        tau = (np.asarray(t, dtype=float) - self._mid) / self._half
        inside = np.abs(tau) <= 1.0
        tc = np.clip(tau, -1.0, 1.0)
        b = sol.coefficients
        # Clenshaw recurrence for sum b_j U_j
        bk1 = np.zeros(np.broadcast_shapes(b.shape[:-1] + (1,), tc.shape))
        bk2 = np.zeros_like(bk1)
        for j in range(self.n - 1, -1, -1):
            bk1, bk2 = b[..., j, None] + 2 * tc * bk1 - bk2, bk1
        g = bk1
        return np.where(inside, np.sqrt(np.clip(1 - tc * tc, 0.0, None)) * g, 0.0)


@lru_cache(maxsize=64)
def _bounded_operators(n: int) -> tuple[NDArray, NDArray]:
    nodes, _, x = bounded_rule(n)
    j = np.arange(n)
    # T_{j+1}(x_k), shape (n+1, n)
    theta_x = np.arccos(x)
    T = np.cos((j + 1)[None, :] * theta_x[:, None])
    coef_from_f = -(2.0 / (n + 1)) * T
    # U_j(tau_i) = sin((j+1) th)/sin(th), shape (n, n) indexed [j, i]
    theta_t = np.arange(1, n + 1) * np.pi / (n + 1)
    U = np.sin((j + 1)[:, None] * theta_t[None, :]) / np.sin(theta_t)[None, :]
    coef_from_f.setflags(write=False)
    U.setflags(write=False)
    return coef_from_f, U


def _log_moment_vector(y: NDArray, n: int) -> NDArray:
    r"""mu_j(y) = int sqrt(1-t^2) U_j(t) ln|y - t| dt, j < n; shape y.shape + (n,)."""
    c0, e = chebyshev_log_expansion(y, n + 1)
    j = np.arange(n)
    mu = np.zeros(y.shape + (n,))
    # (pi/2)[ e_{j+2}/(j+2) - e_j/j (j>=1) ] + c0 (pi/2) delta_j0
    mu += (np.pi / 2) * e[..., j + 2] / (j + 2)
    mu[..., 1:] -= (np.pi / 2) * e[..., 1:n] / j[1:]
    mu[..., 0] += (np.pi / 2) * c0
    return mu


def _log_moment_vector_dv(y: NDArray, n: int) -> NDArray:
    """Derivative of :func:`_log_moment_vector` in v for y = cosh(v) >= 1."""
    y = np.asarray(y, dtype=float)
    v = np.arccosh(np.maximum(y, 1.0))
    k = np.arange(n + 2)
    e = np.exp(-k * v[..., None])  # d(e_k/k)/dv = -e_k
    j = np.arange(n)
    dmu = -(np.pi / 2) * e[..., j + 2]
    dmu[..., 1:] += (np.pi / 2) * e[..., 1:n]
    dmu[..., 0] += np.pi / 2
    return dmu


def log_end_moments(n: int, u: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""Product-integration weights of a logarithm singular at the right end of ``[-1, 1]``.

    For the bounded solution :math:`\phi = \sqrt{1-t^2}\sum_{j<n} b_j U_j(t)` and
    :math:`m = \cosh u \ge 1`,

    .. math::  \int_{-1}^{1}\phi(t)\ln\frac{m - t}{1 - t}\,dt = \sum_j b_j\,\mu_j(u),

    exact for polynomial ``g``; the logarithm is singular at :math:`t = 1` when
    :math:`m = 1`, which product integration does not mind. (The left end follows by
    :math:`t \to -t`, i.e. :math:`b_j \to (-1)^j b_j`.)

    Parameters
    ----------
    n : int
        Number of coefficients, ``n >= 1``.
    u : array_like
        :math:`\operatorname{arccosh}(m) \ge 0`, any shape.

    Returns
    -------
    mu, dmu_du : ndarray, shape u.shape + (n,)
        The weights and their derivatives in ``u``.
    """
    n = _check_n(n)
    u = np.asarray(u, dtype=float)
    e = np.empty(u.shape + (n + 2,))
    e[..., 0] = 1.0
    e[..., 1:] = np.exp(-u)[..., None]
    np.cumprod(e, axis=-1, out=e)  # e_k = exp(-k u)
    j = np.arange(n)
    mu = (np.pi / 2) * e[..., 2:] / (j + 2)
    mu[..., 1:] -= (np.pi / 2) * e[..., 1:n] / j[1:]
    mu[..., 0] += (np.pi / 2) * u  # c0(m) - c0(1) = u
    mu -= _mu_at_one(n)
    dmu = -(np.pi / 2) * e[..., 2:]
    dmu[..., 1:] += (np.pi / 2) * e[..., 1:n]
    dmu[..., 0] += np.pi / 2
    return mu, dmu


@lru_cache(maxsize=64)
def _mu_at_one(n: int) -> NDArray:
    r"""The moments of :math:`\ln(1 - t)` (:math:`m = 1`), subtracted by :func:`log_end_moments`."""
    j = np.arange(n)
    mu1 = (np.pi / 2) / (j + 2)
    mu1[1:] -= (np.pi / 2) / j[1:]
    mu1.setflags(write=False)
    return mu1


class _Dense(_Mapped):
    """A solver whose node values solve one dense system, factored once (LU)."""

    def _cauchy(self) -> NDArray[np.float64]:
        r"""The rows :math:`W_i / (\pi (t_i - x_k))` of the collocation equations on ``[-1, 1]``."""
        return self.weights_unit[None, :] / (
            np.pi * (self.nodes_unit[None, :] - self.collocation_unit[:, None])
        )

    def _factor(self, mat: NDArray[np.float64]) -> None:
        self._lu = _linalg().lu_factor(mat)

    def _solved(self, rhs: NDArray[np.float64]) -> NDArray[np.float64]:
        """The node values for right-hand sides ``rhs`` of shape ``(..., n)``."""
        flat = rhs.reshape(-1, self.n).T
        return _linalg().lu_solve(self._lu, flat).T.reshape(rhs.shape)

    def resultant(self, g: ArrayLike) -> NDArray[np.float64]:
        r""":math:`\int_\alpha^\beta \phi(t)\,dt` from the node values ``g``."""
        return np.asarray(g) @ self.weights


class EndBoundedSolver(_Dense):
    r"""Collocation solver for solutions bounded at one end, unbounded at the other.

    Parameters
    ----------
    n : int
        Number of nodes, ``n >= 1``.
    interval : tuple of float, optional
        ``(alpha, beta)``, default ``(-1, 1)``.
    bounded_at : {"right", "left"}
        The end where the solution is bounded.

    Notes
    -----
    For ``bounded_at="right"``: :math:`\phi = \sqrt{(1-\tau)/(1+\tau)}\,g`, nodes
    :math:`\tau_i = \cos(2\pi i/(2n+1))`, collocation :math:`x_k = \cos(\pi(2k-1)/(2n+1))`,
    weights :math:`2\pi(1-\tau_i)/(2n+1)`: ``n`` equations in ``n`` unknowns, no side
    condition (the index of the problem is zero). ``"left"`` is its mirror image.
    """

    def __init__(
        self, n: int, interval: tuple[float, float] = (-1.0, 1.0), bounded_at: str = "right"
    ) -> None:
        self._on(n, interval)
        if bounded_at not in ("right", "left"):
            raise ValueError(f"bounded_at must be 'right' or 'left', got {bounded_at!r}")
        self.bounded_at = bounded_at
        i = np.arange(1, self.n + 1)
        t = np.cos(2 * np.pi * i / (2 * self.n + 1))
        x = np.cos(np.pi * (2 * i - 1) / (2 * self.n + 1))
        w = 2 * np.pi * (1 - t) / (2 * self.n + 1)
        self._sign = 1.0 if bounded_at == "right" else -1.0
        self.nodes_unit = self._sign * t
        self.collocation_unit = self._sign * x
        self.weights_unit = w
        self._factor(self._cauchy())

    def solve(self, f: ArrayLike) -> NDArray[np.float64]:
        """Values of ``g`` at the nodes for the right-hand side ``f`` at the collocation points.

        ``f`` has shape ``(..., n)``; so has the result.
        """
        return self._solved(_check_rhs("f", f, self.n, "n"))


class UnboundedSolver(_Dense):
    r"""Collocation solver for solutions unbounded at both ends, with a side condition.

    Parameters
    ----------
    n : int
        Number of nodes, ``n >= 2``.
    interval : tuple of float, optional
        ``(alpha, beta)``, default ``(-1, 1)``.

    Notes
    -----
    :math:`\phi = g/\sqrt{1-\tau^2}`, nodes :math:`\tau_i = \cos((2i-1)\pi/(2n))`, weights
    :math:`\pi/n`, collocation :math:`x_k = \cos(k\pi/n)` for :math:`k = 1, \ldots, n-1`; the side
    condition :math:`\int_\alpha^\beta\phi\,dt = C` closes the system.
    """

    def __init__(self, n: int, interval: tuple[float, float] = (-1.0, 1.0)) -> None:
        self._on(n, interval, 2)
        i = np.arange(1, self.n + 1)
        self.nodes_unit = np.cos((2 * i - 1) * np.pi / (2 * self.n))
        self.weights_unit = np.full(self.n, np.pi / self.n)
        self.collocation_unit = np.cos(np.arange(1, self.n) * np.pi / self.n)
        self._factor(np.vstack([self._cauchy(), self.weights_unit * self._half]))

    def solve(self, f: ArrayLike, resultant: ArrayLike) -> NDArray[np.float64]:
        r"""Values of ``g`` at the nodes.

        Parameters
        ----------
        f : array_like, shape (..., n - 1)
            Right-hand side at the collocation points.
        resultant : array_like, shape (...)
            :math:`C = \int_\alpha^\beta \phi\,dt`.
        """
        f = _check_rhs("f", f, self.n - 1, "n - 1")
        try:
            c = np.broadcast_to(np.asarray(resultant, dtype=float), f.shape[:-1])
        except ValueError:
            raise ValueError(
                f"resultant must broadcast to the batch shape of f, "
                f"{f.shape[:-1]}, got shape {np.shape(resultant)}"
            ) from None
        return self._solved(np.concatenate([f, c[..., None]], axis=-1))

    def log_moment(self, g: ArrayLike, y: ArrayLike) -> NDArray[np.float64]:
        r""":math:`\int_\alpha^\beta \phi(t)\ln|y-t|\,dt` by product integration."""
        g = np.asarray(g, dtype=float)
        n = self.n
        # Chebyshev-T coefficients of g from its values at the T_n zeros
        k = np.arange(n)
        theta = (2 * np.arange(1, n + 1) - 1) * np.pi / (2 * n)
        Tm = np.cos(k[:, None] * theta[None, :])  # [k, i]
        a = (2.0 / n) * (g @ Tm.T)
        a[..., 0] *= 0.5
        y_unit = (np.asarray(y, dtype=float) - self._mid) / self._half
        c0, e = chebyshev_log_expansion(y_unit, n)
        # int T_k ln|y-t|/sqrt(1-t^2) = pi c0 (k=0), -pi e_k/k (k>=1)
        mom = np.empty(np.shape(y_unit) + (n,))
        mom[..., 0] = np.pi * c0
        mom[..., 1:] = -np.pi * e[..., 1:n] / k[1:]
        val = np.sum(a * mom, axis=-1)
        return self._half * (val + np.log(self._half) * np.pi * a[..., 0])
