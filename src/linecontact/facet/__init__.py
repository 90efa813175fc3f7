r"""A faceted wire (hexagonal, pentagonal, any regular ``n``-gon) lying on one facet.

The cross-section is a regular polygon of ``n`` sides and circumradius ``R`` whose corners
are rounded with radius ``r_c`` (``0 <= r_c <= R``; ``r_c = R`` is the round wire of
radius ``R``); it lies on a facet, whose flat half-width is ``f = (R - r_c) sin(pi/n)``.
The adhesion is the Maugis--Dugdale law (``sigma0``, ``h``) and the elasticity plane
strain, as for the round wire (:mod:`linecontact.normal`); ``docs/faceted.md`` derives the
closed forms, the readings chosen and the checks.

Units
-----
Lengths over the circumradius ``R`` (``a/R``, ``c/R``, ``r_c/R``), loads per unit length
over ``E h`` (compressive positive), ``R/h`` and ``sigma0/E`` as for the round wire.

In plane strain the approach of remote points is defined only up to a logarithmic
constant, so, as for the round wire, the load is controlled by ``F`` or by ``a`` and the
pull-off is that under load control.
"""

from .contact import FacetContact, facet_contact
from .curve import FacetLoadCurve, facet_load_curve
from .pulloff import FacetPullOff, facet_contact_for_load, facet_pull_off
from .tipping import FacetTipping, facet_tipping

__all__ = [
    "FacetContact",
    "FacetLoadCurve",
    "FacetPullOff",
    "FacetTipping",
    "facet_contact",
    "facet_contact_for_load",
    "facet_load_curve",
    "facet_pull_off",
    "facet_tipping",
]
