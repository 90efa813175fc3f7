"""Deprecated: the closed forms live in :mod:`linecontact.closed_forms`.

``linecontact.reference`` re-exports the public names of :mod:`linecontact.closed_forms`
(``hertz_load``, ``jkr_load``, ``zero_width_load``, ``kappa``, ``maugis_parameter``, ...) with
a :class:`DeprecationWarning`; the library itself imports from :mod:`linecontact.closed_forms`
and never loads this module.
"""

from __future__ import annotations

import warnings
from typing import Any

from . import closed_forms as _closed_forms

__all__ = list(_closed_forms.__all__)


def __getattr__(name: str) -> Any:
    if name in _closed_forms.__all__:
        warnings.warn(
            "linecontact.reference is deprecated; use linecontact.closed_forms",
            DeprecationWarning,
            stacklevel=2,
        )
        return getattr(_closed_forms, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *__all__])
