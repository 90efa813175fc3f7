r"""The Lennard-Jones pull-off beyond the self-consistent domain: the JKR limit, corrected.

For ``mu`` above :data:`MU_SELF_CONSISTENT` (Maugis parameter 104) the pull-off is

.. math::

    F = F_{JKR}(\mu)\,\bigl(1 - C\mu^{-p}\bigr), \qquad
    F_{JKR} = -\tfrac34\,(4\pi/\mu)^{1/3}, \qquad
    \zeta_0 = 1 + \frac{(2/\pi)^{1/3}}{32\,\mu^{2/3}},

in the law's units (:mod:`linecontact.lennard_jones`). ``F_JKR`` is the exact limit (the
pull-off of JKR line contact, Chaudhury et al. 1996). ``C`` and ``p`` are fitted to the
self-consistent pull-offs at :math:`\mu = 100 \ldots 400` (``benchmarks/lennard_jones.py``
reproduces the fit). The central gap is the JKR limit's own: at pull-off the JKR pressure at
the centre is tensile, :math:`-E a/(2R)` with :math:`a^3 = 2 \mu/\pi` (so the whole contact is under
tension and the repulsive region has width 0), and the law linearised about ``z0``,
:math:`P = -16 (\zeta - 1)`, turns it into the gap above.

The error estimate is the whole correction :math:`|F_\text{JKR}|\, C \mu^{-p}`: in the overlap
:math:`\mu = 400 \ldots 700` the self-consistent pull-off differs from this form by at most
:math:`2.2 \times 10^{-7} w \sqrt{R/z_0}`, 17 to 140 times less than the estimate
(``docs/lennard-jones.md``).
"""

from __future__ import annotations

import math

#: The largest ``mu`` solved self-consistently; beyond, :func:`limit_pull_off`.
MU_SELF_CONSISTENT = 400.0
#: :math:`F/F_\text{JKR} - 1 = -C \mu^{-p}`: least squares in ``ln`` on the self-consistent
#: pull-offs at :math:`\mu` = 100, 140, 200, 280, 400 (default mesh).
_C = 0.0774758
_P = 1.26764
#: :math:`\zeta_0 - 1` at pull-off times :math:`\mu^{2/3}` in the JKR limit:
#: :math:`(2/\pi)^{1/3}/32`.
_GAP = (2.0 / math.pi) ** (1.0 / 3.0) / 32.0


def jkr_pull_off(mu: float) -> float:
    r"""The JKR line-contact pull-off :math:`-\tfrac34 (4\pi/\mu)^{1/3}` in the law's units."""
    return -0.75 * (4.0 * math.pi / mu) ** (1.0 / 3.0)


def limit_pull_off(mu: float) -> tuple[float, float, float]:
    r"""``(F, error_estimate, central_gap)`` at pull-off, corrected JKR limit (:math:`\mu > 0`)."""
    F_jkr = jkr_pull_off(mu)
    correction = _C * mu**-_P
    return F_jkr * (1.0 - correction), abs(F_jkr) * correction, 1.0 + _GAP * mu ** (-2.0 / 3.0)
