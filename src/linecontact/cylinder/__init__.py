r"""The dimensional (SI) layer: a cylinder on a substrate, and its problems in SI units.

:class:`Cylinder` holds the radius, the composite modulus, the adhesion ``(sigma0, h)`` and
Dundurs' ``beta``; its methods (one per problem) convert SI inputs to the
paper's groups, call the nondimensional solvers (:mod:`linecontact.normal`,
:mod:`linecontact.tangential`) and convert back. Units: lengths [m], stresses and moduli
[Pa], forces per unit length of cylinder [N/m], work of adhesion [J/m^2]. Materials and
adhesion conventions: :mod:`linecontact.materials`.

The package's modules: ``_body.py`` (:class:`Body`: what every body shares, its fields and
factories), ``_sphere.py`` (:class:`Sphere`: an AFM tip, its contact, pull-off and load curve
in N), ``_cylinder.py`` (:class:`Cylinder`: its fields, factories, the
normal problems under either law, the table of the problems written for each law),
``_problems.py`` (the tangential problems, the pushed fibre, the load histories: functions
that are the class's methods, ``self`` the cylinder), ``_sliding.py`` (steady sliding, the
same way), ``_results.py`` (the SI result classes), ``_checks.py`` (the plausible ranges of the
SI inputs and the checks of the widths).
Import from ``linecontact.cylinder``: every name is here.
"""

# the names of the package's modules, the private ones that other modules and the tests
# import included, are re-exported
# ruff: noqa: F401

from __future__ import annotations

from .. import _moved
from ._body import Body
from ._checks import (
    _S_LJ,
    _UNIT_SLIP,
    _ZERO_WIDTH,
    PLAUSIBLE,
    WIDTH_MIN,
    _check_cylinder_si,
    _first,
    _implausible,
    _plausible,
    _units_question,
    _warn_widths,
    _which,
)
from ._cylinder import Cylinder, _si_load_curve
from ._problems import _cylinder_tangential, _full_slip, _history_contact, _history_solve, _scalar
from ._results import (
    CylinderContact,
    CylinderCyclicLoss,
    CylinderLennardJonesContact,
    CylinderLennardJonesLoadCurve,
    CylinderLennardJonesPullOff,
    CylinderLoadCurve,
    CylinderPullOff,
    CylinderPush,
    CylinderSliding,
    CylinderTangential,
    CylinderTangentialHistory,
)
from ._sliding import hysteresis_adhesion, sliding_pull_off_force
from ._sphere import Sphere, SphereContactSI, SphereLoadCurveSI, SpherePullOffSI

__all__ = [
    "Body",
    "Sphere",
    "SphereContactSI",
    "SphereLoadCurveSI",
    "SpherePullOffSI",
    "CylinderPush",
    "PLAUSIBLE",
    "Cylinder",
    "CylinderContact",
    "CylinderLennardJonesContact",
    "CylinderLennardJonesLoadCurve",
    "CylinderLennardJonesPullOff",
    "CylinderLoadCurve",
    "CylinderPullOff",
    "CylinderSliding",
    "CylinderCyclicLoss",
    "CylinderTangential",
    "CylinderTangentialHistory",
]


def __getattr__(name: str) -> object:
    # a name deleted before 1.0 (linecontact._moved): its error names the replacement
    return _moved.resolve(__name__, name)
