"""The pushed fibre: time of 10,000 points and the worst residuals against independent checks.

    python benchmarks/push.py

Prints the best-of-3 wall time of ``push`` over 10,000 random points (the closed forms; the
sliding inverse takes most of it, and the sliding pull-off search where the load lies below
the zero-width load; target under 10 us per point, issues 22 and 36), then the pull-off
search alone against the former one (a grid of 41 closed forms per point refined by a
secant, kept here as the reference: before/after), with the worst difference of the
pull-off force between them, and over the same points the worst relative residuals of

- Kendall's energy balance ``Q_roll H = R dw`` against the moment ``M - e F`` of the
  sliding solution at ``a_slide``;
- the load carried by the steady contact (``residual_load``);
- the load the collocation solver finds at ``a_slide``, against ``F`` (on 200 points);

then the best-of-3 time of ``push`` from a tip (``tip_friction``) over the same points,
touching at ``H`` in ``[0.8, 1.35] R`` with a friction up to 0.3 (the fixed points of the
tip's load: the sliding inverse's kernel at each iteration, the pull-off search once).
"""

from __future__ import annotations

import numpy as np

import linecontact as lc
from _common import best_of
from linecontact import closed_forms as _cf
from linecontact.sliding import pulloff as SP


def grid_search(kap, r):
    """The former pull-off search: Phi on 41 widths in ln abar, a secant around the least.

    Returns the minimum of Phi = (2/pi) F/(E h2) and the zero-width Phi (flat arrays).
    """
    X1, X2, _ = SP._zero_width(kap, r)
    phi0 = -0.5 * kap * (X1 + X2)
    lab_hi = np.log(3.0 + 3.0 * kap)
    labs = SP._LAB_LO + np.linspace(0.0, 1.0, 41)[:, None] * (lab_hi - SP._LAB_LO)[None, :]
    G, P = labs.shape
    ph, dph = SP._phi_at(labs.reshape(-1), np.tile(kap, G), np.tile(r, G))[:2]
    ph, dph = ph.reshape(G, P), dph.reshape(G, P)
    k = np.argmin(ph, axis=0)
    cols = np.arange(P)
    interior = (k > 0) & (k < G - 1)
    kk = np.clip(k, 1, G - 2)
    xp, fp = labs[kk - 1, cols], dph[kk - 1, cols]
    x, fx = labs[kk + 1, cols], dph[kk + 1, cols]
    lo, hi, phx = xp.copy(), x.copy(), ph[kk + 1, cols]
    active = interior.copy()
    for _ in range(100):
        if not active.any():
            break
        i = np.flatnonzero(active)
        nx = x[i] - fx[i] * (x[i] - xp[i]) / (fx[i] - fp[i])
        ok = np.isfinite(nx) & (nx > lo[i]) & (nx < hi[i])
        nx = np.where(ok, nx, 0.5 * (lo[i] + hi[i]))
        pn, fn = SP._phi_at(nx, kap[i], r[i])[:2]
        xp[i], fp[i], x[i], fx[i], phx[i] = x[i], fx[i], nx, fn, pn
        up = fn > 0
        hi[i] = np.where(up, nx, hi[i])
        lo[i] = np.where(up, lo[i], nx)
        stop = ~(np.abs(nx - xp[i]) > 1e-10 * np.maximum(1.0, np.abs(nx))) | (fn == 0)
        active[i[stop]] = False
    return np.where(interior & (phx < phi0), phx, phi0), phi0


def sample(n: int, rng: np.random.Generator):
    rho = 10 ** rng.uniform(1, 4, n)
    r = 10 ** rng.uniform(0, 1, n)  # h1/h2 in [1, 10]
    s = 10 ** rng.uniform(-3, -1, n)
    tau = 10 ** rng.uniform(-5, -2, n)
    H = rng.uniform(0.0, 2.0, n)
    F0 = lc.sliding_pull_off(rho, r, s).F_pulloff_over_Eh2
    load = rng.uniform(0.01, 3.0, n)
    F = F0 * (1 - load) + load * np.abs(F0)
    return rho, r, s, tau, F, H


def main() -> None:
    rng = np.random.default_rng(20261123)
    n = 10_000
    rho, r, s, tau, F, H = sample(n, rng)
    t, p = best_of(lambda: lc.push(rho, r, s, tau, F, H, 0.5 * tau))
    print(f"push, {n} points (closed forms): {t:.3f} s ({1e6 * t / n:.1f} us/point)")
    t_new, po = best_of(lambda: lc.sliding_pull_off(rho, r, s))
    kap = _cf._kappa(rho, s)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        t_old, (phi_grid, phi0) = best_of(lambda: grid_search(kap, r), repeat=1)
    dF = np.abs(po.F_pulloff_over_Eh2 - np.pi / 2 * phi_grid) / np.abs(np.pi / 2 * phi0)
    print(
        f"  the sliding pull-off search: {1e6 * t_new / n:.1f} us/point (before, the 41-point "
        f"grid: {1e6 * t_old / n:.1f} us/point); worst |F_pulloff - F_grid| / |F_zero_width|: "
        f"{dF.max():.1e}"
    )
    dw = s * (r - 1)
    # Kendall's Q_roll H = R dw against the moment of the steady contact's pressure about
    # the axis, M - e F, from the sliding solution at a_slide
    c = lc.sliding_contact(p.a_slide_over_R, rho, r, s, method="closed-form")
    ok = dw > 0
    kendall = np.abs(np.asarray(c.M_axis_over_Eh2R)[ok] - dw[ok]) / dw[ok]
    print(f"  worst |(M - e F) - R dw| / (R dw):         {kendall.max():.2e}")
    print(f"  worst load residual of the steady contact: {np.max(p.residual_load):.2e}")
    m = 200
    c = lc.sliding_contact(p.a_slide_over_R[:m], rho[:m], r[:m], s[:m], method="collocation")
    scale = np.abs(F[:m]) + np.pi / 4 * rho[:m] * p.a_slide_over_R[:m] ** 2
    rel = np.abs(c.F_over_Eh2 - F[:m]) / scale
    print(f"  worst load of the collocation at a_slide, against F ({m} points): {rel.max():.2e}")
    firsts, counts = np.unique(p.first_motion, return_counts=True)
    print("  first motions: " + ", ".join(f"{k} {v}" for k, v in zip(firsts, counts, strict=True)))
    t1, _ = best_of(lambda: lc.push(100.0, 2.0, 0.01, 1e-3, 0.0, 1.0))
    print(f"push, one point: {1e3 * t1:.2f} ms")
    H_tip = 0.8 + 0.55 * H  # H in [0, 2] above: a tip between 0.8 R and 1.35 R
    mu = rng.uniform(0.0, 0.3, n)
    t, p = best_of(lambda: lc.push(rho, r, s, tau, F, H_tip, 0.5 * tau, tip_friction=mu))
    print(f"push from a tip, {n} points: {t:.3f} s ({1e6 * t / n:.1f} us/point)")
    print(f"  worst load residual of the steady contact: {np.max(p.residual_load):.2e}")
    t1, _ = best_of(lambda: lc.push(100.0, 2.0, 0.01, 1e-3, 0.0, 0.5, tip_friction=0.2))
    print(f"push from a tip, one point: {1e3 * t1:.2f} ms")


if __name__ == "__main__":
    main()
