r"""The adhesive sphere: an AFM tip or a colloidal probe on a flat (``docs/sphere.md``).

The Maugis--Dugdale sphere (Maugis 1992), vectorised over parameter points like the line
contact, in the wire's input groups: ``R/h`` and ``sigma0/E`` (Hertz at ``sigma0 = 0``, JKR
and DMT its limits of the Maugis parameter :math:`\lambda`). Lengths over ``R`` (the contact
radius ``a/R``), the approach over ``h``, the force [N] over ``E h R``; Maugis' unit
:math:`\pi w R` on each result as ``F_over_piwR``.

- :func:`sphere_contact` -- the states at given contact radii;
- :func:`sphere_contact_for_load` -- the stable contact under a load;
- :func:`sphere_pull_off` -- the pull-off under load or displacement control;
- :func:`sphere_load_curve` -- the curve through both branches, the pull-offs marked;
- :func:`sphere_models` -- which model holds (Hertz, DMT, JKR against Maugis--Dugdale);
  :func:`cos_alpha`, :func:`maugis_parameter_of_cos_alpha` -- the COS transition parameter
  fitted to the library's own curves;
- :func:`sphere_lj_pull_off`, :func:`sphere_lj_curve` -- the self-consistent Lennard-Jones
  sphere (Greenwood 1997) in Tabor's parameter: self-consistent up to
  ``lennard_jones.MU_SELF_CONSISTENT``, the pull-off beyond by the JKR limit corrected.

The closed forms of its limits are in :mod:`linecontact.closed_forms.sphere`.
"""

from __future__ import annotations

from .contact import SphereContact, sphere_contact
from .curve import SphereLoadCurve, sphere_load_curve
from .fits import SphereAdhesionFit, SphereModelChoice, sphere_fit_pull_off, sphere_which_model
from .lennard_jones import SphereLJCurve, SphereLJPullOff, sphere_lj_curve, sphere_lj_pull_off
from .models import SphereModels, cos_alpha, maugis_parameter_of_cos_alpha, sphere_models
from .pulloff import SpherePullOff, sphere_contact_for_load, sphere_pull_off
from .shear_fit import SphereShearStrengthFit, sphere_fit_shear_strength

__all__ = [
    "SphereAdhesionFit",
    "SphereModelChoice",
    "SphereShearStrengthFit",
    "sphere_fit_pull_off",
    "sphere_fit_shear_strength",
    "sphere_which_model",
    "SphereLJCurve",
    "SphereLJPullOff",
    "sphere_lj_curve",
    "sphere_lj_pull_off",
    "SphereModels",
    "cos_alpha",
    "maugis_parameter_of_cos_alpha",
    "sphere_models",
    "SphereContact",
    "SphereLoadCurve",
    "SpherePullOff",
    "sphere_contact",
    "sphere_contact_for_load",
    "sphere_load_curve",
    "sphere_pull_off",
]
