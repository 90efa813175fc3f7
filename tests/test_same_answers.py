"""One answer for one question, on every machine (issue: the same answers on every machine).

- A steady-sliding load at the zero-width end of the stable branch is the zero-width state,
  whatever the last bits of the load: the width found for it is not left to rounding, and the
  collocation is not asked to resolve a contact 1e20 times narrower than its adhesive zones.
- The pull-off that ``curve`` marks is the one ``pulloff`` reports, and the label
  ``"zero-width"`` promises a force within 1 % of Eq. (14) at every ``R/h``.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import linecontact as lc
from linecontact.cli import main
from linecontact.normal import ZERO_WIDTH_LOAD_RTOL

# --------------------------------------------------------------------------------------------
# steady sliding at the zero-width end


@pytest.mark.parametrize(
    "rho, r, s",
    [
        (25.0, 2.0, 0.0078125),  # the point that converged only on some machines
        (141.0, 1.0, 0.001),  # a load minimum within round-off of the zero-width load
        (86.19743766571902, 0.7884835164893629, 0.0011017123344672344),
        (61.22658283000318, 1.0016427720768915, 0.003599707101802806),
    ],
)
@pytest.mark.parametrize("rel", [0.0, 1e-15, 1e-14, 1e-13])
def test_a_load_at_the_zero_width_end_is_the_zero_width_state(rho, r, s, rel):
    po = lc.sliding_pull_off(rho, r, s)
    F = po.F_pulloff_over_Eh2 + rel * abs(po.F_pulloff_over_Eh2)
    a_min = lc.domain.DOMAIN["sliding_a_over_R"][0]
    for method in ("collocation", "closed-form"):
        c = lc.sliding_contact_for_load(F, rho, r, s, method=method)
        assert c.a_over_R == a_min and c.converged and c.n_collocation == 0, method
        # the state carries the load to round-off
        assert abs(c.F_over_Eh2 - F) <= 1e-12 * abs(F)
    # arrays: the same, point by point, in a batch with ordinary loads
    Fs = np.array([F, F + 0.5 * abs(F), F + 3 * abs(F)])
    c = lc.sliding_contact_for_load(Fs, rho, r, s, method="collocation")
    assert c.a_over_R[0] == a_min and c.n_collocation[0] == 0
    assert np.all(c.a_over_R[1:] > 1e-6) and np.all(c.n_collocation[1:] > 0)
    assert np.all(c.converged)


def test_just_above_the_band_the_collocation_converges():
    """At 1e-12 above the zero-width load the width is ~1e-7 R and the collocation resolves it."""
    rho, r, s = 25.0, 2.0, 0.0078125
    po = lc.sliding_pull_off(rho, r, s)
    for rel in (2e-12, 1e-11, 1e-9):
        F = po.F_pulloff_over_Eh2 + rel * abs(po.F_pulloff_over_Eh2)
        col = lc.sliding_contact_for_load(F, rho, r, s, method="collocation")
        cf = lc.sliding_contact_for_load(F, rho, r, s, method="closed-form")
        assert col.converged and col.n_collocation > 0 and col.a_over_R > 1e-9
        assert col.a_over_R == pytest.approx(cf.a_over_R, rel=1e-9)
        assert col.error_estimate <= 1e-11


def test_push_at_the_sliding_pull_off_agrees_with_the_collocation():
    """The case of tests/test_push.py that failed on AVX-512 machines, by hand."""
    rho, r, s = 25.0, 2.0, 0.0078125
    F = lc.sliding_pull_off(rho, r, s).F_pulloff_over_Eh2
    p = lc.push(rho, r, s, 0.0078125, F, 0.0)
    c = lc.sliding_contact_for_load(F, rho, r, s, method="collocation")
    assert p.converged and p.a_slide_over_R == pytest.approx(c.a_over_R, rel=1e-9)


# --------------------------------------------------------------------------------------------
# one pull-off, one label


def test_a_pull_off_far_below_eq14_is_not_called_zero_width():
    po = lc.pull_off(1.0, 2.0)  # a/R = 0.87 < h/R = 1, but 39 % below Eq. (14)
    assert po.a_over_R_at_pulloff == pytest.approx(0.8686, rel=1e-3)
    assert po.F_pulloff_over_Eh < 1.38 * po.F_zero_width_over_Eh
    assert po.mechanism == "snap-off"


def test_zero_width_means_within_one_percent_of_eq14_at_every_r_over_h():
    rng = np.random.default_rng(400)
    rho = 10 ** rng.uniform(-3, 6, 4000)
    s = 10 ** rng.uniform(-4, 1, 4000)
    po = lc.pull_off(rho, s)
    F0, F = po.F_zero_width_over_Eh, po.F_pulloff_over_Eh
    zw = np.asarray(po.mechanism) == "zero-width"
    assert zw.any() and (~zw).any()
    gap = (F0 - F) / np.abs(np.where(F0 == 0, 1.0, F0))
    assert np.all(gap[zw] <= ZERO_WIDTH_LOAD_RTOL)
    assert np.all(np.asarray(po.a_over_R_at_pulloff)[zw] < 1 / rho[zw])
    snap = ~zw & (s > 0)
    assert np.all(
        (gap[snap] > ZERO_WIDTH_LOAD_RTOL) | (po.a_over_R_at_pulloff[snap] >= 1 / rho[snap])
    )


def test_sliding_pull_off_labels_as_the_normal_one_at_equal_ranges():
    rho = np.array([1.0, 3.0, 10.0, 100.0, 1e4])
    s = np.array([2.0, 0.5, 0.3, 0.01, 0.2])
    assert list(lc.sliding_pull_off(rho, 1.0, s).mechanism) == list(lc.pull_off(rho, s).mechanism)


ZNO = [
    "--radius",
    "50e-9",
    "--cylinder-material",
    "ZnO",
    "--substrate-material",
    "SiO2",
    "--work-of-adhesion",
    "0.3",
    "--z0",
    "0.3e-9",
    "--json",
]


def _json(capsys, *argv):
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.filterwarnings("ignore::linecontact.errors.CouplingWarning")
def test_curve_marks_the_pull_off_that_pulloff_reports(capsys):
    po = _json(capsys, "pulloff", *ZNO)["results"][0]
    curve = _json(capsys, "curve", *ZNO)["results"]
    marked = [rec for rec in curve if rec["pulloff"]]
    assert len(marked) == 1
    assert marked[0]["F_N_per_m"] == pytest.approx(po["F_pulloff_N_per_m"], rel=1e-12)
    assert marked[0]["a_m"] == pytest.approx(po["a_at_pulloff_m"], rel=1e-12)
    assert po["mechanism"] == "zero-width"  # 0.15 nm < h, 3e-4 below Eq. (14)
    # and it is the most tensile load of the curve
    assert marked[0]["F_N_per_m"] == min(rec["F_N_per_m"] for rec in curve)


@pytest.mark.parametrize("rho, s", [(100.0, 0.2), (100.0, 0.01), (1e4, 1e-4), (1.0, 2.0)])
def test_curve_and_pulloff_agree_in_groups(capsys, rho, s):
    args = ["--R-over-h", str(rho), "--sigma0-over-E", str(s), "--json"]
    po = _json(capsys, "pulloff", *args)["results"][0]
    curve = _json(capsys, "curve", *args)["results"]
    marked = [rec for rec in curve if rec["pulloff"]]
    assert len(marked) == 1
    assert marked[0]["F_over_Eh"] == pytest.approx(po["F_pulloff_over_Eh"], rel=1e-12)
