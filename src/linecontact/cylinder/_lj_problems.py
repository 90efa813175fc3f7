"""The cylinder's problems under the Lennard-Jones law in SI units (``self`` is the cylinder).

:meth:`Cylinder.contact` for a load, :meth:`Cylinder.pull_off` and :meth:`Cylinder.load_curve`
of a cylinder whose adhesion is a :class:`~linecontact.laws.LennardJones` law: the
self-consistent solvers of :mod:`linecontact.laws.lennard_jones`, with SI messages.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._validation import FailurePolicy, scalar
from ..errors import NoEquilibriumError
from ..units import Scales, to_si
from ._checks import _as_given, _normal_load, _small_strain_in_si, _warn_small_strain, _warn_widths
from ._results import (
    CylinderLennardJonesContact,
    CylinderLennardJonesLoadCurve,
    CylinderLennardJonesPullOff,
)

#: ``self`` is a :class:`~linecontact.cylinder.Cylinder` (not imported: it imports this module).
Cylinder = Any


def for_load(
    self: Cylinder, name: str, load: ArrayLike, policy: FailurePolicy = "raise"
) -> CylinderLennardJonesContact:
    """The contact carrying ``load`` [N/m] under the Lennard-Jones law (SI messages)."""
    from .. import lennard_jones_groups as _ljg
    from ..laws import lennard_jones as _lj

    F, Eh = _normal_load(self, name, load)
    F_max = float(_ljg.load_max_over_Eh(self.R_over_h, self.sigma0_over_E)) * Eh
    if np.any(F > F_max):
        raise ValueError(
            f"{name}={float(F[F > F_max].flat[0])!r} N/m is beyond the loads the "
            f"Lennard-Jones solver is asked for, up to {F_max:.6g} N/m here (ten times the "
            "rigid cylinder's pull-off); at such loads both laws approach Hertz, and the "
            "Dugdale law (the default) gives the contact"
        )
    try:
        with _small_strain_in_si():  # said in metres below
            r = _lj.contact_for_load(F / Eh, self.R_over_h, self.sigma0_over_E, on_failure=policy)
    except _ljg.BelowPullOffError as e:
        Fi = float(np.reshape(F, -1)[e.index])
        raise NoEquilibriumError(
            f"no contact carries {name}={Fi!r} N/m under the Lennard-Jones law: it is "
            f"below the pull-off force {e.F_pulloff_over_Eh * Eh!r} N/m (error estimate "
            f"{e.error_estimate_over_Eh * Eh:.2g} N/m); the cylinder has pulled off"
        ) from None

    si = to_si(r, Scales.of(self))
    # the load as given (not back from F/(E h))
    si["load"] = _as_given(F, r.F_over_Eh)
    _warn_widths(si["contact_half_width"], self.radius, stacklevel=4)
    return CylinderLennardJonesContact(
        **si, stable=r.stable, state=r.state, nondimensional=r, scales=Scales.of(self)
    )


def pull_off(self: Cylinder) -> CylinderLennardJonesPullOff:
    """The pull-off under the Lennard-Jones law (warnings point at the caller's caller)."""
    from ..laws import lennard_jones as _lj

    self._check_lennard_jones(pull_off=True)
    q = _lj.pull_off(self.R_over_h, self.sigma0_over_E)
    si = {k: float(v) for k, v in to_si(q, Scales.of(self)).items()}
    _warn_widths(
        si["contact_half_width_at_pull_off"],
        self.radius,
        "the contact half-width at pull-off",
        "the repulsive region vanishes before the pull-off",
        stacklevel=4,
    )
    return CylinderLennardJonesPullOff(**si, method=str(q.method), nondimensional=q)


def load_curve(self: Cylinder, max_load: float | None) -> CylinderLennardJonesLoadCurve:
    """The load curve under the Lennard-Jones law up to the compressive ``max_load`` [N/m].

    Its ``nondimensional`` is the curve in the Dugdale groups, with the pull-off.
    """
    from .. import lennard_jones_groups as _ljg
    from ..laws import lennard_jones as _lj

    self._check_lennard_jones()
    F_max = None
    if max_load is not None:
        max_load = scalar("max_load", max_load)  # a compressive load, > 0
        F_max = float(_ljg.load_max_over_Eh(self.R_over_h, self.sigma0_over_E))
        limit = self.in_si(F_max, "Eh")
        if max_load > limit:
            raise ValueError(
                f"max_load={max_load!r} N/m is beyond the loads the Lennard-Jones solver is "
                f"asked for, up to {limit:.6g} N/m here (ten times the rigid cylinder's "
                "pull-off); at such loads both laws approach Hertz: use law='dugdale'"
            )
        F_max = self.over(max_load, "Eh")
    with _small_strain_in_si():
        c = _lj.load_curve(self.R_over_h, self.sigma0_over_E, F_max_over_Eh=F_max)
    curve = CylinderLennardJonesLoadCurve(
        **to_si(c, Scales.of(self)),
        stable=c.stable,
        turning_point=c.turning_point,
        nondimensional=c,
    )
    _warn_small_strain(curve.contact_half_width, self.radius, stacklevel=4)
    return curve
