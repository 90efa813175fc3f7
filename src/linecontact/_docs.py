"""Parameter documentation that several solvers share, written once.

A docstring names a shared block by a line ``%(name)s`` alone; :func:`shared_docs` puts the
block there, indented as that line (as lmfit's ``COMMON_INIT_DOC`` and SciPy's
``%(before_notes)s`` do). Only such whole lines are replaced, so a docstring may hold any
other ``%`` as it is.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TypeVar

__all__ = ["COLLOCATION", "shared_docs"]

#: The collocation size, its tolerance and the failure policy of the normal and sliding
#: solvers of given widths.
COLLOCATION = """\
n : int or "auto"
    Collocation nodes (``"auto"``: chosen per point for ``tol``).
tol : float
    Target discretisation error of the collocation solver.
on_failure : {"raise", "report"}
    A point that misses its tolerance raises
    :class:`~linecontact.errors.ConvergenceError` (``"raise"``, default), or is
    flagged in ``converged`` (``"report"``); README, "Conventions"."""

_BLOCKS = {"COLLOCATION": COLLOCATION}
_LINE = re.compile(r"^( *)%\((\w+)\)s$", re.M)

F = TypeVar("F", bound=Callable[..., object])


def shared_docs(fn: F) -> F:
    """``fn`` with each line ``%(NAME)s`` of its docstring replaced by the block ``NAME``."""

    def block(m: re.Match[str]) -> str:
        indent, name = m.groups()
        return "\n".join(indent + line if line else line for line in _BLOCKS[name].splitlines())

    if fn.__doc__:
        fn.__doc__ = _LINE.sub(block, fn.__doc__)
    return fn
