r"""A wire bent on its substrate by friction: the shape that friction holds it in.

The measurement behind most nanowire friction numbers (issue 35): a wire dragged or pushed
on the substrate, imaged, and the friction per unit length inferred from its shape. This
package holds the forward models, in the groups of the elastica (lengths over the half
length :math:`l`, the friction over :math:`EI/l^3`):

- :func:`dragged_wire` -- a wire dragged at its midpoint, the kinetic case: each half a
  cantilever under the uniform dead load of friction, at large deflection;
- :func:`static_wire` -- a wire held at rest by friction normal to it (the static case),
  the rod integrated from a free end; :func:`normal_friction_from_curvature`, the exact
  inversion :math:`f_n = EI(\kappa'' + \kappa^3/2)` of a shape;
- :func:`bending_stiffness` -- :math:`EI` of the cross-section: round, a tube, a rounded
  regular polygon (:mod:`.sections`);
- :func:`fit_bent_wire` -- the friction per unit length from a measured profile, by
  orthogonal least squares over the whole profile, with its covariance and bootstrap
  intervals (:mod:`.fit`).

The shear strength :math:`\tau_0 = f/(2a)` with the library's contact width is
:func:`linecontact.inverse.shear_strength_from_bent_wire` (the SI layer); the derivations
are in ``docs/bent-wire.md``.
"""

from __future__ import annotations

from .elastica import DraggedWire, dragged_wire
from .fit import MODELS, BentWireFit, fit_bent_wire
from .sections import bending_stiffness, bending_stiffness_sd, second_moment_of_area
from .static import NormalFriction, StaticWire, normal_friction_from_curvature, static_wire

__all__ = [
    "MODELS",
    "BentWireFit",
    "DraggedWire",
    "NormalFriction",
    "StaticWire",
    "bending_stiffness",
    "bending_stiffness_sd",
    "dragged_wire",
    "fit_bent_wire",
    "normal_friction_from_curvature",
    "second_moment_of_area",
    "static_wire",
]
