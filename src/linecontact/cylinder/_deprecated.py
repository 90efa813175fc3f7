"""The ``cylinder_*`` functions: deprecated aliases of the methods of :class:`Cylinder`.

Each warns (``DeprecationWarning``, naming the method) and returns the method's result.
"""

from __future__ import annotations

import warnings
from typing import Any

from ._cylinder import Cylinder
from ._results import (
    CylinderCyclicLoss,
    CylinderPush,
    CylinderTangential,
    CylinderTangentialHistory,
)


def _method(name: str, method: str, cylinder: Any) -> Any:
    """Warn that ``name`` is deprecated for ``Cylinder.method``; the bound method."""
    warnings.warn(
        f"{name} is deprecated: use Cylinder.{method}(...), the same arguments without the "
        "cylinder",
        DeprecationWarning,
        stacklevel=3,
    )
    if not isinstance(cylinder, Cylinder):
        raise ValueError(
            f"cylinder must be a linecontact.Cylinder (Cylinder.from_modulus or "
            f"Cylinder.from_materials), got {cylinder!r}"
        )
    return getattr(cylinder, method)


def cylinder_sliding_initiation(
    cylinder: Cylinder, *args: Any, **kwargs: Any
) -> CylinderTangential:
    """Deprecated: :meth:`Cylinder.sliding_initiation`."""
    return _method("cylinder_sliding_initiation", "sliding_initiation", cylinder)(*args, **kwargs)


def cylinder_steady_rolling(cylinder: Cylinder, *args: Any, **kwargs: Any) -> CylinderTangential:
    """Deprecated: :meth:`Cylinder.steady_rolling`."""
    return _method("cylinder_steady_rolling", "steady_rolling", cylinder)(*args, **kwargs)


def cylinder_push(cylinder: Cylinder, *args: Any, **kwargs: Any) -> CylinderPush:
    """Deprecated: :meth:`Cylinder.push`."""
    return _method("cylinder_push", "push", cylinder)(*args, **kwargs)


def cylinder_tangential_history(
    cylinder: Cylinder, *args: Any, **kwargs: Any
) -> CylinderTangentialHistory:
    """Deprecated: :meth:`Cylinder.tangential_history`."""
    return _method("cylinder_tangential_history", "tangential_history", cylinder)(*args, **kwargs)


def cylinder_cyclic_loss(cylinder: Cylinder, *args: Any, **kwargs: Any) -> CylinderCyclicLoss:
    """Deprecated: :meth:`Cylinder.cyclic_loss`."""
    return _method("cylinder_cyclic_loss", "cyclic_loss", cylinder)(*args, **kwargs)


def cylinder_sliding(cylinder: Cylinder, *args: Any, **kwargs: Any) -> Any:
    """Deprecated: :meth:`Cylinder.sliding`."""
    return _method("cylinder_sliding", "sliding", cylinder)(*args, **kwargs)
