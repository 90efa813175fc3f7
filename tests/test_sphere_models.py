"""Which model holds for a sphere, and the COS alpha: the tables of docs/sphere.md recomputed.

The tables in the docs are recomputed here to their printed digits (a table that no longer
says what the library computes fails); each simple model's radius is checked against its
own closed-form load (JKR's root, DMT's cube root); the COS fit reproduces the
Maugis-Dugdale curve it was fitted to, as measured; alpha runs from DMT's 0 to JKR's 1, and
its inverse gives lambda back.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from linecontact.closed_forms.sphere import sphere_dmt_load, sphere_jkr_load
from linecontact.errors import ParameterError
from linecontact.sphere import (
    cos_alpha,
    maugis_parameter_of_cos_alpha,
    sphere_contact_for_load,
    sphere_models,
    sphere_pull_off,
)
from linecontact.sphere.models import COS_LOADS, _cos_radius, _radii

DOC = Path(__file__).resolve().parents[1] / "docs" / "sphere.md"
RHO = 1e6


def _s(lam: float) -> float:
    return math.sqrt((lam / 2) ** 3 * 16 * math.pi / (9 * RHO))


def _table(marker: str) -> list[list[str]]:
    text = DOC.read_text(encoding="utf-8")
    block = text.split(marker, 1)[1].split("\n\n", 1)[0]
    rows = [r for r in block.strip().splitlines() if r.startswith("|")][2:]  # head, rule
    return [[c.strip() for c in r.strip("|").split("|")] for r in rows]


def _same(printed: str, value: float) -> bool:
    """``value`` printed with ``printed``'s digits is ``printed`` (-0.000 and +0.000 alike)."""
    decimals = len(printed.split(".")[1]) if "." in printed else 0
    return abs(float(printed) - value) <= 0.5 * 10**-decimals + 1e-12


def test_the_which_model_table_is_what_the_library_computes():
    rows = _table("<!-- which-model table")
    assert len(rows) == 9
    for lam, regime, best, *errors in rows:
        m = sphere_models(0.0, RHO, _s(float(lam)))
        assert (m.regime, m.best) == (regime, best), lam
        got = [
            m.pull_off_error_dmt,
            m.pull_off_error_jkr,
            m.radius_error_dmt,
            m.radius_error_jkr,
        ]
        for printed, value in zip(errors, got, strict=True):
            assert _same(printed, value), (lam, printed, value)


def test_the_alpha_lambda_table_is_what_the_library_computes():
    rows = _table("<!-- alpha-lambda table")
    lams = [float(r[0]) for r in rows]
    alphas = cos_alpha(lams)
    for (lam, alpha, load, disp, ratio), a in zip(rows, alphas, strict=True):
        s = _s(float(lam))
        p = sphere_pull_off(RHO, s)
        d = sphere_pull_off(RHO, s, control="displacement")
        a0 = sphere_contact_for_load(0.0, RHO, s).a_over_R
        assert _same(alpha, a), lam
        assert _same(load, p.F_pulloff_over_piwR) and _same(disp, d.F_pulloff_over_piwR), lam
        assert _same(ratio, p.a_over_R_at_pulloff / a0), lam


def test_each_models_radius_gives_its_own_load_back():
    F = np.array([-0.003, 0.0, 0.01, 1.0])  # JKR comes off at -1.5 pi s = -0.00395
    s = _s(1.0)
    r = _radii(F, np.full(4, RHO), np.full(4, s))
    np.testing.assert_allclose(sphere_jkr_load(r["jkr"], RHO, s), F, rtol=1e-12, atol=1e-15)
    ok = np.isfinite(r["dmt"])
    np.testing.assert_allclose(sphere_dmt_load(r["dmt"][ok], RHO, s), F[ok], rtol=1e-12, atol=1e-15)
    assert np.isnan(r["hertz"][0]) and r["hertz"][1] == 0.0


@pytest.mark.parametrize(("lam", "model"), [(1e-4, "dmt"), (1e3, "jkr")])
def test_in_its_limit_a_model_is_exact(lam, model):
    m = sphere_models([0.0, 0.01], RHO, _s(lam))
    assert np.all(m.best == model)
    pull = getattr(m, f"pull_off_error_{model}")
    radius = getattr(m, f"radius_error_{model}")
    assert np.all(np.abs(pull) < 1e-4) and np.all(np.abs(radius) < 1e-3), (pull, radius)


# measured: the largest relative misfit of the fitted COS curve over its loads
COS_MISFIT = {0.01: 0.012, 0.1: 0.053, 1.0: 0.0067, 10.0: 0.0003}


@pytest.mark.parametrize("lam", list(COS_MISFIT))
def test_the_cos_curve_follows_the_maugis_curve_it_was_fitted_to(lam):
    s = _s(lam)
    alpha = cos_alpha(lam)
    Fc = float(sphere_pull_off(RHO, s).F_pulloff_over_EhR)
    loads = np.linspace(Fc, -COS_LOADS * Fc, 200)
    md = sphere_contact_for_load(loads, RHO, s).a_over_R
    a0 = float(sphere_contact_for_load(0.0, RHO, s).a_over_R)
    misfit = np.max(np.abs(_cos_radius(alpha, loads, a0, Fc) / md - 1))
    assert misfit <= COS_MISFIT[lam], (lam, misfit)
    # and no other alpha fits it better (the fit is the least-squares minimum)
    for other in (alpha * 0.9, min(alpha * 1.1, 1.5)):
        worse = np.sum((_cos_radius(other, loads, a0, Fc) / md - 1) ** 2)
        best = np.sum((_cos_radius(alpha, loads, a0, Fc) / md - 1) ** 2)
        assert worse >= best, (lam, other)


def test_alpha_runs_from_dmt_to_jkr_and_its_inverse_gives_lambda_back():
    lams = np.geomspace(1e-3, 1e3, 13)
    alphas = cos_alpha(lams)
    assert np.all(np.diff(alphas) > 0) and alphas[0] < 1e-3 and alphas[-1] > 0.9999
    for lam in (0.7,):  # a root-find of fits: seconds each
        assert maugis_parameter_of_cos_alpha(cos_alpha(lam)) == pytest.approx(lam, rel=1e-6)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: sphere_models(0.0, 100.0, 0.0), "sigma0_over_E"),
        (lambda: cos_alpha(1e5), "maugis_parameter"),
        (lambda: maugis_parameter_of_cos_alpha(1.2), "alpha"),
    ],
)
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ParameterError, match=re.escape(name)):
        call()
