"""Worked cases of the pushed fibre (README, ``docs/push.md`` section 7), from literature inputs.

A ZnO nanowire on thermal SiO2 and a multi-wall nanotube on graphite, pushed halfway up to
the axis (``H = R/2``) and at the axis (``H = R``). The sources of every input are in
``docs/push.md``; the advancing works of adhesion are assumptions (no hysteresis has been
measured for these pairs), which the docs say.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import linecontact as lc


def _case(R, E1, nu1, E2, nu2, w_receding, w_advancing, z0, tau0, H):
    # one sigma0 for both edges (Maugis matching of the receding work): h = w / sigma0
    s0, h1 = lc.adhesion_from_work(w_receding, z0)
    h2 = w_advancing / s0
    E = lc.composite_modulus(E1, nu1, E2, nu2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.ModelValidityWarning)  # a/R = 0.23 for the tube
        p = lc.push(R / h2, h1 / h2, s0 / E, tau0 / E, 0.0, np.asarray(H) / R)
    return p, E * h2


ZNO = dict(R=50e-9, E1=127e9, nu1=0.30, E2=72e9, nu2=0.17, w_receding=0.05, w_advancing=0.025)
MWNT = dict(R=10e-9, E1=30e9, nu1=0.2, E2=26e9, nu2=0.2, w_receding=0.37, w_advancing=0.30)


def test_zno_nanowire_on_silica_slides_below_the_axis_and_rolls_at_it():
    p, Eh2 = _case(**ZNO, z0=0.3e-9, tau0=1.0e6, H=[25e-9, 50e-9])
    assert list(p.first_motion) == ["slide", "roll"]
    # Kendall: Q_roll H = R dw = 50 nm x 0.025 J/m^2
    np.testing.assert_allclose(p.Q_roll_over_Eh2 * Eh2, [0.05, 0.025], rtol=1e-12)
    # the sliding resistance is mostly the hysteresis: 2 a tau0 = 2.9e-3 N/m beside 0.025
    assert p.Q_slide_over_Eh2[0] * Eh2 == pytest.approx(0.02794, rel=1e-3)
    assert p.H_critical_over_R[0] == pytest.approx(0.895, rel=1e-3)
    # across the measured friction stresses (0.25 to 5 MPa) the answer stays the same
    for tau0 in (0.25e6, 5e6):
        q, _ = _case(**ZNO, z0=0.3e-9, tau0=tau0, H=[25e-9, 50e-9])
        assert list(q.first_motion) == ["slide", "roll"]


def test_nanotube_on_graphite_slides_out_of_registry_and_rolls_in_it():
    # Falvo et al. (1999): rolling in registry, sliding out of it
    out, _ = _case(**MWNT, z0=0.335e-9, tau0=0.5e6, H=[5e-9, 10e-9])
    assert list(out.first_motion) == ["slide", "roll"]
    inside, Eh2 = _case(**MWNT, z0=0.335e-9, tau0=140e6, H=[5e-9, 10e-9])
    assert list(inside.first_motion) == ["roll", "roll"]
    assert inside.H_critical_over_R[0] == pytest.approx(0.0999, rel=1e-3)
    assert inside.creep_over_V[0] > 0 and inside.creep_over_V[1] == 0
