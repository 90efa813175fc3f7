r"""Normal contact of a cylinder with Maugis--Dugdale adhesion (paper Eqs. 5--14).

Units as in :mod:`linecontact.closed_forms`: ``a/R``, ``c/R``, ``F/(E h)``, ``sigma0/E``,
``R/h``; compressive pressure and load positive.

Two solvers give the same :class:`NormalContact`:

``method="closed-form"`` (default)
    The Maugis--Dugdale line-contact solution (Baney & Hui 1997; Johnson & Greenwood
    2008), one scalar root per point.
``method="collocation"``
    The paper's route: the singular integral equation (Eq. 9) for the bounded pressure
    :math:`\bar p = p + \sigma_0` on :math:`|x| < a`, solved by Gauss--Chebyshev collocation
    (:class:`linecontact.sie.BoundedSolver`), with the separation condition (Eq. 11) for the
    end ``c`` of the adhesive zone and equilibrium (Eq. 12) for the load. The log kernel of
    Eq. 11, singular at :math:`\xi = a`, is integrated by product integration. The number of
    collocation points adapts per point to the distance between ``c`` and ``a`` (the log
    source at ``x = c`` limits the convergence rate to :math:`(c/a + \sqrt{c^2/a^2-1})^{-n}`).

In plane strain the rigid approach of remote points is defined only up to a logarithmic
constant, so no approach is reported: the load is controlled by ``F`` or by ``a``.

Modules
-------
:mod:`~linecontact.normal.contact` (:func:`normal_contact`, both solvers),
:mod:`~linecontact.normal.pulloff` (:func:`pull_off`),
:mod:`~linecontact.normal.inverse` (:func:`contact_for_load`, :func:`equilibria`),
:mod:`~linecontact.normal.noncontact` (:func:`non_contact`),
:mod:`~linecontact.normal.curve` (:func:`load_curve`); this package re-exports them.
"""

from .contact import NormalContact, normal_contact
from .curve import NUM_MAX as NUM_MAX
from .curve import LoadCurve, load_curve
from .inverse import Equilibrium, contact_for_load, equilibria
from .noncontact import NonContact, non_contact
from .pulloff import SNAP_OFF_MIN_WIDTH_OVER_H, ZERO_WIDTH_LOAD_RTOL, PullOff, pull_off

__all__ = [
    "Equilibrium",
    "LoadCurve",
    "NonContact",
    "NormalContact",
    "PullOff",
    "SNAP_OFF_MIN_WIDTH_OVER_H",
    "ZERO_WIDTH_LOAD_RTOL",
    "contact_for_load",
    "equilibria",
    "load_curve",
    "non_contact",
    "normal_contact",
    "pull_off",
]
