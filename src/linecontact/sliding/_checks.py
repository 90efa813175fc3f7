"""The input checks that every public function of :mod:`linecontact.sliding` shares."""

from __future__ import annotations

from .. import domain as _domain
from .._validation import (
    check_solver_options,
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
