r"""Shared machinery of the tangential problems: the collocation driver and the result bases.

Used by :mod:`linecontact.tangential.initiation` and :mod:`linecontact.tangential.rolling`
(units, conventions and references: :mod:`linecontact.tangential`). A problem is described
by a :class:`_Problem` (its collocation kernel, convergence rate and closed forms, all in
the units of ``T`` over ``a tau0`` or over ``mu F``, the :class:`_Zone` of its stick zone
and its result class); :func:`_run` validates the state variable, solves on the points that
have a stick zone and returns the fields of the result, and :func:`_constant_friction` /
:func:`_coulomb_friction` are the public functions of each friction law around it. The
results of each law share a base (:class:`_ConstantStress`, :class:`_CoulombFriction`) that
assembles the traction from the result's stick-zone traction.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import ClassVar, Generic, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validation
from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import (
    broadcast,
    check_array,
    check_solver_options,
    first_point,
    point_text,
    positions,
    scalar_or_array,
)
from ..errors import ConvergenceError, NoEquilibriumError
from ..results import SI, Result, as_output
from ..sie import SIZES as _SIE_SIZES
from ..sie import BoundedSolver, _chunks

#: Collocation sizes tried by ``n="auto"`` (the largest bounds the work per point).
SIZES = _SIE_SIZES
#: Nodes used for the Coulomb problems (their right-hand sides are linear: exact for n >= 2).
N_COULOMB = 8
_N_CHECK = 16  # points of the stick zone where the stick condition is re-evaluated
_CHECK_THETA = np.pi * (np.arange(_N_CHECK) + 0.25) / _N_CHECK
_CHECK_Y = np.cos(_CHECK_THETA)
_FORCE_TOL = 1e-12  # Newton tolerance on T (relative to the full-slip load)

_R = TypeVar("_R", bound="_Tangential")

_STICK = "stick"
_STICK_SLIP = "stick-slip"
_SLIDING = "sliding"


# --------------------------------------------------------------------------------------------
# elementary functions


def _xlogy(x, y):
    """``x ln y``, zero where ``x = 0`` (unless ``y`` is nan): ``scipy.special.xlogy``.

    In NumPy, so that importing the package does not import ``scipy.special`` (~0.1 s).
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        v = x * np.log(y)
    return np.where((x == 0) & ~np.isnan(y), 0.0, v)


# --------------------------------------------------------------------------------------------
# input checks


def _check_options(method, n, tol):
    if method not in ("closed-form", "collocation"):
        raise ValueError(f"method must be 'closed-form' or 'collocation', got {method!r}")
    check_solver_options(n, tol, n_max=SIZES[-1])


def _one_of(d_over_a, load, load_name: str) -> None:
    if (d_over_a is None) == (load is None):
        raise ValueError(f"give exactly one of d_over_a or {load_name}")


# --------------------------------------------------------------------------------------------
# collocation plumbing


@lru_cache(maxsize=32)
def _solver(n: int) -> BoundedSolver:
    return BoundedSolver(n)


@lru_cache(maxsize=32)
def _check_matrix(n: int) -> NDArray:
    """cos((j+1) theta_c): the Hilbert transform -sum_j b_j T_{j+1} at the check points."""
    m = np.cos(np.arange(1, n + 1)[:, None] * _CHECK_THETA[None, :])
    m.setflags(write=False)
    return m


def _rounding(f: NDArray, lam: NDArray) -> NDArray:
    """Relative rounding error of an extra unknown ``lam`` fixed by the consistency condition.

    ``lam`` is a mean of right-hand-side values of size ``max |f|``; as it vanishes (the creep
    at full stick) its relative error grows like ``eps max|f| / |lam|``. Measured against the
    closed forms (rolling and Carter, ``1 + d/a`` from 1e-9 to 0.1, ``n`` from 64 to 8192) the
    actual error is 0.1 to 1.4 times that, independent of n, once the truncation error is
    resolved; twice it is counted in the error estimate, so that such a point is not reported
    converged.
    """
    scale = np.max(np.abs(f), axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(lam != 0, 2 * 2.2e-16 * scale / np.abs(lam), 0.0)


def _tail(b: NDArray) -> NDArray:
    """Chebyshev tail: the largest of the last three coefficients over the largest one.

    The coefficients are in units of the friction stress (``tau0`` or ``mu p0``); a solution
    much smaller than that (a short stick zone) is measured against it instead, so that
    round-off in a tiny solution does not count as truncation error.
    """
    big = np.maximum(np.max(np.abs(b), axis=-1), 1.0)
    return np.max(np.abs(b[..., -3:]), axis=-1) / big


def _adaptive(kernel, delta: NDArray, rate: NDArray, n, tol: float) -> dict[str, NDArray]:
    """Run ``kernel(delta, n)`` per point with ``n`` chosen for ``tol``.

    The right-hand sides have logarithmic sources a distance ``cosh(rate)`` (in units of the
    interval's half-length) from the interval's centre, so the Chebyshev coefficients fall
    like ``exp(-rate j)``: start at the smallest size with ``exp(-rate n) <= tol`` and move
    points whose tail still exceeds ``tol`` one size up.
    """
    P = delta.size
    sizes = np.asarray(SIZES)
    if n == "auto":
        need = np.log(1.0 / tol) / np.maximum(rate, 1e-300)
        k = np.minimum(np.searchsorted(sizes, need), sizes.size - 1)
        nsel = sizes[k]
    else:
        nsel = np.full(P, int(n))
    out: dict[str, NDArray] = {}
    pending = np.ones(P, bool)
    while pending.any():
        for nn in np.unique(nsel[pending]):
            sel = np.flatnonzero(pending & (nsel == nn))
            for c in _chunks(sel.size, int(nn)):  # bounded memory for any number of points
                idx = sel[c]
                r = kernel(delta[idx], int(nn))
                # the a-priori truncation error exp(-rate n) is a floor under the tail: near
                # full stick the last coefficients understate the error of a solution that
                # the size does not resolve yet
                with np.errstate(over="ignore"):
                    r["tail"] = np.maximum(r["tail"], np.exp(-rate[idx] * nn))
                for key, v in r.items():
                    if key not in out:
                        out[key] = np.zeros(P, dtype=np.asarray(v).dtype)
                    out[key][idx] = v
        if n != "auto":
            break
        pending = pending & (out["tail"] > tol) & (nsel < sizes[-1])
        nsel = np.where(
            pending, sizes[np.minimum(np.searchsorted(sizes, nsel) + 1, sizes.size - 1)], nsel
        )
    out["n"] = nsel
    return out


# --------------------------------------------------------------------------------------------
# shared driver


def _solve_points(
    delta,
    active,
    method,
    n,
    tol,
    kernel,
    rate,
    T_closed,
    dT_closed,
    T_target=None,
    T_full=2.0,
    lo=0.0,
    hi=1.0,
):
    """Closed form or collocation on the active points; Newton on delta for a given T.

    All in the units of the kernel (``T`` over ``a tau0`` or ``mu F``; ``T_full`` is the
    full-slip load in those units). Returns the arrays ``delta``, ``T`` (of the solution),
    ``creep``, ``n``, ``stick``, ``cons``, ``tail`` and ``force`` (``|T(d) - T|/T_full``).
    """
    P = delta.size
    out = dict(
        delta=delta.copy(),
        T=np.full(P, np.nan),
        n=np.zeros(P, int),
        stick=np.zeros(P),
        cons=np.zeros(P),
        tail=np.zeros(P),
        force=np.zeros(P),
        creep=np.full(P, np.nan),
    )
    idx = np.flatnonzero(active)
    if idx.size == 0:
        return out
    d = delta[idx]
    if method == "closed-form":
        out["T"][idx] = T_closed(d)
    else:
        # Newton on d with the closed-form slope; a point whose force is met leaves the
        # iteration (only the others are solved again)
        act = np.arange(idx.size)
        r = {}
        for _ in range(12):
            ra = _adaptive(kernel, d[act], rate(d[act]), n, tol)
            for key, v in ra.items():
                if key not in r:
                    r[key] = np.zeros(idx.size, dtype=v.dtype)
                r[key][act] = v
            if T_target is None:
                break
            err = ra["T"] - T_target[idx[act]]
            with np.errstate(divide="ignore", invalid="ignore"):  # infinite slope at d = a
                slope = dT_closed(d[act])
            ok = np.abs(err) <= _FORCE_TOL * T_full
            if ok.all():
                break
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(ok | (np.abs(slope) < 1e-300), 0.0, err / slope)
            d[act] = np.clip(d[act] - step, lo, hi)
            act = act[~ok]
        out["delta"][idx] = d
        out["T"][idx] = r["T"]
        for key in ("n", "stick", "cons", "tail"):
            out[key][idx] = r[key]
        if "creep" in r:
            out["creep"][idx] = r["creep"]
    if T_target is not None:
        out["force"][idx] = np.abs(out["T"][idx] - T_target[idx]) / T_full
    return out


def _raise_unconverged(name, converged, labels: dict, out, n) -> None:
    if np.all(converged):
        return
    # the inputs at the first failing point, after broadcasting (``out`` is flat over them)
    i, at = first_point(~np.asarray(converged, bool), **labels)
    where = point_text(at)
    raise ConvergenceError(
        f"{name} (collocation) did not converge at {where} (error estimate "
        f"{out['tail'][i]:.3g}, stick residual {out['stick'][i]:.3g}, force residual "
        f"{out['force'][i]:.3g}, n = {out['n'][i]}): "
        + (
            f"the stick zone is too close to its limit for n <= {SIZES[-1]}; use "
            f"method='closed-form'"
            if n == "auto"
            else f"n = {out['n'][i]} nodes are too few for tol; try n='auto'"
        )
    )


def _raise_sliding(name, sliding, labels: dict, given: str, T_name, T, T_full) -> None:
    """NoEquilibriumError at the first sliding point, naming the inputs there.

    ``labels`` are the inputs under the caller's names (``given`` among them: the load or
    ``d_over_a``), ``T`` the tangential load and ``T_full`` the full-slip load, both in the
    unit of ``T_name``; all are broadcast to the points before the first is picked.
    """
    if not np.any(sliding):
        return
    _, at = first_point(sliding, **labels, _T=T, _T_full=T_full)
    Ti, Tf = at.pop("_T"), at.pop("_T_full")
    if given == T_name:
        head = f"{T_name}={Ti!r} is at or above the full-slip load {Tf!r}"
    else:  # d_over_a = 0: the load is the full-slip one
        head = f"{given}={at[given]!r} is full slip ({T_name}={Ti!r}, the full-slip load)"
    others = point_text({k: v for k, v in at.items() if k != given})
    raise NoEquilibriumError(
        f"{name}: {head}" + (f" at {others}" if others else "") + ": the whole contact slips "
        "(sliding), there is no stick zone"
    )


def _states(sliding, stick, shape):
    st = np.full(shape, _STICK_SLIP, dtype=object)
    st[np.asarray(sliding, bool)] = _SLIDING
    st[np.asarray(stick, bool)] = _STICK
    return st.astype(str)


@dataclass(frozen=True)
class _Zone:
    """Where the stick zone lies, given its end ``d`` (lengths over ``a``).

    ``|x| < d`` for the initiation of sliding (``d`` from 1 at ``T = 0`` down to 0, full slip),
    ``d < x < a`` for steady rolling (``d`` from -1 at ``T = 0`` up to 1, full slip: excluded).
    """

    d_low: float
    d_low_inclusive: bool
    d_stick: float  # delta at T = 0
    inside: Callable[[NDArray, NDArray], NDArray]  # (x, d): the points of the stick zone
    unit: Callable[[NDArray, NDArray], NDArray]  # (x, d): t in [-1, 1] over the stick zone


def _centred_unit(x: NDArray, d: NDArray) -> NDArray:
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(d > 0, x / d, 2.0)


#: The central stick zone ``|x| < d`` of the initiation of sliding.
_CENTRED = _Zone(0.0, True, 1.0, lambda x, d: np.abs(x) < d, _centred_unit)
#: The leading-edge stick zone ``d < x < a`` of steady rolling (``t`` exact at ``d`` and ``a``).
_LEADING = _Zone(-1.0, False, -1.0, lambda x, d: x > d, lambda x, d: (2 * x - 1 - d) / (1 - d))


# --------------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class _Tangential(Result):
    """Fields shared by the four tangential results (see the subclasses)."""

    # the SI forms scale by ``a``, the contact half-width; the bases of the two friction laws
    # declare T_over_Ea (after T_over_muF for Coulomb friction)
    d_over_a: NDArray | float = field(metadata=SI("stick_zone_end", "a", "m"))
    T_over_T_full_slip: NDArray | float
    state: NDArray | str
    method: str
    n_collocation: NDArray | int
    residual_stick: NDArray | float
    residual_force: NDArray | float
    residual_consistency: NDArray | float
    error_estimate: NDArray | float
    converged: NDArray | bool

    #: Where the stick zone lies (set by each result).
    _zone: ClassVar[_Zone]

    def _points(self, x_over_a):
        x = positions("x_over_a", x_over_a, np.shape(self.d_over_a))
        dlt = np.asarray(self.d_over_a, dtype=float)[..., None]
        st = np.asarray(self.state)[..., None]
        return x, dlt, st

    def _coefficients(self, kernel_solve) -> NDArray:
        """Re-solve the collocation system at the stored sizes: (points..., n_max)."""
        dlt = np.atleast_1d(np.asarray(self.d_over_a, dtype=float)).reshape(-1)
        nn = np.atleast_1d(np.asarray(self.n_collocation)).reshape(-1)
        nmax = max(int(nn.max()), 1)
        b = np.zeros((dlt.size, nmax))
        for n in np.unique(nn[nn > 0]):
            sel = nn == n
            b[sel, :n] = kernel_solve(dlt[sel], int(n))
        return b

    def _series(self, x: NDArray, dlt: NDArray, kernel_solve) -> tuple[NDArray, NDArray]:
        """The collocation solution on the stick zone: ``t``, ``sqrt(1 - t^2) sum b_j U_j(t)``.

        ``t`` maps the stick zone onto [-1, 1]; ``x``, ``dlt`` as from :meth:`_points`,
        ``kernel_solve`` as for :meth:`_coefficients`. Both of shape ``points.shape + (m,)``.
        """
        b = self._coefficients(kernel_solve)
        dd = np.atleast_1d(dlt[..., 0]).reshape(-1)
        xx = np.broadcast_to(x, dd.shape + x.shape[-1:])
        tt = self._zone.unit(xx, dd[:, None])
        shape = np.shape(dlt[..., 0]) + x.shape[-1:]
        return tt.reshape(shape), _cheb_u_series(b, tt).reshape(shape)

    def _stick(self, x: NDArray, dlt: NDArray) -> NDArray:  # pragma: no cover - in each result
        """The traction of the stick zone over the friction scale, by the result's method."""
        raise NotImplementedError


@dataclass(frozen=True)
class _ConstantStress(_Tangential):
    """Fields and traction shared by the results under a constant friction stress ``tau0``."""

    inputs: ClassVar[tuple[str, ...]] = ("tau0_over_E", "method")

    T_over_Ea: NDArray | float = field(metadata=SI("tangential_load", "Ea", "N/m"))

    def _traction(self, x_over_a: ArrayLike, tau0_over_E) -> NDArray:
        """Traction q/E: ``tau0`` times :meth:`_stick` in the stick zone.

        ``tau0`` in the slip zones (everywhere when sliding), zero outside the contact and at
        ``T = 0``.
        """
        x, dlt, st = self._points(x_over_a)
        inner = self._stick(x, dlt)
        stick = self._zone.inside(x, dlt) & (st == _STICK_SLIP)
        q = np.where(np.abs(x) <= 1.0, np.where(stick, inner, 1.0), 0.0)
        q = np.where(st == _STICK, 0.0, q)
        return np.asarray(tau0_over_E, dtype=float)[..., None] * q


@dataclass(frozen=True)
class _CoulombFriction(_Tangential):
    """Fields and traction shared by the results under Coulomb friction on the Hertz contact."""

    inputs: ClassVar[tuple[str, ...]] = ("mu", "a_over_R", "method")

    T_over_muF: NDArray | float
    T_over_Ea: NDArray | float = field(metadata=SI("tangential_load", "Ea", "N/m"))

    def _traction(self, x_over_a: ArrayLike, mu, a_over_R) -> NDArray:
        """Traction q/E: mu p less :meth:`_stick` (over mu p0) in the stick zone; 0 at ``T = 0``."""
        x, dlt, st = self._points(x_over_a)
        p0 = np.asarray(a_over_R, dtype=float)[..., None] / 2
        m = np.asarray(mu, dtype=float)[..., None]
        xq = np.clip(x, -2.0, 2.0)  # the terms vanish beyond |x| = a; no overflow of x*x
        hertz = np.sqrt(np.clip(1 - xq * xq, 0.0, None))
        corr = self._stick(x, dlt)
        stick = self._zone.inside(x, dlt) & (st == _STICK_SLIP)
        q = hertz - np.where(stick, corr, 0.0)
        q = np.where(st == _STICK, 0.0, q)
        return m * p0 * q


def _cheb_u_series(b: NDArray, t: NDArray) -> NDArray:
    """sqrt(1 - t^2) sum_j b_j U_j(t) (zero outside [-1, 1]); b (P, n), t (P, m)."""
    inside = np.abs(t) <= 1.0
    tc = np.clip(t, -1.0, 1.0)
    bk1 = np.zeros(tc.shape)
    bk2 = np.zeros(tc.shape)
    for j in range(b.shape[-1] - 1, -1, -1):
        bk1, bk2 = b[:, j, None] + 2 * tc * bk1 - bk2, bk1
    return np.where(inside, np.sqrt(np.clip(1 - tc * tc, 0.0, None)) * bk1, 0.0)


# --------------------------------------------------------------------------------------------
# public functions (nondimensional)


@dataclass(frozen=True)
class _Problem(Generic[_R]):
    """What distinguishes the four problems (units: T over a tau0, or over mu F)."""

    name: str
    result: type[_R]
    kernel: Callable[[NDArray, int], dict[str, NDArray]]
    rate: Callable[[NDArray], NDArray]
    T_closed: Callable[[NDArray], NDArray]  # T(delta)
    dT_closed: Callable[[NDArray], NDArray]  # dT/d delta
    delta_closed: Callable[[NDArray], NDArray]  # delta(T/T_full), for 0 <= T/T_full <= 1
    T_full: float
    zone: _Zone
    constant: bool = True  # constant tau0 (load T_over_Ea) or Coulomb (load T_over_muF)
    creep_closed: Callable[[NDArray], NDArray] | None = None  # rolling only
    # the creep from T over the full-slip load, without the loss of precision of going
    # through d near full stick (rolling only)
    creep_of_r: Callable[[NDArray], NDArray] | None = None
    n_auto: int | None = None  # fixed n for n="auto" (Coulomb: linear right-hand sides)

    @property
    def d_low(self) -> float:
        """The lower bound of ``d_over_a`` (its zone's)."""
        return self.zone.d_low

    @property
    def d_low_inclusive(self) -> bool:
        """Whether ``d_over_a`` may equal :attr:`d_low` (full slip, in the initiation)."""
        return self.zone.d_low_inclusive


def _run(
    pb: _Problem,
    d_over_a,
    load,
    load_name,
    method,
    n,
    tol,
    policy,
    params: dict,
):
    """Validate the state variable and solve.

    Returns ``(arrays, load, creep, diag, scalar)``: the broadcast parameters, the tangential
    load in the problem's unit (``T_over_Ea`` for constant ``tau0``, ``T_over_muF`` for
    Coulomb; the one given is returned exactly), the creep over its scale (rolling), the
    diagnostic fields and whether the call was scalar.
    """
    _one_of(d_over_a, load, load_name)
    _check_options(method, n, tol)
    zone = pb.zone
    names = list(params)
    arrays = list(params.values())
    if d_over_a is not None:
        dl = check_array(
            "d_over_a", d_over_a, low=zone.d_low, low_inclusive=zone.d_low_inclusive, high=1.0
        )
        given = ("d_over_a", dl)
    else:
        dl = None
        given = (load_name, _domain.check(load_name, load))
    scalar = scalar_or_array(*arrays, given[1])
    *arrays, g = (
        np.asarray(v, float)
        for v in broadcast(**dict(zip(names, arrays, strict=True)), **{given[0]: given[1]})
    )
    shape = g.shape
    if dl is not None:
        dl = g
        r = pb.T_closed(dl) / pb.T_full  # T over the full-slip load
        T_target = None
        # the state follows from d (T rounds to the full-slip load long before d reaches 0)
        sliding = dl == 0 if zone.d_low_inclusive else np.zeros(shape, bool)
        stick = np.zeros(shape, bool)
    else:
        r = g / (2 * arrays[0]) if pb.constant else g.copy()
        dl = np.where(r <= 1, pb.delta_closed(np.minimum(r, 1.0)), np.nan)
        T_target = pb.T_full * np.minimum(r, 1.0)
        sliding = r >= 1
        stick = r == 0
    active = ~(sliding | stick)
    nn = pb.n_auto if (pb.n_auto is not None and n == "auto") else n
    out = _solve_points(
        np.where(np.isfinite(dl), dl, 0.0).reshape(-1),
        active.reshape(-1),
        method,
        nn,
        tol,
        pb.kernel,
        pb.rate,
        pb.T_closed,
        pb.dT_closed,
        None if T_target is None else T_target.reshape(-1),
        pb.T_full,
        lo=zone.d_low + (0.0 if zone.d_low_inclusive else 1e-16),
        hi=1.0 - 1e-16,
    )
    act = active.reshape(-1)
    if T_target is None:
        T_unit = np.where(act, out["T"], pb.T_full * r.reshape(-1)).reshape(shape)
    else:
        T_unit = pb.T_full * r
        dl = np.where(active, out["delta"].reshape(shape), np.where(stick, zone.d_stick, dl))
    if pb.creep_closed is not None:
        if method == "collocation":
            creep = out["creep"]
        elif T_target is not None and pb.creep_of_r is not None:
            creep = pb.creep_of_r(np.where(act, r.reshape(-1), 0.0))
        else:
            creep = pb.creep_closed(out["delta"])
        creep = np.where(act, creep, np.nan).reshape(shape)
        creep = np.where(stick, 0.0, creep)
    else:
        creep = None
    # the load in the caller's unit: the one given, exactly, or the one of the d/a given
    if T_target is not None:
        load = g
    else:
        load = arrays[0] * T_unit if pb.constant else T_unit
    # the inputs under the caller's names, for the errors at a failing point
    labels = {**dict(zip(names, arrays, strict=True)), given[0]: g}
    if policy == "raise":
        _raise_sliding(
            pb.name,
            sliding,
            labels,
            given[0],
            load_name,
            load,
            2 * arrays[0] if pb.constant else np.ones(shape),
        )
    converged = np.ones(shape, bool)
    if method == "collocation":
        converged = (
            ((out["tail"] <= 10 * tol) & (out["force"] <= 1e-10) & np.isfinite(out["T"])) | ~act
        ).reshape(shape)
        if policy == "raise":
            _raise_unconverged(pb.name, converged, labels, out, n)
    diag = dict(
        n_collocation=out["n"].reshape(shape),
        residual_stick=out["stick"].reshape(shape),
        residual_force=out["force"].reshape(shape),
        residual_consistency=out["cons"].reshape(shape),
        error_estimate=out["tail"].reshape(shape),
        converged=converged,
        state=_states(sliding, stick, shape),
        d_over_a=dl,
        T_over_T_full_slip=T_unit / pb.T_full,
    )
    return arrays, load, creep, diag, scalar


def _build(cls, method, scalar, **vals):
    return cls(method=method, **{k: as_output(np.asarray(v), scalar) for k, v in vals.items()})


def _constant_friction(
    pb: _Problem[_R], tau0_over_E, d_over_a, T_over_Ea, method, n, tol, on_failure
) -> _R:
    """The public function of a problem with constant friction stress ``tau0``.

    Its result holds ``T_over_Ea`` and ``tau0_over_E`` (and ``creep_over_V`` where
    the problem has a creep).
    """
    policy = _validation.failure_policy(on_failure)
    params = {"tau0_over_E": _domain.check("tau0_over_E", tau0_over_E)}
    arrays, load, creep, diag, scalar = _run(
        pb, d_over_a, T_over_Ea, "T_over_Ea", method, n, tol, policy, params
    )
    (t0,) = arrays
    if creep is not None:
        diag["creep_over_V"] = t0 * creep
    return _build(pb.result, method, scalar, T_over_Ea=load, tau0_over_E=t0, **diag)


def _coulomb_friction(
    pb: _Problem[_R], mu, a_over_R, d_over_a, T_over_muF, method, n, tol, on_failure
) -> _R:
    """The public function of a problem with Coulomb friction on the Hertz contact.

    Its result holds ``T_over_muF``, ``T_over_Ea``, ``mu`` and ``a_over_R`` (and
    ``creep_over_V`` where the problem has a creep).
    """
    policy = _validation.failure_policy(on_failure)
    params = {"mu": _domain.check("mu", mu), "a_over_R": _domain.check("a_over_R", a_over_R)}
    _cf._warn_wide(params["a_over_R"], stacklevel=4)  # the caller of the public function
    arrays, load, creep, diag, scalar = _run(
        pb, d_over_a, T_over_muF, "T_over_muF", method, n, tol, policy, params
    )
    m, A = arrays
    if creep is not None:
        diag["creep_over_V"] = m * A * creep
    return _build(
        pb.result,
        method,
        scalar,
        T_over_muF=load,
        T_over_Ea=(np.pi / 4) * m * A * load,
        mu=m,
        a_over_R=A,
        **diag,
    )
