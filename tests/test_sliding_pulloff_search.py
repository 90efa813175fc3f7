"""The sliding pull-off by a bracketed search gives the grid search's minimum (issue 22).

``sliding_pull_off`` (and the inverse and ``push``, which start from it) found the load
minimum on a grid of 41 closed forms per point in ``ln abar``, refined by a secant; it now
walks from a start near the minimum to a bracket and refines that (``_minimum_step``). The
grid search is kept here as the reference (:func:`_grid_search`). The minimum load is the
same to round-off everywhere; its width is compared where the minimum is deep enough for
the width to be defined beyond round-off (a load flat to 1e-10 of itself over a range of
widths leaves them undetermined: the error in ln(a) grows like 1e-15/depth^(1/2)); the
label is the same.
"""

from __future__ import annotations

import numpy as np
import pytest

import linecontact as lc
from linecontact import closed_forms as _cf
from linecontact.sliding import pulloff as SP


def _grid_search(kap, r):
    """The former search: Phi on 41 widths in ln abar, the secant on dPhi around the least."""
    X1, X2, _ = SP._zero_width(kap, r)
    phi0 = -0.5 * kap * (X1 + X2)
    lab_hi = np.log(3.0 + 3.0 * kap)
    grid = np.linspace(0.0, 1.0, 41)
    labs = SP._LAB_LO + grid[:, None] * (lab_hi - SP._LAB_LO)[None, :]
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
    interior &= phx < phi0
    return np.where(interior, phx, phi0), np.where(interior, x, -np.inf), phi0, interior


def _points(n, seed):
    rng = np.random.default_rng(seed)
    rho = 10 ** rng.uniform(1, 4, n)
    r = 10 ** rng.uniform(-1, 1, n)
    s = 10 ** rng.uniform(-4, np.log10(0.3), n)
    return rho, r, s


@pytest.mark.parametrize("seed", [1, 2])
def test_the_bracketed_search_finds_the_grid_minimum(seed):
    rho, r, s = _points(400, seed)
    kap = _cf._kappa(rho, s)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        phi_ref, lab_ref, phi0, _ = _grid_search(kap, r)
        d = SP._pulloff_flat(kap, r)
    # the load at the minimum: the same to round-off (relative to the zero-width load)
    assert np.max(np.abs(d["phi_min"] - phi_ref) / np.abs(phi0)) <= 1e-13
    assert np.all(d["phi_min"] <= phi0)
    depth = (phi0 - phi_ref) / np.abs(phi0)
    for low, tol in ((1e-8, 1e-6), (1e-6, 1e-8), (1e-4, 1e-10)):
        deep = depth > low
        assert np.all(d["interior"][deep])
        assert np.max(np.abs(d["lab_min"][deep] - lab_ref[deep])) <= tol, low
    # the public result: force, label and (where defined) width
    po = lc.sliding_pull_off(rho, r, s)
    F_ref = (np.pi / 2) * phi_ref
    F0 = po.F_zero_width_over_Eh2
    assert np.max(np.abs(po.F_pulloff_over_Eh2 - F_ref) / np.abs(F0)) <= 1e-13
    a_ref = np.where(np.isfinite(lab_ref), np.exp(lab_ref) * np.sqrt(2 / rho), 0.0)
    deep = depth > 1e-6
    np.testing.assert_allclose(po.a_over_R_at_pulloff[deep], a_ref[deep], rtol=1e-8)
    snap = depth > 1e-2  # a snap-off by its depth; by its width only where it is defined
    assert np.all(po.mechanism[snap] == "snap-off")
    wide = a_ref >= np.minimum(1.0, r) / rho
    assert np.all((po.mechanism == "snap-off")[wide & deep] == wide[wide & deep])


def test_the_search_at_equal_ranges_is_the_normal_pull_off():
    rho, _, s = _points(200, 3)
    po = lc.sliding_pull_off(rho, 1.0, s)
    ref = lc.pull_off(rho, s)
    F0 = np.abs(ref.F_zero_width_over_Eh)
    assert np.max(np.abs(po.F_pulloff_over_Eh2 - ref.F_pulloff_over_Eh) / F0) <= 1e-13
    assert list(po.mechanism) == list(ref.mechanism)
    deep = (ref.F_zero_width_over_Eh - ref.F_pulloff_over_Eh) / F0 > 1e-6
    np.testing.assert_allclose(
        po.a_over_R_at_pulloff[deep], ref.a_over_R_at_pulloff[deep], rtol=1e-8
    )


def test_scalar_search_is_the_array_one():
    rho, r, s = _points(12, 4)
    arr = lc.sliding_pull_off(rho, r, s)
    for i in range(rho.size):
        one = lc.sliding_pull_off(rho[i], r[i], s[i])
        assert one.mechanism == arr.mechanism[i]
        assert abs(one.F_pulloff_over_Eh2 - arr.F_pulloff_over_Eh2[i]) <= 1e-14 * abs(
            arr.F_zero_width_over_Eh2[i]
        )
        assert np.isclose(one.a_over_R_at_pulloff, arr.a_over_R_at_pulloff[i], rtol=1e-9)


def test_loads_from_the_pull_off_up_are_carried():
    """The inverse, started at the width of the minimum the search found, carries the load."""
    rho, r, s = _points(300, 5)
    po = lc.sliding_pull_off(rho, r, s)
    rel = 10 ** np.random.default_rng(6).uniform(-12, 1, rho.size)
    F = po.F_pulloff_over_Eh2 + rel * np.abs(po.F_pulloff_over_Eh2)
    c = lc.sliding_contact_for_load(F, rho, r, s)
    assert np.all(c.converged) and np.all(c.stable)
    scale = np.abs(F) + np.pi / 4 * rho * c.a_over_R**2
    assert np.max(np.abs(c.F_over_Eh2 - F) / scale) <= 1e-12
    # exactly at the pull-off force: a contact carries it
    c = lc.sliding_contact_for_load(po.F_pulloff_over_Eh2, rho, r, s)
    assert np.all(c.converged)
