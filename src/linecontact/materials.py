r"""Dimensional (SI) layer: materials, adhesion and a cylinder on a substrate.

Everything here converts SI inputs to the paper's groups, calls the nondimensional solvers of
:mod:`linecontact.normal` and converts back. Units: lengths [m], stresses and moduli [Pa],
forces per unit length of cylinder [N/m], work of adhesion [J/m^2].

Materials (Eq. 7 of the paper): body 1 is the cylinder, body 2 the substrate,

.. math::

    \frac{1}{E} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2},\quad
    A = \frac{4(1-\nu_1)}{G_1} + \frac{4(1-\nu_2)}{G_2} = \frac{8}{E},\quad
    B = \frac{2-4\nu_1}{G_1} - \frac{2-4\nu_2}{G_2}.

The solvers assume the uncoupled case :math:`B = 0`; :func:`dundurs_beta` gives Dundurs' second
parameter :math:`\beta = -B/A` and a :class:`~linecontact.errors.CouplingWarning` is issued when
:math:`|\beta|` exceeds ``BETA_WARN``.

Adhesion is given either as the Dugdale stress and range ``(sigma0, h)`` or as the work of
adhesion and equilibrium spacing ``(w, z0)`` of a Lennard-Jones surface potential (Eq. 1).
The Maugis convention takes ``sigma0`` as the theoretical strength of that potential,
:math:`\sigma_0 = 16 w/(9\sqrt{3} z_0)`, and
:math:`h = w/\sigma_0 = 9\sqrt{3} z_0/16 \approx 0.974 z_0` (the paper's "0.97 z0").

References
----------
D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
J. Colloid Interface Sci. 150 (1992) 243--269. doi:10.1016/0021-9797(92)90285-T
J. Dundurs, discussion, J. Appl. Mech. 36 (1969) 650--652. doi:10.1115/1.3564739
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._validation import broadcast, check_array, first_point, scalar
from .domain import DOMAIN, check

__all__ = [
    "BETA_WARN",
    "MAUGIS_H_OVER_Z0",
    "MAUGIS_STRENGTH",
    "adhesion_from_work",
    "composite_modulus",
    "compliance_constants",
    "dundurs_beta",
]

#: |beta| = |B/A| above which a CouplingWarning is issued.
BETA_WARN = 0.05

#: The Maugis strength :math:`S = 16/(9 \sqrt 3)` (1.0264): the peak tension of the Lennard-Jones
#: law (Eq. 1) over :math:`w/z_0`, the Dugdale stress of the Maugis convention
#: :math:`\sigma_0 = S w/z_0`.
#: The one home of this constant (``lennard_jones.MAUGIS_MATCH_SIGMA0``, ``inverse.S_LJ``
#: are aliases).
MAUGIS_STRENGTH = 16.0 / (9.0 * math.sqrt(3.0))
#: :math:`h/z_0 = 1/S = 9 \sqrt{3}/16` (0.974): the Dugdale range of the Maugis convention.
MAUGIS_H_OVER_Z0 = 1.0 / MAUGIS_STRENGTH


def _modulus(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """A Young's modulus inside the domain of ``name``, or inf (a rigid body)."""
    E = check_array(name, value, allow_inf=True)
    lo, _, hi, _ = DOMAIN[name]
    finite = E[np.isfinite(E)]
    if finite.size and (finite.min() < lo or finite.max() > hi):
        bad = finite[(finite < lo) | (finite > hi)].flat[0]
        raise ValueError(
            f"{name} must be in [{lo:g}, {hi:g}] (or inf for a rigid body), got {float(bad)}"
        )
    return E


def _moduli(
    E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    E1 = _modulus("E1", E1)
    E2 = _modulus("E2", E2)
    nu1 = check_array("nu1", nu1, low=-1.0, high=0.5, high_inclusive=True)
    nu2 = check_array("nu2", nu2, low=-1.0, high=0.5, high_inclusive=True)
    E1, nu1, E2, nu2 = broadcast(E1=E1, nu1=nu1, E2=E2, nu2=nu2)
    if np.any(np.isinf(E1) & np.isinf(E2)):
        raise ValueError("E1 and E2 cannot both be infinite (two rigid bodies)")
    return E1, nu1, E2, nu2


def composite_modulus(E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike):
    r"""Plane-strain composite modulus ``E`` [Pa], Eq. (7); :math:`E_2 = \infty`: a rigid substrate.

    Examples
    --------
    >>> round(composite_modulus(70e9, 0.17, 70e9, 0.17) / 1e9, 6)  # E1/(2(1 - nu^2))
    36.041602
    """
    e1, n1, e2, n2 = _moduli(E1, nu1, E2, nu2)
    val = 1.0 / ((1 - n1**2) / e1 + (1 - n2**2) / e2)
    return val.item() if val.ndim == 0 else val


def compliance_constants(E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike):
    """The constants ``A`` and ``B`` of Eq. (7) [1/Pa]."""
    e1, n1, e2, n2 = _moduli(E1, nu1, E2, nu2)
    G1 = e1 / (2 * (1 + n1))
    G2 = e2 / (2 * (1 + n2))
    A = 4 * (1 - n1) / G1 + 4 * (1 - n2) / G2
    B = (2 - 4 * n1) / G1 - (2 - 4 * n2) / G2
    return (A.item(), B.item()) if A.ndim == 0 else (A, B)


def dundurs_beta(E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike):
    r"""Dundurs' second parameter :math:`\beta = -B/A` (Eq. 7; 0 for identical materials).

    With the cylinder as body 1: :math:`\beta = [G_1(1-2\nu_2) - G_2(1-2\nu_1)] /
    [2(G_1(1-\nu_2) + G_2(1-\nu_1))]`, the sign of Hutchinson & Suo (1992)
    with the cylinder as material 1: a rigid cylinder on a substrate of Poisson ratio
    :math:`\nu_2` gives :math:`\beta = (1-2\nu_2)/(2(1-\nu_2))`, 2/7 for 0.3. Some texts
    write the opposite sign; only :math:`|\beta|` matters here (the coupling warning).
    """
    A, B = compliance_constants(E1, nu1, E2, nu2)
    return -B / A


def adhesion_from_work(work_of_adhesion: ArrayLike, equilibrium_spacing: ArrayLike):
    r"""Dugdale stress and range :math:`(\sigma_0, h)` [Pa, m] from :math:`(w, z_0)` [J/m^2, m].

    Maugis convention: :math:`\sigma_0 = 16w/(9\sqrt3 z_0)` (the strength of the
    Lennard-Jones law, Eq. 1) and :math:`h = w/\sigma_0`.

    Examples
    --------
    >>> s0, h = adhesion_from_work(0.1, 0.3e-9)
    >>> round(h / 0.3e-9, 4)
    0.9743
    """
    w = check("work_of_adhesion", work_of_adhesion)
    z0 = check("equilibrium_spacing", equilibrium_spacing)
    w, z0 = broadcast(work_of_adhesion=w, equilibrium_spacing=z0)
    with np.errstate(over="ignore", under="ignore"):
        s0 = MAUGIS_STRENGTH * w / z0
    bad = ~(np.isfinite(s0) & (s0 > 0))
    if np.any(bad):
        _, at = first_point(bad, w=w, z0=z0, s0=s0)
        raise ValueError(
            f"work_of_adhesion={at['w']!r} and equilibrium_spacing="
            f"{at['z0']!r} give sigma0 = 16 w/(9 sqrt(3) z0) = "
            f"{at['s0']!r} [Pa], not a finite positive number"
        )
    h = w / s0
    return (s0.item(), h.item()) if s0.ndim == 0 else (s0, h)


def _adhesion(s0, h, w, z0) -> tuple[float, float]:
    by_stress = s0 is not None or h is not None
    by_work = w is not None or z0 is not None
    if by_stress and by_work:
        raise ValueError(
            "give adhesion either as (cohesive_stress, adhesion_range) or as "
            "(work_of_adhesion, equilibrium_spacing), not both"
        )
    if by_work:
        if w is None or z0 is None:
            raise ValueError("give both work_of_adhesion and equilibrium_spacing")
        s, hh = adhesion_from_work(scalar("work_of_adhesion", w), scalar("equilibrium_spacing", z0))
        return float(s), float(hh)
    if h is None:
        raise ValueError(
            "give adhesion_range h (> 0): it sets the length scale R/h even without adhesion"
        )
    hh = scalar("adhesion_range", h)
    s = 0.0 if s0 is None else scalar("cohesive_stress", s0, low_inclusive=True)
    return s, hh
