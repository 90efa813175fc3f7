r"""Tangential loading of the line contact: initiation of sliding, steady rolling, histories.

Load histories with memory (reversals, hysteresis loops, the energy dissipated per cycle)
are in :mod:`linecontact.tangential.history` (``docs/load-histories.md``).

Paper Eqs (15)--(17) (initiation of sliding, Mindlin-type) and Eqs (23)--(29) (steady
rolling, Carter-type), in the uncoupled case :math:`B = 0` (Eq 7): the shear tractions do not
change the pressure, so the contact half-width ``a`` is that of the normal problem
(:mod:`linecontact.normal`) and enters here only as the unit of length.

Units and scaling
-----------------
Positions over the contact half-width (:math:`x/a`, :math:`d/a`), the tangential force per unit
length over :math:`E a` (:math:`T/(E a)`), stresses over the composite modulus :math:`E`
(:math:`\tau_0/E`, :math:`q/E`), the creep (rigid slip) velocity over the rolling speed :math:`V`
(:math:`\dot C/V`). For Coulomb friction :math:`T/(\mu F)` is used as well, and :math:`a/R` fixes
the Hertz pressure :math:`p_0 = E a/(2R)` (then :math:`T/(Ea) = (\pi/4)\,\mu\,(a/R)\,T/(\mu F)`).

Friction laws
-------------
``constant`` (the paper's nano-scale law, adhesion theory of friction): the shear traction
has the constant magnitude :math:`\tau_0` wherever the surfaces slip; full slip carries
:math:`T = 2a\tau_0`. ``coulomb`` (the macro-scale counterpart, non-adhesive Hertz contact):
magnitude :math:`\mu p(x)`; full slip carries :math:`T = \mu F`.

Sign conventions
----------------
Body 1 is the cylinder, body 2 the substrate, ``x`` along the surface, origin at the contact
centre. :math:`T \ge 0` is the tangential force per unit length transmitted through the
interface and ``traction(x)`` the shear traction carrying it (positive in the direction of
``T``, its integral over the contact is ``T``, magnitude :math:`\tau_0` or :math:`\mu p` in the
slip zones). ``docs/tangential.md`` works with ``q``, the traction on the substrate, which is
the traction for the initiation and minus it for rolling.

* **Initiation of sliding**: a force ``T`` pulls the cylinder along ``+x``; the traction is
  the one the cylinder exerts on the substrate. Stick zone :math:`|x| < d`, slip zones
  :math:`d < |x| < a`. The slip :math:`s(x)` is the tangential displacement of the cylinder's
  surface relative to the substrate's surface in a slip zone, measured from the nearer end of
  the stick zone (where it vanishes): :math:`s(x) = \int_d^{|x|}
  \partial(u_x^{(1)} - u_x^{(2)})/\partial x\,dx \ge 0`, the cylinder slipping forward.
  (The rigid shift of remote points is not reported: plane strain fixes it only up to a
  logarithmic constant.)
* **Steady rolling**: the cylinder rolls towards ``+x`` at speed ``V`` (the contact moves
  along ``+x``, the leading edge is :math:`x = +a`) and is the **driving** body (a torque
  turns it, as a locomotive wheel); the substrate exerts the tractive force ``T`` on the
  cylinder along ``+x`` (the cylinder pushes the substrate backwards). Stick zone at the
  leading edge :math:`d < x < a`, slip zone at the trailing edge :math:`-a < x < d`.
  ``creep_over_V`` is :math:`\dot C/V = (V - \omega R)/V`, the velocity of the cylinder's
  rigid surface relative to the substrate in the rolling direction over ``V``: **negative**
  for a driving cylinder, whose circumference runs faster than it advances
  (:math:`\omega R > V`), as the paper says. A braking (driven) cylinder is the mirror image
  (all signs of ``T``, the traction and the creep reversed).

Failures
--------
Every solver here takes ``on_failure`` (README, "Conventions"): a given load at or beyond full slip
(:math:`T \ge 2 a \tau_0` or :math:`\mu F`; for the initiation also ``d_over_a = 0``) and a
collocation point that misses its tolerance raise :class:`~linecontact.errors.NoEquilibriumError`
and :class:`~linecontact.errors.ConvergenceError` by default (``"raise"``); with
``on_failure="report"`` the point is returned with ``state == "sliding"`` or ``converged == False``.
(Up to 0.2.0 a load beyond full slip was reported by default, ``on_sliding="report"``.) The load
histories slide at full slip under either policy: there ``on_failure`` concerns the incremental
solver's tolerance only.

Solvers
-------
``method="closed-form"`` (default) evaluates the closed forms derived in
``docs/tangential.md``; ``method="collocation"`` solves the singular integral equations
(Eq 16 on the stick zone :math:`(-d, d)`; Eq 27 on :math:`(d, a)`, whose extra consistency equation
gives the creep) with :class:`linecontact.sie.BoundedSolver`, choosing the number of nodes
per point. The two agree to ~1e-14 (``benchmarks/tangential.py``).

Closed forms (constant ``tau0``; :math:`\delta = d/a`):

.. math::

    \text{initiation:}\quad \frac{T}{2a\tau_0} = \sqrt{1 - \delta^2},\qquad
    \mathrm{traction} = \frac{2\tau_0}{\pi}\arctan\sqrt{\frac{a^2 - d^2}{d^2 - x^2}}
    \ (|x| < d),

    \text{rolling:}\quad \frac{T}{2a\tau_0} = \sqrt{\frac{1 + \delta}{2}},\qquad
    \frac{\dot C}{V} = -\frac{4\tau_0}{\pi E}\,\operatorname{artanh}\frac{T}{2a\tau_0},\qquad
    \mathrm{traction} = \frac{2\tau_0}{\pi}\arctan\sqrt{\frac{(a + d)(a - x)}{2a(x - d)}}
    \ (d < x < a).

Coulomb: Cattaneo--Mindlin :math:`T/(\mu F) = 1 - \delta^2`; Carter
:math:`T/(\mu F) = 1 - ((1 - \delta)/2)^2`, :math:`\dot C/V = -(\mu a/R)(1 + \delta)/2`.

References
----------
F. W. Carter, "On the action of a locomotive driving wheel", Proc. R. Soc. Lond. A 112
(1926) 151--157. doi:10.1098/rspa.1926.0100
R. D. Mindlin, "Compliance of elastic bodies in contact", J. Appl. Mech. 16 (1949)
259--268. doi:10.1115/1.4009973
C. Cattaneo, "Sul contatto di due corpi elastici: distribuzione locale degli sforzi",
Rend. Accad. Naz. Lincei 27 (1938) 342--348, 434--436, 474--478.
K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), Ch. 7
(Cattaneo--Mindlin) and Ch. 8 (Carter). doi:10.1017/CBO9781139171731
"""

from . import history
from ._core import N_COULOMB, SIZES
from .history import *  # noqa: F403 (its __all__, re-exported below)
from .initiation import (
    CoulombSlidingInitiation,
    SlidingInitiation,
    sliding_initiation,
    sliding_initiation_coulomb,
)
from .rolling import CoulombRolling, SteadyRolling, steady_rolling, steady_rolling_coulomb

__all__ = [
    "N_COULOMB",
    "SIZES",
    *history.__all__,
    "CoulombRolling",
    "CoulombSlidingInitiation",
    "SlidingInitiation",
    "SteadyRolling",
    "sliding_initiation",
    "sliding_initiation_coulomb",
    "steady_rolling",
    "steady_rolling_coulomb",
]
