r"""The Lennard-Jones law of Eq. 1 solved self-consistently for line contact (in progress).

A cylinder of radius ``R`` on an elastic half-plane (composite plane-strain modulus ``E``),
the surface traction the Lennard-Jones law (Eq. 1) at the local gap everywhere -- no
separate contact and adhesive zones. In plane strain the displacement has no datum, so the
state is controlled by the gap at the centre ``g0``; the gap elsewhere is

.. math::

    z(x) = g_0 + \frac{x^2}{2R} + \frac{2}{\pi E}\int p(s)\,\bigl(\ln|x - s| - \ln|s|\bigr)\,ds,

the pressure ``p`` (compressive positive) pushing the surfaces together where it acts.
With ``x = sqrt(R z0) xi``, ``z = z0 zeta`` and ``p = (w/z0) P(zeta)``,
``P(zeta) = -(8/3)(zeta^-3 - zeta^-9)``, the gap is

.. math::

    \zeta(\xi) = \zeta_0 + \frac{\xi^2}{2}
        + \frac{2\mu}{\pi}\int_0^\infty P(\zeta(\eta))\,\ln\frac{|\xi^2 - \eta^2|}{\eta^2}\,d\eta,
    \qquad \mu = \frac{w\sqrt{R/z_0}}{E z_0},

and the load is ``F/(w sqrt(R/z0)) = 2 int_0^inf P d eta``. ``mu`` is the one group of the
problem (a Tabor parameter for cylinders): ``mu -> 0`` is the rigid limit
(:func:`linecontact.reference.lennard_jones_rigid_load`). Derivation:
``docs/lennard-jones.md``.

Discretisation: ``P`` piecewise linear on a graded mesh of ``[0, L]`` (fine near the
centre, geometric to ``L = 1000``, where the attraction has decayed like ``xi^-6``), the
logarithmic kernel integrated exactly on each element (product integration), collocation
at the nodes, Newton on the gaps.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["LJState", "lj_state"]


def _mesh(n: int, core: float = 6.0, far: float = 1000.0) -> NDArray:
    """Nodes on [0, far]: ``n`` uniform on [0, core], then geometric to ``far``."""
    inner = np.linspace(0.0, core, n + 1)
    h = inner[1] - inner[0]
    ratio = 1.0 + 3.0 / n  # geometric beyond the core, refined with n (tail ~ xi^-6)
    outer = [core]
    while outer[-1] < far:
        step = max(h, (outer[-1] - outer[-2]) * ratio if len(outer) > 1 else h * ratio)
        outer.append(outer[-1] + step)
    outer[-1] = far
    return np.concatenate([inner, np.asarray(outer[1:])])


def _log_antiderivatives(t: NDArray, c: NDArray) -> tuple[NDArray, NDArray]:
    """``int ln|t - c| dt`` and ``int t ln|t - c| dt`` at ``t`` (0 log 0 = 0)."""
    s = t - c
    with np.errstate(divide="ignore", invalid="ignore"):
        ls = np.where(s == 0, 0.0, np.log(np.abs(s)))
    a0 = s * ls - s
    a1 = 0.5 * s * s * ls - 0.25 * s * s + c * (s * ls - s)
    return a0, a1


def _kernel(nodes: NDArray) -> NDArray:
    """``K[i, j] = int phi_j(eta) ln(|xi_i^2 - eta^2| / eta^2) d eta`` on the mesh.

    ``phi_j`` the hat functions of ``nodes``; the kernel is ``ln|xi - eta| + ln|xi + eta| -
    2 ln|eta|``, each term integrated exactly against the linear pieces.
    """
    xi = nodes[:, None, None]
    a, b = nodes[:-1][None, :, None], nodes[1:][None, :, None]
    K = np.zeros((nodes.size, nodes.size))
    for c, weight in ((xi, 1.0), (-xi, 1.0), (0.0 * xi, -2.0)):
        A0b, A1b = _log_antiderivatives(b, c)
        A0a, A1a = _log_antiderivatives(a, c)
        i0, i1 = (A0b - A0a)[..., 0], (A1b - A1a)[..., 0]  # (nodes, elements)
        h = (b - a)[..., 0]
        # phi_left = (b - t)/h, phi_right = (t - a)/h on each element
        left = (b[..., 0] * i0 - i1) / h
        right = (i1 - a[..., 0] * i0) / h
        K[:, :-1] += weight * left
        K[:, 1:] += weight * right
    return K


def _law(zeta: NDArray) -> tuple[NDArray, NDArray]:
    """P(zeta) = -(8/3)(zeta^-3 - zeta^-9) and its derivative."""
    z3 = zeta**-3
    z9 = z3 * z3 * z3
    return -(8.0 / 3.0) * (z3 - z9), (8.0 / 3.0) * (3.0 * z3 - 9.0 * z9) / zeta


@dataclass(frozen=True)
class LJState:
    """One equilibrium state under the Lennard-Jones law (nondimensional).

    Attributes
    ----------
    central_gap_over_z0, mu : float
        The control ``zeta0 = g0/z0`` and the group ``mu``.
    F_over_w_sqrt_R_over_z0 : float
        The load per unit length, compressive positive.
    xi, gap_over_z0, pressure : ndarray
        The nodes ``x/sqrt(R z0)`` (half line), the gap over ``z0`` and ``p z0/w`` there.
    residual : float
        Largest residual of the gap equation at the nodes, relative to the gap there.
    n : int
        Number of nodes.
    converged : bool
    """

    central_gap_over_z0: float
    mu: float
    F_over_w_sqrt_R_over_z0: float
    xi: NDArray
    gap_over_z0: NDArray
    pressure: NDArray
    residual: float
    n: int
    converged: bool


_CACHE: dict[int, tuple[NDArray, NDArray, NDArray]] = {}


def _operators(n: int) -> tuple[NDArray, NDArray, NDArray]:
    """Nodes, kernel matrix and trapezoid weights for ``n`` core elements (cached)."""
    if n not in _CACHE:
        nodes = _mesh(n)
        h = np.diff(nodes)
        wts = np.zeros(nodes.size)
        wts[:-1] += 0.5 * h
        wts[1:] += 0.5 * h
        _CACHE[n] = (nodes, _kernel(nodes), wts)
    return _CACHE[n]


def lj_state(
    central_gap_over_z0: float,
    mu: float,
    *,
    n: int = 120,
    guess: NDArray | None = None,
    tol: float = 1e-12,
) -> LJState:
    """The equilibrium state at the central gap ``zeta0`` for the group ``mu``.

    Newton on the gaps at the nodes. Without ``guess`` (the gaps of a nearby state) it
    starts from the rigid profile at ``mu = 0`` and continues in ``mu`` up to the value
    asked (steps that double after a success and halve after a failure). Raises
    ``ValueError`` for ``zeta0 <= 0`` or ``mu < 0``.
    """
    if not (np.isfinite(central_gap_over_z0) and central_gap_over_z0 > 0):
        raise ValueError(f"central_gap_over_z0 must be > 0, got {central_gap_over_z0!r}")
    if not (np.isfinite(mu) and mu >= 0):
        raise ValueError(f"mu must be a finite number >= 0, got {mu!r}")
    if guess is not None:
        return _newton(central_gap_over_z0, mu, n, np.asarray(guess, float), tol)
    state = _newton(central_gap_over_z0, 0.0, n, None, tol)
    done, step = 0.0, min(mu, 0.1)
    while done < mu and step > 1e-6 * max(mu, 1.0):
        nxt = min(mu, done + step)
        trial = _newton(central_gap_over_z0, nxt, n, state.gap_over_z0, tol)
        if trial.converged:
            state, done, step = trial, nxt, 2.0 * step
        else:
            step *= 0.5
    return state


def _newton(
    central_gap_over_z0: float, mu: float, n: int, guess: NDArray | None, tol: float
) -> LJState:
    max_iter = 40
    nodes, K, wts = _operators(n)
    rigid = central_gap_over_z0 + 0.5 * nodes * nodes
    zeta = rigid.copy() if guess is None else np.asarray(guess, float).copy()
    c = 2.0 * mu / np.pi
    eye = np.eye(nodes.size)
    res = np.inf
    ok = False
    for _ in range(max_iter):
        P, dP = _law(zeta)
        r = zeta - rigid - c * (K @ P)
        res = float(np.max(np.abs(r) / zeta))  # relative: far out the gap is ~xi^2/2
        if res <= tol:
            ok = True
            break
        J = eye - c * K * dP[None, :]
        step = np.linalg.solve(J, r)
        # keep the gaps positive (the law is singular at contact): damp a step that would not
        lam = 1.0
        while np.any(zeta - lam * step <= 0.05 * zeta) and lam > 1e-6:
            lam *= 0.5
        zeta = zeta - lam * step
    P, _ = _law(zeta)
    F = 2.0 * float(wts @ P)
    return LJState(central_gap_over_z0, mu, F, nodes, zeta, P, res, nodes.size, ok)
