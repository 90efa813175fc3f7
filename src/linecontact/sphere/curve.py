r"""The load curve of an adhesive sphere: :func:`sphere_load_curve`.

Its non-contact branch (the sphere held off at a central gap ``g0`` from ``h`` down to 0,
the adhesive zone growing) then its contact branch from ``a -> 0`` to the largest radius,
each state with its load and approach; the pull-offs under load and displacement control
marked. Units as in :mod:`linecontact.sphere`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from .. import domain as _domain
from ..errors import ParameterError
from ..results import SI, Result
from . import _branch as _b
from .contact import INPUTS, check_adhesion, states
from .pulloff import SpherePullOff, _unit, sphere_contact_for_load, sphere_pull_off

#: The most points of each branch.
NUM_MAX = 100_000


@dataclass(frozen=True)
class SphereLoadCurve(Result):
    """The load curve of an adhesive sphere, the pull-offs marked.

    Arrays run along the curve: the non-contact branch from ``g0 = h`` to touching, then
    the contact branch from ``a -> 0`` outwards.

    Attributes
    ----------
    branch : ndarray of str
        ``"non-contact"`` or ``"contact"``.
    central_gap_over_h : ndarray
        The central gap over ``h`` (0 in contact).
    a_over_R, c_over_R, F_over_EhR, delta_over_h : ndarray
        The states: as in :class:`~linecontact.sphere.SphereContact`.
    stable, stable_displacement : ndarray of bool
        Stability under load and displacement control (out of contact: both).
    pull_off_load, pull_off_displacement : ndarray of bool
        The point of each pull-off (none where it is the ``a -> 0`` end).
    pulloff, pulloff_displacement : SpherePullOff
        The two pull-offs.
    """

    inputs: ClassVar[tuple[str, ...]] = INPUTS

    branch: NDArray
    central_gap_over_h: NDArray
    a_over_R: NDArray = field(metadata=SI("contact_radius", "R", "m"))
    c_over_R: NDArray = field(metadata=SI("adhesive_zone_radius", "R", "m"))
    F_over_EhR: NDArray = field(metadata=SI("load", "EhR", "N"))
    delta_over_h: NDArray = field(metadata=SI("approach", "h", "m"))
    stable: NDArray
    stable_displacement: NDArray
    pull_off_load: NDArray
    pull_off_displacement: NDArray
    R_over_h: float
    sigma0_over_E: float
    pulloff: SpherePullOff = field(repr=False)
    pulloff_displacement: SpherePullOff = field(repr=False)


def sphere_load_curve(
    R_over_h: float,
    sigma0_over_E: float,
    *,
    a_max_over_R: float | None = None,
    num: int = 200,
    num_noncontact: int = 40,
) -> SphereLoadCurve:
    r"""The load curve of an adhesive sphere (one parameter point).

    Parameters
    ----------
    R_over_h, sigma0_over_E : float
        As in :func:`~linecontact.sphere.sphere_contact`.
    a_max_over_R : float, optional
        The largest contact radius over ``R``; default: where the load is ten times the
        load-control pull-off in compression, at most 10 (Hertz: ``a/R = 0.05``).
    num, num_noncontact : int
        Points of the contact branch (geometric in ``a``, the pull-offs inserted) and of
        the non-contact branch (0: none), each at most :data:`NUM_MAX`.

    Returns
    -------
    SphereLoadCurve

    Examples
    --------
    >>> c = sphere_load_curve(1e4, 0.001, num=50, num_noncontact=10)
    >>> print(c.branch[0], c.branch[-1], bool(c.pull_off_load.any()))
    non-contact contact True
    """
    rho = _domain.scalar("R_over_h", R_over_h)
    s = _domain.scalar("sigma0_over_E", sigma0_over_E)
    check_adhesion(np.asarray(s))
    for name, value, low in (("num", num, 2), ("num_noncontact", num_noncontact, 0)):
        if not isinstance(value, int | np.integer) or not low <= value <= NUM_MAX:
            raise ParameterError(
                name, f"{name} must be an integer in [{low}, {NUM_MAX}], got {value!r}"
            )
    po = sphere_pull_off(rho, s)
    pd = sphere_pull_off(rho, s, control="displacement")
    if a_max_over_R is None:
        load = 10 * abs(float(po.F_pulloff_over_EhR)) if s > 0 else 0.0
        try:
            a_end = float(sphere_contact_for_load(load, rho, s).a_over_R) if s > 0 else 0.05
        except ParameterError:  # wider than the domain's 10 R: the curve ends there
            a_end = _domain.DOMAIN["a_over_R"][2]
    else:
        a_end = _domain.scalar("a_max_over_R", a_max_over_R)
    a0 = float(_unit(rho, s)) * 1e-4 if s > 0 else a_end * 1e-4
    a_end = max(a_end, 2 * a0)
    marks = [float(p.a_over_R_at_pulloff) for p in (po, pd)]
    A = np.geomspace(a0, a_end, num)
    A = np.unique(np.concatenate([A, [m for m in marks if a0 < m < a_end]]))
    contact = states(A, np.full(A.shape, rho), np.full(A.shape, s))
    gap = np.linspace(1.0, 0.0, num_noncontact, endpoint=False) if s > 0 else np.zeros(0)
    x, F, delta = _b.separated(gap, np.full(gap.shape, rho), np.full(gap.shape, s))
    n = gap.size
    return SphereLoadCurve(
        branch=np.array(["non-contact"] * n + ["contact"] * A.size),
        central_gap_over_h=np.concatenate([gap, np.zeros(A.size)]),
        a_over_R=np.concatenate([np.zeros(n), A]),
        c_over_R=np.concatenate([x, contact["c_over_R"]]),
        F_over_EhR=np.concatenate([F, contact["F_over_EhR"]]),
        delta_over_h=np.concatenate([delta, contact["delta_over_h"]]),
        stable=np.concatenate([np.ones(n, bool), contact["stable"]]),
        stable_displacement=np.concatenate([np.ones(n, bool), contact["stable_displacement"]]),
        pull_off_load=np.concatenate([np.zeros(n, bool), A == marks[0]]),
        pull_off_displacement=np.concatenate([np.zeros(n, bool), A == marks[1]]),
        R_over_h=rho,
        sigma0_over_E=s,
        pulloff=po,
        pulloff_displacement=pd,
    )
