r"""A wire bent on its substrate by friction: the shape that friction holds it in.

The measurement behind most nanowire friction numbers (issue 35): a wire dragged or pushed
on the substrate, imaged, and the friction per unit length inferred from its shape. This
package holds the forward models, in the groups of the elastica (lengths over the half
length :math:`l`, the friction over :math:`EI/l^3`):

- :func:`dragged_wire` -- a wire dragged at its midpoint, the kinetic case: each half a
  cantilever under the uniform dead load of friction, at large deflection.

The inversion from a measured profile, the other end conditions and the static case are
not written yet (``docs/bent-wire.md``).
"""

from __future__ import annotations

from .elastica import DraggedWire, dragged_wire
from .sections import bending_stiffness, second_moment_of_area
from .static import NormalFriction, StaticWire, normal_friction_from_curvature, static_wire

__all__ = ["DraggedWire", "dragged_wire"]
__all__ += ["bending_stiffness", "second_moment_of_area"]
__all__ += ["NormalFriction", "StaticWire", "normal_friction_from_curvature", "static_wire"]
