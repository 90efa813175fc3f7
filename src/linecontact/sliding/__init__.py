r"""Steady sliding with different trailing and leading adhesion (paper Eqs. 18--22).

A cylinder slides steadily over the substrate. Sliding wipes the surface ahead of it, so the
adhesion at the trailing edge has a longer range ``h1`` than at the leading edge ``h2``
(the Dugdale stress ``sigma0`` is the same at both); the contact, its adhesive zones and the
pressure lose their symmetry, the cylinder's apex is offset from the contact centre and the
pressure has a resultant moment. Any positive :math:`h_1/h_2` is accepted (:math:`h_1 < h_2` is
the mirror image).

Axes and signs
--------------
``x`` runs along the sliding direction (the cylinder moves towards ``+x``), with its origin
at the centre of the contact :math:`-a < x < a`; ``y`` is normal to the substrate, pointing up
into the cylinder, which lies above the substrate. Figures are drawn with ``x`` to the right
and ``y`` up, so the cylinder moves to the right and "clockwise" is as seen in them.

- Trailing adhesive zone :math:`-c_1 < x < -a` (range :math:`h_1`), leading zone
  :math:`a < x < c_2` (range :math:`h_2`); the apex of the cylinder (its axis) is at :math:`x = e`
  (eccentricity).
- The pressure :math:`p` is compressive positive: :math:`p = \bar p - \sigma_0` on
  :math:`[-c_1, c_2]` with :math:`\bar p` supported on the contact and bounded (zero) at both of its
  ends (Eq. 8).
- The load :math:`F = \int p\, dx` is compressive positive (Eq. 12 with two zones).
- The moment :math:`M = \int x\, p(x)\, dx` about the contact centre is **clockwise positive**: it
  is the clockwise moment of the contact pressure on the substrate, equivalently the clockwise
  moment about the contact centre that must act on the cylinder, together with the load, to hold it
  in equilibrium. The pressure's own moment on the cylinder is ``M`` counterclockwise: with
  :math:`h_1 > h_2` it opposes forward (clockwise) rolling -- the resisting moment.
  :math:`M_\text{axis} = M - e F` is the same moment taken about the cylinder's axis.

Units (as in :mod:`linecontact.closed_forms`, with ``h2`` as the unit of gap): lengths over
:math:`R` (:math:`a/R`, :math:`c_1/R`, :math:`c_2/R`, :math:`e/R`), force per unit length over
:math:`E h_2`, moment per unit length over :math:`E h_2 R`, stresses over :math:`E`, :math:`R/h_2`
and :math:`h_1/h_2`.

Equations
---------
Eq. (20), the bounded pressure on the contact,

.. math::

    \frac{1}{\pi E}\int_{-a}^{a}\frac{\bar p(\xi)}{\xi - x}\,d\xi = -\frac{x - e}{2R}
    + \frac{\sigma_0}{\pi E}\ln\frac{c_2 - x}{c_1 + x}, \qquad |x| < a,

is not odd, so its consistency condition (the extra collocation equation) does not hold by
itself: it fixes the eccentricity, which enters linearly through :math:`e/(2R)`. The two
separation conditions are the gap :math:`h_2` at :math:`x = c_2` (Eq. 21) and :math:`h_1` at
:math:`x = -c_1` (Eq. 22, corrupted in the text; derived in ``docs/sliding.md``):

.. math::

    \frac{2}{\pi E}\int_{-a}^{a}\bar p\ln\frac{c_2-\xi}{a-\xi}\,d\xi
    = \frac{(c_2-e)^2-(a-e)^2}{2R} - h_2 - \frac{2\sigma_0}{\pi E}\int_a^{c_2}
      \ln\frac{c_2-x}{c_1+x}\,dx,

    \frac{2}{\pi E}\int_{-a}^{a}\bar p\ln\frac{c_1+\xi}{a+\xi}\,d\xi
    = \frac{(c_1+e)^2-(a+e)^2}{2R} - h_1 + \frac{2\sigma_0}{\pi E}\int_{-c_1}^{-a}
      \ln\frac{c_2-x}{c_1+x}\,dx.

Two solvers give the same :class:`SlidingContact`:

``method="collocation"``
    The paper's route: Eq. (20) by Gauss--Chebyshev collocation
    (:class:`linecontact.sie.BoundedSolver` with the eccentricity as the extra unknown of the
    consistency condition), Eqs. (21)--(22) by product integration of their logarithmic
    kernels (singular at the contact edges), Newton's method in
    :math:`u_i = \operatorname{arccosh}(c_i/a)`, an adaptive number of nodes with a
    Chebyshev-tail error estimate (as :func:`linecontact.normal.normal_contact`).
``method="closed-form"`` (default, as for every other problem)
    The asymmetric Maugis--Dugdale solution derived in ``docs/sliding.md``. With
    :math:`c_i = a\cosh u_i`, :math:`\sigma = (u_1+u_2)/2`, :math:`\delta = (u_1-u_2)/2`,
    :math:`t = x/a = \cos\theta`, :math:`q_i = e^{-u_i}`:

    .. math::

        \bar p/E = \frac{a}{2R}\sin\theta + \frac{2\sigma_0}{\pi E}\left[
            \arctan\frac{q_2\sin\theta}{1 - q_2\cos\theta}
            + \arctan\frac{q_1\sin\theta}{1 + q_1\cos\theta}\right],

        e = \frac{2\sigma_0 R}{\pi E}(u_1 - u_2),\qquad
        F = \frac{\pi E a^2}{4R} - \sigma_0\left(\sqrt{c_1^2-a^2} + \sqrt{c_2^2-a^2}\right),

        M = \frac{\sigma_0}{2}\left(c_1\sqrt{c_1^2-a^2} - c_2\sqrt{c_2^2-a^2}\right),

        h_i = \frac{a^2}{2R}f_1(u_i) + \frac{4\sigma_0 a}{\pi E}\cosh\delta\left[
            u_i\sinh\sigma - \cosh\sigma\ln\frac{\cosh\sigma}{\cosh\delta}\right],

    :math:`f_1 = \sinh u\cosh u - u`; at :math:`u_1 = u_2` the last bracket is Baney & Hui's
    :math:`f_2`, so everything reduces to :mod:`linecontact.normal`. Two algebraic
    equations in :math:`(u_1, u_2)` per point, solved by a safeguarded Newton iteration.

With :math:`\bar a = (a/R)\sqrt{R/(2h_2)}` and :math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h_2}`
the separation conditions read :math:`\bar a^2 f_1(u_2) + \kappa\bar a\,G_2 = 1`,
:math:`\bar a^2 f_1(u_1) + \kappa\bar a\,G_1 = h_1/h_2`, and
:math:`F/(Eh_2) = (\pi/2)(\bar a^2 - \kappa\bar a\sinh\sigma\cosh\delta)`: the family depends
on :math:`\kappa` and :math:`h_1/h_2` once :math:`a` is scaled.

References
----------
I. Sari, G. G. Adams, S. Müftü, "Nano-scale effects in the adherence, sliding and rolling of
a cylinder on a substrate" (Eqs. 18--22, Figs. 8--12).
J. M. Baney, C.-Y. Hui, "A cohesive zone model for the adhesion of cylinders",
J. Adhesion Sci. Technol. 11 (1997) 393--406. doi:10.1163/156856197X00796
F. Erdogan, G. D. Gupta, T. S. Cook, "Numerical solution of singular integral equations"
(1973). doi:10.1007/978-94-017-2260-5_7

Modules
-------
:mod:`~linecontact.sliding.contact` (:func:`sliding_contact`, :class:`SlidingContact`),
:mod:`~linecontact.sliding.closed_form` and :mod:`~linecontact.sliding.collocation` (the two
solvers), :mod:`~linecontact.sliding.pulloff` (:func:`sliding_pull_off`),
:mod:`~linecontact.sliding.inverse` (:func:`sliding_contact_for_load`); this package
re-exports them.
"""

from .closed_form import _cf_eval as _cf_eval
from .collocation import _colloc_rhs as _colloc_rhs
from .contact import SlidingContact, sliding_contact
from .inverse import sliding_contact_for_load
from .pulloff import SNAP_OFF_MIN_WIDTH_OVER_H as SNAP_OFF_MIN_WIDTH_OVER_H
from .pulloff import SlidingPullOff, sliding_pull_off

__all__ = [
    "SlidingContact",
    "SlidingPullOff",
    "sliding_contact",
    "sliding_contact_for_load",
    "sliding_pull_off",
]
