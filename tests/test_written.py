"""The Python lines of a computation (operations/_written.py): written from the calls made.

Each line is the library call an operation made, so running the lines gives the operation's
own numbers (bit for bit here: the same calls in the same process); every number is written
so that it reads back exactly; a computation on the groups writes nothing. The pages show
these lines (tests/test_web_pages.py runs them against the API in a browser); the API gives
them on ``Prefer: python``.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import linecontact as lc
from linecontact import operations
from linecontact.geometry import Polygon
from linecontact.operations._declare import Inputs
from linecontact.operations._written import _float, _value, python

WIRE = {"radius": 5e-8, "modulus": 4.8e10, "work_of_adhesion": 0.3, "z0": 3e-10}
PRESETS = {
    "radius": 5e-8,
    "cylinder_material": "ZnO",
    "substrate_material": "SiO2",
    "work_of_adhesion": 0.3,
    "z0": 3e-10,
}
FOUR = {"E1": 1.24e11, "nu1": 0.36, "E2": 7.2e10, "nu2": 0.17}


def _run(command: str, values: dict) -> tuple[dict, str]:
    op = operations.get(command)
    typed = {op.parameter(k).name: op.parameter(k).convert(v, k) for k, v in values.items()}
    inputs = Inputs(op, typed)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        table = op.run(inputs)
    return table.columns, python(inputs)


def _exec(code: str) -> dict:
    space: dict = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exec(compile(code.replace("print(result)", ""), "<lines>", "exec"), space)
    return space


CASES = [
    ("pulloff", PRESETS, [("pull_off_force", "F_pulloff_N_per_m")]),
    ("pulloff", {**WIRE, "length": 5e-6}, [("pull_off_force", "F_pulloff_N_per_m")]),
    (
        "pulloff",
        {"radius": 8e-8, **FOUR, "sigma0": 2e8, "h": 1e-9},
        [
            ("pull_off_force", "F_pulloff_N_per_m"),
            ("contact_half_width_at_pull_off", "a_at_pulloff_m"),
        ],
    ),
    (
        "pulloff",
        {**WIRE, "cross_section": "hexagon", "corner_radius": 5e-9},
        [("pull_off_force", "F_pulloff_N_per_m")],
    ),
    ("pulloff", {**WIRE, "law": "lennard-jones"}, [("pull_off_force", "F_pulloff_N_per_m")]),
    ("normal", {**PRESETS, "load": [0, 1, 5]}, [("contact_half_width", "a_m")]),
    (
        "normal",
        {**WIRE, "cross_section": "square", "load": [0.5, 2]},
        [("contact_half_width", "a_m")],
    ),
    ("curve", WIRE, [("load", "F_N_per_m"), ("contact_half_width", "a_m")]),
    ("curve", {**WIRE, "a_max": 2e-8, "num": 30}, [("load", "F_N_per_m")]),
    (
        "cycle",
        {**WIRE, "load": 1, "tau0": 1e7, "tangential_amplitude": [0.01, 0.04]},
        [("energy_per_cycle", "W_J_per_m")],
    ),
    (
        "history",
        {**WIRE, "load": 1, "tau0": 1e7, "tangential_load": [0.01, -0.02, 0.03]},
        [("displacement", "displacement_m"), ("dissipation", "dissipation_J_per_m")],
    ),
    (
        "push",
        {
            **WIRE,
            "work_of_adhesion_receding": 0.6,
            "tau0": 1e7,
            "height": [1e-8, 5e-8, 9e-8],
        },
        [("rolling_resistance", "Q_roll_N_per_m"), ("sliding_resistance", "Q_slide_N_per_m")],
    ),
    (
        "push",
        {
            "radius": 5e-8,
            "modulus": 4.8e10,
            "sigma0": 1e8,
            "h2": 3e-10,
            "h1": 6e-10,
            "tau0": 1e7,
            "tip_height": [2e-8, 6e-8],
            "tip_friction": 0.3,
        },
        [("rolling_resistance", "Q_roll_N_per_m")],
    ),
]


@pytest.mark.parametrize(("command", "values", "pairs"), CASES)
def test_the_lines_give_the_operations_numbers(command, values, pairs):
    columns, code = _run(command, values)
    assert code.startswith("import linecontact as lc\ncyl = lc.Cylinder.from_")
    assert code.endswith("print(result)")
    space = _exec(code)
    for attr, key in pairs:
        got = np.ravel(np.asarray(getattr(space["result"], attr), float))
        want = np.asarray(columns[key], float)
        np.testing.assert_allclose(got, want, rtol=1e-12, err_msg=f"{command} {attr}")


def test_the_lines_say_the_shape_and_the_law_and_the_presets():
    _, hexagon = _run("pulloff", {**WIRE, "cross_section": "hexagon", "corner_radius": 5e-9})
    assert "cyl = cyl.shaped(lc.Polygon(sides=6, corner_radius=5e-9))" in hexagon
    _, lj = _run("pulloff", {**WIRE, "law": "lennard-jones"})
    assert "cyl = cyl.under(lc.LennardJones)" in lj
    _, presets = _run("pulloff", PRESETS)
    assert "from_materials(5e-8, 1.24e11, 0.36, " in presets
    assert "# the presets' moduli: ZnO (E1, nu1), SiO2 (E2, nu2)" in presets
    _, four = _run("pulloff", {"radius": 5e-8, **FOUR, "work_of_adhesion": 0.3, "z0": 3e-10})
    assert "presets" not in four  # numbers typed are not a preset's


def test_the_fit_writes_its_data_into_the_lines(tmp_path):
    data = tmp_path / "pulloffs.csv"
    data.write_text("radius_nm,pull_off_force_N_per_m\n20,-2.9\n50,-4.6\n100,-6.4\n")
    columns, code = _run(
        "fit-adhesion",
        {"cylinder_material": "SiO2", "substrate_material": "Si", "z0": 3e-10, "data": str(data)},
    )
    # the radii as the file gave them, in metres (50 nm is 5.0000000000000004e-8 m)
    radii = "[2e-8, 5.0000000000000004e-8, 1.0000000000000001e-7]"
    assert f"result = lc.fit_pull_off({radii}, [-2.9, -4.6, -6.4], " in code
    assert str(tmp_path) not in code
    space = _exec(code)
    assert space["result"].work_of_adhesion == pytest.approx(columns["work_of_adhesion"][0])


def test_a_computation_on_the_groups_writes_nothing():
    columns, code = _run("pulloff", {"R_over_h": 100, "sigma0_over_E": 0.01})
    assert code == "" and columns["F_pulloff_over_Eh"][0] < 0


def test_a_refused_call_writes_no_result_line():
    op = operations.get("pulloff")
    inputs = Inputs(op, {"radius": -5e-8, "modulus": 4.8e10, "sigma0": 1e9, "h": 3e-10})
    with pytest.raises(ValueError, match="radius"):
        op.run(inputs)
    assert not any(call.name == "result" for call in inputs.python)


# ------------------------------------------------------------------------------------------
# numbers and values, written so that they read back


@given(st.floats(allow_nan=False, allow_infinity=False))
@settings(max_examples=500, deadline=None)
def test_a_float_reads_back_exactly(x):
    text = _float(x)
    assert float(text) == x and math.copysign(1, float(text)) == math.copysign(1, x)
    assert "+" not in text and "e-0" not in text  # 5e-8, not 5e-08
    assert len(text) <= len(repr(x))  # never longer than Python's own


@pytest.mark.parametrize(
    ("x", "text"),
    [(5e-8, "5e-8"), (1.24e11, "1.24e11"), (0.36, "0.36"), (1.0, "1.0"), (100.0, "100.0"),
     (1e7, "1e7"), (-0.0, "-0.0"), (2052800957.1186697, "2052800957.1186697")],
)  # fmt: skip
def test_a_float_as_a_person_writes_it(x, text):
    assert _float(x) == text


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (None, "None"),
        (True, "True"),
        ("hexagon", "'hexagon'"),
        (3, "3"),
        (np.float64(0.25), "0.25"),
        (np.array([1.0, 2e-9]), "[1.0, 2e-9]"),
        (np.array([[1, 2], [3, 4]]), "[[1, 2], [3, 4]]"),
        ((0.5,), "(0.5,)"),
        (float("inf"), "float('inf')"),
        (float("nan"), "float('nan')"),
        (Polygon(4, 0.0), "lc.Polygon(sides=4, corner_radius=0.0)"),
        (lc.LennardJones, "lc.LennardJones"),
    ],
)
def test_a_value_as_python(value, text):
    assert _value(value) == text
    if "lc." not in text:
        back = eval(text)  # noqa: S307 - the text written above, nothing else
        assert repr(back) == repr(value.tolist() if hasattr(value, "tolist") else value)


def test_a_value_with_no_python_spelling_is_refused():
    with pytest.raises(TypeError, match="no Python line for a value of type object"):
        _value(object())


def test_the_lines_are_written_only_where_asked_for():
    pytest.importorskip("starlette")
    from linecontact.web._workers import compute

    values = {"radius": 5e-8, "modulus": 4.8e10, "work_of_adhesion": 0.3, "z0": 3e-10}
    assert compute("pulloff", values).python == ""  # the API's own answer: none written
    lines = compute("pulloff", values, python=True).python
    assert lines.startswith("import linecontact as lc\ncyl = lc.Cylinder.from_modulus(5e-8")
