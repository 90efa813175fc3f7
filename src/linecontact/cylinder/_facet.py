"""The polygonal wire's problems in SI units (``self`` is the cylinder).

:meth:`Cylinder.contact` (and the contact for a load that the initiation of sliding
takes), :meth:`Cylinder.pull_off` and :meth:`Cylinder.load_curve` of a wire whose
cross-section is a :class:`~linecontact.geometry.Polygon`, and :meth:`Cylinder.shaped`.

The results are the round wire's SI classes (:class:`CylinderContact`,
:class:`CylinderPullOff`, :class:`CylinderLoadCurve`), built from the declarations of the
facet's nondimensional results (:mod:`linecontact.facet`): a new cross-section needs no SI
class of its own.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .. import facet as _fc
from .._validation import FailurePolicy, positive
from ..errors import NoEquilibriumError
from ..geometry import CrossSection
from ..units import Scales, to_si
from ._checks import _as_given, _normal_load
from ._results import CylinderContact, CylinderLoadCurve, CylinderPullOff

#: ``self`` is a :class:`~linecontact.cylinder.Cylinder` (not imported: it imports this module).
Cylinder = Any


def shaped(self: Cylinder, cross_section: CrossSection) -> Cylinder:
    """The same wire (radius, modulus, adhesion) with another ``cross_section``.

    >>> from linecontact import Cylinder
    >>> from linecontact.geometry import Polygon
    >>> wire = Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    >>> hexagon = wire.shaped(Polygon(6, corner_radius=5e-9))
    >>> round(hexagon.pull_off().pull_off_force, 4)
    -16.2314
    """
    if not isinstance(cross_section, CrossSection):
        raise ValueError(
            "cross_section must be a cross-section (linecontact.geometry.Round or Polygon), "
            f"got {cross_section!r}"
        )
    return self._made(
        self.radius,
        self.modulus,
        self.adhesion,
        self.dundurs_beta,
        cross_section=cross_section.checked(self.radius),
    )


def _groups(self: Cylinder) -> dict:
    return {
        "R_over_h": self.R_over_h,
        "sigma0_over_E": self.sigma0_over_E,
        **self.cross_section.groups(self.radius),
    }


def contact(
    self: Cylinder,
    contact_half_width: ArrayLike | None,
    load: ArrayLike | None,
    method: str,
    branch: str,
    policy: FailurePolicy,
) -> CylinderContact:
    """The contact of a polygonal wire at half-widths ``a`` [m] or loads ``F`` [N/m]."""
    named = [
        k for k, v in (("method", method != "closed-form"), ("branch", branch != "stable")) if v
    ]
    if named:
        self._not_written(f"the contact with {', '.join(named)}")
    if load is not None:
        return for_load(self, "load", load, policy)
    assert contact_half_width is not None  # exactly one of the two (Cylinder.contact)
    a = positive("contact_half_width", contact_half_width)
    _domain.check_si("contact_half_width", a, self.radius, "facet_a_over_R", "m")
    r = _fc.facet_contact(a / self.radius, **_groups(self))
    return _wrap(self, r, None)


def for_load(self: Cylinder, name: str, load: ArrayLike, policy: FailurePolicy) -> CylinderContact:
    """The stable contact carrying ``load`` [N/m]; messages name the caller's parameter."""
    g = _groups(self)
    F, Eh = _normal_load(self, name, load)
    r = _fc.facet_contact_for_load(F / Eh, on_failure="report", **g)
    bad = np.asarray(r.region) == "no-equilibrium"
    if policy == "raise" and np.any(bad):
        p = _fc.facet_pull_off(**g)
        Fi = float(np.reshape(np.broadcast_to(F, bad.shape), -1)[np.argmax(bad.reshape(-1))])
        raise NoEquilibriumError(
            f"no contact carries {name}={Fi!r} N/m: it is below the pull-off force of this "
            f"{self.cross_section.name} wire, {p.F_pulloff_over_Eh * Eh!r} N/m; the wire has "
            "pulled off"
        )
    return _wrap(self, r, F)


def _wrap(self: Cylinder, r: _fc.FacetContact, F: NDArray | None) -> CylinderContact:
    """The SI contact of ``r``; the load as given where one was (not back from ``F/(E h)``)."""
    # (no small-strain warning at a/R: a contact on the flat facet strains nothing; the
    # corner's parabola is the model's reading, docs/faceted.md)
    scales = Scales.of(self)
    si = to_si(r, scales)
    state = np.where(np.asarray(r.region) == "no-equilibrium", "no-equilibrium", "contact")
    if F is not None:
        si["load"] = _as_given(F, si["load"])
    return CylinderContact(
        **si,
        stable=r.stable,
        state=state.item() if state.ndim == 0 else state,
        nondimensional=r,  # type: ignore[arg-type]
        scales=scales,
    )


def load_curve(
    self: Cylinder, max_half_width: float | None, num: int, num_noncontact: int
) -> CylinderLoadCurve:
    """The load curve of a polygonal wire (its contact branch) up to ``max_half_width`` [m]."""
    if num_noncontact != 40:
        self._not_written("the load curve with num_noncontact (a polygon's begins at touch-down)")
    a_max = None
    if max_half_width is not None:
        _domain.check_si("max_half_width", max_half_width, self.radius, "facet_a_over_R", "m")
        a_max = max_half_width / self.radius
    c = _fc.facet_load_curve(**_groups(self), a_max_over_R=a_max, num=num)
    return CylinderLoadCurve(
        branch=c.branch,
        **to_si(c, Scales.of(self)),
        stable=c.stable,
        turning_point=c.turning_point,
        nondimensional=c,  # type: ignore[arg-type]
    )


def pull_off(self: Cylinder) -> CylinderPullOff:
    """The pull-off of a polygonal wire on its facet [N/m] (:func:`linecontact.facet_pull_off`)."""
    p = _fc.facet_pull_off(**_groups(self))
    si = to_si(p, Scales.of(self))
    return CylinderPullOff(**si, mechanism=p.mechanism, nondimensional=p)  # type: ignore[arg-type]
