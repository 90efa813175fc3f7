"""The fast paths give the results of the general ones.

- A scalar call runs the vectorised kernels on NumPy scalars (``_numerics._where``): it must
  give the element of the same call on an array, to rounding.
- The per-point iterations (``_numerics._iterate``) drop converged points: a batch with an
  extreme or unconvergeable point returns the other points as when each is alone.
- The collocation solvers work on chunks of points (``sie._CHUNK_ELEMENTS``): any chunk size
  gives the same results, to rounding. So do the vectorised closed forms (``sie._in_chunks``,
  bounded memory for any number of points; issue 22).

"To rounding", never bit for bit (README, "Same answers on every machine"): NumPy's SIMD loops
for ``exp``/``log`` on arrays round differently from its scalar code on some CPUs (AVX-512),
and BLAS rounds with the number of rows in a batch. A quantity is compared to :data:`ULPS`
units in its last place (:func:`_same`, :func:`_close`); a round-off quantity (a residual, an
error estimate) holds little but rounding errors and is compared with an absolute bound
(:data:`ROUNDOFF`); labels and flags exactly.
- The input checks recognise valid input without building messages; invalid input still gets
  the detailed message.
- ``import linecontact`` does not import SciPy (it is imported where it is used).

No timings here: these tests catch a broken fast path, not a slow one.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import scipy.special
from numpy.testing import assert_array_equal

import linecontact as lc
from linecontact import _numerics, closed_forms, sie
from linecontact._validation import check_array, non_negative, positive
from linecontact.tangential._core import _xlogy

RNG = np.random.default_rng(20240611)


def _sample(n, rng):
    """a/R, R/h, sigma0/E over the benchmark domain (log-uniform)."""
    s = 10 ** rng.uniform(-4, np.log10(0.3), n)
    rho = 10 ** rng.uniform(1, 4, n)
    A = 10 ** rng.uniform(-4, np.log10(0.2), n)
    return A, rho, s


#: Units in the last place that two code paths may differ by (the iterations converge to the
#: last bits of their inputs, which may themselves differ by an ulp between the paths).
ULPS = 64
#: Round-off quantities (residuals, error estimates) of the two paths may differ by this much
#: (absolute: their scale is 1, that of the nondimensional equations they measure).
ROUNDOFF = 1e-12
_ROUNDOFF_FIELDS = ("residual", "error_estimate")


def _agree(a, b, name: str, ulps: int = ULPS) -> bool:
    """``a`` and ``b`` the same quantity from two code paths: equal to rounding."""
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind in "biuUSO" or b.dtype.kind in "biuUSO":
        return bool(np.array_equal(a, b))
    a, b = a.astype(float), b.astype(float)
    same_nan = np.isnan(a) & np.isnan(b)
    if name.startswith(_ROUNDOFF_FIELDS):
        return bool(np.all(same_nan | (np.abs(a - b) <= ROUNDOFF)))
    with np.errstate(invalid="ignore"):
        tol = ulps * np.spacing(np.maximum(np.abs(a), np.abs(b)))
        return bool(np.all(same_nan | (a == b) | (np.abs(a - b) <= tol)))


#: The same for the inverse problems (the width for a load): near the pull-off the width is
#: conditioned like 1/sqrt(F - F_pulloff), up to 1e4 at the loads drawn here (1e-8 above
#: it); 46 ulp seen on an AVX-512 machine.
INVERSE_ULPS = 4096


def _same(scalar_result, array_result, i, fields, ulps=ULPS):
    for f in fields:
        a, b = getattr(scalar_result, f), getattr(array_result, f)
        b = np.asarray(b)[i]
        assert _agree(a, b, f, ulps), f"{f}: scalar {a!r} != array {b!r} (point {i})"


# --------------------------------------------------------------------------------------------
# scalar calls = elements of array calls


NORMAL_FIELDS = ["c_over_R", "F_over_Eh", "residual_separation", "converged", "stable"]


def test_normal_contact_scalar_is_array_element():
    A, rho, s = _sample(150, np.random.default_rng(1))
    s[:10] = 0.0  # Hertz
    arr = lc.normal_contact(A, rho, s)
    for i in range(A.size):
        r = lc.normal_contact(float(A[i]), float(rho[i]), float(s[i]))
        assert isinstance(r.F_over_Eh, float) and isinstance(r.stable, bool)
        _same(r, arr, i, NORMAL_FIELDS)


def test_pull_off_and_contact_for_load_scalar_is_array_element():
    _, rho, s = _sample(120, np.random.default_rng(2))
    s[:5] = 0.0
    po = lc.pull_off(rho, s)
    fields = [
        "F_pulloff_over_Eh",
        "a_over_R_at_pulloff",
        "c_over_R_at_pulloff",
        "mechanism",
        "F_zero_width_over_Eh",
        "F_minimum_over_Eh",
        "a_over_R_at_minimum",
        "kappa",
    ]
    for i in range(rho.size):
        _same(lc.pull_off(float(rho[i]), float(s[i])), po, i, fields)
    # stable branch, from the pull-off force itself up to Hertz-dominated loads
    F = po.F_pulloff_over_Eh + np.abs(po.F_pulloff_over_Eh) * 10 ** RNG.uniform(-8, 3, rho.size)
    F[:5] = 10 ** RNG.uniform(-3, 1, 5)  # no adhesion: positive loads
    F[5] = po.F_pulloff_over_Eh[5]
    cl = lc.contact_for_load(F, rho, s)
    fields = ["a_over_R", "c_over_R", "F_over_Eh", "error_estimate", "stable"]
    for i in range(rho.size):
        r = lc.contact_for_load(float(F[i]), float(rho[i]), float(s[i]))
        _same(r, cl, i, fields, INVERSE_ULPS)
    # unstable branch, where it exists
    snap = (np.asarray(po.mechanism) == "snap-off") & (
        po.F_minimum_over_Eh < po.F_zero_width_over_Eh
    )
    frac = RNG.uniform(1e-6, 1 - 1e-6, rho.size)
    Fu = po.F_minimum_over_Eh + frac * (po.F_zero_width_over_Eh - po.F_minimum_over_Eh)
    idx = np.flatnonzero(snap & (Fu > po.F_minimum_over_Eh) & (Fu < po.F_zero_width_over_Eh))
    assert idx.size > 10
    cu = lc.contact_for_load(Fu[idx], rho[idx], s[idx], branch="unstable")
    for k, i in enumerate(idx):
        r = lc.contact_for_load(float(Fu[i]), float(rho[i]), float(s[i]), branch="unstable")
        _same(r, cu, k, fields, INVERSE_ULPS)
        assert not r.stable


SLIDING_FIELDS = [
    "c1_over_R",
    "c2_over_R",
    "e_over_R",
    "F_over_Eh2",
    "M_over_Eh2R",
    "residual_trailing",
    "residual_leading",
    "converged",
    "stable",
]


def test_sliding_closed_form_scalar_is_array_element():
    A, rho, s = _sample(80, np.random.default_rng(3))
    ratio = 10 ** np.random.default_rng(4).uniform(-1, 1, A.size)
    arr = lc.sliding_contact(A, rho, ratio, s, method="closed-form")
    for i in range(A.size):
        r = lc.sliding_contact(
            float(A[i]), float(rho[i]), float(ratio[i]), float(s[i]), method="closed-form"
        )
        _same(r, arr, i, SLIDING_FIELDS)


def test_sliding_pull_off_and_inverse_scalar_is_array_element():
    _, rho, s = _sample(12, np.random.default_rng(5))
    ratio = 10 ** np.random.default_rng(6).uniform(-1, 1, rho.size)
    po = lc.sliding_pull_off(rho, ratio, s)
    fields = [
        "F_pulloff_over_Eh2",
        "a_over_R_at_pulloff",
        "mechanism",
        "F_zero_width_over_Eh2",
        "c1_over_R_zero_width",
        "c2_over_R_zero_width",
    ]
    for i in range(rho.size):
        _same(lc.sliding_pull_off(float(rho[i]), float(ratio[i]), float(s[i])), po, i, fields)
    F = po.F_pulloff_over_Eh2 + np.abs(po.F_pulloff_over_Eh2) * 10 ** RNG.uniform(-3, 2, rho.size)
    cl = lc.sliding_contact_for_load(F, rho, ratio, s, method="closed-form")
    for i in range(rho.size):
        r = lc.sliding_contact_for_load(
            float(F[i]), float(rho[i]), float(ratio[i]), float(s[i]), method="closed-form"
        )
        _same(r, cl, i, ["a_over_R", *SLIDING_FIELDS], INVERSE_ULPS)


def test_scalar_fast_path_keeps_the_result_types():
    r = lc.normal_contact(0.02, 100.0, 0.01)
    assert type(r.n_collocation) is int and type(r.converged) is bool
    assert type(r.residual_consistency) is float and type(r.c_over_R) is float
    p = lc.pull_off(100.0, 0.2)
    assert type(p.mechanism) is str and type(p.F_pulloff_over_Eh) is float
    s = lc.sliding_contact(0.03, 100.0, 2.0, 0.01, method="closed-form")
    assert type(s.n_collocation) is int and type(s.stable) is bool and s.T_over_Eh2 != s.T_over_Eh2


# --------------------------------------------------------------------------------------------
# per-point iteration


def test_iterate_drops_finished_points():
    """Each point leaves the loop when it stops; one that never stops runs to the cap alone."""
    sizes = []

    def step(x, target):
        sizes.append(x.size)
        x = x + 1.0
        return (x,), x >= target

    target = np.array([3.0, 1.0, np.inf, 5.0])
    (x,), its = _numerics._iterate(step, (np.zeros(4),), (target,), 8)
    assert_array_equal(its, [3, 1, 8, 5])
    assert_array_equal(x, [3.0, 1.0, 8.0, 5.0])
    assert sizes == [4, 3, 3, 2, 2, 1, 1, 1]
    # scalars: the same iteration on NumPy scalars
    (xs,), k = _numerics._iterate(step, (np.float64(0.0),), (np.float64(3.0),), 8)
    assert (xs, k) == (3.0, 3)
    # points marked done are not iterated at all
    sizes.clear()
    (x,), its = _numerics._iterate(
        step, (np.zeros(3),), (np.array([2.0, 2.0, 2.0]),), 8, done=np.array([True, False, True])
    )
    assert_array_equal(its, [0, 2, 0])
    assert sizes == [1, 1]
    assert_array_equal(x, [0.0, 2.0, 0.0])


def test_u_of_abar_counts_iterations_per_point():
    ab = np.array([0.14, 1e-200, 3.0, 1e20])
    kap = np.full(4, 0.11)
    u, res, it = closed_forms._u_of_abar(ab, kap)
    for i in (0, 2):
        ui, ri, ki = closed_forms._u_of_abar(ab[i], kap[i])
        assert _agree(u[i], ui, "u") and _agree(res[i], ri, "residual")
        assert abs(int(it[i]) - int(ki)) <= 1  # a last bit may cost or save a Newton step
    assert it.max() <= 8
    # the closed form over a broad sample needs a handful of Newton steps per point
    A, rho, s = _sample(20_000, np.random.default_rng(7))
    kap = (4 / np.pi) * s * np.sqrt(2 * rho)
    _, res, it = closed_forms._u_of_abar(A * np.sqrt(rho / 2), kap)
    assert it.max() <= 6 and res.max() < 1e-13


def test_u_stationary_matches_bisection():
    """The Newton iteration for the load minimum finds the root of the bisection it replaced."""
    kap = 10 ** np.random.default_rng(8).uniform(-8, 12, 2000)
    lo = np.full(kap.shape, np.log(1e-10))
    hi = np.full(kap.shape, np.log(1e9))
    for _ in range(90):
        mid = 0.5 * (lo + hi)
        above = closed_forms._kappa_stationary(np.exp(mid)) > kap
        lo, hi = np.where(above, mid, lo), np.where(above, hi, mid)
    np.testing.assert_allclose(closed_forms._u_stationary(kap), np.exp(0.5 * (lo + hi)), rtol=1e-14)
    scalar = closed_forms._u_stationary(np.float64(1.0))
    assert _agree(scalar, closed_forms._u_stationary(np.array([1.0]))[0], "u")


def test_batch_with_an_unconvergeable_point_keeps_the_others():
    # inside the domain the closed forms converge almost everywhere; the collocation cannot
    # resolve an adhesive zone of c/a - 1 ~ 1e-9 with n <= 2048 nodes, nor the sliding
    # closed form this corner (R/h2 = 3e11, sigma0/E = 5e4) to its tolerance
    A = np.array([0.02, 1.6596315985408394, 0.15])
    rho = np.array([100.0, 21153758.746772554, 100.0])
    s = np.array([0.01, 7.749102910688328, 0.01])
    batch = lc.normal_contact(A, rho, s, method="collocation", on_failure="report")
    assert not batch.converged[1]
    for i in (0, 2):
        one = lc.normal_contact(float(A[i]), float(rho[i]), float(s[i]), method="collocation")
        for f in NORMAL_FIELDS:
            _close(getattr(one, f), np.asarray(getattr(batch, f))[i], f)
    # the sliding collocation cannot resolve zones 1e14 times the contact (a = 1e-15 R)
    batch = lc.sliding_contact(
        np.array([0.03, 1e-15, 0.01]),
        np.array([100.0, 10.0, 100.0]),
        np.array([2.0, 0.5, 2.0]),
        np.array([0.01, 0.0078125, 0.01]),
        method="collocation",
        on_failure="report",
    )
    assert not batch.converged[1]
    for i, a in ((0, 0.03), (2, 0.01)):
        one = lc.sliding_contact(a, 100.0, 2.0, 0.01, method="collocation")
        for f in SLIDING_FIELDS:
            _close(getattr(one, f), np.asarray(getattr(batch, f))[i], f)


def test_the_thin_zone_corner_converges():
    # c1 = c2 = a to double precision (u below 1e-9, the old end of the bracket): it did not
    # converge before; now its separation residuals are at round-off, as are the normal
    # problem's at a = 10 R, kappa = 7.6e11 (against JKR, the thin-zone limit)
    corner = (1.7821645537950392, 334651438040.73004, 0.0027394827605628914, 53570.51032412535)
    with pytest.warns(lc.ModelValidityWarning):
        r = lc.sliding_contact(*corner, method="closed-form")
    assert r.converged and max(r.residual_trailing, r.residual_leading) < 1e-14
    rho, s = 177827941003.89227, 1e6
    with pytest.warns(lc.ModelValidityWarning):
        n = lc.normal_contact(10.0, rho, s)
    assert n.F_over_Eh == pytest.approx(lc.jkr_load(10.0, rho, s), rel=1e-14)


def _close(a, b, err_msg=""):
    """Equal to rounding: the collocation's matrix products (BLAS) round differently with the
    number of rows in a batch, so a point's result can move in its last bits with its batch;
    the collocation's Newton iterations stop at 1e-13, so the tolerance is that."""
    a, b = np.asarray(a), np.asarray(b)
    name = err_msg.rsplit(".", 1)[-1]
    if a.dtype.kind in "biuUSO":
        assert_array_equal(a, b, err_msg=err_msg)
    elif name.startswith(_ROUNDOFF_FIELDS):
        assert _agree(a, b, name), f"{err_msg}: {a!r} and {b!r} differ by more than round-off"
    else:
        np.testing.assert_allclose(a, b, rtol=1e-13, atol=1e-15, err_msg=err_msg)


def test_collocation_batch_with_a_failing_point_keeps_the_others():
    """A point that misses its tolerance at a fixed n does not change the others."""
    A = np.array([0.01, 0.15, 0.02])
    rho = np.array([100.0, 5000.0, 100.0])
    s = np.array([0.01, 0.2, 0.01])
    batch = lc.normal_contact(A, rho, s, method="collocation", n=24, on_failure="report")
    assert not batch.converged[1] and batch.converged[0] and batch.converged[2]
    fields = [*NORMAL_FIELDS, "error_estimate", "residual_consistency", "n_collocation"]
    for i in (0, 2):
        r = lc.normal_contact(A[i], rho[i], s[i], method="collocation", n=24)
        for f in fields:
            _close(getattr(r, f), np.asarray(getattr(batch, f))[i], err_msg=f)


# --------------------------------------------------------------------------------------------
# chunked collocation


def _collocation_results():
    A, rho, s = _sample(10, np.random.default_rng(9))
    A[:3] = [0.1, 0.15, 0.12]  # thin adhesive zones: several sizes n
    rho[:3] = [3000.0, 5000.0, 2000.0]
    s[:3] = [0.1, 0.2, 0.15]
    ratio = 10 ** np.random.default_rng(10).uniform(-1, 1, 6)
    t0 = 10 ** np.random.default_rng(11).uniform(-4, -1, 8)
    d = np.linspace(0.05, 0.97, 8)
    return dict(
        normal=lc.normal_contact(A, rho, s, method="collocation"),
        sliding=lc.sliding_contact(A[:6], rho[:6], ratio, s[:6], method="collocation"),
        initiation=lc.sliding_initiation(t0, d, method="collocation"),
        initiation_T=lc.sliding_initiation(t0, T_over_Ea=1.5 * t0 * d, method="collocation"),
        rolling=lc.steady_rolling(t0, 2 * d - 1, method="collocation"),
    )


def test_chunked_collocation_equals_unchunked(monkeypatch):
    """Chunks of one or two points give the results of one batch."""
    whole = _collocation_results()
    monkeypatch.setattr(sie, "_CHUNK_ELEMENTS", 40)
    assert len(sie._chunks(10, 16)) == 5 and len(sie._chunks(10, 48)) == 10
    chunked = _collocation_results()
    for key, r in whole.items():
        for name, col in r.columns().items():
            _close(chunked[key].columns()[name], col, err_msg=f"{key}.{name}")


def _closed_form_results():
    """The vectorised closed forms on a few points (the loads from their pull-off up)."""
    rng = np.random.default_rng(12)
    m = 23
    A = 10 ** rng.uniform(-4, np.log10(0.2), m)
    rho = 10 ** rng.uniform(1, 4, m)
    s = 10 ** rng.uniform(-4, np.log10(0.3), m)
    r = 10 ** rng.uniform(-1, 1, m)
    po = lc.pull_off(rho, s)
    F = po.F_pulloff_over_Eh + 10 ** rng.uniform(-6, 1, m) * np.abs(po.F_pulloff_over_Eh)
    F_unstable = 0.5 * (po.F_pulloff_over_Eh + po.F_zero_width_over_Eh)
    spo = lc.sliding_pull_off(rho, r, s)
    Fs = spo.F_pulloff_over_Eh2 + 10 ** rng.uniform(-6, 1, m) * np.abs(spo.F_pulloff_over_Eh2)
    Fs[:3] = spo.F_pulloff_over_Eh2[:3] - 1.0  # below the pull-off force: reported
    return dict(
        normal=lc.normal_contact(A, rho, s),
        pull_off=po,
        for_load=lc.contact_for_load(F, rho, s),
        for_load_unstable=lc.contact_for_load(
            F_unstable, rho, s, branch="unstable", on_failure="report"
        ),
        sliding=lc.sliding_contact(A, rho, r, s),
        sliding_pull_off=spo,
        sliding_for_load=lc.sliding_contact_for_load(Fs, rho, r, s, on_failure="report"),
    )


def test_chunked_closed_forms_equal_unchunked(monkeypatch):
    """The closed forms in chunks of 1 to 7 points give the results of one batch."""
    whole = _closed_form_results()
    for size in (1, 7):
        monkeypatch.setattr(sie, "_CHUNK_ELEMENTS", size)
        assert len(sie._chunks(23, 0)) == -(-23 // size)
        chunked = _closed_form_results()
        for key, r in whole.items():
            for name, col in r.columns().items():
                _close(chunked[key].columns()[name], col, err_msg=f"{key}.{name}")


def test_in_chunks_joins_arrays_tuples_and_dicts(monkeypatch):
    monkeypatch.setattr(sie, "_CHUNK_ELEMENTS", 3)
    x = np.arange(10.0)
    assert_array_equal(sie._in_chunks(lambda a, k: a * k, 10, x, 2.0), 2 * x)
    a, b = sie._in_chunks(lambda a: (a + 1, a > 4), 10, x)
    assert_array_equal(a, x + 1) and assert_array_equal(b, x > 4)
    assert b.dtype == bool
    d = sie._in_chunks(lambda a: {"m": np.where(a > 4, "snap-off", "zero-width")}, 10, x)
    assert list(d["m"]) == ["zero-width"] * 5 + ["snap-off"] * 5


def test_chunks_cover_the_points():
    for size, n in ((0, 16), (1, 16), (100_000, 16), (7, 8192)):
        sl = sie._chunks(size, n)
        covered = np.concatenate([np.arange(size)[c] for c in sl]) if sl else np.array([])
        assert_array_equal(covered, np.arange(size))
        assert all(c.stop - c.start <= max(1, sie._CHUNK_ELEMENTS // (n + 1)) for c in sl)


# --------------------------------------------------------------------------------------------
# input checks, elementary functions, import


def test_checks_return_valid_input_unchanged():
    x = np.linspace(0.1, 1.0, 5)
    assert positive("a", x) is x
    assert positive("a", 0.5).shape == () and positive("a", 0.5).dtype == np.float64
    assert_array_equal(positive("a", [1, 2]), [1.0, 2.0])
    assert non_negative("s", -0.0) == 0.0


@pytest.mark.parametrize(
    "value, message",
    [
        (np.array([0.5, np.nan]), r"^a must be a finite number in \(0, inf\), got nan$"),
        (np.array([0.5, np.inf]), r"^a must be a finite number in \(0, inf\), got inf$"),
        (np.array([0.5, -1.0]), r"^a must be in \(0, inf\), got -1.0$"),
        (0.0, r"^a must be in \(0, inf\), got 0.0$"),
        (np.array([]), r"^a must not be empty$"),
        (True, r"^a must be a real number or an array of them, got True$"),
        ("0.5", r"^a must be a real number or an array of them, got '0.5'$"),
        (None, r"^a must be a real number or an array of them, got None$"),
        ([1.0, 2j], r"^a must be a real number or an array of them, got \[1.0, 2j\]$"),
    ],
)
def test_checks_still_name_the_offending_value(value, message):
    with pytest.raises(ValueError, match=message):
        positive("a", value)


def test_check_array_bounds_and_infinities():
    assert check_array("g", 1.0, low=0.0, low_inclusive=True, high=1.0, high_inclusive=True) == 1.0
    with pytest.raises(ValueError, match=r"^g must be in \[0, 1\), got 1.0$"):
        check_array("g", [0.5, 1.0], low=0.0, low_inclusive=True, high=1.0)
    with pytest.raises(ValueError, match=r"^x must be a finite number, got -inf$"):
        check_array("x", [0.0, -np.inf], low=-np.inf, low_inclusive=True)
    assert check_array("x", np.inf, allow_inf=True) == np.inf


def test_xlogy_is_scipys():
    x = np.array([0.0, 0.0, 0.0, 1.0, 2.5, 1e-300, -1.0, 0.0, 3.0])
    y = np.array([0.0, 2.0, -1.0, 0.0, 1.7, 1e-300, 2.0, np.nan, np.inf])
    got = _xlogy(x, y)
    want = scipy.special.xlogy(x, y)
    assert_array_equal(np.isnan(got), np.isnan(want))
    ok = ~np.isnan(want)
    np.testing.assert_allclose(got[ok], want[ok], rtol=1e-15, atol=0)
    t = np.linspace(-1, 1, 101)
    np.testing.assert_allclose(_xlogy((1 - t) / 2, 1 - t), scipy.special.xlogy((1 - t) / 2, 1 - t))


def test_import_does_not_import_scipy():
    code = (
        "import sys, linecontact; "
        "print(sorted(m for m in sys.modules if m == 'scipy' or m.startswith('scipy.')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_inputs_are_not_modified():
    """Valid float arrays are used as given (no copy): no solver may write into them."""
    A, rho, s = _sample(20, np.random.default_rng(12))
    ratio = np.linspace(0.5, 3.0, 20)
    keep = [v.copy() for v in (A, rho, s, ratio)]
    lc.normal_contact(A, rho, s)
    lc.normal_contact(A, rho, s, method="collocation")
    po = lc.pull_off(rho, s)
    F = po.F_pulloff_over_Eh + 1.0
    keepF = F.copy()
    lc.contact_for_load(F, rho, s)
    lc.sliding_contact(A, rho, ratio, s, method="collocation")
    lc.sliding_contact(A, rho, ratio, s, method="closed-form")
    lc.sliding_pull_off(rho[:3], ratio[:3], s[:3])
    d = np.linspace(0.1, 0.9, 20)
    keepd = d.copy()
    lc.sliding_initiation(s, d, method="collocation")
    lc.steady_rolling(s, d, method="collocation")
    for v, k in zip((A, rho, s, ratio, F, d), (*keep, keepF, keepd), strict=True):
        assert_array_equal(v, k)
