r"""The paper's route for steady sliding: Eq. (20) by Gauss--Chebyshev collocation.

The eccentricity is the extra unknown of the consistency condition; Eqs. (21)--(22) by
product integration of their logarithmic kernels; Newton's method in ``u_i =
arccosh(c_i/a)`` with an adaptive number of nodes.
"""

from __future__ import annotations

from typing import cast

import numpy as np
from numpy.typing import NDArray

from .. import _numerics as _num
from .. import closed_forms as _cf
from ..sie import SIZES, BoundedSolver, _chunks, log_end_moments
from .closed_form import _initial_u, _newton2

#: Collocation sizes tried by ``n="auto"``.
_SIZES = SIZES[: SIZES.index(2048) + 1]


def _colloc_rhs(x, A, s, u1, u2):
    """Eq. 20 on t = x/a (without the e/(2R) term) and its derivatives in u1, u2."""
    A, s, u1, u2 = (v[:, None] for v in (A, s, u1, u2))
    m1m1 = 2 * np.sinh(u1 / 2) ** 2
    m2m1 = 2 * np.sinh(u2 / 2) ** 2
    m2mx = m2m1 + (1 - x)  # m2 - x
    m1px = m1m1 + (1 + x)  # m1 + x
    c = s / np.pi
    f = -0.5 * A * x + c * np.log(m2mx / m1px)
    df1 = -c * np.sinh(u1) / m1px
    df2 = c * np.sinh(u2) / m2mx
    return np.stack([f, df1, df2], axis=1)  # (P, 3, n + 1)


def _K(mm1_own, m_own, m_other):
    """(1/a) int over the own zone of ln((c_own - x)/(c_other + x)) and its d/dm's.

    K = (m-1) ln((m-1)/(m+m')) + (m'+1) ln((m'+1)/(m+m')); dK/dm = ln((m-1)/(m+m')),
    dK/dm' = ln((m'+1)/(m+m')).
    """
    tot = m_own + m_other
    with np.errstate(divide="ignore", invalid="ignore"):
        l_own = np.log(mm1_own / tot)
        l_oth = np.log((m_other + 1) / tot)
    K = np.where(mm1_own > 0, mm1_own * l_own, 0.0) + (m_other + 1) * l_oth
    return K, np.where(mm1_own > 0, l_own, -np.inf), l_oth


def _colloc_eval(solver: BoundedSolver, A, s, rho, r, u1, u2):
    """Residuals of Eqs. 22 (trailing, over h1) and 21 (leading, over h2), Jacobian, extras."""
    n = solver.n
    x = solver.collocation_unit
    f = _colloc_rhs(x, A, s, u1, u2)
    sol = solver.solve(f, extra=np.full(n + 1, 0.5), values=False)
    B = sol.coefficients  # (P, 3, n): b, db/du1, db/du2
    lam = cast(NDArray, sol.extra)  # (P, 3): e/R and its derivatives
    b, db1, db2 = B[:, 0], B[:, 1], B[:, 2]
    ecc, de1, de2 = lam[:, 0], lam[:, 1], lam[:, 2]
    sg = (-1.0) ** np.arange(n)
    mu2, dmu2 = log_end_moments(n, u2)  # ln((m2 - t)/(1 - t)) moments
    mu1, dmu1 = log_end_moments(n, u1)  # ln((m1 + t)/(1 + t)) moments of g(-t)
    mu1s, dmu1s = mu1 * sg, dmu1 * sg
    J2 = np.einsum("pj,pj->p", b, mu2)
    J1 = np.einsum("pj,pj->p", b, mu1s)
    dJ2 = (
        np.einsum("pj,pj->p", db1, mu2),
        np.einsum("pj,pj->p", db2, mu2) + np.einsum("pj,pj->p", b, dmu2),
    )
    dJ1 = (
        np.einsum("pj,pj->p", db1, mu1s) + np.einsum("pj,pj->p", b, dmu1s),
        np.einsum("pj,pj->p", db2, mu1s),
    )
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    m1, m2 = np.cosh(u1), np.cosh(u2)
    mm1_1 = 2 * np.sinh(u1 / 2) ** 2
    mm1_2 = 2 * np.sinh(u2 / 2) ** 2
    K2, dK2_own, dK2_oth = _K(mm1_2, m2, m1)
    K1, dK1_own, dK1_oth = _K(mm1_1, m1, m2)
    with np.errstate(invalid="ignore"):
        dK2 = (dK2_oth * sh1, np.where(sh2 > 0, dK2_own * sh2, 0.0))
        dK1 = (np.where(sh1 > 0, dK1_own * sh1, 0.0), dK1_oth * sh2)
    c = 2 * A / np.pi
    rho1 = rho / r
    # leading: 1 + (R/h2)[(2A/pi) J2 + (2 s A/pi) K2 - A^2 sh2^2/2 + A e (m2 - 1)]
    R2 = 1 + rho * (c * J2 + c * s * K2 - 0.5 * A * A * sh2 * sh2 + A * ecc * mm1_2)
    R1 = 1 + rho1 * (c * J1 + c * s * K1 - 0.5 * A * A * sh1 * sh1 - A * ecc * mm1_1)
    J21 = rho * (c * dJ2[0] + c * s * dK2[0] + A * de1 * mm1_2)
    J22 = rho * (c * dJ2[1] + c * s * dK2[1] - A * A * sh2 * m2 + A * de2 * mm1_2 + A * ecc * sh2)
    J11 = rho1 * (c * dJ1[0] + c * s * dK1[0] - A * A * sh1 * m1 - A * de1 * mm1_1 - A * ecc * sh1)
    J12 = rho1 * (c * dJ1[1] + c * s * dK1[1] - A * de2 * mm1_1)
    res = (np.pi / 2) * b[:, 0]
    mom = (np.pi / 4) * b[:, 1] if n > 1 else np.zeros_like(res)
    tail = np.max(np.abs(b[:, -3:]), axis=-1) / np.maximum(np.max(np.abs(b), axis=-1), 1e-300)
    # residuals as (gap - h)/h, the sign of the closed-form ones; the extras as in _EXTRA
    return (
        *(-R1, -R2, -J11, -J12, -J21, -J22),
        *(ecc, res, mom, np.abs(sol.consistency[:, 0]), tail),
    )


#: The extra quantities of :func:`_colloc_eval`, in its order.
_EXTRA = ("ecc", "resultant", "moment", "consistency", "tail")


def _collocation(A, rho, r, s, n, tol):
    """Flat arrays in, dict of flat arrays out."""
    sizes = np.asarray(_SIZES)
    ab = A * np.sqrt(rho / 2)
    kap = _cf._kappa(rho, s)
    u1, u2 = _initial_u(ab, kap, r)  # each edge from the symmetric solution with its range

    def run(nn, idx, v1, v2):
        """Newton at nn nodes on the points idx, in chunks of bounded memory."""
        solver = BoundedSolver(int(nn))

        def evaluate(w1, w2, A_, s_, rho_, r_):
            return _colloc_eval(solver, A_, s_, rho_, r_, w1, w2)

        out = [np.empty(idx.size) for _ in range(4 + len(_EXTRA))]
        for c in _chunks(idx.size, int(nn)):
            g = idx[c]
            w1, w2, f1, f2, ex_ = _newton2(
                evaluate, v1[c], v2[c], (A[g], s[g], rho[g], r[g]), nextra=len(_EXTRA)
            )
            for o, v in zip(out, (w1, w2, f1, f2, *ex_), strict=True):
                o[c] = v
        return (*out[:4], dict(zip(_EXTRA, out[4:], strict=True)))

    n0 = 16 if n == "auto" else int(n)
    P = A.size
    idx = np.arange(P)
    u1, u2, e1, e2, ex = run(n0, idx, u1, u2)
    nsel = np.full(P, n0)
    if n == "auto":  # the thinner zone sets the size (_numerics._auto_sizes)

        def solve(nn, sel):
            v1, v2, f1, f2, x2 = run(nn, sel, u1[sel], u2[sel])
            u1[sel], u2[sel], e1[sel], e2[sel] = v1, v2, f1, f2
            for k in ex:
                ex[k][sel] = x2[k]

        nsel = _num._auto_sizes(sizes, np.minimum(u1, u2), ex["tail"], tol, nsel, solve)
    m1, m2 = np.cosh(u1), np.cosh(u2)
    F = rho * A * (ex["resultant"] - s * (m1 + m2))
    # strips: -sigma0 (int_a^c2 x + int_-c1^-a x) = sigma0 (c1^2 - c2^2)/2,
    # (m1^2 - m2^2) = sinh(u1 + u2) sinh(u1 - u2)
    M = rho * A * A * (ex["moment"] + 0.5 * s * np.sinh(u1 + u2) * np.sinh(u1 - u2))
    converged = (np.maximum(e1, e2) <= 1e-10) & (ex["tail"] <= 10 * tol) & np.isfinite(F)
    return dict(
        u1=u1,
        u2=u2,
        ecc=ex["ecc"],
        F=F,
        M=M,
        res1=e1,
        res2=e2,
        cons=ex["consistency"],
        tail=ex["tail"],
        n=nsel,
        converged=converged,
    )
