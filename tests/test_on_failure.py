"""One failure-policy keyword, ``on_failure`` (issue 21).

The keywords it replaced (``raise_on_failure``, ``on_no_equilibrium``, ``on_sliding``) were
deprecated after 0.2.0 and deleted before 1.0 (issue 32): each is an unknown keyword now. The
library's own calls (API and command line) never give a ``DeprecationWarning``.
"""

from __future__ import annotations

import functools
import inspect
import warnings

import numpy as np
import pytest

import linecontact as lc
from linecontact import inverse as inv
from linecontact import lennard_jones_groups as ljg
from linecontact._validation import failure_policy
from linecontact.adhesion_map import md_half_width
from linecontact.cli import main
from linecontact.errors import ConvergenceError, NoEquilibriumError

CYL = lc.Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
HERTZ = lc.Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=0.0, adhesion_range=0.5e-9)


def _state(r):
    return np.asarray(getattr(r, "state", "")).tolist()


def _converged(r):
    return np.asarray(r.converged).tolist()


# (name, call taking the policy keywords, the deleted keyword, its value, the on_failure it
#  meant, what to compare between calls)
DELETED = [
    # raise_on_failure: a collocation point that misses its tolerance (n too small)
    (
        "normal_contact",
        lambda **k: lc.normal_contact(0.1, 1e4, 0.3, method="collocation", n=16, **k),
        "raise_on_failure", False, "report", _converged,
    ),
    (
        "normal_contact",
        lambda **k: lc.normal_contact(0.1, 1e4, 0.3, method="collocation", n=16, **k),
        "raise_on_failure", True, "raise", _converged,
    ),
    (
        "sliding_contact",
        lambda **k: lc.sliding_contact(0.15, 5000.0, 2.0, 0.2, method="collocation", n=16, **k),
        "raise_on_failure", False, "report", _converged,
    ),
    (
        "steady_rolling",
        lambda **k: lc.steady_rolling(0.01, -0.9999999, method="collocation", **k),
        "raise_on_failure", False, "report", _converged,
    ),
    (
        "tangential_history",
        lambda **k: lc.tangential_history(
            0.01, [1e-9], method="incremental", n=16, tol=1e-15, **k
        ),
        "raise_on_failure", False, "report", _converged,
    ),
    # on_no_equilibrium: a load below the pull-off force
    (
        "contact_for_load",
        lambda **k: lc.contact_for_load([-5.0, -2.0], 100.0, 0.2, **k),
        "on_no_equilibrium", "report", "report", _state,
    ),
    (
        "contact_for_load",
        lambda **k: lc.contact_for_load([-5.0, -2.0], 100.0, 0.2, **k),
        "on_no_equilibrium", "raise", "raise", _state,
    ),
    (
        "sliding_contact_for_load",
        lambda **k: lc.sliding_contact_for_load([-5.0, 0.5], 100.0, 2.0, 0.04, **k),
        "on_no_equilibrium", "report", "report", _state,
    ),
    (
        "sliding_contact_for_load",
        lambda **k: lc.sliding_contact_for_load([-5.0, 0.5], 100.0, 2.0, 0.04, **k),
        "raise_on_failure", False, "report", _state,
    ),
    (
        "Cylinder.contact",
        lambda **k: CYL.contact(load=[-100.0, 1.0], **k),
        "on_no_equilibrium", "report", "report", _state,
    ),
    # on_sliding: a tangential load beyond full slip
    (
        "sliding_initiation",
        lambda **k: lc.sliding_initiation(0.01, T_over_Ea=[0.01, 0.03], **k),
        "on_sliding", "report", "report", _state,
    ),
    (
        "sliding_initiation",
        lambda **k: lc.sliding_initiation(0.01, T_over_Ea=[0.01, 0.03], **k),
        "on_sliding", "raise", "raise", _state,
    ),
    (
        "steady_rolling",
        lambda **k: lc.steady_rolling(0.01, T_over_Ea=[0.01, 0.03], **k),
        "on_sliding", "report", "report", _state,
    ),
    (
        "sliding_initiation_coulomb",
        lambda **k: lc.sliding_initiation_coulomb(0.3, 0.01, T_over_muF=[0.5, 1.5], **k),
        "on_sliding", "report", "report", _state,
    ),
    (
        "steady_rolling_coulomb",
        lambda **k: lc.steady_rolling_coulomb(0.3, 0.01, T_over_muF=[0.5, 1.5], **k),
        "on_sliding", "report", "report", _state,
    ),
    (
        "steady_rolling",
        lambda **k: lc.steady_rolling(0.01, T_over_Ea=[0.01, 0.03], **k),
        "raise_on_failure", False, "report", _state,
    ),
    (
        "Cylinder.sliding_initiation",
        lambda **k: CYL.sliding_initiation(
            1.0, friction_stress=1e9, tangential_load=[1.0, 100.0], **k
        ),
        "on_sliding", "report", "report", _state,
    ),
    (
        "Cylinder.steady_rolling",
        lambda **k: HERTZ.steady_rolling(
            1.0, friction_coefficient=0.3, tangential_load=[0.1, 1.0], **k
        ),
        "on_sliding", "report", "report", _state,
    ),
]  # fmt: skip


def _outcome(call, **kw):
    """What a call gives: the compared quantity, or the type of the error it raises."""
    try:
        return call(**kw)
    except (ConvergenceError, NoEquilibriumError) as exc:
        return type(exc)


@pytest.mark.parametrize(
    "name, call, old, value, new, read",
    DELETED,
    ids=[f"{c[0]}-{c[2]}={c[3]!r}" for c in DELETED],
)
def test_each_deleted_keyword_is_unknown(name, call, old, value, new, read):
    with pytest.raises(TypeError, match=rf"unexpected keyword argument '{old}'"):
        call(**{old: value})
    got = _outcome(call, on_failure=new)  # the keyword that replaced it
    if new == "report":  # the failed point reported, not raised
        assert not isinstance(got, type)
        read(got)


def test_the_reports_mark_the_points():
    """What "report" returns for each kind of failure (the old report modes, unchanged)."""
    assert _state(lc.contact_for_load([-5.0, -2.0], 100.0, 0.2, on_failure="report")) == [
        "no-equilibrium",
        "contact",
    ]
    r = lc.sliding_initiation(0.01, T_over_Ea=[0.01, 0.03], on_failure="report")
    assert _state(r) == ["stick-slip", "sliding"] and np.isnan(r.d_over_a[1])
    c = lc.normal_contact(0.1, 1e4, 0.3, method="collocation", n=16, on_failure="report")
    assert c.converged is False


def test_a_keyword_the_function_never_had_is_a_type_error():
    with pytest.raises(TypeError, match=r"normal_contact\(\) got an unexpected keyword .*on_sl"):
        lc.normal_contact(0.05, 100.0, 0.01, on_sliding="report")
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'raise_on_failre'"):
        lc.sliding_contact(0.05, 100.0, 2.0, 0.01, raise_on_failre=False)


def test_bad_values_name_the_keyword():
    with pytest.raises(ValueError, match=r"^on_failure must be 'raise' or 'report', got 'no'$"):
        lc.contact_for_load(1.0, 100.0, 0.2, on_failure="no")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^on_failure must be 'raise' or 'report', got 'x'$"):
        lc.steady_rolling(0.01, 0.5, on_failure="x")  # type: ignore[arg-type]


def test_the_policy_check():
    assert failure_policy("raise") == "raise"
    assert failure_policy("report") == "report"
    for bad in (True, None, "Raise", ["report"]):
        with pytest.raises(ValueError, match=r"^on_failure must be 'raise' or 'report', got "):
            failure_policy(bad)


def test_the_default_is_raise_everywhere():
    """Every public function with the keyword defaults to "raise" (the tangential ones too)."""
    fns = [
        lc.normal_contact,
        lc.contact_for_load,
        lc.sliding_contact,
        lc.sliding_contact_for_load,
        lc.sliding_initiation,
        lc.sliding_initiation_coulomb,
        lc.steady_rolling,
        lc.steady_rolling_coulomb,
        lc.tangential_history,
        lc.tangential_history_coulomb,
        lc.Cylinder.sliding_initiation,
        lc.Cylinder.steady_rolling,
        lc.Cylinder.contact,
        ljg.contact_for_load_in_dugdale_groups,
    ]
    for fn in fns:
        params = inspect.signature(fn).parameters
        assert params["on_failure"].default == "raise", fn
        for old in ("raise_on_failure", "on_no_equilibrium", "on_sliding"):
            assert old not in params, fn
    with pytest.raises(NoEquilibriumError, match="full-slip load"):
        lc.steady_rolling(0.01, T_over_Ea=0.03)
    with pytest.raises(NoEquilibriumError, match="full-slip load"):
        CYL.sliding_initiation(1.0, friction_stress=1e9, tangential_load=100.0)


def test_sliding_defaults_to_the_closed_form():
    for fn in (lc.sliding_contact, lc.sliding_contact_for_load):
        assert inspect.signature(fn).parameters["method"].default == "closed-form"
    assert lc.sliding_contact(0.03, 100.0, 2.0, 0.01).method == "closed-form"
    assert lc.sliding_contact_for_load(0.5, 100.0, 2.0, 0.04).n_collocation == 0


def test_no_private_keywords_in_public_signatures():
    for mod in (lc, inv):
        for name in getattr(mod, "__all__", dir(mod)):
            fn = getattr(mod, name)
            if not callable(fn) or isinstance(fn, type):
                continue
            try:
                params = inspect.signature(fn).parameters
            except (TypeError, ValueError):
                continue
            assert not [p for p in params if p.startswith("_")], name


def test_propagate_still_gives_nan_for_unreachable_draws():
    F = float(inv.pull_off_force(50e-9, 50e9, 0.1, 0.3e-9))
    x = dict(pull_off_force=F, radius=50e-9, modulus=50e9, equilibrium_spacing=0.3e-9)
    # a pull-off force this uncertain has draws no w reaches (F >= 0)
    est = inv.propagate(
        inv.work_of_adhesion_from_pull_off, x, dict(pull_off_force=abs(F)), n_samples=50
    )
    assert 0 < est.n_failed < 50


# --------------------------------------------------------------------------------------------
# the library's own calls never give a DeprecationWarning


def test_api_calls_give_no_deprecation_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        lc.push(100.0, 2.0, 0.01, 1e-3, 0.0, [0.25, 1.0, 2.0], [1e-4, 1e-2, 1.0])
        lc.tip_push([0.5, 1.0], 0.1)
        CYL.push(
            friction_stress=1e6,
            normal_load=1.0,
            height=[25e-9, 100e-9],
            receding_range=1e-9,
            push=[1e-3, 1.0],
        )
        CYL.contact(load=[-100.0, 1.0], on_failure="report")
        CYL.contact(contact_half_width=2e-9, method="collocation")
        CYL.steady_rolling(
            1.0, friction_stress=1e9, tangential_load=[1.0, 100.0], on_failure="report"
        )
        wire = lc.Cylinder.from_modulus(
            50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9
        )
        a = wire.contact(load=[-0.5, 0.5]).contact_half_width
        inv.work_of_adhesion_from_width(a, [-0.5, 0.5], 50e-9, 50e9, 0.3e-9)
        R = np.array([20e-9, 50e-9, 100e-9])
        inv.fit_pull_off(R, inv.pull_off_force(R, 50e9, 0.1, 0.3e-9), 50e9, bootstrap=0)
        md_half_width([-5.0, 0.5], 0.5)  # NaN below the pull-off


def _no_deprecation(capsys, *argv):
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)  # not even a caught one
        code = main(list(argv))
    out, err = capsys.readouterr()
    assert "deprecated" not in err.lower(), err
    return code, out, err


_SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h", "0.5e-9"]


@pytest.mark.parametrize(
    "argv",
    [
        ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.2", "--F-over-Eh", "-5", "1"],
        ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--a-over-R", "0.01"],
        ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--a-over-R", "0.01",
         "--method", "collocation"],
        ["slide-init", "--tau0-over-E", "0.01", "--T-over-Ea", "0.01", "0.03"],
        ["slide-init", "--tau0-over-E", "0.01", "--d-over-a", "0", "0.5"],
        ["roll", "--friction", "coulomb", "--mu", "0.3", "--a-over-R", "0.01",
         "--T-over-muF", "0.5", "1.5"],
        ["roll", "--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h", "0.5e-9",
         "--load", "1", "--tau0", "1e8", "--tangential-load", "0.3", "100"],
        ["slide", "--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.04",
         "--F-over-Eh2", "-5", "1"],
        ["slide", "--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.04",
         "--a-over-R", "0.01"],
        ["push", "--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.01",
         "--tau0-over-E", "1e-3", "--H-over-R", "0.25", "1", "2"],
        ["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.016", "-0.008", "0.03"],
        # the SI runs, through the methods of Cylinder (the cylinder_* functions deprecated)
        ["slide-init", *_SI, "--load", "1", "--tau0", "1e9", "--tangential-load", "1", "5"],
        ["push", "--radius", "50e-9", "--modulus", "48e9", "--sigma0", "1e8", "--h2", "0.3e-9",
         "--h1", "0.6e-9", "--tau0", "1e6", "--height", "10e-9", "50e-9", "--length", "1e-6"],
        ["history", *_SI, "--load", "1", "--tau0", "1e9", "--tangential-load", "1", "-1", "1"],
        ["cycle", *_SI, "--load", "1", "--tau0", "1e9", "--tangential-amplitude", "0.5", "9"],
    ],
    ids=lambda a: " ".join(a[:1] + a[-2:]),
)  # fmt: skip
def test_cli_commands_give_no_deprecation_warning(capsys, argv):
    code, out, err = _no_deprecation(capsys, *argv)
    assert code in (0, 1), err  # 1: a command whose every point has no state
    assert out


def test_an_inversion_reports_an_unreachable_force_as_nan_and_propagate_agrees_either_way():
    # the state travels as an argument: no context of propagate's changes what an inversion
    # gives; asked to report, it gives nan where no w reaches and w elsewhere
    F = float(inv.pull_off_force(50e-9, 50e9, 0.1, 0.3e-9))
    forces = np.array([F, 0.5 * F, 1e-3, 2 * F])  # 1e-3 N/m: not tensile, no w reaches it
    with pytest.raises(ValueError, match="cannot be produced by any work of adhesion"):
        inv.work_of_adhesion_from_pull_off(forces, 50e-9, 50e9, 0.3e-9)
    got = inv.work_of_adhesion_from_pull_off(forces, 50e-9, 50e9, 0.3e-9, on_failure="report")
    assert np.isnan(got[2]) and np.all(np.isfinite(got[[0, 1, 3]]))
    one = [
        float(inv.work_of_adhesion_from_pull_off(f, 50e-9, 50e9, 0.3e-9)) for f in forces[[0, 1, 3]]
    ]
    assert np.allclose(got[[0, 1, 3]], one, rtol=1e-12)
    with pytest.raises(ValueError, match="on_failure must be 'raise' or 'report'"):
        inv.work_of_adhesion_from_pull_off(F, 50e-9, 50e9, 0.3e-9, on_failure="nan")
    with pytest.raises(ValueError, match="on_failure must be 'raise' or 'report'"):
        inv.work_of_adhesion_from_width(1e-9, 0.5, 50e-9, 50e9, 0.3e-9, on_failure=None)
    # propagate: the raising function's batches are split around the unreachable draws, the
    # reporting one's run whole; the same draws fail and the estimates agree
    x = dict(pull_off_force=F, radius=50e-9, modulus=50e9, equilibrium_spacing=0.3e-9)
    sds = dict(pull_off_force=abs(F))
    raw = inv.propagate(inv.work_of_adhesion_from_pull_off, x, sds, n_samples=60)
    rep = inv.propagate(
        functools.partial(inv.work_of_adhesion_from_pull_off, on_failure="report"),
        x,
        sds,
        n_samples=60,
    )
    assert 0 < raw.n_failed == rep.n_failed < 60
    assert raw.value == pytest.approx(rep.value, rel=1e-12)
    assert raw.sd == pytest.approx(rep.sd, rel=1e-9)


def test_propagate_says_the_range_of_n_samples_it_takes():
    x = dict(pull_off_force=-1.0, radius=50e-9, modulus=50e9, equilibrium_spacing=0.3e-9)
    with pytest.raises(ValueError, match=r"n_samples must be an integer in \[10, 1e7\]"):
        inv.propagate(inv.work_of_adhesion_from_pull_off, x, {}, n_samples=10_000_001)
