"""The deprecated ``law=`` argument of the normal problem's functions (a law is a module)."""

from __future__ import annotations

import warnings


def _check_law(law: object, where: str, instead: str | None = None, stacklevel: int = 3) -> None:
    """The deprecated ``law=`` of ``where``: a law is a module (:mod:`linecontact.laws`).

    ``"dugdale"`` (the default) is accepted silently; ``"lennard-jones"`` gives a
    ``DeprecationWarning`` naming ``instead`` (default
    ``linecontact.laws.lennard_jones.<where>``); any other value is a ``ValueError``.
    ``stacklevel`` 3 points at the caller of a public function that calls this one.
    """
    if law not in ("dugdale", "lennard-jones"):
        raise ValueError(f"law must be 'dugdale' or 'lennard-jones', got {law!r}")
    if law == "lennard-jones":
        instead = instead or f"linecontact.laws.lennard_jones.{where}"
        warnings.warn(
            f"{where}(law='lennard-jones') is deprecated: use {instead} (a law is a module, "
            "linecontact.laws)",
            DeprecationWarning,
            stacklevel=stacklevel,
        )
