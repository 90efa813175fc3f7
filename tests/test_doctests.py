"""The examples in the docstrings of every module of the installed package run and agree."""

import doctest
import importlib
import pkgutil

import numpy as np
import pytest

import linecontact

MODULES = sorted(
    m.name
    for m in pkgutil.walk_packages(linecontact.__path__, "linecontact.")
    if not m.name.endswith("__main__")
)


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    with np.printoptions(legacy="1.25"):
        result = doctest.testmod(
            module,
            optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE,
            report=True,
            verbose=False,
        )
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {name}"


def test_the_examples_are_many():
    # the modules that carry examples keep them: a walk that found nothing would pass above
    total = 0
    for name in MODULES:
        finder = doctest.DocTestFinder()
        total += sum(len(t.examples) for t in finder.find(importlib.import_module(name)))
    assert total >= 40
