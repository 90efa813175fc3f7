"""The Lennard-Jones law of Eq. 1 on a rigid cylinder: closed form against quadrature.

The first piece of the self-consistent Lennard-Jones solver (issue 11): its rigid limit.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import minimize_scalar

from linecontact.closed_forms import lennard_jones_rigid_load, lennard_jones_rigid_pull_off


def _by_quadrature(zeta: float) -> float:
    """F/(w sqrt(R/z0)) by integrating Eq. 1 over x/sqrt(R z0) at the gap zeta + x^2/2."""

    def p(x):  # p/(w/z0), compressive positive, at the gap over z0
        z = zeta + 0.5 * x * x
        return -(8.0 / 3.0) * (z**-3 - z**-9)

    near, _ = quad(p, 0.0, 4.0, epsabs=0.0, epsrel=1e-12, limit=400)
    far, _ = quad(p, 4.0, np.inf, epsabs=0.0, epsrel=1e-12, limit=400)
    return 2.0 * (near + far)


@pytest.mark.parametrize("zeta", [0.6, 0.9, 1.0, 1.1, 1.5, 3.0, 30.0])
def test_closed_form_is_the_quadrature_of_eq1(zeta):
    assert lennard_jones_rigid_load(zeta) == pytest.approx(_by_quadrature(zeta), rel=1e-11)


def test_pull_off_is_the_most_tensile_load_by_a_search():
    F, g = lennard_jones_rigid_pull_off()
    best = minimize_scalar(_by_quadrature, bracket=(0.9, 1.1, 1.5), tol=1e-12)
    assert g == pytest.approx(best.x, rel=1e-6)  # a minimum: flat, located to sqrt(eps)
    assert F == pytest.approx(best.fun, rel=1e-11)
    # the Maugis-Dugdale rigid pull-off with the Maugis matching is 16 % larger
    dugdale = 2.0 * math.sqrt(2.0 / (9.0 * math.sqrt(3.0) / 16.0))
    assert dugdale / -F == pytest.approx(1.16198, rel=1e-5)


def test_far_field_decays_like_the_attraction_only():
    # beyond a few z0 the repulsion is negligible: F ~ -(8/3) sqrt(2 pi) C3 zeta^(-5/2)
    z = np.array([1e2, 1e4])
    c3 = math.gamma(2.5) / math.gamma(3.0)
    np.testing.assert_allclose(
        lennard_jones_rigid_load(z), -(8 / 3) * math.sqrt(2 * math.pi) * c3 * z**-2.5, rtol=1e-12
    )


def test_bad_gap_names_the_parameter():
    with pytest.raises(ValueError, match=r"^central_gap_over_z0 must be in \[0.01, 1e\+06\]"):
        lennard_jones_rigid_load(0.0)
