r"""Tangential load histories with memory: reversals, hysteresis loops, the loss per cycle.

A tangential force :math:`T(t)` varies back and forth on a contact of fixed half-width ``a``
(from the normal problem; :math:`B = 0`, so ``T`` does not change the pressure). The slip zones
remember the path: a reversal starts new slip zones at the edges while the old ones freeze
with their slip locked in. Two friction laws, as for the initiation of sliding
(:mod:`linecontact.tangential.initiation`): the constant friction stress :math:`\tau_0` (the
paper's nano-scale law) and Coulomb friction on the Hertz contact.

Two solvers that share nothing but the problem:

* ``method="closed-form"``: the Masing (Mindlin--Deresiewicz) memory rules. After a
  reversal at :math:`T_m` the change of the state is the monotone solution for twice the
  friction stress under the load change :math:`T - T_m` (the problem is linear in the friction
  stress), so every state is a sum of monotone solutions over a stack of turning points; a
  branch that passes its predecessor's turning point closes a loop and erases both
  (``docs/load-histories.md``). Closed forms for every term (traction, slip, displacement,
  energy dissipated).
* ``method="incremental"``: at each step the stick condition is solved directly with the
  Gauss--Chebyshev collocation of :class:`linecontact.sie.BoundedSolver`, from the previous
  traction: the traction in the slip zones is the friction stress in the step's direction,
  the stick zone :math:`|x| < c` keeps its relative displacement, and ``c`` is the root of the
  force balance. It knows no superposition rule and no memory rule.

Units: lengths over ``a``, forces per unit length over ``E a``, stresses over ``E``, slips
and displacements over ``a``, energies per unit length over :math:`E a^2`; for Coulomb friction
loads also over :math:`\mu F`, with :math:`p_0 = E a/(2R)`.

Conventions: ``T`` is the force on the cylinder along ``+x`` (either sign), the traction is the one
the cylinder exerts on the substrate (its integral is ``T``). The **slip** ``s(x)`` is the
tangential displacement of the cylinder's surface point relative to the substrate's, minus that at
the centre :math:`x = 0` (which never slips before gross sliding): well defined at every step, even
after a slide. The **displacement** ``D`` of the cylinder relative to the substrate carries the
datum of plane strain (remote points move by :math:`T/(\pi E) \ln\rho` for a datum depth
:math:`\rho`); the one reported takes :math:`\rho = a`. The datum adds :math:`\kappa T` to
:math:`D`, which adds :math:`\kappa\oint T\,dT = 0` to a loop's area: the energy dissipated does not
depend on it.

The package, one module per seam: ``_laws.py`` (the monotone closed forms of the two
friction laws), ``_masing_rules.py`` (the memory rules), ``_collocation.py`` (the
incremental solver), ``_histories.py`` (:func:`tangential_history`,
:func:`tangential_history_coulomb` and their results), ``_loss.py`` (:func:`cyclic_loss`,
:func:`cyclic_loss_coulomb` and their results). The public names are re-exported here.
"""

# the public names, and (``name as name``) the other names that modules, tests and benchmarks
# import from here; not the solver ``_incremental``: patch it where it is read
# (``_loss._incremental``)
from ._collocation import N_INCREMENTAL as N_INCREMENTAL
from ._collocation import N_MAX_INCREMENTAL as N_MAX_INCREMENTAL
from ._collocation import _graded as _graded
from ._histories import _T_LIMIT as _T_LIMIT
from ._histories import (
    CoulombTangentialHistory,
    TangentialHistory,
    tangential_history,
    tangential_history_coulomb,
)
from ._laws import _LAWS as _LAWS
from ._loss import CoulombCyclicLoss, CyclicLoss, cyclic_loss, cyclic_loss_coulomb

__all__ = [
    "CoulombCyclicLoss",
    "CoulombTangentialHistory",
    "CyclicLoss",
    "TangentialHistory",
    "cyclic_loss",
    "cyclic_loss_coulomb",
    "tangential_history",
    "tangential_history_coulomb",
]
