r"""The Lennard-Jones law in the groups of the Maugis--Dugdale problem: load curve and contact.

:mod:`linecontact.lennard_jones` solves the Lennard-Jones law (Eq. 1) self-consistently in
its own units (lengths along the surface over :math:`\sqrt{R z_0}`, gaps over :math:`z_0`, loads
over :math:`w \sqrt{R/z_0}`, one group :math:`\mu = w \sqrt{R/z_0}/(E z_0)`). Here its load curve
and its contact for a load are given in the groups of the rest of the library -- :math:`R/h`,
:math:`\sigma_0/E`, loads over :math:`E h`, widths over ``R``, gaps over ``h`` -- for the
:func:`~linecontact.laws.lennard_jones.load_curve` and
:func:`~linecontact.laws.lennard_jones.contact_for_load` of :mod:`linecontact.laws.lennard_jones`
(and the ``lennard_jones_*`` methods of :class:`linecontact.Cylinder`).

The law keeps the Dugdale step's work of adhesion :math:`w = \sigma_0 h` and its peak tension
:math:`\sigma_0 = S w/z_0` (the Maugis matching, :math:`S` = :data:`~linecontact.lennard_jones.
MAUGIS_MATCH_SIGMA0` = :math:`16/(9 \sqrt 3)`), so

.. math::

    z_0 = S h,\qquad \frac{R}{z_0} = \frac{R/h}{S},\qquad
    \mu = \frac{\sigma_0/E}{S}\sqrt{\frac{R}{z_0}},\qquad
    \frac{w\sqrt{R/z_0}}{E h} = \frac{\sigma_0}{E}\sqrt{\frac{R}{z_0}},

a half-width :math:`a/R = \xi / \sqrt{R/z_0}` and a gap :math:`g/h = \zeta S`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from . import closed_forms as _cf
from ._validation import FailurePolicy, failure_policy, first_point
from .errors import ConvergenceError, NoEquilibriumError
from .lennard_jones import (  # lj_groups, pull_off_of: defined there, re-exported here
    MAUGIS_MATCH_SIGMA0,
    LennardJonesPullOff,
    LJContinuation,
    LJState,
    lj_curve,
    lj_groups,
    lj_pull_off,
    maugis_parameter_of_mu,
    pull_off_of,
)
from .results import SI, Result, as_output

__all__ = [
    "LJ_LOAD_MAX",
    "BelowPullOffError",
    "LennardJonesContact",
    "LennardJonesLoadCurve",
    "contact_for_load_in_dugdale_groups",
    "lj_groups",
    "load_curve_in_dugdale_groups",
    "load_max_over_Eh",
    "pull_off_of",
]

#: Most compressive load the Lennard-Jones solver is asked for, over :math:`w \sqrt{R/z_0}`: ten
#: times the rigid cylinder's pull-off (2.466), 3.3 times the default end of its curve. At
#: such loads both laws approach Hertz and the Dugdale law (the default) gives the contact;
#: the contact widens with the load (like :math:`\sqrt{\mu F}`), and the meshes with it.
LJ_LOAD_MAX = 25.0

#: The inputs of both results (:attr:`linecontact.results.Result.inputs`): the Dugdale groups
#: and the law's own group with the Maugis parameter of the matched step.
_INPUTS = ("R_over_h", "sigma0_over_E", "law", "mu", "maugis_parameter")


@dataclass(frozen=True)
class LennardJonesLoadCurve(Result):
    r"""The load curve under the Lennard-Jones law, in the groups of :class:`linecontact.LoadCurve`.

    One point per state of the continuation of :func:`linecontact.lennard_jones.lj_curve`,
    the central gap decreasing (from far away, through the pull-off, to the largest load).
    No state is split into contact and adhesive zones: ``a_over_R`` is the half-width of the
    repulsive region (the gap below ``z0``), 0 where there is none.

    Attributes
    ----------
    F_over_Eh, error_estimate_over_Eh : ndarray
        The load (compressive positive) and its estimated error (nested meshes).
    a_over_R : ndarray
        Half-width of the repulsive region over ``R``.
    central_gap_over_h : ndarray
        The gap at the centre over ``h`` (:math:`z_0 = 1.026\, h`).
    stable : ndarray of bool
        Stable under load control (:math:`dF/dg_0 < 0`).
    turning_point : ndarray of bool
        The samples at the extrema of the load (pull-off and, where the curve is S-shaped,
        the jump-in load and the local minimum before it).
    mu, maugis_parameter : float
        The group :math:`w \sqrt{R/z_0}/(E z_0)` and the Maugis parameter of the matched step.
    law : str
        ``"lennard-jones"``.
    R_over_h, sigma0_over_E : float
        The parameters.
    pulloff : LennardJonesPullOff
        The pull-off (refined between the samples).
    """

    inputs: ClassVar[tuple[str, ...]] = _INPUTS

    F_over_Eh: NDArray = field(metadata=SI("load", "Eh", "N/m"))
    a_over_R: NDArray = field(metadata=SI("contact_half_width", "R", "m"))
    central_gap_over_h: NDArray = field(metadata=SI("central_gap", "h", "m"))
    error_estimate_over_Eh: NDArray = field(metadata=SI("error_estimate", "Eh", "N/m"))
    stable: NDArray
    turning_point: NDArray
    mu: float
    maugis_parameter: float
    law: str
    R_over_h: float
    sigma0_over_E: float
    pulloff: LennardJonesPullOff = field(repr=False)


@dataclass(frozen=True)
class LennardJonesContact(Result):
    r"""The contact carrying a load under the Lennard-Jones law (as :class:`NormalContact`).

    Attributes
    ----------
    a_over_R : ndarray or float
        Half-width of the repulsive region (the gap below ``z0``) over ``R``.
    central_gap_over_h : ndarray or float
        The gap at the centre over ``h``.
    F_over_Eh : ndarray or float
        The load asked for (the state carries it to the root-search tolerance).
    error_estimate_over_Eh : ndarray or float
        Estimated discretisation error of the state's load (nested meshes).
    R_over_h, sigma0_over_E : ndarray or float
        The parameters, broadcast.
    mu, maugis_parameter : ndarray or float
        The group :math:`w \sqrt{R/z_0}/(E z_0)` and the Maugis parameter of the matched step.
    law : str
        ``"lennard-jones"``.
    n : ndarray or int
        Nodes of the finest mesh.
    residual : ndarray or float
        Largest residual of the gap equation at the nodes, relative to the gap.
    converged : ndarray or bool
        All tolerances met (a state that does not converge raises ``ConvergenceError``).
    stable : ndarray or bool
        Stable under load control: always, on the branch beyond the pull-off.
    state : ndarray of str or str
        ``"contact"``; ``"no-equilibrium"`` for a load below the pull-off force, reported
        with ``on_failure="report"`` (its values are NaN).
    """

    inputs: ClassVar[tuple[str, ...]] = _INPUTS

    a_over_R: NDArray | float = field(metadata=SI("contact_half_width", "R", "m"))
    central_gap_over_h: NDArray | float = field(metadata=SI("central_gap", "h", "m"))
    F_over_Eh: NDArray | float = field(metadata=SI("load", "Eh", "N/m"))
    error_estimate_over_Eh: NDArray | float = field(metadata=SI("error_estimate", "Eh", "N/m"))
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    mu: NDArray | float
    maugis_parameter: NDArray | float
    law: str
    n: NDArray | int
    residual: NDArray | float
    converged: NDArray | bool
    stable: NDArray | bool
    state: NDArray | str


class BelowPullOffError(NoEquilibriumError):
    """A load below the pull-off force under the Lennard-Jones law (Dugdale groups).

    ``index`` (flat, C order), ``F_over_Eh``, ``F_pulloff_over_Eh`` and
    ``error_estimate_over_Eh`` (of the pull-off) let the SI layer say it in N/m.
    """

    def __init__(
        self,
        message: str,
        index: int,
        F_over_Eh: float,
        F_pulloff_over_Eh: float,
        error_estimate_over_Eh: float,
    ) -> None:
        super().__init__(message)
        self.index = index
        self.F_over_Eh = F_over_Eh
        self.F_pulloff_over_Eh = F_pulloff_over_Eh
        self.error_estimate_over_Eh = error_estimate_over_Eh


# --------------------------------------------------------------------------------------------
# the groups


def load_max_over_Eh(R_over_h, sigma0_over_E) -> NDArray:
    """:data:`LJ_LOAD_MAX` over ``E h`` at the Dugdale groups (validated as :func:`lj_groups`)."""
    return LJ_LOAD_MAX * lj_groups(R_over_h, sigma0_over_E)[2]


def _check_load(F_native: NDArray, F_over_Eh: NDArray, name: str) -> None:
    """Refuse loads beyond :data:`LJ_LOAD_MAX` (in the units of the caller's ``name``)."""
    over = np.reshape(F_native > LJ_LOAD_MAX, -1)
    if np.any(over):
        _, at = first_point(F_native > LJ_LOAD_MAX, F=F_over_Eh, Fn=F_native)
        Fi = at["F"]
        limit = Fi / at["Fn"] * LJ_LOAD_MAX
        raise ValueError(
            f"{name}={Fi!r} is beyond the loads the Lennard-Jones solver is asked for, up to "
            f"F_over_Eh = {limit:.6g} here ({LJ_LOAD_MAX:g} w sqrt(R/z0), ten times the rigid "
            "cylinder's pull-off); at such loads both laws approach Hertz, and the Dugdale "
            "law (the default) gives the contact"
        )


# --------------------------------------------------------------------------------------------
# the load curve


def load_curve_in_dugdale_groups(
    R_over_h: float, sigma0_over_E: float, F_max_over_Eh: float | None = None
) -> LennardJonesLoadCurve:
    """:func:`~linecontact.lennard_jones.lj_curve` at validated scalar Dugdale groups.

    ``F_max_over_Eh`` (> 0) ends the curve; default the solver's (7.5 w sqrt(R/z0), three
    times the rigid cylinder's pull-off).
    """
    rho, s = float(R_over_h), float(sigma0_over_E)
    mu_a, root_a, scale_a = lj_groups(rho, s)
    mu, root, scale = float(mu_a), float(root_a), float(scale_a)
    F_max = None  # the solver's default
    if F_max_over_Eh is not None:
        Fm = float(F_max_over_Eh)
        if not (math.isfinite(Fm) and Fm > 0):
            raise ValueError(f"F_max_over_Eh must be a finite load > 0, got {F_max_over_Eh!r}")
        F_max = Fm / scale
        _check_load(np.asarray(F_max), np.asarray(Fm), "F_max_over_Eh")
    c = lj_curve(mu, F_max=F_max)
    A = c.half_width / root
    _cf._warn_wide(A, stacklevel=4)
    return LennardJonesLoadCurve(
        F_over_Eh=c.F * scale,
        a_over_R=A,
        central_gap_over_h=c.central_gap_over_z0 * MAUGIS_MATCH_SIGMA0,
        error_estimate_over_Eh=c.error_estimate * scale,
        stable=c.stable,
        turning_point=c.turning,
        mu=mu,
        maugis_parameter=float(maugis_parameter_of_mu(mu)),
        law="lennard-jones",
        R_over_h=rho,
        sigma0_over_E=s,
        pulloff=pull_off_of(c.pull_off, rho, s),
    )


# --------------------------------------------------------------------------------------------
# the contact for a load


def contact_for_load_in_dugdale_groups(
    F_over_Eh: NDArray,
    R_over_h: NDArray,
    sigma0_over_E: NDArray,
    *,
    scalar: bool,
    on_failure: FailurePolicy = "raise",
) -> LennardJonesContact:
    """:func:`~linecontact.lennard_jones.lj_contact_for_load` at validated, broadcast groups.

    The points are solved one by one (each continues the curve from the pull-off of its
    ``mu``, searched once per ``mu``: :class:`~linecontact.lennard_jones.LJContinuation`), by
    increasing load within each ``mu``, so that a load below the pull-off is met first: it
    raises :class:`BelowPullOffError` (a :class:`~linecontact.errors.NoEquilibriumError`,
    naming the first such point) before any other point of its ``mu`` is solved, or with
    ``on_failure="report"`` gives ``state == "no-equilibrium"`` and NaN values (README,
    "Conventions").
    Points with the same load and ``mu`` are solved once. A failed search of the solver
    raises :class:`~linecontact.errors.ConvergenceError`.
    """
    F = np.asarray(F_over_Eh, float)
    rho = np.asarray(R_over_h, float)
    s = np.asarray(sigma0_over_E, float)
    shape = F.shape
    mu, root, scale = (np.reshape(v, -1) for v in lj_groups(rho, s))
    Ff = np.reshape(F, -1)
    Fn = Ff / scale  # over w sqrt(R/z0)
    _check_load(Fn, Ff, "F_over_Eh")
    report = failure_policy(on_failure) == "report"
    P = Ff.size
    A, G, E = np.full(P, np.nan), np.full(P, np.nan), np.full(P, np.nan)
    res = np.full(P, np.nan)
    n = np.zeros(P, int)
    bad = np.zeros(P, bool)
    solved: dict[tuple[float, float], LJState | None] = {}  # None: below the pull-off
    curve: LJContinuation | None = None  # at one mu: its pull-off is searched once
    for i in np.lexsort((Fn, mu)):  # by mu, then by load
        key = (float(mu[i]), float(Fn[i]))
        if key not in solved:
            if curve is None or curve.mu != key[0]:
                curve = LJContinuation(key[0])
            try:
                solved[key] = curve.contact_for_load(key[1])
            except NoEquilibriumError:
                solved[key] = None
            except ValueError as e:  # the inputs are valid: the solver's search failed
                raise ConvergenceError(
                    f"the Lennard-Jones contact for a load did not converge at F_over_Eh="
                    f"{float(Ff[i])!r} (mu={key[0]:.6g}, F={key[1]:.6g} w sqrt(R/z0)): {e}"
                ) from e
        st = solved[key]
        if st is None:
            if not report:
                raise _below_pull_off(int(i), Ff, rho, s, mu, scale, shape) from None
            bad[i] = True
            continue
        A[i] = st.half_width / root[i]
        G[i] = st.central_gap_over_z0 * MAUGIS_MATCH_SIGMA0
        E[i] = st.error_estimate * scale[i]
        res[i] = st.residual
        n[i] = st.n
    _cf._warn_wide(A.reshape(shape) if shape else A[0], stacklevel=4)
    vals = dict(
        a_over_R=A,
        central_gap_over_h=G,
        F_over_Eh=Ff,
        error_estimate_over_Eh=E,
        R_over_h=np.reshape(rho, -1),
        sigma0_over_E=np.reshape(s, -1),
        mu=mu,
        maugis_parameter=maugis_parameter_of_mu(mu),
        n=n,
        residual=res,
        converged=~bad,
        stable=~bad,
        state=np.where(bad, "no-equilibrium", "contact"),
    )
    out = {k: as_output(np.reshape(v, shape), scalar) for k, v in vals.items()}
    return LennardJonesContact(law="lennard-jones", **out)


def _below_pull_off(i, F, rho, s, mu, scale, shape) -> BelowPullOffError:
    """The error for the load ``i`` (flat) found below the pull-off, in the Dugdale groups.

    It names the first point in C order of that ``mu`` below the pull-off force (``i``, the
    lowest load, where the pull-off of :func:`lj_pull_off` differs from the solver's within
    its error estimate).
    """
    po = lj_pull_off(float(mu[i]))
    below = np.flatnonzero((mu == mu[i]) & (F / scale < po.F_pulloff))
    i = int(below[0]) if below.size else i
    F_po = po.F_pulloff * float(scale[i])
    err = po.error_estimate * float(scale[i])
    rho_i = float(np.reshape(np.broadcast_to(rho, shape), -1)[i])
    s_i = float(np.reshape(np.broadcast_to(s, shape), -1)[i])
    return BelowPullOffError(
        f"no contact carries F_over_Eh={float(F[i])!r} under the Lennard-Jones law: it is "
        f"below the pull-off force, the most tensile load of the curve F_pulloff_over_Eh="
        f"{F_po!r} (error estimate {err:.2g}; R_over_h={rho_i!r}, sigma0_over_E={s_i!r}, "
        f"mu={float(mu[i]):.6g}); the contact has pulled off",
        int(i),
        float(F[i]),
        F_po,
        err,
    )
