r"""Adhesion laws, one module each, with the same functions in the paper's groups.

A law is a module, not a flag: each module below has ``pull_off(R_over_h, sigma0_over_E)``,
``contact_for_load(F_over_Eh, R_over_h, sigma0_over_E, ...)`` and
``load_curve(R_over_h, sigma0_over_E, ...)``, with the same names and argument order, each
returning its own result type (loads over ``E h``, widths over ``R``, gaps over ``h``):

- :mod:`linecontact.laws.dugdale` -- the Maugis--Dugdale step of the paper (the functions of
  :mod:`linecontact.normal`, the default of the whole library);
- :mod:`linecontact.laws.lennard_jones` -- the Lennard-Jones law of Eq. (1), solved
  self-consistently, with the Dugdale step's work of adhesion :math:`w = \sigma_0 h` and
  peak tension :math:`\sigma_0` (the Maugis matching).

In SI units a law is a value (:mod:`linecontact.laws._values`): :class:`Dugdale` and
:class:`LennardJones` hold their parameters, ``(sigma0, h)`` or ``(w, z0)``, and convert
themselves to the groups these functions take; a :class:`~linecontact.Cylinder` is built
with one (``adhesion=LennardJones(0.1, 0.3e-9)``) and its methods solve under it.
"""

from . import dugdale, lennard_jones
from ._values import LAWS, Dugdale, Law, LennardJones

__all__ = ["LAWS", "Dugdale", "Law", "LennardJones", "dugdale", "lennard_jones"]
