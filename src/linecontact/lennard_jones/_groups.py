"""The Lennard-Jones pull-off in the groups of the Dugdale problem.

The conversion of the Dugdale groups ``(R/h, sigma0/E)`` to the law's own units
(:func:`lj_groups`) and of the pull-off (:func:`pull_off_of`), once:
:mod:`linecontact.laws.lennard_jones` and :mod:`linecontact.lennard_jones_groups` use them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from .._validation import first_point
from ..results import SI, Result
from ._curve import LJPullOff, lj_pull_off
from ._matching import MAUGIS_MATCH_SIGMA0, maugis_parameter_of_mu, mu_of_dugdale


@dataclass(frozen=True)
class LennardJonesPullOff(Result):
    """Pull-off under the Lennard-Jones law, in the groups of the Maugis-Dugdale problem.

    The law has the work of adhesion ``w = sigma0 h`` of the Dugdale step and its peak
    tension ``sigma0`` (the Maugis matching: ``z0 = h / 0.974``). Loads over ``E h``, widths
    over ``R``, gaps over ``h``: the same units as :class:`linecontact.PullOff`.

    Attributes
    ----------
    F_pulloff_over_Eh, error_estimate_over_Eh : float or ndarray
        The pull-off force (the most tensile load) and its estimated error.
    a_over_R_at_pulloff : float or ndarray
        Half-width of the repulsive region there (0: the pull-off precedes it).
    central_gap_over_h_at_pulloff : float or ndarray
    F_jump_in_over_Eh : float or ndarray
        The jump-in load where the curve is S-shaped, else ``nan``.
    mu, maugis_parameter : float or ndarray
        The group ``w sqrt(R/z0)/(E z0)`` and the Maugis parameter of the step.
    law : str
        ``"lennard-jones"``.
    n : int
        Nodes of the finest mesh (0 for the limit form).
    converged : bool or ndarray
    method : str or ndarray
        ``"self-consistent"`` or ``"limit"`` (:class:`LJPullOff`).
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    F_pulloff_over_Eh: NDArray | float = field(metadata=SI("pull_off_force", "Eh", "N/m"))
    a_over_R_at_pulloff: NDArray | float = field(
        metadata=SI("contact_half_width_at_pull_off", "R", "m")
    )
    central_gap_over_h_at_pulloff: NDArray | float = field(
        metadata=SI("central_gap_at_pull_off", "h", "m")
    )
    F_jump_in_over_Eh: NDArray | float = field(metadata=SI("jump_in_force", "Eh", "N/m"))
    error_estimate_over_Eh: NDArray | float = field(metadata=SI("error_estimate", "Eh", "N/m"))
    mu: NDArray | float
    maugis_parameter: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    law: str
    n: NDArray | int
    converged: NDArray | bool
    method: NDArray | str = "self-consistent"


def lj_groups(
    R_over_h, sigma0_over_E, *, pull_off: bool = False
) -> tuple[NDArray, NDArray, NDArray]:
    """``(mu, sqrt(R/z0), load scale w sqrt(R/z0)/(E h))`` at validated Dugdale groups.

    Refuses ``sigma0_over_E = 0`` (no work of adhesion) and ``mu`` beyond the domain
    ``DOMAIN["lj_mu"]`` of the self-consistent solver, naming the point; with ``pull_off``
    every ``mu`` (the pull-off has a limit form beyond). The one conversion of the Dugdale
    groups to the law's own units (:mod:`linecontact.lennard_jones_groups` re-exports it).
    """
    rho = np.asarray(R_over_h, float)
    s = np.asarray(sigma0_over_E, float)
    if np.any(s <= 0):
        raise ValueError(
            "sigma0_over_E must be > 0 for the Lennard-Jones law (it sets the work of "
            f"adhesion w = sigma0 h), got {float(s[s <= 0].flat[0])!r}"
        )
    mu, R_over_z0 = mu_of_dugdale(rho, s)
    hi = math.inf if pull_off else _DOMAIN_MU_HIGH()
    if np.any(mu > hi):
        _, at = first_point(mu > hi, rho=rho, s=s, mu=mu)
        raise ValueError(
            f"the Lennard-Jones law's contacts and load curves are solved for mu = "
            f"(sigma0/E) sqrt(R/h) * {MAUGIS_MATCH_SIGMA0**-1.5:.4f} in [0, {hi:g}] (Maugis "
            f"parameter up to {float(maugis_parameter_of_mu(hi)):.3g}; its pull-off at every "
            f"mu); R_over_h={at['rho']!r}, "
            f"sigma0_over_E={at['s']!r} give mu={at['mu']:.6g}"
        )
    root = np.sqrt(R_over_z0)
    return np.asarray(mu, float), root, s * root


def pull_off_of(po: LJPullOff, R_over_h: float, sigma0_over_E: float) -> LennardJonesPullOff:
    """The native pull-off ``po`` in the Dugdale groups (scalars): the one conversion."""
    mu, root, scale = (float(v) for v in lj_groups(R_over_h, sigma0_over_E, pull_off=True))
    return LennardJonesPullOff(
        F_pulloff_over_Eh=po.F_pulloff * scale,
        a_over_R_at_pulloff=po.half_width_at_pulloff / root,
        central_gap_over_h_at_pulloff=po.central_gap_at_pulloff * MAUGIS_MATCH_SIGMA0,
        F_jump_in_over_Eh=po.F_jump_in * scale,
        error_estimate_over_Eh=po.error_estimate * scale,
        mu=po.mu,
        maugis_parameter=po.maugis_parameter,
        R_over_h=float(R_over_h),
        sigma0_over_E=float(sigma0_over_E),
        law="lennard-jones",
        n=po.n,
        converged=po.converged,
        method=po.method,
    )


def pull_off_in_dugdale_groups(R_over_h, sigma0_over_E) -> LennardJonesPullOff:
    """:func:`lj_pull_off` at Dugdale groups (validated arrays of one shape, or scalars).

    Each point is :func:`pull_off_of` its native pull-off; the public entry point is
    :func:`linecontact.laws.lennard_jones.pull_off`.
    """
    from ..results import as_output

    rho = np.asarray(R_over_h, float)
    s = np.asarray(sigma0_over_E, float)
    scalar = rho.ndim == 0 and s.ndim == 0
    rho, s = np.broadcast_arrays(rho, s)
    mu = lj_groups(rho, s, pull_off=True)[0]
    fields = {
        "F_pulloff_over_Eh": float,
        "a_over_R_at_pulloff": float,
        "central_gap_over_h_at_pulloff": float,
        "F_jump_in_over_Eh": float,
        "error_estimate_over_Eh": float,
        "n": int,
        "method": object,
    }
    vals: dict[str, NDArray] = {k: np.empty(rho.shape, dt) for k, dt in fields.items()}
    for i in np.ndindex(rho.shape):
        q = pull_off_of(lj_pull_off(float(mu[i])), float(rho[i]), float(s[i]))
        for k in fields:
            vals[k][i] = getattr(q, k)

    def o(v):
        return as_output(v, scalar)

    return LennardJonesPullOff(
        **{k: o(v) for k, v in vals.items()},
        mu=o(mu),
        maugis_parameter=o(maugis_parameter_of_mu(mu)),
        R_over_h=o(rho),
        sigma0_over_E=o(s),
        law="lennard-jones",
        converged=o(np.ones(rho.shape, bool)),
    )


def _DOMAIN_MU_HIGH() -> float:  # noqa: N802
    from ..domain import DOMAIN

    return DOMAIN["lj_mu"][2]
