"""The one table of moved names (``linecontact._moved``, issue 32): before 1.0 a name is deleted.

Every entry comes off the table at its version: this file fails once the package's version
reaches it. A deleted name's error names its replacement, however it is reached (an attribute,
``from ... import``, ``import``); a name kept one more version gives the new object with one
``DeprecationWarning`` naming it.
"""

from __future__ import annotations

import importlib
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest

import linecontact
from linecontact._moved import MOVED, MovedNameError, _target
from linecontact._version import __version__

#: Methods of the Cylinder deleted (a law is the cylinder's value, not a method's prefix).
METHODS = sorted(old for old in MOVED if old.startswith("linecontact.Cylinder."))
DELETED = sorted(old for old, moved in MOVED.items() if not moved.works and old not in METHODS)
KEPT = sorted(old for old, moved in MOVED.items() if moved.works)


def _version(text: str) -> tuple[int, ...]:
    """``"0.2.0"`` (or ``"0.3.0.dev1"``, ``"1.0rc1"``) as ``(0, 2, 0)``: its release part."""
    m = re.match(r"\d+(\.\d+)*", text)
    assert m, text
    return tuple(int(p) for p in m.group().split("."))


def test_the_version_reader():
    assert _version("0.2.0") == (0, 2, 0)
    assert _version("0.3.0.dev4") == (0, 3, 0)
    assert _version("1.0rc1") == (1, 0)
    assert _version("1.0.0") >= _version("1.0")


@pytest.mark.parametrize("old", sorted(MOVED))
def test_no_entry_outlives_its_version(old):
    moved = MOVED[old]
    assert _version(__version__) < _version(moved.until), (
        f"linecontact {__version__} has reached {moved.until}, the version that removes "
        f"{old} from linecontact._moved.MOVED: take the entry off the table (and a name "
        "that still works: delete it, or keep it one more version as an error naming "
        f"{moved.new})"
    )


@pytest.mark.parametrize("old", sorted(MOVED))
def test_each_entry_names_a_real_object(old):
    moved = MOVED[old]
    assert moved.new.startswith("linecontact.") and moved.new != old
    assert _target(moved.new) is not None
    # a moved name is in no __all__ (nor in the API reference built from it), a moved
    # method on no class
    module, _, name = old.rpartition(".")
    if old in METHODS:
        assert name not in dir(linecontact.Cylinder)
        return
    assert name not in getattr(importlib.import_module(module), "__all__", ())


@pytest.mark.parametrize("old", METHODS)
def test_a_deleted_method_names_its_replacement(old):
    cyl = linecontact.Cylinder.from_modulus(
        50e-9, 100e9, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9
    )
    name = old.rpartition(".")[2]
    with pytest.raises(
        MovedNameError,
        match=rf"^{re.escape(old)} .*LennardJones.* use {re.escape(MOVED[old].new)}$",
    ):
        getattr(cyl, name)
    # the replacement gives what the method gave: the cylinder's adhesion under the law
    method = MOVED[old].new.rpartition(".")[2]
    kwargs = {"contact": {"load": 0.5}, "load_curve": {}}.get(method, {})
    got = getattr(cyl.under(linecontact.LennardJones), method)(**kwargs)
    assert type(got).__name__.startswith("CylinderLennardJones")


def _parts(old: str) -> tuple[object, str]:
    module, _, name = old.rpartition(".")
    return importlib.import_module(module), name


@pytest.mark.parametrize("old", DELETED)
def test_a_deleted_name_names_its_replacement(old):
    new = MOVED[old].new
    module, name = _parts(old)
    with pytest.raises(MovedNameError, match=rf"^{re.escape(old)} .* use {re.escape(new)}$"):
        getattr(module, name)
    # "from package import name" keeps the message (an AttributeError would lose it)
    with pytest.raises(ImportError, match=rf"use {re.escape(new)}$"):
        exec(f"from {module.__name__} import {name}", {})
    # "import package.name" too, and "from package.name import x" (a deleted module)
    with pytest.raises(ModuleNotFoundError, match=rf"use {re.escape(new)}$"):
        importlib.import_module(old)
    with pytest.raises(ModuleNotFoundError, match=rf"use {re.escape(new)}$"):
        exec(f"from {old} import x", {})


@pytest.mark.parametrize("old", KEPT)
def test_a_kept_name_warns_once_and_gives_the_new_object(old):
    moved = MOVED[old]
    module, name = _parts(old)
    with pytest.warns(DeprecationWarning) as record:
        got = getattr(module, name)
    (w,) = [w for w in record if w.category is DeprecationWarning]
    assert str(w.message) == f"{old} is deprecated and goes in {moved.until}: use {moved.new}"
    assert w.filename == __file__  # it points at the caller's line
    assert got is _target(moved.new)


def test_the_kept_functions_still_take_the_cylinder_first():
    """``lc.cylinder_steady_rolling(cyl, ...)`` as the README of 0.2.0 taught: same result."""
    cyl = linecontact.Cylinder.from_modulus(
        50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9
    )
    for old, method, kwargs in [
        ("cylinder_steady_rolling", "steady_rolling", {"friction_stress": 1e9}),
        ("cylinder_sliding_initiation", "sliding_initiation", {"friction_stress": 1e9}),
    ]:
        with pytest.warns(DeprecationWarning, match=f"use linecontact.Cylinder.{method}$"):
            fn = getattr(linecontact, old)
        got = fn(cyl, 1.0, tangential_load=[0.5, 1.0], **kwargs)
        with warnings.catch_warnings():
            warnings.simplefilter("error", DeprecationWarning)
            want = getattr(cyl, method)(1.0, tangential_load=[0.5, 1.0], **kwargs)
        np.testing.assert_array_equal(got.stick_zone_end, want.stick_zone_end)


def test_other_names_are_plain_errors():
    with pytest.raises(AttributeError, match="has no attribute 'no_such_name'"):
        linecontact.no_such_name  # noqa: B018
    assert not hasattr(linecontact, "no_such_name")
    assert not hasattr(linecontact.cylinder, "no_such_name")
    with pytest.raises(ModuleNotFoundError, match="No module named 'linecontact.no_such_name'"):
        importlib.import_module("linecontact.no_such_name")


def test_the_table_covers_the_deleted_modules_and_functions():
    # the cylinder_* functions, the module reference: each either works or names its successor
    for old in ("linecontact.reference", "linecontact.cylinder_push"):
        assert old in MOVED
    code = "import sys, linecontact; print('linecontact.reference' in sys.modules)"
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert run.stdout.strip() == "False"
