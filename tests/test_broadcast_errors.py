"""Error paths over every broadcast shape: the first failing point is named, never a crash.

Each vectorised function that raises for a point (``on_failure="raise"``, the domain
checks) is called with each argument in a drawn layout, a scalar, ``(n,)``, ``(1, n)`` or
``(m, 1)``, so that any argument may be the one that sets the points' shape, and with one
failing value placed at a drawn element of a drawn argument. The error must be the
documented one (never an ``IndexError`` from a message builder that indexes an input that
was broadcast with the flat index of the point) and its message must give every input named
at the first failing point, as broadcast, under the caller's names. The report policies
must return the broadcast shape with the failing points marked and the others finite.

The good values differ from element to element (and from argument to argument), so that a
message giving the value of another point is caught. Values are compared as their ``repr``
(the messages print the inputs as given); no float computed by two code paths is compared.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import linecontact as lc
from linecontact import ConvergenceError, NoEquilibriumError
from linecontact._validation import first_point, point_text

SETTINGS = settings(
    derandomize=True,
    deadline=None,
    database=None,
    max_examples=30,
    suppress_health_check=[HealthCheck.too_slow],
)

M, N = 2, 3
SHAPES: dict[str, tuple[int, ...]] = {"scalar": (), "n": (N,), "1n": (1, N), "m1": (M, 1)}


@dataclass(frozen=True)
class Case:
    """A function, its arguments' good ranges, a failing value and what it must raise."""

    call: Callable[..., object]
    args: tuple[str, ...]  # the names the caller uses (and the message gives)
    good: tuple[tuple[float, float], ...]  # every value in these ranges is a good point
    bad: dict[str, float]  # argument -> a value that fails at any point
    error: type[Exception]
    named: tuple[str, ...] = ()  # the inputs the message must give at the point
    kwargs: dict = field(default_factory=dict)


def _rolling(tau, T, **kw):
    return lc.steady_rolling(tau, T_over_Ea=T, **kw)


def _initiation(tau, T, **kw):
    return lc.sliding_initiation(tau, T_over_Ea=T, **kw)


def _rolling_c(m, a, T, **kw):
    return lc.steady_rolling_coulomb(m, a, T_over_muF=T, **kw)


def _initiation_c(m, a, T, **kw):
    return lc.sliding_initiation_coulomb(m, a, T_over_muF=T, **kw)


_TAU = ("tau0_over_E", "T_over_Ea")
_COUL = ("mu", "a_over_R", "T_over_muF")
_NORMAL = ("F_over_Eh", "R_over_h", "sigma0_over_E")
_SLIDING = ("F_over_Eh2", "R_over_h2", "h1_over_h2", "sigma0_over_E")
_RAISE = {"on_failure": "raise"}

CASES: dict[str, Case] = {
    # beyond full slip: T >= 2 a tau0 (a load too large, or a shear strength too small)
    "steady_rolling": Case(
        _rolling, _TAU, ((0.5, 1.0), (0.1, 0.9)), {"tau0_over_E": 0.01, "T_over_Ea": 2.5},
        NoEquilibriumError, _TAU, _RAISE,
    ),
    "sliding_initiation": Case(
        _initiation, _TAU, ((0.5, 1.0), (0.1, 0.9)), {"tau0_over_E": 0.01, "T_over_Ea": 2.5},
        NoEquilibriumError, _TAU, _RAISE,
    ),
    # d/a = 0 is full slip
    "sliding_initiation_d": Case(
        lc.sliding_initiation, ("tau0_over_E", "d_over_a"), ((0.5, 1.0), (0.3, 0.9)),
        {"d_over_a": 0.0}, NoEquilibriumError, ("tau0_over_E", "d_over_a"), _RAISE,
    ),
    "steady_rolling_coulomb": Case(
        _rolling_c, _COUL, ((0.2, 0.5), (0.005, 0.02), (0.1, 0.9)), {"T_over_muF": 1.5},
        NoEquilibriumError, _COUL, _RAISE,
    ),
    "sliding_initiation_coulomb": Case(
        _initiation_c, _COUL, ((0.2, 0.5), (0.005, 0.02), (0.1, 0.9)), {"T_over_muF": 1.5},
        NoEquilibriumError, _COUL, _RAISE,
    ),
    # below the pull-off force
    "contact_for_load": Case(
        lc.contact_for_load, _NORMAL, ((0.0, 1.0), (50.0, 150.0), (0.1, 0.3)),
        {"F_over_Eh": -50.0}, NoEquilibriumError, _NORMAL,
    ),
    "contact_for_load_unstable": Case(
        lc.contact_for_load, _NORMAL, ((-2.3, -2.1), (50.0, 50.0), (0.3, 0.3)),
        {"F_over_Eh": 5.0}, NoEquilibriumError, _NORMAL, {"branch": "unstable"},
    ),
    "sliding_contact_for_load": Case(
        lc.sliding_contact_for_load, _SLIDING, ((0.5, 2.0), (50.0, 150.0), (1.2, 2.0), (0.1, 0.3)),
        {"F_over_Eh2": -50.0}, NoEquilibriumError, _SLIDING, {"method": "closed-form"},
    ),
    "push": Case(
        lc.push,
        ("R_over_h2", "h1_over_h2", "sigma0_over_E", "tau0_over_E", "F_over_Eh2", "H_over_R"),
        ((50.0, 150.0), (1.2, 2.0), (0.1, 0.3), (1e-3, 1e-2), (0.5, 2.0), (0.5, 1.5)),
        {"F_over_Eh2": -50.0}, NoEquilibriumError, _SLIDING,
    ),
    # the collocation at too few nodes: Hertz converges, an adhesive point does not
    "normal_contact": Case(
        lc.normal_contact, ("a_over_R", "R_over_h", "sigma0_over_E"),
        ((0.02, 0.05), (50.0, 150.0), (0.0, 0.0)), {"sigma0_over_E": 0.2}, ConvergenceError,
        ("a_over_R", "R_over_h", "sigma0_over_E"), {"method": "collocation", "n": 4},
    ),
    "sliding_contact": Case(
        lc.sliding_contact, ("a_over_R", "R_over_h2", "h1_over_h2", "sigma0_over_E"),
        ((0.02, 0.05), (50.0, 150.0), (1.2, 2.0), (0.0, 0.0)), {"sigma0_over_E": 0.2},
        ConvergenceError, ("a_over_R", "R_over_h2", "h1_over_h2", "sigma0_over_E"),
        {"method": "collocation", "n": 4},
    ),
    # a stick zone too close to its limit for the largest collocation
    "steady_rolling_collocation": Case(
        lc.steady_rolling, ("tau0_over_E", "d_over_a"), ((0.01, 0.02), (-0.5, 0.5)),
        {"d_over_a": -0.9999999}, ConvergenceError, ("tau0_over_E", "d_over_a"),
        {"method": "collocation"},
    ),
    # the tip's force turned backwards
    "tip_push": Case(
        lc.tip_push, ("H_over_R", "tip_friction"), ((0.2, 1.0), (0.5, 1.0)), {"H_over_R": 1.99},
        ValueError, ("H_over_R", "tip_friction"),
    ),
}  # fmt: skip

# out of the domain: any argument, any function (a ValueError naming it and the value)
DOMAIN_CASES: dict[str, Case] = {
    "normal_contact": Case(
        lc.normal_contact, ("a_over_R", "R_over_h", "sigma0_over_E"),
        ((0.01, 0.05), (50.0, 150.0), (0.0, 0.3)),
        {"a_over_R": 20.0, "R_over_h": -1.0, "sigma0_over_E": -0.5}, ValueError,
    ),
    "contact_for_load": Case(
        lc.contact_for_load, _NORMAL, ((0.0, 1.0), (50.0, 150.0), (0.1, 0.3)),
        {"F_over_Eh": 1e13, "R_over_h": 1e-4, "sigma0_over_E": 2e6}, ValueError,
    ),
    "pull_off": Case(
        lc.pull_off, ("R_over_h", "sigma0_over_E"), ((50.0, 150.0), (0.1, 0.3)),
        {"R_over_h": 0.0, "sigma0_over_E": -1.0}, ValueError,
    ),
    "sliding_contact_for_load": Case(
        lc.sliding_contact_for_load, _SLIDING, ((0.5, 2.0), (50.0, 150.0), (1.2, 2.0), (0.1, 0.3)),
        {"F_over_Eh2": -1e13, "R_over_h2": 2e12, "h1_over_h2": 1e4, "sigma0_over_E": -0.1},
        ValueError, (), {"method": "closed-form"},
    ),
    "steady_rolling": Case(
        _rolling, _TAU, ((0.5, 1.0), (0.1, 0.9)), {"tau0_over_E": 2.0, "T_over_Ea": -1.0},
        ValueError,
    ),
    "sliding_initiation_coulomb": Case(
        _initiation_c, _COUL, ((0.2, 0.5), (0.005, 0.02), (0.1, 0.9)),
        {"mu": 1000.0, "a_over_R": 20.0, "T_over_muF": -0.5}, ValueError,
    ),
    "cyclic_loss": Case(
        lc.cyclic_loss, ("tau0_over_E", "T_amplitude_over_Ea"), ((0.5, 1.0), (0.1, 0.9)),
        {"tau0_over_E": 2.0, "T_amplitude_over_Ea": -1.0}, ValueError,
    ),
    "tip_push": Case(
        lc.tip_push, ("H_over_R", "tip_friction"), ((0.2, 1.0), (0.0, 1.0)),
        {"H_over_R": 3.0, "tip_friction": 11.0}, ValueError,
    ),
}  # fmt: skip


@dataclass(frozen=True)
class Draw:
    """The arguments as called, the failing argument and the points where it fails."""

    args: list
    bad_arg: str
    bad_value: float
    failing: np.ndarray  # bool, the broadcast shape


@st.composite
def draws(draw, case: Case) -> Draw:
    """Each argument in a drawn layout; the failing value at a drawn element of one of them."""
    layouts = [draw(st.sampled_from(list(SHAPES))) for _ in case.args]
    bad_arg = draw(st.sampled_from(sorted(case.bad)))
    pos = draw(st.integers(0, M * N - 1))
    args: list = []
    for k, (name, (lo, hi), lay) in enumerate(zip(case.args, case.good, layouts, strict=True)):
        shape = SHAPES[lay]
        size = math.prod(shape)
        # distinct good values, in a different order for each argument
        vals = np.linspace(lo, hi, size) if size > 1 else np.array([0.5 * (lo + hi)])
        vals = np.roll(vals, k).reshape(shape)
        if name == bad_arg:
            vals = vals.copy()
            vals.reshape(-1)[pos % size] = case.bad[name]
        args.append(float(vals) if lay == "scalar" else vals)
    bad_value = case.bad[bad_arg]
    arrays = [np.asarray(a) for a in args]
    shape = np.broadcast_shapes(*(a.shape for a in arrays))
    j = case.args.index(bad_arg)
    failing = np.broadcast_to(arrays[j] == bad_value, shape)
    return Draw(args, bad_arg, bad_value, failing)


def _expected(case: Case, d: Draw) -> dict[str, float]:
    """The inputs at the first failing point (C order), from the arrays as broadcast."""
    shape = d.failing.shape
    at = np.unravel_index(int(np.argmax(d.failing.reshape(-1))), shape)
    return {
        name: float(np.broadcast_to(np.asarray(a), shape)[at])
        for name, a in zip(case.args, d.args, strict=True)
    }


def _raises(case: Case, d: Draw) -> str:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.ModelValidityWarning)
        with pytest.raises(case.error) as info:
            case.call(*d.args, **case.kwargs)
    # a subclass of the documented type is fine; a crash of the message builder is not
    assert not isinstance(info.value, (IndexError, TypeError, KeyError))
    return str(info.value)


@pytest.mark.parametrize("name", sorted(CASES))
def test_raise_names_the_first_failing_point(name):
    """The documented error, naming every input at the first failing point as broadcast."""
    case = CASES[name]

    @SETTINGS
    @given(draws(case))
    def check(d: Draw) -> None:
        msg = _raises(case, d)
        expected = _expected(case, d)
        assert f"{d.bad_arg}={d.bad_value!r}" in msg, msg
        for arg in case.named:
            assert f"{arg}={expected[arg]!r}" in msg, (arg, expected, msg)

    check()


@pytest.mark.parametrize("name", sorted(DOMAIN_CASES))
def test_out_of_domain_names_the_argument(name):
    """Out of the domain, whatever the layouts: a ValueError naming the argument and value."""
    case = DOMAIN_CASES[name]

    @settings(SETTINGS, max_examples=15)
    @given(draws(case))
    def check(d: Draw) -> None:
        msg = _raises(case, d)
        assert msg.startswith(d.bad_arg), msg
        assert repr(float(d.bad_value)) in msg, msg

    check()


# --------------------------------------------------------------------------------------------
# the report policies: the broadcast shape, the failing points marked, the others finite

REPORTS: dict[str, tuple[str, dict, Callable[[object], tuple[np.ndarray, np.ndarray]]]] = {
    # case -> (the keyword that reports, its value, (marked, finite value) of a result)
    "steady_rolling": (
        "on_failure", {"on_failure": "report"},
        lambda r: (np.asarray(r.state) == "sliding", np.asarray(r.d_over_a, float)),
    ),
    "sliding_initiation": (
        "on_failure", {"on_failure": "report"},
        lambda r: (np.asarray(r.state) == "sliding", np.asarray(r.d_over_a, float)),
    ),
    "steady_rolling_coulomb": (
        "on_failure", {"on_failure": "report"},
        lambda r: (np.asarray(r.state) == "sliding", np.asarray(r.d_over_a, float)),
    ),
    "sliding_initiation_coulomb": (
        "on_failure", {"on_failure": "report"},
        lambda r: (np.asarray(r.state) == "sliding", np.asarray(r.d_over_a, float)),
    ),
    "contact_for_load": (
        "on_failure", {"on_failure": "report"},
        lambda r: (np.asarray(r.state) == "no-equilibrium", np.asarray(r.a_over_R, float)),
    ),
    "sliding_contact_for_load": (
        "on_failure", {"method": "closed-form", "on_failure": "report"},
        lambda r: (np.asarray(r.state) == "no-equilibrium", np.asarray(r.a_over_R, float)),
    ),
    "normal_contact": (
        "on_failure", {"method": "collocation", "n": 4, "on_failure": "report"},
        lambda r: (~np.asarray(r.converged, bool), np.asarray(r.F_over_Eh, float)),
    ),
    "sliding_contact": (
        "on_failure", {"method": "collocation", "n": 4, "on_failure": "report"},
        lambda r: (~np.asarray(r.converged, bool), np.asarray(r.F_over_Eh2, float)),
    ),
    "steady_rolling_collocation": (
        "on_failure", {"method": "collocation", "on_failure": "report"},
        lambda r: (~np.asarray(r.converged, bool), np.asarray(r.d_over_a, float)),
    ),
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(REPORTS))
def test_report_marks_the_failing_points(name):
    case = CASES[name]
    _, kwargs, read = REPORTS[name]

    @settings(SETTINGS, max_examples=20)
    @given(draws(case))
    def check(d: Draw) -> None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", lc.ModelValidityWarning)
            r = case.call(*d.args, **kwargs)
        marked, value = read(r)
        assert marked.shape == d.failing.shape
        assert value.shape == d.failing.shape
        np.testing.assert_array_equal(marked, d.failing)
        assert np.all(np.isfinite(value[~d.failing]))
        if name in ("contact_for_load", "sliding_contact_for_load"):
            assert np.all(np.isnan(value[d.failing]))

    check()


# --------------------------------------------------------------------------------------------
# the cases found, exactly


@pytest.mark.parametrize("fn", [lc.steady_rolling, lc.sliding_initiation])
def test_regression_scalar_load_over_two_shear_strengths(fn):
    """The load broadcast over two points: the message builder indexed it at point 1."""
    with pytest.raises(NoEquilibriumError) as info:
        fn([1.0, 0.5], T_over_Ea=1.5, on_failure="raise")
    msg = str(info.value)
    assert "T_over_Ea=1.5 is at or above the full-slip load 1.0" in msg
    assert "tau0_over_E=0.5" in msg


def test_regression_row_and_column():
    """A row of loads and a column of strengths: the first failing point is (0, 1)."""
    with pytest.raises(NoEquilibriumError, match=r"T_over_Ea=2\.5 .* tau0_over_E=0\.5\b"):
        lc.steady_rolling([[0.5], [1.0]], T_over_Ea=[0.1, 2.5], on_failure="raise")
    with pytest.raises(NoEquilibriumError, match=r"T_over_muF=1\.5 .* a_over_R=0\.02\b"):
        lc.sliding_initiation_coulomb(
            0.3, [[0.02], [0.01]], T_over_muF=[0.5, 0.5, 1.5], on_failure="raise"
        )


def test_d_over_a_at_full_slip_names_d():
    """Full slip given as d/a = 0 names d/a and the load it means, not d/a as the load."""
    with pytest.raises(NoEquilibriumError) as info:
        lc.sliding_initiation([[1.0], [0.25]], [0.5, 0.0], on_failure="raise")
    msg = str(info.value)
    assert "d_over_a=0.0 is full slip (T_over_Ea=2.0, the full-slip load)" in msg
    assert "tau0_over_E=1.0" in msg


def test_kappa_limit_over_a_row_and_a_column():
    """The joint limit kappa <= 1e12 at point (1, 1) of a (2, 1) by (2,) grid."""
    with pytest.raises(ValueError, match=r"at R_over_h=1000000000000\.0, sigma0_over_E=1000000\.0"):
        lc.normal_contact(0.01, [[1.0], [1e12]], [0.0, 1e6])


def test_lennard_jones_limit_and_pull_off_over_a_grid():
    with pytest.raises(ValueError, match=r"R_over_h=100\.0, sigma0_over_E=1000000\.0 give mu"):
        lc.laws.lennard_jones.contact_for_load(0.5, [[100.0], [1.0]], [0.1, 1e6])
    # the pull-off answers at every mu: beyond the solver's domain, the limit form
    p = lc.laws.lennard_jones.pull_off([[100.0], [0.01]], [1e-3, 1e6])
    assert p.method.tolist() == [["self-consistent", "limit"], ["self-consistent", "limit"]]
    with pytest.raises(NoEquilibriumError, match=r"F_over_Eh=-50\.0 .*R_over_h=50\.0"):
        lc.laws.lennard_jones.contact_for_load([[0.5], [-50.0]], [50.0, 100.0], 0.2)


def test_cylinder_push_too_wide_over_a_grid():
    """A column of loads over a row of heights: the contact too wide is at flat index 2."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.CouplingWarning)  # these materials' Dundurs beta
        cyl = lc.Cylinder.from_materials(
            50e-9, 70e9, 0.17, 160e9, 0.22, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9
        )
    wide = 1e5 * cyl.modulus * cyl.adhesion_range
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.ModelValidityWarning)
        with pytest.raises(ValueError, match=rf"normal_load={wide!r} N/m needs a contact"):
            cyl.push(
                friction_stress=1e6,
                height=[10e-9, 50e-9],
                normal_load=[[1.0], [wide]],
                receding_range=1.5 * cyl.adhesion_range,
            )


def test_inverse_over_a_grid():
    with pytest.raises(ValueError, match=r"pull_off_force=1\.0 N/m .* radius=5e-08 m"):
        lc.work_of_adhesion_from_pull_off([[-0.1], [1.0]], [5e-8, 6e-8], 50e9, 0.3e-9)
    with pytest.raises(ValueError, match=r"normal_load=-50\.0 N/m has no contact"):
        lc.shear_strength_from_friction([[0.2], [0.3]], [0.5, -50.0], 50e-9, 50e9, 0.1, 0.3e-9)
    with pytest.raises(ValueError, match=r"got 0\.05 for 0\.1"):
        lc.shear_strength_from_friction(
            0.2, 0.5, 50e-9, 50e9, 0.1, 0.3e-9, receding_work_of_adhesion=[0.2, 0.05]
        )


# --------------------------------------------------------------------------------------------
# the helper


def test_first_point_broadcasts_before_indexing():
    bad = np.array([[False, False, True], [True, False, False]])
    i, at = first_point(bad, x=np.array([[1.0], [2.0]]), y=np.array([10.0, 20.0, 30.0]), z=5.0)
    assert i == 2
    assert at == {"x": 1.0, "y": 30.0, "z": 5.0}
    assert point_text(at) == "x=1.0, y=30.0, z=5.0"
    # a mask smaller than the inputs: its first point in the broadcast shape
    i, at = first_point(np.array([False, True]), x=np.array([[1.0], [2.0], [3.0]]))
    assert (i, at) == (1, {"x": 1.0})
    # all scalars
    assert first_point(np.bool_(True), x=0.5) == (0, {"x": 0.5})
