r"""The Lennard-Jones law of Eq. 1 solved self-consistently for line contact.

A cylinder of radius ``R`` on an elastic half-plane (composite plane-strain modulus ``E``),
the surface traction the Lennard-Jones law (Eq. 1) at the local gap everywhere -- no
separate contact and adhesive zones. In plane strain the displacement has no datum, so the
state is controlled by the gap at the centre ``g0``; the gap elsewhere is

.. math::

    z(x) = g_0 + \frac{x^2}{2R} - \frac{2}{\pi E}\int p(s)\,\bigl(\ln|x - s| - \ln|s|\bigr)\,ds,

the pressure ``p`` (compressive positive) pressing the surface in most under the centre.
With ``x = sqrt(R z0) xi``, ``z = z0 zeta`` and ``p = (w/z0) P(zeta)``,
``P(zeta) = -(8/3)(zeta^-3 - zeta^-9)``, the gap is

.. math::

    \zeta(\xi) = \zeta_0 + \frac{\xi^2}{2}
        - \frac{2\mu}{\pi}\int_0^\infty P(\zeta(\eta))\,\ln\frac{|\xi^2 - \eta^2|}{\eta^2}\,d\eta,
    \qquad \mu = \frac{w\sqrt{R/z_0}}{E z_0},

and the load is ``F/(w sqrt(R/z0)) = 2 int_0^inf P d eta``. ``mu`` is the one group of the
problem (a Tabor parameter for cylinders): ``mu -> 0`` is the rigid limit
(:func:`linecontact.closed_forms.lennard_jones_rigid_load`). With the Maugis matching of the
Dugdale step (``sigma0 = 16 w/(9 sqrt(3) z0)``, ``h = w/sigma0``) the Maugis parameter of
line contact (:func:`linecontact.maugis_parameter`) is a function of ``mu`` alone
(:func:`maugis_parameter_of_mu`). Derivation and mesh study: ``docs/lennard-jones.md``.

Discretisation: ``P`` piecewise linear on a mesh uniform on ``[0, X]`` (the contact and its
edge zones; ``X`` follows the widest contact asked for) and geometric beyond, to
``L = 2000`` where the attraction has decayed like ``xi^-6``; the logarithmic kernel is
integrated exactly on each element (product integration); collocation at the nodes; a
Newton (chord) iteration on the gaps. Every state is solved on that mesh and on the meshes
with every second and every fourth node (their kernels follow from the fine one exactly);
the load returned is the Richardson extrapolation of the two finer loads, and its error
estimate the change of that extrapolation from the coarser pair.

The package: ``_solver.py`` (the meshes, the kernels, Newton, one state on three meshes),
``_curve.py`` (the continuation, :func:`lj_curve`, :func:`lj_pull_off`, :func:`lj_state`,
:func:`lj_contact_for_load` and their results), ``_matching.py`` (the Maugis matching:
:data:`MAUGIS_MATCH_SIGMA0`, :func:`mu_of_dugdale`, :func:`maugis_parameter_of_mu`) and
``_groups.py`` (the pull-off in the groups of the Dugdale problem). Every public name is
re-exported here; the private ones are read where they are defined (patch
``_curve._arc_newton``, not ``lennard_jones._arc_newton``).
"""

from ._curve import F_MAX_DEFAULT as F_MAX_DEFAULT
from ._curve import (
    LJCurve,
    LJPullOff,
    LJState,
    lj_contact_for_load,
    lj_curve,
    lj_pull_off,
    lj_state,
)
from ._groups import LennardJonesPullOff, lj_groups, pull_off_in_dugdale_groups, pull_off_of
from ._matching import (
    MAUGIS_MATCH_H_OVER_Z0,
    MAUGIS_MATCH_SIGMA0,
    maugis_parameter_of_mu,
    mu_of_dugdale,
)

__all__ = [
    "LJCurve",
    "LennardJonesPullOff",
    "LJPullOff",
    "LJState",
    "MAUGIS_MATCH_H_OVER_Z0",
    "MAUGIS_MATCH_SIGMA0",
    "lj_contact_for_load",
    "lj_curve",
    "lj_groups",
    "lj_pull_off",
    "lj_state",
    "maugis_parameter_of_mu",
    "mu_of_dugdale",
    "pull_off_in_dugdale_groups",
    "pull_off_of",
]
