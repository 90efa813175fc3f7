"""The Lennard-Jones solves run on one BLAS thread, and a caller's own settings stay (issue 37).

The dense systems are too small to gain from BLAS threads, and on a busy machine the
threads fight the other jobs for the cores (``benchmarks/busy_core.py``); the limit is set
around the solve only, so a caller who imported the library keeps its own thread counts.
"""

from __future__ import annotations

import numpy as np
import pytest
from threadpoolctl import threadpool_info, threadpool_limits

import linecontact as lc
from linecontact import _threads
from linecontact.lennard_jones import _solver


def _blas_threads() -> list[int]:
    return [d["num_threads"] for d in threadpool_info() if d["user_api"] == "blas"]


@pytest.fixture
def seen(monkeypatch):
    """The BLAS thread counts at each LU factorisation of the solver."""
    counts: list[list[int]] = []
    factor = _solver._lu_factor

    def spy(J):
        if len(counts) < 3:  # threadpool_info is slow: the first few suffice
            counts.append(_blas_threads())
        return factor(J)

    monkeypatch.setattr(_solver, "_lu_factor", spy)
    return counts


@pytest.mark.parametrize("caller", [None, 2, 1])
def test_a_solve_runs_on_one_thread_and_gives_the_callers_settings_back(seen, caller):
    import scipy.linalg  # noqa: F401 - its BLAS loaded, as in any solve

    def calls():
        before = _blas_threads()
        lc.lennard_jones.lj_pull_off(2.0)
        cyl = lc.Cylinder.from_modulus(
            50e-9, 50e9, adhesion=lc.LennardJones(work_of_adhesion=0.1, equilibrium_spacing=3e-10)
        )
        cyl.contact(load=[0.5, 1.0])
        return before, _blas_threads()

    if caller is None:  # the process's own (default) counts
        before, after = calls()
    else:
        with threadpool_limits(caller, user_api="blas"):
            if _blas_threads() != [caller] * len(_blas_threads()):
                pytest.skip(f"this machine's BLAS does not run {caller} threads")
            before, after = calls()
    assert after == before  # the caller's settings, unchanged
    assert seen and all(c == [1] * len(c) for c in seen)  # the solve's: one thread each


def test_the_limit_is_given_back_when_the_solve_fails(seen):
    import scipy.linalg  # noqa: F401

    before = _blas_threads()
    with pytest.raises(ValueError):
        lc.lennard_jones.lj_contact_for_load(float("nan"), 1.0)
    with pytest.raises(lc.errors.NoEquilibriumError):
        lc.lennard_jones.lj_contact_for_load(-100.0, 1.0)  # below the pull-off
    assert _blas_threads() == before


def test_the_direct_lapack_calls_solve_as_scipy_does():
    import scipy.linalg

    rng = np.random.default_rng(0)
    J = np.eye(40) + 0.1 * rng.standard_normal((40, 40))
    b = rng.standard_normal(40)
    mine = _solver._lu_solve(_solver._lu_factor(J.copy()), b)
    theirs = scipy.linalg.lu_solve(scipy.linalg.lu_factor(J), b)
    assert np.allclose(mine, theirs, rtol=1e-13, atol=1e-13)
    assert np.allclose(J @ mine, b, rtol=1e-12, atol=1e-12)
    with _threads.one_blas_thread():  # nested limits give back in order
        with _threads.one_blas_thread():
            assert _blas_threads() == [1] * len(_blas_threads())


def test_overlapping_solves_of_several_threads_give_the_callers_settings_back():
    """Threads that solve at once share the limit: none leaves the process on one thread.

    The first thread enters, the second enters, the first leaves, the second leaves: each
    limit given back on its own would leave the process with the second's "before" (one
    thread) at the end.
    """
    import threading

    import scipy.linalg  # noqa: F401

    before = _blas_threads()
    first_in, second_in, first_out = threading.Event(), threading.Event(), threading.Event()

    def first() -> None:
        with _threads.one_blas_thread():
            first_in.set()
            second_in.wait(10)
        first_out.set()

    def second() -> None:
        first_in.wait(10)
        with _threads.one_blas_thread():
            second_in.set()
            first_out.wait(10)

    workers = [threading.Thread(target=first), threading.Thread(target=second)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    assert first_out.is_set()
    assert _blas_threads() == before
