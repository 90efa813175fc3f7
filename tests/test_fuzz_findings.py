"""Regression tests for what the fuzz suite (``test_fuzz.py``) found, one exact case each.

The fuzz draws change with hypothesis' versions; these cases do not.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import linecontact as lc
from linecontact import NoEquilibriumError


def test_the_adhesive_zone_never_ends_inside_the_contact():
    # c = a coth-like product rounded to c < a by an ulp at a thin zone
    r = lc.normal_contact(1.0, 1e10, 1e6)
    assert r.c_over_R >= r.a_over_R


def test_non_contact_at_the_range_without_adhesion_is_zero_not_nan():
    r = lc.non_contact([1.0, 0.5], 1e-3, 0.0)
    np.testing.assert_array_equal(r.c_over_R, [0.0, math.sqrt(2 * 0.5 / 1e-3)])
    np.testing.assert_array_equal(r.F_over_Eh, [0.0, 0.0])


@pytest.mark.parametrize("F", [1e-300, 1e-30, 1e-3])
def test_sliding_contact_for_tiny_loads_without_adhesion_is_hertz(F):
    # F = 1e-300 came back as a contact carrying 3.5e-16 (the bracket stopped at abar = 1e-9)
    a_hertz = math.sqrt(4 * F / (math.pi * 1e-3))  # F/(E h) = (pi/4)(R/h)(a/R)^2
    if a_hertz < 1e-20:
        with pytest.raises(ValueError, match=r"needs a contact of half-width [0-9.e+-]+ radii, "):
            lc.sliding_contact_for_load(F, 1e-3, 2.0, 0.0, method="closed-form")
        return
    r = lc.sliding_contact_for_load(F, 1e-3, 2.0, 0.0, method="closed-form")
    assert r.a_over_R == pytest.approx(a_hertz, rel=1e-12)
    assert r.F_over_Eh2 == pytest.approx(F, rel=1e-12)


def test_sliding_contact_at_the_zero_width_pull_off_force():
    # the load equal to the reported pull-off force was refused, and its contact (at the
    # domain's end, a = 1e-20 R) called unstable from a derivative lost in round-off
    args = (10.0, 0.5, 0.0078125)
    po = lc.sliding_pull_off(*args)
    assert po.mechanism == "zero-width"
    r = lc.sliding_contact_for_load(po.F_pulloff_over_Eh2, *args, method="closed-form")
    assert r.a_over_R == 1e-20 and r.stable
    assert r.F_over_Eh2 == pytest.approx(po.F_pulloff_over_Eh2, rel=1e-12)
    assert np.all(lc.sliding_contact([1e-20, 1e-15, 1e-10], *args, method="closed-form").stable)


def test_a_load_whose_sliding_contact_is_narrower_than_the_domain_is_refused():
    # sigma0/E = 1e-300: F = 0 needs a ~ 1e-300 R
    with pytest.raises(ValueError, match=r"below 1e-20 radii, below the domain of the solvers"):
        lc.sliding_contact_for_load(0.0, 1e-3, 1e-3, 1e-300)


@pytest.mark.parametrize("F", [0.0, -1.0])
def test_no_contact_carries_a_tensile_or_zero_load_without_adhesion(F):
    # contact_for_load(0, ., 0) returned a width of 4e-322; sliding said no contact
    for fn in (lc.contact_for_load, lc.sliding_contact_for_load):
        args = (F, 100.0, 0.0) if fn is lc.contact_for_load else (F, 100.0, 2.0, 0.0)
        with pytest.raises(NoEquilibriumError, match=r"without adhesion .* must be > 0"):
            fn(*args)


def test_sliding_pull_off_without_adhesion_matches_pull_off():
    assert lc.sliding_pull_off(100.0, 1.0, 0.0).F_pulloff_over_Eh2 == 0.0
    assert lc.pull_off(100.0, 0.0).F_pulloff_over_Eh == 0.0


def test_load_curve_default_stays_in_the_domain():
    # the default a_max (1.5 x the pull-off width, 1290 R here) raised an error naming
    # a_max_over_R, a parameter the user had not given
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.ModelValidityWarning)
        c = lc.load_curve(1e-3, 1e6)
    assert c.a_over_R.max() == 10.0 and not c.turning_point.any()
    # a minimum at 8e-152 R (below the domain) is not a point of the curve
    c = lc.load_curve(0.01, 0.03162277660168379)
    assert lc.pull_off(0.01, 0.03162277660168379).a_over_R_at_minimum < 1e-150
    assert np.all(c.a_over_R[c.branch == "contact"] >= 1e-150)


@pytest.mark.parametrize("T", [1e-300, 0.003, 0.019999999999999997])
def test_the_tangential_load_given_is_returned_exactly(T):
    # steady_rolling(0.01, T_over_Ea=1e-300) returned 9.999999999999999e-301
    assert lc.steady_rolling(0.01, T_over_Ea=T).T_over_Ea == T
    assert lc.sliding_initiation(0.01, T_over_Ea=T).T_over_Ea == T
