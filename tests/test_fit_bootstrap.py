"""The bootstrap of the joint pull-off fit (linecontact.fits): its refits solved all at once
agree with the one-by-one refits (never compared bit for bit), from the same resamples."""

import math

import numpy as np
import pytest

import linecontact as lc
from linecontact import _least_squares, fits

E = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))
W, Z0 = 0.1, 0.3e-9
RADII = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])  # Maugis parameter 0.21 to 1.4
LO, HI = np.log([1e-8, 1e-12]), np.log([1e3, 1e-7])


def noisy(R, rel, seed, w=W):
    F = fits.pull_off_force(R, E, w, Z0)
    sd = rel * np.abs(F)
    return F + sd * np.random.default_rng(seed).standard_normal(F.size), sd


def one_by_one(monkeypatch):
    """Every refit of the bootstrap by :func:`fits._solve`, as before the batch."""

    def none(fun, Fd, sig, start, lo, hi):
        return np.full((len(Fd), start.size), np.nan)

    monkeypatch.setattr(fits, "_refit_rows", none)


def test_a_batch_of_draws_is_the_draws_one_at_a_time():
    """The resamples: one (n, m) draw is n draws of m, in order (the same seed, the same)."""
    a, b = np.random.default_rng(11), np.random.default_rng(11)
    assert np.array_equal(b.standard_normal((100, 5)), [a.standard_normal(5) for _ in range(100)])


@pytest.mark.parametrize(
    ("R", "rel", "seed", "z_fixed"),
    [
        (RADII, 0.05, 1, None),
        (RADII, 0.02, 3, None),
        (RADII[1:], 0.08, 5, None),
        (RADII, 0.05, 1, Z0),
    ],
)
def test_each_batched_refit_is_the_one_by_one_refit(R, rel, seed, z_fixed):
    F, sd = noisy(R, rel, seed)
    fit = fits.fit_pull_off(R, F, E, sd=sd, equilibrium_spacing=z_fixed, bootstrap=0)
    n = 2 if z_fixed is None else 1
    p = np.log([fit.work_of_adhesion, fit.equilibrium_spacing])[:n]
    fun = lambda P: fits._model_rows(P, R, E, z_fixed)  # noqa: E731
    Fd = fun(p[None]) + sd * np.random.default_rng(seed + 1).standard_normal((12, R.size))
    batch = fits._refit_rows(fun, Fd, sd, p, LO[:n], HI[:n])
    seq = np.array([fits._solve(lambda q: fun(q[None])[0], f, sd, p, LO[:n], HI[:n]).x for f in Fd])
    assert not np.any(np.isnan(batch))
    # the optimum to the precision of the fit (the model's round-off: ~1e-9 in ln w, ln z0)
    assert np.max(np.abs(batch - seq)) < 1e-6
    cost = lambda P: np.sum(((fun(P) - Fd) / sd) ** 2, axis=1)  # noqa: E731
    assert np.all(cost(batch) <= cost(seq) * (1 + 1e-9))


@pytest.mark.parametrize(("rel", "seed", "have_sd"), [(0.03, 2026, True), (0.05, 1, False)])
def test_the_intervals_are_those_of_the_one_by_one_bootstrap(monkeypatch, rel, seed, have_sd):
    F, sd = noisy(RADII, rel, seed)
    kw = dict(sd=sd if have_sd else None, bootstrap=25, seed=seed)
    fast = fits.fit_pull_off(RADII, F, E, **kw)
    assert fast.identifiable
    with monkeypatch.context() as m:
        one_by_one(m)
        slow = fits.fit_pull_off(RADII, F, E, **kw)
    for k in ("work_of_adhesion_ci95", "equilibrium_spacing_ci95"):
        assert getattr(fast, k) == pytest.approx(getattr(slow, k), rel=1e-6), k
        assert getattr(fast, k) != getattr(fast, k + "_linear")  # the bootstrap ran
    assert fast.work_of_adhesion == slow.work_of_adhesion  # the fit itself is untouched


def test_the_data_that_do_not_determine_z0_are_refitted_one_by_one(monkeypatch):
    """Where the cost may have several minima the refits stay those of the fit's solver."""
    R = np.array([2e-6, 4e-6, 8e-6, 16e-6])  # JKR: z0 not determined
    F, sd = noisy(R, 0.2, 5, w=1.0)
    calls = []
    real = fits._refit_rows
    monkeypatch.setattr(fits, "_refit_rows", lambda *a: calls.append(1) or real(*a))
    fit = fits.fit_pull_off(R, F, E, sd=sd, bootstrap=20)
    assert not fit.identifiable and not calls
    assert fit.work_of_adhesion_ci95 != fit.work_of_adhesion_ci95_linear


def test_a_refit_the_model_refuses_is_left_to_the_one_by_one_solver():
    fun = lambda P: fits._model_rows(P, RADII, E, None)  # noqa: E731

    def picky(P):  # refuses any w above 0.12 J/m^2, as the model outside its domain would
        if np.any(P[:, 0] > math.log(0.12)):
            raise ValueError("work_of_adhesion out of range")
        return fun(P)

    p = np.log([W, Z0])
    Fd = np.stack([fun(p[None])[0], 1.5 * fun(p[None])[0]])  # the second wants w ~ 0.15
    out = fits._refit_rows(picky, Fd, 0.03 * np.abs(Fd[0]), p, LO, HI)
    assert out[0] == pytest.approx(p, abs=1e-8)
    assert np.all(np.isnan(out[1]))
    # the rows that raise are found by halving: nan there, the model's values elsewhere
    P = np.log([[0.1, Z0], [0.2, Z0], [0.05, Z0]])
    got = _least_squares._rows_or_nan(picky, P, RADII.size)
    assert np.all(np.isnan(got[1])) and np.allclose(got[[0, 2]], fun(P[[0, 2]]), rtol=1e-14)


def test_a_failing_batch_gives_the_one_by_one_result(monkeypatch):
    F, sd = noisy(RADII, 0.05, 1)
    fast = fits.fit_pull_off(RADII, F, E, sd=sd, bootstrap=20)

    def broken(P, *a):
        raise ValueError("out of the domain")

    monkeypatch.setattr(fits, "_model_rows", broken)
    slow = fits.fit_pull_off(RADII, F, E, sd=sd, bootstrap=20)
    assert slow.work_of_adhesion_ci95 == pytest.approx(fast.work_of_adhesion_ci95, rel=1e-6)
    assert slow.equilibrium_spacing_ci95 == pytest.approx(fast.equilibrium_spacing_ci95, rel=1e-6)
