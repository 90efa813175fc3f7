"""The input checks that every public function of :mod:`linecontact.sliding` shares."""

from __future__ import annotations

import numpy as np

from .. import _numerics as _num
from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import (
    broadcast,
    check_solver_options,
    failure_policy,
    scalar_or_array,
)


def _check_common(R_over_h2, h1_over_h2, sigma0_over_E):
    rho = _domain.check("R_over_h2", R_over_h2)
    r = _domain.check("h1_over_h2", h1_over_h2)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    return rho, r, s


def _check_method(method, n, tol):
    if method not in ("closed-form", "collocation"):
        raise ValueError(f"method must be 'closed-form' or 'collocation', got {method!r}")
    check_solver_options(n, tol, n_max=8192)


def _check_state_inputs(
    R_over_h2, h1_over_h2, sigma0_over_E, tau0_over_E, method, n, tol, on_failure
):
    """The groups, ``tau0_over_E`` (NaN when not given), the solver options and the policy.

    The checks after the first argument of :func:`~linecontact.sliding.sliding_contact` and
    :func:`~linecontact.sliding.sliding_contact_for_load`, in their order; returns
    ``(rho, r, s, tau, policy)``.
    """
    rho, r, s = _check_common(R_over_h2, h1_over_h2, sigma0_over_E)
    tau = (
        np.full((), np.nan)
        if tau0_over_E is None
        else _domain.check("tau0_over_E", tau0_over_E, "friction_tau0_over_E")
    )
    _check_method(method, n, tol)
    return rho, r, s, tau, failure_policy(on_failure)


def _broadcast_state(first_name: str, first, rho, r, s, tau):
    """The checked state inputs broadcast together, with ``kappa`` checked.

    ``first`` is the checked first argument of :func:`~linecontact.sliding.sliding_contact`
    or :func:`~linecontact.sliding.sliding_contact_for_load` (named ``first_name`` when the
    shapes do not broadcast), the rest as :func:`_check_state_inputs` returns them; returns
    ``(scalar, first, rho, r, s, tau)``, ``scalar`` when every input is a scalar.
    """
    scalar = scalar_or_array(first, rho, r, s, tau)
    first, rho, r, s, tau = broadcast(
        **{first_name: first}, R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s, tau0_over_E=tau
    )
    _cf._check_kappa(rho, s, "R_over_h2")
    return scalar, first, rho, r, s, tau


def _flat_points(scalar: bool, *values):
    """The broadcast inputs as NumPy scalars (``scalar``: the scalar fast path) or flat floats."""
    if scalar:
        return _num._scalars(*values)
    return tuple(np.ascontiguousarray(v, dtype=float).reshape(-1) for v in values)
