"""Bad and edge input at every public entry point: plain ValueErrors, never garbage.

The messages are part of the API (they name the parameter and its valid range); the
inputs here are the ones an adversarial sweep found mishandled.
"""

import warnings

import numpy as np
import pytest

import linecontact as lc
from linecontact import ConvergenceError, Cylinder, Dugdale, NoEquilibriumError

X = object()  # placeholder for the argument under test


def _call(fn, args, kwargs, value):
    args = tuple(value if a is X else a for a in args)
    kwargs = {k: (value if v is X else v) for k, v in kwargs.items()}
    return fn(*args, **kwargs)


# every vectorised entry point, with the parameter under test
ENTRY_POINTS = [
    (lc.kappa, (X, 0.01), {}, "R_over_h"),
    (lc.maugis_parameter, (100.0, X), {}, "sigma0_over_E"),
    (lc.hertz_load, (X, 100.0), {}, "a_over_R"),
    (lc.jkr_load, (0.01, 100.0, X), {}, "sigma0_over_E"),
    (lc.zero_width_load, (X, 0.01), {}, "R_over_h"),
    (lc.normal_contact, (X, 100.0, 0.01), {}, "a_over_R"),
    (lc.contact_for_load, (X, 100.0, 0.01), {}, "F_over_Eh"),
    (lc.non_contact, (X, 100.0, 0.2), {}, "central_gap_over_h"),
    (lc.pull_off, (100.0, X), {}, "sigma0_over_E"),
    (lc.equilibria, (X, 100.0, 0.2), {}, "F_over_Eh"),
    (lc.load_curve, (X, 0.01), {}, "R_over_h"),
    (lc.sliding_initiation, (0.01, X), {}, "d_over_a"),
    (lc.steady_rolling, (0.01,), {"T_over_Ea": X}, "T_over_Ea"),
    (lc.sliding_initiation_coulomb, (X, 0.01, 0.5), {}, "mu"),
    (lc.steady_rolling_coulomb, (0.3, 0.01), {"T_over_muF": X}, "T_over_muF"),
    (lc.sliding_contact, (0.03, 100.0, X, 0.01), {}, "h1_over_h2"),
    (lc.sliding_contact_for_load, (X, 100.0, 2.0, 0.01), {}, "F_over_Eh2"),
    (lc.sliding_pull_off, (100.0, 2.0, X), {}, "sigma0_over_E"),
    (lc.composite_modulus, (70e9, X, 160e9, 0.22), {}, "nu1"),
    (lc.dundurs_beta, (70e9, 0.17, X, 0.22), {}, "E2"),
    (lc.adhesion_from_work, (X, 0.3e-9), {}, "work_of_adhesion"),
    (
        Cylinder.from_modulus,
        (X, 100e9),
        {"cohesive_stress": 1e9, "adhesion_range": 0.5e-9},
        "radius",
    ),
    (
        Cylinder.from_modulus,
        (50e-9, 100e9),
        {"cohesive_stress": X, "adhesion_range": 0.5e-9},
        "cohesive_stress",
    ),
]

NOT_REAL = [
    True,
    np.bool_(False),
    "0.5",
    b"1",
    1 + 1j,
    np.array([0.5 + 1j]),
    [0.5, None],
    np.datetime64("2020-01-01"),
]


def _ids(entry):
    return f"{entry[0].__qualname__}-{entry[3]}"


@pytest.mark.parametrize("value", NOT_REAL, ids=repr)
@pytest.mark.parametrize("entry", ENTRY_POINTS, ids=_ids)
def test_not_a_real_number_is_refused(entry, value):
    """A bool, a numeric string, a complex number or None is not silently converted."""
    fn, args, kwargs, name = entry
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # ComplexWarning would mean a silent conversion
        with pytest.raises(
            ValueError,
            match=rf"^{name} must be a real number or an array of "
            r"them, got ",
        ):
            _call(fn, args, kwargs, value)


# None means "not given" for the optional state variables and adhesion parameters
_NONE_IS_A_DEFAULT = ("d_over_a", "T_over_Ea", "T_over_muF", "cohesive_stress")


@pytest.mark.parametrize(
    "entry", [e for e in ENTRY_POINTS if e[3] not in _NONE_IS_A_DEFAULT], ids=_ids
)
def test_none_is_refused_where_it_is_no_default(entry):
    fn, args, kwargs, name = entry
    with pytest.raises(
        ValueError,
        match=rf"^{name} must be a real number or an array of "
        r"them, got None",
    ):
        _call(fn, args, kwargs, None)


def test_non_finite_loads_name_the_range():
    with pytest.raises(
        ValueError, match=r"^F_over_Eh must be a finite number in \[-1e\+12, 1e\+12\], got nan$"
    ):
        lc.contact_for_load(np.nan, 100.0, 0.01)
    with pytest.raises(
        ValueError, match=r"^F_over_Eh2 must be a finite number in \[-1e\+12, 1e\+12\], got inf$"
    ):
        lc.sliding_contact_for_load(np.inf, 100.0, 2.0, 0.01)


CYL = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
A3, B2 = [0.01, 0.02, 0.03], [1.0, 2.0]


@pytest.mark.parametrize(
    "fn, args, kwargs, message",
    [
        (lc.kappa, (A3, B2), {}, r"R_over_h has shape \(3,\), sigma0_over_E has shape \(2,\)"),
        (lc.jkr_load, (A3, B2, 0.01), {}, r"a_over_R has shape \(3,\), R_over_h has shape \(2,\)"),
        (
            lc.normal_contact,
            (A3, B2, 0.01),
            {},
            r"a_over_R has shape \(3,\), R_over_h has shape \(2,\)",
        ),
        (
            lc.contact_for_load,
            (A3, 100.0, B2),
            {},
            r"F_over_Eh has shape \(3,\), sigma0_over_E has shape \(2,\)",
        ),
        (
            lc.non_contact,
            (A3, B2, 0.01),
            {},
            r"central_gap_over_h has shape \(3,\), R_over_h has shape \(2,\)",
        ),
        (lc.pull_off, (A3, B2), {}, r"R_over_h has shape \(3,\), sigma0_over_E has shape \(2,\)"),
        (
            lc.sliding_initiation,
            (A3, [0.1, 0.2]),
            {},
            r"tau0_over_E has shape \(3,\), d_over_a has shape \(2,\)",
        ),
        (
            lc.steady_rolling_coulomb,
            (0.3, A3),
            {"T_over_muF": B2},
            r"a_over_R has shape \(3,\), T_over_muF has shape \(2,\)",
        ),
        (
            lc.sliding_contact,
            (0.03, A3, B2, 0.01),
            {},
            r"R_over_h2 has shape \(3,\), h1_over_h2 has shape \(2,\)",
        ),
        (
            lc.sliding_pull_off,
            (100.0, A3, B2),
            {},
            r"h1_over_h2 has shape \(3,\), sigma0_over_E has shape \(2,\)",
        ),
        (
            lc.composite_modulus,
            ([1e9, 2e9, 3e9], 0.3, [1e9, 2e9], 0.3),
            {},
            r"E1 has shape \(3,\), E2 has shape \(2,\)",
        ),
        (
            lc.adhesion_from_work,
            (A3, [1e-9, 2e-9]),
            {},
            r"work_of_adhesion has shape \(3,\), equilibrium_spacing has shape \(2,\)",
        ),
        (
            lc.Cylinder.steady_rolling,
            (CYL, [0.5, 1.0, 2.0]),
            {"friction_stress": 1e9, "tangential_load": [0.1, 0.2]},
            r"normal_load has shape \(3,\), tangential_load has shape \(2,\)",
        ),
        (
            lc.Cylinder.sliding_initiation,
            (CYL, 1.0),
            {"friction_stress": [1e9, 2e9, 3e9], "d_over_a": [0.1, 0.2]},
            r"friction_stress has shape \(3,\), d_over_a has shape \(2,\)",
        ),
    ],
)
def test_shapes_that_do_not_broadcast_are_named(fn, args, kwargs, message):
    with pytest.raises(
        ValueError, match=r"^the array arguments must broadcast together: " + message + "$"
    ):
        fn(*args, **kwargs)


@pytest.mark.parametrize(
    "fn, d, message",
    [
        (lc.Cylinder.sliding_initiation, 1.0, r"^d_over_a must be in \[0, 1\), got 1.0$"),
        (lc.Cylinder.steady_rolling, -1.0, r"^d_over_a must be in \(-1, 1\), got -1.0$"),
    ],
)
def test_cylinder_functions_check_the_stick_zone_first(fn, d, message):
    with pytest.raises(ValueError, match=message):
        fn(CYL, 1.0, friction_stress=1e9, d_over_a=d)


@pytest.mark.parametrize(
    "fn, args, kwargs, name",
    [
        (lc.equilibria, ([-1.0, 0.0], 100.0, 0.2), {}, "F_over_Eh"),
        (lc.equilibria, (-1.0, np.full((2, 2), 100.0), 0.2), {}, "R_over_h"),
        (lc.load_curve, (100.0, [0.01]), {}, "sigma0_over_E"),
        (lc.load_curve, (100.0, 0.01), {"a_max_over_R": [0.1, 0.2]}, "a_max_over_R"),
        (Cylinder.from_modulus, ([50e-9, 60e-9], 100e9), {"adhesion_range": 0.5e-9}, "radius"),
        (
            Cylinder.from_modulus,
            (50e-9, 100e9),
            {"cohesive_stress": [1e9, 2e9], "adhesion_range": 0.5e-9},
            "cohesive_stress",
        ),
        (
            Cylinder.from_modulus,
            (50e-9, 100e9),
            {"work_of_adhesion": [0.1, 0.2], "equilibrium_spacing": 0.3e-9},
            "work_of_adhesion",
        ),
        (
            Cylinder.from_materials,
            (50e-9, [70e9, 80e9], 0.17, 160e9, 0.22),
            {"adhesion_range": 0.5e-9},
            "E1",
        ),
    ],
)
def test_scalar_parameters_refuse_arrays(fn, args, kwargs, name):
    """These take one parameter point; an array gave TypeError from float()."""
    with pytest.raises(
        ValueError,
        match=rf"^{name} must be a single number, got an array of "
        r"shape \(",
    ):
        fn(*args, **kwargs)


def _direct(R, E, s0, h, *beta):
    """The cylinder built directly (a frozen dataclass), its adhesion a Dugdale law."""
    return Cylinder(R, E, Dugdale(cohesive_stress=s0, adhesion_range=h), *beta)


@pytest.mark.parametrize(
    "fields, message",
    [
        ((-1.0, 100e9, 1e9, 0.5e-9), r"^radius must be in \(0, inf\), got -1.0$"),
        ((50e-9, "x", 1e9, 0.5e-9), r"^modulus must be a real number"),
        ((50e-9, 100e9, "x", 0.5e-9), r"^cohesive_stress must be a real number"),
        ((50e-9, 100e9, 1e9, 0.0), r"^adhesion_range must be in \(0, inf\), got 0.0$"),
        (
            (50e-9, 100e9, 1e9, 0.5e-9, np.nan),
            r"^dundurs_beta must be a finite number in \[-0\.75, 0\.75\], got nan$",
        ),
        # |beta| < 3/4 for any pair of materials: 1e300 was accepted
        ((50e-9, 100e9, 1e9, 0.5e-9, 1e300), r"^dundurs_beta must be in \[-0\.75, 0\.75\]"),
        (
            (50e-9, 1e-300, 1e9, 0.5e-9),
            r"^cohesive_stress/modulus = inf is not a finite positive number",
        ),
        ((1e-300, 100e9, 1e9, 1e300), r"^radius/adhesion_range = 0.0 is not"),
        (
            (50e-9, 1e-300, 0.0, 1e-300),
            r"^modulus\*adhesion_range \(the unit of force per length\) = 0.0 is not",
        ),
    ],
)
def test_cylinder_checks_its_fields(fields, message):
    """Built directly (a frozen dataclass) or through from_modulus: same checks."""
    with pytest.raises(ValueError, match=message):
        _direct(*fields)


def test_cylinder_from_modulus_with_groups_out_of_range():
    """sigma0/E = inf from E = 1e-300 Pa: refused, not an overflow in the load conversion."""
    with pytest.raises(
        ValueError,
        match=r"^cohesive_stress=1000000000\.0 Pa must be at most 1e\+06 times the modulus, "
        r"1e-294 Pa here, got modulus=1e-300 Pa",
    ):
        Cylinder.from_modulus(50e-9, 1e-300, cohesive_stress=1e9, adhesion_range=0.5e-9)


def test_cylinder_fields_are_python_floats():
    c = _direct(np.float64(50e-9), 100_000_000_000, np.array(1e9), 0.5e-9)
    assert all(
        type(v) is float
        for v in (c.radius, c.modulus, c.cohesive_stress, c.adhesion_range, c.dundurs_beta)
    )


def test_cylinder_contact_scalar_in_python_scalars_out():
    r = CYL.contact(load=1.0)
    assert type(r.contact_half_width) is float and type(r.load) is float
    assert type(r.adhesive_zone_half_width) is float and type(r.stable) is bool
    r = CYL.contact(contact_half_width=np.array(3e-9))
    assert type(r.contact_half_width) is float
    assert CYL.contact(load=[0.5, 1.0]).load.shape == (2,)


SOLVERS = [
    (lc.normal_contact, (0.01, 100.0, 0.01), {"method": "collocation"}),
    (lc.sliding_initiation, (0.01, 0.5), {"method": "collocation"}),
    (lc.steady_rolling_coulomb, (0.3, 0.01, 0.5), {"method": "collocation"}),
    (lc.sliding_contact, (0.03, 100.0, 2.0, 0.01), {"method": "collocation"}),
    (lc.sliding_contact_for_load, (0.5, 100.0, 2.0, 0.01), {"method": "closed-form"}),
]


@pytest.mark.parametrize(
    "option, value, message",
    [
        ("on_failure", "no", r"^on_failure must be 'raise' or 'report', got 'no'$"),
        ("on_failure", None, r"^on_failure must be 'raise' or 'report', got None$"),
        ("on_failure", False, r"^on_failure must be 'raise' or 'report', got False$"),
        ("tol", True, r"^tol must be in \[1e-15, 1e-2\), got True$"),
        ("tol", np.nan, r"^tol must be in \[1e-15, 1e-2\), got nan$"),
        ("tol", "1e-10", r"^tol must be in \[1e-15, 1e-2\), got '1e-10'$"),
        ("n", np.array(16), r"^n must be 'auto' or an integer in \[2, \d+\], got array\(16\)$"),
        ("n", "AUTO", r"^n must be 'auto' or an integer in \[2, \d+\], got 'AUTO'$"),
    ],
)
@pytest.mark.parametrize("fn, args, kwargs", SOLVERS, ids=lambda v: getattr(v, "__name__", ""))
def test_solver_options(fn, args, kwargs, option, value, message):
    with pytest.raises(ValueError, match=message):
        fn(*args, **kwargs, **{option: value})


@pytest.mark.parametrize("fn, args, kwargs", SOLVERS, ids=lambda v: getattr(v, "__name__", ""))
def test_numpy_float_tolerance_is_accepted(fn, args, kwargs):
    """np.float32(1e-10) was refused as 'tol must be in [1e-15, 1e-2)'."""
    assert np.all(fn(*args, **kwargs, tol=np.float32(1e-10)).converged)


def test_fixed_n_too_small_says_so():
    with pytest.raises(
        ConvergenceError,
        match=r"n = 16 nodes are too few for tol; try "
        r"n='auto'$",
    ):
        lc.sliding_initiation(0.01, 0.5, method="collocation", n=16)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"load": 1.0, "method": "x"}, r"^method must be 'closed-form' or 'collocation', got 'x'$"),
        (
            {"load": 1.0, "method": "collocation"},
            r"^the contact for a given load is found by the "
            r"closed form",
        ),
        ({"contact_half_width": 3e-9, "branch": "x"}, r"^branch must be 'stable' or 'unstable'"),
        (
            {"contact_half_width": 3e-9, "branch": "unstable"},
            r"^branch applies to a given load "
            r"only",
        ),
    ],
)
def test_cylinder_contact_options_are_never_ignored(kwargs, message):
    """method was ignored for a load, branch for a half-width."""
    with pytest.raises(ValueError, match=message):
        CYL.contact(**kwargs)


# --- huge and tiny parameters: correct, or refused; never an overflow or a silent zero ---


def _eq14(rho, s):
    """Eq. 14 as printed, in 60-digit decimal arithmetic (an independent reference)."""
    from decimal import Decimal, getcontext

    getcontext().prec = 60
    pi = Decimal("3.14159265358979323846264338327950288419716939937510582097494")
    ln2 = Decimal(2).ln()
    rho, s = Decimal(rho), Decimal(s)
    k = (pi / ln2) ** 2 / 8 / rho
    return float(8 * ln2 / pi * rho * s * (s - (s * s + k).sqrt()))


def test_zero_width_load_at_the_edges_of_its_domain():
    """s^2 overflowed for sigma0/E = 1e300 and Eq. 14 came out as -0.0; now the domain
    ends at sigma0/E = 1e6, R/h = 1e12, where Eq. 14 is near its limit, and beyond it the
    input is refused."""
    limit = -np.pi / (2 * np.log(2.0))  # sigma0/E -> inf at fixed R/h
    for rho, s in [(100.0, 1e6), (1e12, 0.01), (100.0, 1e-300), (1e-3, 1e6), (1e12, 1e6)]:
        assert lc.zero_width_load(rho, s) == pytest.approx(_eq14(rho, s), rel=1e-13)
    assert lc.zero_width_load(1e12, 1e6) == pytest.approx(limit, rel=1e-9)
    with pytest.raises(ValueError, match=r"^sigma0_over_E must be in \[0, 1e\+06\], got 1e\+300$"):
        lc.zero_width_load(100.0, 1e300)
    with pytest.raises(ValueError, match=r"^R_over_h must be in \[0.001, 1e\+12\], got 1e\+300$"):
        lc.zero_width_load(1e300, 0.01)


def test_non_contact_at_the_edge_of_its_domain():
    # g0/h = 0.5: 1 - g0/h = (R/h)(C^2/2 + k C), k = 4 ln2 (sigma0/E)/pi, C = c/R, solved in
    # 60-digit decimals
    from decimal import Decimal, getcontext

    getcontext().prec = 60
    rho, s = Decimal(100), Decimal(10) ** 6
    pi = Decimal("3.14159265358979323846264338327950288419716939937510582097494")
    k = 4 * Decimal(2).ln() * s / pi
    c = -k + (k * k + 2 * Decimal("0.5") / rho).sqrt()
    expected = float(-2 * s * rho * c)
    assert lc.non_contact(0.5, 100.0, 1e6).F_over_Eh == pytest.approx(expected, rel=1e-12)
    with pytest.raises(ValueError, match=r"^sigma0_over_E must be in \[0, 1e\+06\]"):
        lc.non_contact(0.5, 100.0, 1e300)


@pytest.mark.parametrize(
    "fn, args, message",
    [
        (lc.hertz_load, (1e300, 100.0), r"^a_over_R must be in \[1e-150, 10\], got 1e\+300$"),
        (lc.jkr_load, (1e300, 100.0, 0.01), r"^a_over_R must be in \[1e-150, 10\]"),
        (lc.kappa, (1e300, 1e300), r"^R_over_h must be in \[0.001, 1e\+12\], got 1e\+300$"),
        (
            lc.adhesion_from_work,
            (1e300, 3e-10),
            r"^work_of_adhesion must be in \[1e-100, 1e\+100\], got 1e\+300$",
        ),
        (
            lc.adhesion_from_work,
            (1e-300, 1e-10),
            r"^work_of_adhesion must be in \[1e-100, 1e\+100\], got 1e-300$",
        ),
    ],
)
def test_inputs_beyond_the_domain_are_refused(fn, args, message):
    with pytest.raises(ValueError, match=message):
        fn(*args)


_KAPPA = (
    r"kappa = \(4/pi\) sigma0_over_E sqrt\(2 {}\) must be <= 1e\+12 \(the range of the "
    r"solvers\), got kappa="
)


@pytest.mark.parametrize(
    "fn, args, rho_name",
    [
        (lc.pull_off, (1e12, 1e6), "R_over_h"),
        (lc.normal_contact, (0.01, 1e12, 1e6), "R_over_h"),
        (lc.contact_for_load, (0.0, 1e12, 1e6), "R_over_h"),
        (lc.equilibria, (-1.0, 1e12, 1e6), "R_over_h"),
        (lc.load_curve, (1e12, 1e6), "R_over_h"),
        (lc.sliding_pull_off, (1e12, 2.0, 1e6), "R_over_h2"),
        (lc.sliding_contact, (0.03, 1e12, 2.0, 1e6), "R_over_h2"),
        (lc.sliding_contact_for_load, (0.5, 1e12, 2.0, 1e6), "R_over_h2"),
    ],
)
def test_kappa_beyond_the_solvers_is_refused(fn, args, rho_name):
    """pull_off(100, 1e300) gave F = -0.0 with overflow warnings; contact_for_load at
    kappa ~ 1e20 a load of -3e12 flagged converged. Inside the domain of R/h and sigma0/E
    kappa still reaches 1.8e12, beyond the solvers' 1e12."""
    with pytest.raises(ValueError, match="^" + _KAPPA.format(rho_name)):
        fn(*args)


def test_kappa_at_the_limit_is_solved():
    s = 1e12 * np.pi / 4 / np.sqrt(2 * 1e12)
    po = lc.pull_off(1e12, s)
    assert po.F_pulloff_over_Eh <= po.F_zero_width_over_Eh < 0
    nc = lc.normal_contact(po.a_over_R_at_minimum, 1e12, s)
    assert nc.F_over_Eh == pytest.approx(po.F_minimum_over_Eh, rel=1e-10)


def test_contact_for_load_at_the_edge_of_its_domain():
    """F/(Eh) = 1e300 came back as a contact carrying 2.4e36, flagged converged. The load's
    domain ends at 1e12, and a load whose contact would be wider than a/R = 10 is refused."""
    r = lc.contact_for_load(7800.0, 100.0, 0.01)  # a/R just below 10
    assert r.converged and r.F_over_Eh == 7800.0 and 9 < r.a_over_R < 10
    with pytest.raises(
        ValueError,
        match=r"^F_over_Eh=1000000000000.0 needs a contact of half-width 112838 radii, "
        r"beyond the domain of the solvers \(at most 10 radii\)$",
    ):
        lc.contact_for_load(1e12, 100.0, 0.01)
    with pytest.raises(ValueError, match=r"^F_over_Eh must be in \[-1e\+12, 1e\+12\]"):
        lc.contact_for_load(1e300, 100.0, 0.01)


# --- no RuntimeWarning escapes for any positive input (pytest turns them into errors) ---


def test_tiny_contact_width_closed_form_is_silent():
    """a/R = 1e-300 gave the right load (Eq. 14) with a divide-by-zero RuntimeWarning; the
    domain now starts at 1e-150."""
    r = lc.normal_contact(1e-150, 100.0, 0.01)
    assert r.F_over_Eh == pytest.approx(lc.zero_width_load(100.0, 0.01), rel=1e-12)
    assert not r.stable  # narrower than the load minimum (one definition, see below)


def test_tiny_widths_by_collocation():
    """At a/R = 1e-150 the normal collocation agrees with the closed form; the sliding
    problem's domain starts at 1e-20, where both of its solvers still converge."""
    col = lc.normal_contact(1e-150, 100.0, 0.01, method="collocation")
    assert col.converged and col.c_over_R == pytest.approx(
        lc.normal_contact(1e-150, 100.0, 0.01).c_over_R, rel=1e-12
    )
    col = lc.sliding_contact(1e-20, 100.0, 2.0, 0.01, method="collocation")
    cf = lc.sliding_contact(1e-20, 100.0, 2.0, 0.01, method="closed-form")
    assert col.converged and cf.converged
    assert col.F_over_Eh2 == pytest.approx(cf.F_over_Eh2, rel=1e-12)


def test_thin_zones_beyond_the_collocation_say_so():
    """An adhesive zone of c/a - 1 ~ 1e-9 needs more than n = 2048 nodes."""
    args = (1.6596315985408394, 21153758.746772554, 7.749102910688328)
    with pytest.raises(ConvergenceError, match=r"the adhesive zone is too thin"):
        lc.normal_contact(*args, method="collocation")
    assert not lc.normal_contact(*args, method="collocation", on_failure="report").converged
    assert lc.normal_contact(*args).converged  # the closed form is exact there


@pytest.mark.parametrize(
    "fn, args, message",
    [
        (lc.normal_contact, (100.0, 0.01), r"^a_over_R must be in \[1e-150, 10\]"),
        (lc.sliding_contact, (100.0, 2.0, 0.01), r"^a_over_R must be in \[1e-20, 10\]"),
    ],
)
@pytest.mark.parametrize("a_over_R", [1e-300, 1e300, 11.0])
def test_widths_beyond_the_domain_are_refused(fn, args, message, a_over_R):
    with pytest.raises(ValueError, match=message):
        fn(a_over_R, *args)


@pytest.mark.parametrize("fn", [lc.sliding_initiation, lc.steady_rolling])
def test_newton_on_the_stick_zone_is_silent_at_its_end(fn):
    """A load of 1e-300 puts d at a, where dT/dd is infinite: divide-by-zero warning."""
    with pytest.raises(ConvergenceError, match=r"use method='closed-form'$"):
        fn(0.01, T_over_Ea=1e-300, method="collocation")


# --- the distribution methods: positions checked, one shape rule, no overflow ---

_R = {
    "normal/collocation": lambda: lc.normal_contact(0.01, 100.0, 0.01, method="collocation"),
    "normal/vector": lambda: lc.normal_contact([0.01, 0.02], 100.0, 0.01),
    "initiation/collocation": lambda: lc.sliding_initiation(0.01, 0.5, method="collocation"),
    "rolling/vector": lambda: lc.steady_rolling(0.01, [0.2, 0.5], method="collocation"),
    "cattaneo-mindlin": lambda: lc.sliding_initiation_coulomb(0.3, 0.01, 0.5),
    "carter": lambda: lc.steady_rolling_coulomb(0.3, 0.01, [0.2, 0.5]),
    "sliding/vector": lambda: lc.sliding_contact(
        [0.03, 0.05], 100.0, 2.0, 0.01, method="closed-form"
    ),
}
_METHODS = [
    (k, m)
    for k, m in [
        ("normal/collocation", "pressure"),
        ("normal/vector", "pressure"),
        ("initiation/collocation", "traction"),
        ("initiation/collocation", "slip"),
        ("rolling/vector", "traction"),
        ("cattaneo-mindlin", "traction"),
        ("carter", "traction"),
        ("sliding/vector", "pressure"),
        ("sliding/vector", "gap"),
    ]
]


def _method(key, name):
    r = _R[key]()
    return r, getattr(r, name), "x_over_a" if name in ("traction", "slip") else "x_over_R"


@pytest.mark.parametrize("key, name", _METHODS)
@pytest.mark.parametrize(
    "x, message",
    [
        (np.nan, "must be a finite number, got nan$"),
        (np.inf, "must be a finite number, got inf$"),
        (None, "must be a real number or an array of them, got None$"),
        (True, "must be a real number or an array of them, got True$"),
        ([], "must not be empty$"),
        (
            np.zeros((1, 1, 3)),
            r"must have shape \(m,\) or broadcast to the points' shape plus one "
            r"axis, \(.*\), got shape \(1, 1, 3\)$",
        ),
    ],
)
def test_distribution_positions_are_checked(key, name, x, message):
    """NaN positions gave 0 or nan silently; a 0-d position gave TypeError (collocation
    pressure) or 'cannot reshape array of size 4 into shape (2,)' (gap)."""
    _, method, xname = _method(key, name)
    with pytest.raises(ValueError, match=f"^{xname} {message}"):
        method(x)


@pytest.mark.parametrize("key, name", _METHODS)
def test_distribution_of_one_position(key, name):
    """A single position is m = 1: shape points.shape + (1,), as for the closed forms."""
    r, method, _ = _method(key, name)
    points = np.shape(getattr(r, "a_over_R", None) if name in ("pressure", "gap") else r.d_over_a)
    one = method(0.001)
    assert one.shape == points + (1,)
    # to rounding: a scalar and an array may take different SIMD paths
    np.testing.assert_allclose(one, method(np.array([0.001])), rtol=1e-14, atol=1e-300)


@pytest.mark.parametrize("key, name", [(k, m) for k, m in _METHODS if m != "gap"])
def test_distribution_far_outside_the_contact_is_silent(key, name):
    """x*x overflowed (RuntimeWarning) at |x| = 1e300; the value there is 0 (nan for slip)."""
    _, method, _ = _method(key, name)
    v = method(np.array([-1e300, 1e300]))
    assert np.all((v == 0) | np.isnan(v))


def test_gap_beyond_the_floating_point_range_is_refused():
    with pytest.raises(
        ValueError,
        match=r"^the gap is beyond the floating-point range at "
        r"x_over_R=1e\+300$",
    ):
        _R["sliding/vector"]().gap(np.array([0.5, 1e300]))


@pytest.mark.parametrize("ratio", [1e-300, 1e-4, 1e4, 1e12])
def test_sliding_ranges_far_from_equal_are_refused(ratio):
    """h1/h2 = 1e-300 or 1e12 overflowed through RuntimeWarnings to values that jumped about
    as the ratio changed (unverified, and one of them pinned by a test that failed on
    another machine): outside [1e-3, 1e3] the ratio is refused."""
    with pytest.raises(ValueError, match=r"^h1_over_h2 must be in \[0.001, 1000\], got "):
        lc.sliding_pull_off(100.0, ratio, 0.01)
    with pytest.raises(ValueError, match=r"^h1_over_h2 must be in \[0.001, 1000\], got "):
        lc.sliding_contact_for_load(0.5, 100.0, ratio, 0.01, method="closed-form")


@pytest.mark.parametrize("ratio", [1e-3, 1e3])
def test_sliding_at_the_edges_of_the_ratio_domain(ratio):
    # the pull-off is the minimum of the load over a dense grid of widths, and the two
    # solvers agree there
    po = lc.sliding_pull_off(100.0, ratio, 0.01)
    a = np.geomspace(1e-6, 0.2, 400)
    F = lc.sliding_contact(a, 100.0, ratio, 0.01, method="closed-form").F_over_Eh2
    assert po.F_pulloff_over_Eh2 <= F.min() * (1 - 1e-12)
    assert F.min() - po.F_pulloff_over_Eh2 <= 1e-3 * abs(po.F_pulloff_over_Eh2)
    col = lc.sliding_contact(0.05, 100.0, ratio, 0.01, method="collocation")
    cf = lc.sliding_contact(0.05, 100.0, ratio, 0.01, method="closed-form")
    assert col.F_over_Eh2 == pytest.approx(cf.F_over_Eh2, rel=1e-9)
    assert col.c1_over_R == pytest.approx(cf.c1_over_R, rel=1e-9)


# --- the Gauss-Chebyshev core ---


@pytest.mark.parametrize("interval", [("a", 1.0), None, (1.0, 2.0, 3.0), 5.0])
def test_sie_interval_must_be_a_pair(interval):
    """("a", 1) gave "could not convert string to float", None a TypeError."""
    from linecontact.sie import BoundedSolver

    with pytest.raises(ValueError, match=r"^interval must be a pair \(lo, hi\) of real numbers"):
        BoundedSolver(4, interval)


@pytest.mark.parametrize(
    "solve, message",
    [
        (
            lambda s: s.BoundedSolver(4).solve(1.0),
            r"^f must have n \+ 1 = 5 values on its last "
            r"axis, got a scalar$",
        ),
        (lambda s: s.BoundedSolver(4).solve(None), r"^f must have n \+ 1 = 5 .* got a scalar$"),
        (lambda s: s.EndBoundedSolver(4).solve(1.0), r"^f must have n = 4 values .* got a scalar$"),
        (
            lambda s: s.UnboundedSolver(4).solve(1.0, 0.0),
            r"^f must have n - 1 = 3 values .* got a "
            r"scalar$",
        ),
        (
            lambda s: s.UnboundedSolver(4).solve(np.zeros((2, 3)), np.zeros(3)),
            r"^resultant must broadcast to the batch shape of f, \(2,\), got shape \(3,\)$",
        ),
        (
            lambda s: s.BoundedSolver(4).solve(np.ones(5), extra=np.zeros(5)),
            r"^extra must have a non-zero mean over the collocation points",
        ),
        (lambda s: s.chebyshev_log_expansion(0.5, "3"), r"^kmax must be an integer >= 0, got '3'$"),
    ],
)
def test_sie_right_hand_sides(solve, message):
    """A scalar f raised IndexError: tuple index out of range; an extra right-hand side of
    zero mean gave nan with an 'invalid value' warning."""
    from linecontact import sie

    with pytest.raises(ValueError, match=message):
        solve(sie)


def test_cylinder_load_below_pull_off_is_said_in_newton_per_metre():
    """The SI layer said 'no contact carries F_over_Eh=-2.0' for a load of -100 N/m."""
    with pytest.raises(
        NoEquilibriumError,
        match=r"^no contact carries load=-100.0 N/m: it is "
        r"below the pull-off force, the minimum load "
        r"on the contact branch -13.287\d* N/m",
    ):
        CYL.contact(load=[1.0, -100.0])
    # and the tangential functions name their own parameter
    with pytest.raises(NoEquilibriumError, match=r"^no contact carries normal_load=-50.0 N/m"):
        CYL.steady_rolling(-50.0, friction_stress=1e8, d_over_a=0.1)


def test_si_inputs_outside_the_validated_domain_are_named_in_si():
    # E h = 50 N/m, R = 50 nm: F/(Eh) in [-1e12, 1e12] is F in [-5e13, 5e13] N/m
    with pytest.raises(
        ValueError,
        match=r"^load must be in \[-5e\+13, 5e\+13\] N/m \(-1e\+12 to 1e\+12 times the modulus "
        r"times the adhesion range, the domain of the solvers\), got 1e\+20$",
    ):
        CYL.contact(load=[1.0, 1e20])
    with pytest.raises(ValueError, match=r"^normal_load must be in \[-5e\+13, 5e\+13\] N/m"):
        CYL.steady_rolling(1e20, friction_stress=1e8, d_over_a=0.1)
    # a load inside that range whose contact is wider than 10 radii (Hertz: 3.9e5 N/m)
    with pytest.raises(
        ValueError,
        match=r"^normal_load=1000000\.0 N/m needs a contact of half-width 7\.979\d*e-07 m, "
        r"15\.9\d* radii: beyond the domain of the solvers \(at most 10 radii\)$",
    ):
        CYL.steady_rolling(1e6, friction_stress=1e8, d_over_a=0.1)
    with pytest.raises(ValueError, match=r"^load=1000000\.0 N/m needs a contact"):
        CYL.contact(load=1e6)
    with pytest.raises(
        ValueError,
        match=r"^contact_half_width must be in \[5e-158, 5e-07\] m \(1e-150 to 10 radii, the "
        r"domain of the solvers\), got 1e-06$",
    ):
        CYL.contact(contact_half_width=[1e-9, 1e-6])
    # the groups of the cylinder itself
    with pytest.raises(
        ValueError,
        match=r"^radius / adhesion_range must be in \[0\.001, 1e\+12\] \(the domain of the "
        r"solvers\), got radius=1\.0 m, adhesion_range=1e-15 m; is the radius in metres\?$",
    ):
        Cylinder.from_modulus(1.0, 1e11, cohesive_stress=1e9, adhesion_range=1e-15)
    with pytest.raises(
        ValueError,
        match=r"^cohesive_stress=1000000000\.0 Pa must be at most 1e\+06 times the modulus, "
        r"1e\+08 Pa here, got modulus=100\.0 Pa \(the domain of the solvers\); is the "
        r"modulus in Pa\?$",
    ):
        Cylinder.from_modulus(5e-8, 100.0, cohesive_stress=1e9, adhesion_range=5e-10)
