"""The pushed fibre in SI units (``Cylinder.push``): the same numbers as the groups."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import linecontact as lc

S0, H1 = lc.adhesion_from_work(0.05, 0.3e-9)


@pytest.fixture
def cyl():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.CouplingWarning)
        return lc.Cylinder.from_materials(
            50e-9, 127e9, 0.30, 72e9, 0.17, cohesive_stress=S0, adhesion_range=0.025 / S0
        )


def test_si_is_the_groups_times_their_units(cyl):
    p = cyl.push(
        friction_stress=1e6,
        height=[25e-9, 50e-9],
        receding_range=H1,
        normal_load=0.01,
        push=0.026,
        length=5e-6,
    )
    h2, E, R = cyl.adhesion_range, cyl.modulus, cyl.radius
    g = lc.push(R / h2, H1 / h2, S0 / E, 1e6 / E, 0.01 / (E * h2), [0.5, 1.0], 0.026 / (E * h2))
    np.testing.assert_allclose(p.sliding_resistance, g.Q_slide_over_Eh2 * E * h2, rtol=1e-15)
    np.testing.assert_allclose(p.rolling_resistance, g.Q_roll_over_Eh2 * E * h2, rtol=1e-15)
    np.testing.assert_allclose(p.critical_height, g.H_critical_over_R * R, rtol=1e-15)
    assert list(p.first_motion) == ["slide", "roll"] and list(p.state) == ["rest", "roll"]
    # Kendall in SI: Q_roll H = R (w1 - w2)
    np.testing.assert_allclose(p.rolling_resistance * p.height, R * (0.05 - 0.025), rtol=1e-12)
    np.testing.assert_allclose(p.sliding_resistance_total, p.sliding_resistance * 5e-6)


def test_receding_work_of_adhesion_is_the_range_times_sigma0(cyl):
    a = cyl.push(friction_stress=1e6, height=3e-8, receding_range=H1)
    b = cyl.push(friction_stress=1e6, height=3e-8, receding_work_of_adhesion=0.05)
    assert a.sliding_resistance == pytest.approx(b.sliding_resistance, rel=1e-14)
    with pytest.raises(ValueError, match="give length="):
        _ = a.rolling_resistance_total


@pytest.mark.parametrize(
    ("kw", "message"),
    [
        (
            {"receding_range": 1e-11},
            r"^receding_range must be in \[1.46\d*e-10, 1.46\d*e-07\], got 1e-11",
        ),
        ({"receding_range": H1, "receding_work_of_adhesion": 0.05}, r"exactly one"),
        ({"receding_range": H1, "height": 2e-7}, r"^height must be in \[0, 1e-07\]"),
        ({"receding_range": H1, "friction_stress": -1.0}, r"^friction_stress must be in"),
        ({"receding_range": H1, "normal_load": float("nan")}, r"^normal_load must be a finite"),
        ({"receding_range": H1, "push": -1.0}, r"^push must be in \[0, inf\), got -1.0$"),
        ({"receding_range": H1, "normal_load": 1e14}, r"^normal_load must be in \[.*\] N/m"),
        (
            {"receding_range": H1, "normal_load": 1e9},
            r"^normal_load=1000000000.0 N/m needs a contact of half-width .* radii: beyond",
        ),
    ],
)
def test_bad_si_input(cyl, kw, message):
    args = {"friction_stress": 1e6, "height": 3e-8, **kw}
    with pytest.raises(ValueError, match=message):
        cyl.push(**args)
