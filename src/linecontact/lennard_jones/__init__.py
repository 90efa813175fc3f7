r"""The Lennard-Jones law of Eq. 1 solved self-consistently for line contact.

A cylinder of radius ``R`` on an elastic half-plane (composite plane-strain modulus ``E``),
the surface traction the Lennard-Jones law (Eq. 1) at the local gap everywhere -- no
separate contact and adhesive zones. In plane strain the displacement has no datum, so the
state is controlled by the gap at the centre ``g0``; the gap elsewhere is

.. math::

    z(x) = g_0 + \frac{x^2}{2R} - \frac{2}{\pi E}\int p(s)\,\bigl(\ln|x - s| - \ln|s|\bigr)\,ds,

the pressure :math:`p` (compressive positive) pressing the surface in most under the centre.
With :math:`x = \sqrt{R z_0}\, \xi`, :math:`z = z_0 \zeta` and :math:`p = (w/z_0) P(\zeta)`,
:math:`P(\zeta) = -\tfrac83 (\zeta^{-3} - \zeta^{-9})`, the gap is

.. math::

    \zeta(\xi) = \zeta_0 + \frac{\xi^2}{2}
        - \frac{2\mu}{\pi}\int_0^\infty P(\zeta(\eta))\,\ln\frac{|\xi^2 - \eta^2|}{\eta^2}\,d\eta,
    \qquad \mu = \frac{w\sqrt{R/z_0}}{E z_0},

and the load is :math:`F/(w \sqrt{R/z_0}) = 2 \int_0^\infty P\, d\eta`. :math:`\mu` is the one group
of the problem (a Tabor parameter for cylinders): :math:`\mu \to 0` is the rigid limit
(:func:`linecontact.closed_forms.lennard_jones_rigid_load`). With the Maugis matching of the Dugdale
step (:math:`\sigma_0 = 16 w/(9 \sqrt{3} z_0)`, :math:`h = w/\sigma_0`) the Maugis parameter of line
contact (:func:`linecontact.maugis_parameter`) is a function of ``mu`` alone
(:func:`maugis_parameter_of_mu`). Derivation and mesh study: ``docs/lennard-jones.md``.

Discretisation: :math:`P` piecewise linear on graded meshes out to :math:`L = 2000` (the attraction
there has decayed like :math:`\xi^{-6}`), uniform about the edge of the contact (where the gap
crosses :math:`1.5\, z_0`) at a fraction of the edge length :math:`1/\mu`; the logarithmic kernel is
integrated exactly on each element (product integration); collocation at the nodes; a chord
Newton iteration. Far away the states hold their central gap; from there on they hold their
edge, on meshes scaled per factor 2 of it (the kernel scales with the mesh exactly). Every
state is solved on its mesh and on the meshes with every second and every fourth node (their
kernels follow from the fine one exactly); the load (and for a state held at its edge, the
central gap) returned is the Richardson extrapolation of the two finer meshes', and the
load's error estimate the change of that extrapolation from the coarser pair. Self-consistent
for :math:`\mu \le` ``MU_SELF_CONSISTENT`` (400); the pull-off beyond by the JKR limit with a fitted
correction (``_limit.py``).

The package: ``_solver.py`` (the meshes, the kernels, Newton, one state on three meshes),
``_branch.py`` (the curve along its edge: the far part, the climb, the extrema, the pull-off
search), ``_curve.py`` (:func:`lj_curve`, :func:`lj_pull_off`, :func:`lj_state`,
:func:`lj_contact_for_load`, :class:`LJContinuation` and their results), ``_limit.py``
(the pull-off beyond the self-consistent domain), ``_matching.py`` (the Maugis matching:
:data:`MAUGIS_MATCH_SIGMA0`,
:func:`mu_of_dugdale`, :func:`maugis_parameter_of_mu`) and ``_groups.py`` (the pull-off in
the groups of the Dugdale problem). Every public name is re-exported here; the private ones
are read where they are defined (patch ``_solver._iterate``, not
``lennard_jones._iterate``).
"""

from ._curve import F_MAX_DEFAULT as F_MAX_DEFAULT
from ._curve import (
    LJContinuation,
    LJCurve,
    LJPullOff,
    LJState,
    lj_contact_for_load,
    lj_curve,
    lj_pull_off,
    lj_state,
)
from ._groups import LennardJonesPullOff, lj_groups, pull_off_in_dugdale_groups, pull_off_of
from ._limit import MU_SELF_CONSISTENT
from ._matching import (
    MAUGIS_MATCH_H_OVER_Z0,
    MAUGIS_MATCH_SIGMA0,
    maugis_parameter_of_mu,
    mu_of_dugdale,
)

__all__ = [
    "LJContinuation",
    "LJCurve",
    "LennardJonesPullOff",
    "LJPullOff",
    "LJState",
    "MAUGIS_MATCH_H_OVER_Z0",
    "MAUGIS_MATCH_SIGMA0",
    "MU_SELF_CONSISTENT",
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
