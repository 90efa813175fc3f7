"""Fuzz the adhesive sphere (``linecontact.sphere``, ``Sphere``, ``--body sphere``).

Over the whole validated domain (:data:`linecontact.domain.DOMAIN`, its edges included:
``R/h`` in ``[1e-3, 1e12]``, ``sigma0/E`` 0 or in ``[1e-100, 1e6]`` (a sphere's: below,
its adhesion is lost to rounding, and a value there is refused, naming it),
``a/R`` in ``[1e-150, 10]``, ``F/(E h R)`` in ``[-1e12, 1e12]``):

1. inside the domain every function returns finite numbers with converged diagnostics, or
   a documented error (``NoEquilibriumError`` below the pull-off, ``ConvergenceError``, a
   ``ValueError`` naming the parameter); never NaN silently, never a ``RuntimeWarning``
   (pytest turns them into errors, ``pyproject.toml``), never another exception;
2. outside it a ``ValueError`` names the parameter;
3. the physics: the load-control pull-off in ``[-2, -1.5] pi w R``, the displacement-control
   one above it and at most ``-5/6 pi w R``; ``sphere_contact_for_load`` undone by
   ``sphere_contact``; the stable radius grows with the load; shapes and broadcasting;
4. the command line (``pulloff``, ``normal``, ``curve`` with ``--body sphere``, the wire's
   flags mixed in): status 0 with JSON, or status 2 with one ``error:`` line naming a flag;
5. the SI layer (``Sphere``) at extreme but valid SI inputs: finite results.

Each defect found by the fuzzing campaign is pinned as an ``@example`` of the property it
breaks. The draws are derandomized and bounded (about 30 s on two cores);
``LINECONTACT_FUZZ_EXAMPLES=400 pytest tests/test_sphere_fuzz.py`` runs a longer campaign.
"""

from __future__ import annotations

import io
import json
import os
import warnings
from contextlib import redirect_stderr, redirect_stdout

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from linecontact import (
    NoEquilibriumError,
    Sphere,
    sphere_shear_strength_from_friction,
    sphere_work_of_adhesion_from_pull_off,
)
from linecontact.cli import main
from linecontact.errors import ModelValidityWarning, ParameterError
from linecontact.sphere import (
    sphere_contact,
    sphere_contact_for_load,
    sphere_load_curve,
    sphere_models,
    sphere_pull_off,
)

EXAMPLES = int(os.environ.get("LINECONTACT_FUZZ_EXAMPLES", "40"))
FUZZ = settings(
    derandomize=True,
    database=None,
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)

SUBNORMAL = 5e-324


def log_uniform(lo: float, hi: float, edges: tuple[float, ...] = ()) -> st.SearchStrategy:
    """Numbers ``10**u``, ``u`` uniform in ``[lo, hi]``, the ``edges`` drawn on their own."""
    body = st.floats(lo, hi).map(lambda u: float(min(max(10.0**u, 10.0**lo), 10.0**hi)))
    return st.one_of(st.sampled_from(edges), body) if edges else body


RHO = log_uniform(-3, 12, (1e-3, 1e12, 1.0))
SIGMA = st.one_of(st.sampled_from([0.0, 1e-100, 1e6]), log_uniform(-100, 6))
SIGMA_POS = st.one_of(st.sampled_from([1e-100, 1e6]), log_uniform(-100, 6))
ALPHA = log_uniform(-150, 1, (1e-150, 10.0))


def too_wide(call):
    """``call()``, or None where its contact is wider than the domain's 10 R (refused, named).

    At the domain's far corner (small R/h, large sigma0/E) even the pull-off's contact is
    wider than the sphere: a load there is refused, naming ``F_over_EhR`` (or ``load``).
    """
    try:
        return call()
    except ParameterError as e:
        assert "beyond 10" in str(e) or "(10 radii, the domain" in str(e), e
        return None


def finite(*values) -> bool:
    return all(np.all(np.isfinite(np.asarray(v, float))) for v in values)


# -- 1, 3: the nondimensional functions ------------------------------------------------------


@settings(FUZZ, max_examples=4 * EXAMPLES)
@given(alpha=ALPHA, rho=RHO, s=SIGMA)
def test_contact_at_a_radius_is_finite_and_converged(alpha, rho, s):
    r = sphere_contact(alpha, rho, s)
    assert finite(r.c_over_R, r.F_over_EhR, r.delta_over_h, r.residual_separation)
    assert r.converged
    assert isinstance(r.F_over_EhR, float) and isinstance(r.stable, bool)


@settings(FUZZ, max_examples=3 * EXAMPLES)
@given(rho=RHO, s=SIGMA)
def test_pull_off_lies_between_dmt_and_jkr(rho, s):
    po = sphere_pull_off(rho, s)
    pd = sphere_pull_off(rho, s, control="displacement")
    for p in (po, pd):
        assert finite(
            p.F_pulloff_over_EhR,
            p.a_over_R_at_pulloff,
            p.c_over_R_at_pulloff,
            p.delta_over_h_at_pulloff,
            p.residual_separation,
        )
        assert p.converged
    if s == 0:
        assert po.F_pulloff_over_EhR == 0 and po.mechanism == "no-adhesion"
        return
    load, disp = po.F_pulloff_over_piwR, pd.F_pulloff_over_piwR
    assert -2 - 1e-9 <= load <= -1.5 + 1e-9
    assert disp <= -5 / 6 + 1e-9
    assert pd.F_pulloff_over_EhR >= po.F_pulloff_over_EhR * (1 + 1e-12)


def loads(rho: float, s: float, po: float, pick: float, kind: int) -> float:
    """A load at or above the pull-off ``po``: near it, at it, or anywhere up to 1e12."""
    if kind == 0:
        F = po * (1 - pick)  # between the pull-off and 0
    elif kind == 1:
        F = 10.0 ** (-300 + 312 * pick)  # any positive size
    elif kind == 2:
        F = po
    else:
        F = -po * 10.0 ** (6 * pick)  # compressive, in the pull-off's unit
    return float(np.clip(F, -1e12, 1e12))


@settings(FUZZ, max_examples=4 * EXAMPLES)
@given(rho=RHO, s=SIGMA, pick=st.floats(0, 1), kind=st.integers(0, 3))
@example(rho=1.0, s=0.0, pick=(-250 + 300) / 312, kind=1)  # Hertz, F = 1e-250: a wrong root
@example(rho=1e12, s=1e-100, pick=1.0, kind=1)  # F = 1e12: overflow in the Newton step
def test_contact_for_load_gives_back_its_load(rho, s, pick, kind):
    po = float(sphere_pull_off(rho, s).F_pulloff_over_EhR)
    F = loads(rho, s, po, pick, kind)
    r = too_wide(lambda: sphere_contact_for_load(F, rho, s))
    if r is None:
        return
    assert finite(r.a_over_R, r.c_over_R, r.F_over_EhR, r.delta_over_h)
    assert r.converged and r.stable
    assert 1e-150 <= r.a_over_R <= 10 or F == po
    assert abs(r.F_over_EhR - F) <= 1e-10 * max(abs(F), abs(po))
    if r.a_over_R >= 1e-150:  # at a pull-off of zero radius: a/R below the domain
        back = sphere_contact(r.a_over_R, rho, s)
        assert abs(back.F_over_EhR - F) <= 1e-10 * max(abs(F), abs(po))


@settings(FUZZ, max_examples=EXAMPLES)
@given(rho=RHO, s=SIGMA)
def test_below_the_pull_off_no_contact_and_the_stable_radius_grows(rho, s):
    po = float(sphere_pull_off(rho, s).F_pulloff_over_EhR)
    unit = max(abs(po), 1e-30)
    F = np.clip(np.concatenate([[po], po + unit * np.geomspace(1e-6, 1e4, 25)]), -1e12, 1e12)
    r = too_wide(lambda: sphere_contact_for_load(F, rho, s))
    if r is None:
        return
    assert np.all(np.diff(r.a_over_R) >= 0)
    assert np.all(r.stable[1:])
    if s > 0:
        below = po * (1 + 1e-6) - 1e-300
        with pytest.raises(NoEquilibriumError, match="F_over_EhR"):
            sphere_contact_for_load(below, rho, s)


@settings(FUZZ, max_examples=EXAMPLES)
@given(rho=RHO, s=SIGMA)
def test_report_marks_a_load_below_the_pull_off_as_not_converged(rho, s):
    # as the wire's inverse (normal.inverse): the point without a state has NaN, converged
    # and stable False
    po = float(sphere_pull_off(rho, s).F_pulloff_over_EhR)
    below = max(2 * po - 1e-300, -1e12)
    r = too_wide(lambda: sphere_contact_for_load([below, 0.0], rho, s, on_failure="report"))
    if r is None:
        return
    assert np.isnan(r.a_over_R[0]) and np.isnan(r.F_over_EhR[0])
    assert not r.converged[0] and not r.stable[0]
    assert finite(r.a_over_R[1]) and r.converged[1]


@settings(FUZZ, max_examples=EXAMPLES)
@given(rho=RHO, s=SIGMA_POS, pick=st.floats(0, 1), kind=st.integers(0, 3))
def test_models_are_finite(rho, s, pick, kind):
    po = float(sphere_pull_off(rho, s).F_pulloff_over_EhR)
    m = too_wide(lambda: sphere_models(loads(rho, s, po, pick, kind), rho, s))
    if m is None:
        return
    assert finite(m.pull_off_error_hertz, m.pull_off_error_dmt, m.pull_off_error_jkr)
    assert m.regime in ("DMT", "JKR", "transition") and m.best in ("hertz", "dmt", "jkr")


@settings(FUZZ, max_examples=EXAMPLES)
@given(
    rho=RHO,
    s=SIGMA,
    a_max=st.one_of(st.none(), log_uniform(-100, 1, (1e-100, 10.0))),
    num=st.integers(2, 60),
    num_noncontact=st.integers(0, 20),
)
def test_load_curve_is_finite(rho, s, a_max, num, num_noncontact):
    c = sphere_load_curve(rho, s, a_max_over_R=a_max, num=num, num_noncontact=num_noncontact)
    assert finite(c.a_over_R, c.c_over_R, c.F_over_EhR, c.delta_over_h)
    assert np.sum(c.branch == "contact") >= num
    assert np.all(np.diff(c.a_over_R[c.branch == "contact"]) > 0)


def test_shapes_and_broadcasting():
    r = sphere_contact(np.full((2, 1, 3), 0.01), np.array([1e3, 1e4]).reshape(1, 2, 1), 0.01)
    assert np.shape(r.F_over_EhR) == np.shape(r.converged) == np.shape(r.F_over_piwR)
    assert np.shape(r.F_over_EhR) == (2, 2, 3)
    p = sphere_pull_off(np.full((2, 3), 1e3), [0.0, 0.01, 1.0])
    assert np.shape(p.F_pulloff_over_EhR) == np.shape(p.mechanism) == (2, 3)
    q = sphere_pull_off(1e3, 0.01)
    assert isinstance(q.F_pulloff_over_EhR, float) and isinstance(q.mechanism, str)
    f = sphere_contact_for_load([[0.0, 1.0]], [[1e3], [1e4]], 0.01)
    assert np.shape(f.a_over_R) == (2, 2)
    assert np.shape(sphere_models(np.zeros((2, 2)), 1e3, 0.01).best) == (2, 2)


# -- 2: outside the domain -------------------------------------------------------------------

OUTSIDE = [np.nan, np.inf, -np.inf, -1.0]


@settings(FUZZ, max_examples=EXAMPLES)
@given(
    which=st.sampled_from(["a_over_R", "R_over_h", "sigma0_over_E", "F_over_EhR"]),
    bad=st.one_of(st.sampled_from(OUTSIDE), st.integers(0, 1)),
)
def test_outside_the_domain_names_the_parameter(which, bad):
    beyond = {  # just outside each end
        "a_over_R": (9.9e-151, 10.01),
        "R_over_h": (9.99e-4, 1.01e12),
        "sigma0_over_E": (-1e-300, 1.01e6),
        "F_over_EhR": (-1.01e12, 1.01e12),
    }
    value = beyond[which][bad] if isinstance(bad, int) else bad
    args = {"a_over_R": 0.01, "R_over_h": 1e3, "sigma0_over_E": 0.01, "F_over_EhR": 0.0}
    args[which] = value
    rest = {k: args[k] for k in ("R_over_h", "sigma0_over_E")}
    if which != "F_over_EhR":
        with pytest.raises(ValueError, match=which):
            sphere_contact(args["a_over_R"], **rest)
    if which != "a_over_R":
        with pytest.raises(ValueError, match=which):
            sphere_contact_for_load(args["F_over_EhR"], **rest)
    if which in rest:
        with pytest.raises(ValueError, match=which):
            sphere_pull_off(**rest)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: sphere_pull_off(1e3, 0.01, control="Load"), "control"),
        (lambda: sphere_contact_for_load(0.0, 1e3, 0.01, on_failure="x"), "on_failure"),
        (lambda: sphere_load_curve(1e3, 0.01, num=1), "num"),
        (lambda: sphere_load_curve(1e3, 0.01, num=2.0), "num"),
        (lambda: sphere_load_curve(1e3, 0.01, num_noncontact=-1), "num_noncontact"),
        (lambda: sphere_load_curve(1e3, 0.01, a_max_over_R=11.0), "a_max_over_R"),
        (lambda: sphere_load_curve(1e3, 0.01, a_max_over_R=0.0), "a_max_over_R"),
        (lambda: sphere_models(0.0, 1e3, 0.0), "sigma0_over_E"),
    ],
)
def test_other_arguments_outside_their_range_name_them(call, name):
    with pytest.raises(ValueError, match=name):
        call()


# -- 4: the command line ---------------------------------------------------------------------


def run(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err), warnings.catch_warnings():
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse's usage errors
            code = exc.code
    return int(code or 0), out.getvalue(), err.getvalue()


def check_cli(argv: list[str]) -> None:
    code, out, err = run(argv)
    assert "Traceback" not in err and "internal error" not in err, (argv, err)
    for word in ("overflow", "divide by zero", "invalid value", "underflow"):
        assert word not in err, (argv, err)  # a RuntimeWarning shown as a warning
    if code == 0:
        json.loads(out)
        assert "NaN" not in out and "Infinity" not in out, argv
        return
    errors = [line for line in err.splitlines() if "error:" in line]
    assert code == 2, (argv, err)
    assert len(errors) == 1, (argv, err)
    assert "--" in errors[0], (argv, err)  # names a flag


NUM = st.one_of(
    st.sampled_from(["0", "-0", "nan", "inf", "-inf", "1e400", "5e-324", "abc", "", "1e-300"]),
    st.floats(-12, 13).map(lambda u: f"{10**u:.6g}"),
    st.floats(-12, 13).map(lambda u: f"{-(10**u):.6g}"),
)
WIRE_FLAGS = st.sampled_from(
    [
        [],
        [],
        [],
        ["--length", "1e-3"],
        ["--F-over-Eh", "0.1"],
        ["--load", "1"],
        ["--branch", "unstable"],
        ["--method", "collocation"],
        ["--cross-section", "hexagon"],
        ["--corner-radius-over-R", "0.1"],
        ["--F-max-over-Eh", "1"],
        ["--F-max", "1"],
        ["--a-over-R-range", "1e-3", "1e-1", "5"],
        ["--body", "wire"],
    ]
)


@st.composite
def cli_args(draw) -> list[str]:
    cmd = draw(st.sampled_from(["pulloff", "normal", "curve"]))
    si = draw(st.booleans())
    argv = [cmd, "--body", "sphere"]
    if si:
        argv += ["--radius", draw(st.one_of(NUM, log_uniform(-9, -2).map(str)))]
        argv += ["--modulus", draw(st.one_of(NUM, log_uniform(6, 12).map(str)))]
        argv += ["--work-of-adhesion", draw(st.one_of(NUM, log_uniform(-4, 1).map(str)))]
        argv += ["--z0", draw(st.one_of(NUM, log_uniform(-11, -8).map(str)))]
    else:
        argv += ["--R-over-h", draw(st.one_of(NUM, RHO.map(repr)))]
        argv += ["--sigma0-over-E", draw(st.one_of(NUM, SIGMA.map(repr)))]
    if cmd == "normal":
        flag = draw(st.sampled_from(["--a-over-R", "--F-over-EhR", "--force", "--half-width"]))
        argv += [flag, *draw(st.lists(st.one_of(NUM, ALPHA.map(repr)), min_size=1, max_size=3))]
    elif cmd == "curve":
        if draw(st.booleans()):
            argv += ["--num", draw(st.sampled_from(["2", "3", "1", "-5", "100001", "2.5", "x"]))]
        if draw(st.booleans()):
            argv += ["--num-noncontact", draw(st.sampled_from(["0", "1", "-1", "100001"]))]
        argv += draw(
            st.sampled_from(
                [
                    [],
                    ["--a-max-over-R", draw(NUM)],
                    ["--a-max", draw(NUM)],
                    ["--a-max", "1e-7", "--a-max-over-R", "0.5"],
                ]
            )
        )
    elif draw(st.integers(0, 4)) == 0:  # the Lennard-Jones sphere: its domain checks only
        argv += ["--law", "lennard-jones"]
        if not si:
            argv[4] = draw(st.sampled_from(["-5", "0", "nan", "1e13"]))
    return [*argv, *draw(WIRE_FLAGS), "--json"]


@settings(FUZZ, max_examples=3 * EXAMPLES)
@given(argv=cli_args())
@example(argv="normal --body sphere --radius 1e-6 --modulus 50e9 --sigma0 1e8 --h 1e-9 "
         "--force 1e30 --json".split())  # fmt: skip
@example(argv="normal --body sphere --radius 1e-6 --modulus 50e9 --sigma0 1e8 --h 1e-9 "
         "--force nan --json".split())  # fmt: skip
@example(argv="pulloff --body sphere --R-over-h -5 --sigma0-over-E 0.01 "
         "--law lennard-jones --json".split())  # fmt: skip
@example(argv="curve --body sphere --radius 1e-6 --modulus 50e9 --sigma0 1e8 --h 1e-9 "
         "--a-max 1 --num 2 --json".split())  # fmt: skip
@example(argv="curve --body sphere --R-over-h 206.948 --sigma0-over-E 5e-324 --num 2 "
         "--json".split())  # fmt: skip
def test_cli_exits_0_with_json_or_2_naming_a_flag(argv):
    check_cli(argv)


@pytest.mark.parametrize(
    "argv",
    [
        # an SI flag without the SI inputs, silently ignored
        "curve --body sphere --R-over-h 1e3 --sigma0-over-E 0.01 --a-max 1e-6 --num 2",
        # two ends of the curve, one silently ignored
        "curve --body sphere --radius 1e-6 --modulus 50e9 --sigma0 1e8 --h 1e-9 "
        "--a-max 1e-7 --a-max-over-R 0.5 --num 2",
        # R/h outside its domain, solved under the Lennard-Jones law
        "pulloff --body sphere --R-over-h 0 --sigma0-over-E 0.01 --law lennard-jones",
        "pulloff --body sphere --R-over-h 1e13 --sigma0-over-E 1e-9 --law lennard-jones",
    ],
)
def test_cli_refuses_inputs_it_would_ignore_or_that_lie_outside_the_domain(argv):
    code, _, err = run([*argv.split(), "--json"])
    assert code == 2, err
    assert len([line for line in err.splitlines() if "error:" in line]) == 1


# -- 5: the SI layer -------------------------------------------------------------------------

SI_RADIUS = log_uniform(-9, -2, (1e-9, 1e-2))
SI_MODULUS = log_uniform(6, 12, (1e6, 1e12))
SI_W = log_uniform(-4, 1, (1e-4, 10.0))
SI_Z0 = log_uniform(-11, -8, (1e-11, 1e-8))


@settings(FUZZ, max_examples=EXAMPLES)
@given(R=SI_RADIUS, E=SI_MODULUS, w=SI_W, z0=SI_Z0, pick=st.floats(-20, 1))
def test_si_sphere_is_finite_and_consistent(R, E, w, z0, pick):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ModelValidityWarning)  # the units notes
        if 16 * w / (9 * np.sqrt(3) * z0) > 1e6 * E:  # sigma0/E beyond its domain: refused
            with pytest.raises(ValueError, match="modulus"):
                Sphere.from_modulus(R, E, work_of_adhesion=w, equilibrium_spacing=z0)
            return
        tip = Sphere.from_modulus(R, E, work_of_adhesion=w, equilibrium_spacing=z0)
        po = tip.pull_off()
        pd = tip.pull_off("displacement")
        assert finite(po.pull_off_force, po.approach_at_pull_off, pd.pull_off_force)
        assert po.pull_off_force < 0 and pd.pull_off_force >= po.pull_off_force
        F = po.pull_off_force * pick
        c = too_wide(lambda: tip.contact(load=F))
        if c is None:
            return
        assert finite(c.contact_radius, c.load, c.approach)
        assert abs(c.load - F) <= 1e-9 * max(abs(F), abs(po.pull_off_force))
        curve = tip.load_curve(num=10, num_noncontact=3)
        assert finite(curve.load, curve.contact_radius, curve.approach)
        w_back = sphere_work_of_adhesion_from_pull_off(po.pull_off_force, R, E, z0)
        assert abs(w_back / w - 1) < 1e-8
        tau = sphere_shear_strength_from_friction(1e-9, max(F, 0.0), R, E, w, z0)
        assert np.isfinite(tau) and tau > 0
        with pytest.raises(NoEquilibriumError):
            tip.contact(load=2 * po.pull_off_force)


@pytest.mark.parametrize("s", [SUBNORMAL, 1e-320, 1e-300, 9.9e-101])
def test_an_adhesion_lost_to_rounding_is_refused_naming_it(s):
    # found by the fuzzing: at subnormal sigma0/E the pull-off was -0.0 or -1.885 pi w R, a
    # log(0) warned, the load curve's geometric radii began at 0 (issue 34's session)
    for call in (
        lambda: sphere_pull_off(1e-3, s),
        lambda: sphere_contact(0.01, 1e6, s),
        lambda: sphere_contact_for_load(0.0, 1e6, s),
        lambda: sphere_models(0.0, 1e-3, s),
        lambda: sphere_load_curve(206.948, s, num=2),
    ):
        with pytest.raises(ValueError, match=r"sigma0_over_E must be 0 \(no adhesion"):
            call()
