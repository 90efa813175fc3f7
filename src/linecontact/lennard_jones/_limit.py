r"""The Lennard-Jones pull-off beyond the self-consistent domain: the JKR limit, corrected.

For ``mu`` above :data:`MU_SELF_CONSISTENT` (Maugis parameter 104) the pull-off is

.. math::

    F = F_{JKR}(\mu)\,\bigl(1 - C\mu^{-p}\bigr), \qquad
    F_{JKR} = -\tfrac34\,(4\pi/\mu)^{1/3}, \qquad
    \zeta_0 = 1 + \frac{(2/\pi)^{1/3}}{32\,\mu^{2/3}},

in the law's units (:mod:`linecontact.lennard_jones`). ``F_JKR`` is the exact limit (the
pull-off of JKR line contact, Chaudhury et al. 1996). ``C`` and ``p`` are fitted to the
self-consistent pull-offs at ``mu = 100 ... 400`` (``benchmarks/lennard_jones.py``
reproduces the fit). The central gap is the JKR limit's own: at pull-off the JKR pressure at
the centre is tensile, ``-E a/(2R)`` with ``a^3 = 2 mu/pi`` (so the whole contact is under
tension and the repulsive region has width 0), and the law linearised about ``z0``,
``P = -16 (zeta - 1)``, turns it into the gap above.

The error estimate is the whole correction ``|F_JKR| C mu^-p``: in the overlap
``mu = 400 ... 700`` the self-consistent pull-off differs from this form by at most
``2.2e-7 w sqrt(R/z0)``, 17 to 140 times less than the estimate (``docs/lennard-jones.md``).
"""

from __future__ import annotations

import math

#: The largest ``mu`` solved self-consistently; beyond, :func:`limit_pull_off`.
MU_SELF_CONSISTENT = 400.0
#: ``F/F_JKR - 1 = -C mu^-p``: least squares in ``ln`` on the self-consistent pull-offs at
#: ``mu = 100, 140, 200, 280, 400`` (default mesh).
_C = 0.0774758
_P = 1.26764
#: ``zeta0 - 1`` at pull-off times ``mu^(2/3)`` in the JKR limit: ``(2/pi)^(1/3)/32``.
_GAP = (2.0 / math.pi) ** (1.0 / 3.0) / 32.0


def jkr_pull_off(mu: float) -> float:
    """The JKR line-contact pull-off ``-(3/4)(4 pi/mu)^(1/3)`` in the law's units."""
    return -0.75 * (4.0 * math.pi / mu) ** (1.0 / 3.0)


def limit_pull_off(mu: float) -> tuple[float, float, float]:
    """``(F, error_estimate, central_gap)`` at pull-off by the corrected JKR limit (``mu > 0``)."""
    F_jkr = jkr_pull_off(mu)
    correction = _C * mu**-_P
    return F_jkr * (1.0 - correction), abs(F_jkr) * correction, 1.0 + _GAP * mu ** (-2.0 / 3.0)
