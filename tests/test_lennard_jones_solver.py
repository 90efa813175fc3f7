"""The self-consistent Lennard-Jones solver (issue 11, in progress): what it does so far.

Checked here: the rigid limit against the closed form with its O(h^2) convergence, the gap
equation solved to round-off, and refinement converging for elastic states. Not yet: the
accuracy target of 1e-6 for elastic states (an adapted mesh), the whole load curve through
its turning points, the JKR and Maugis-Dugdale comparisons (docs/lennard-jones.md).
"""

from __future__ import annotations

import numpy as np
import pytest

from linecontact.lennard_jones import lj_state
from linecontact.reference import lennard_jones_rigid_load


@pytest.mark.parametrize("zeta0", [0.95, 1.1, 2.0])
def test_rigid_limit_is_the_closed_form_to_second_order(zeta0):
    exact = lennard_jones_rigid_load(zeta0)
    errs = [abs(lj_state(zeta0, 0.0, n=n).F_over_w_sqrt_R_over_z0 / exact - 1) for n in (120, 240)]
    assert errs[1] < 1e-7
    assert errs[0] / errs[1] == pytest.approx(4.0, rel=0.15)  # trapezoid rule: O(h^2)


@pytest.mark.parametrize("mu", [0.3, 1.0])
def test_elastic_states_solve_the_gap_equation_and_converge_with_the_mesh(mu):
    F = []
    for n in (60, 120, 240):
        s = lj_state(1.05, mu, n=n)
        assert s.converged and s.residual < 1e-12
        assert s.gap_over_z0[0] == 1.05 and np.all(s.gap_over_z0 > 0)
        F.append(s.F_over_w_sqrt_R_over_z0)
    d1, d2 = abs(F[1] - F[0]), abs(F[2] - F[1])
    assert d2 < d1 / 2  # refinement converges


def test_compliance_pulls_harder_at_a_given_central_gap():
    # with mu > 0 the surfaces around the centre approach under the attraction
    F = [lj_state(1.05, mu, n=60).F_over_w_sqrt_R_over_z0 for mu in (0.0, 0.3, 1.0, 3.0)]
    assert np.all(np.diff(F) < 0)


def test_bad_input():
    with pytest.raises(ValueError, match="central_gap_over_z0 must be > 0"):
        lj_state(0.0, 1.0)
    with pytest.raises(ValueError, match="mu must be a finite number >= 0"):
        lj_state(1.0, -1.0)
