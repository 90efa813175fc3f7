r"""The adhesion laws as values: :class:`Dugdale` and :class:`LennardJones`, in SI units.

A law value holds its SI parameters, given as ``(cohesive_stress, adhesion_range)``
:math:`(\sigma_0, h)` [Pa, m] or as ``(work_of_adhesion, equilibrium_spacing)`` :math:`(w, z_0)`
[J/m^2, m], and converts itself to what its kernels take: the Dugdale step of the same work of
adhesion and peak tension (the Maugis matching, :math:`\sigma_0 = 16 w/(9\sqrt3 z_0)`,
:math:`h = w/\sigma_0`), whose groups :math:`R/h` and :math:`\sigma_0/E` both laws' kernels
take (:mod:`linecontact.laws.dugdale`, :mod:`linecontact.laws.lennard_jones`). A body is a
geometry and a law (:class:`~linecontact.Cylinder`: ``adhesion=LennardJones(0.1, 0.3e-9)``);
its problems are those written for the pair, the others refused in one place.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

from ..materials import MAUGIS_STRENGTH, _adhesion

__all__ = ["Dugdale", "Law", "LennardJones"]


@dataclass(frozen=True, init=False)
class Law:
    r"""An adhesion law and its SI parameters (the base of :class:`Dugdale`, :class:`LennardJones`).

    The parameters are keywords (``Dugdale(0.1, 3e-10)`` would leave open whether ``3e-10`` is
    the range ``h`` or the spacing ``z0``, which differ by 2.6 %); :class:`LennardJones` also
    takes its own ``(w, z0)`` in order.

    Parameters
    ----------
    work_of_adhesion, equilibrium_spacing : float, optional
        :math:`w` [J/m^2] and :math:`z_0` [m] (both, or neither).
    cohesive_stress, adhesion_range : float, optional
        :math:`\sigma_0` [Pa] (0: no adhesion) and :math:`h` [m] of the matched Dugdale step,
        instead of :math:`(w, z_0)`.

    Attributes
    ----------
    cohesive_stress, adhesion_range : float
        The Dugdale step of the same work of adhesion and peak tension, whose groups the
        law's kernels take.
    given : dict
        The parameters as given (for messages in the caller's terms).
    """

    #: The law's name (``law`` of the operations, the provenance's ``law``).
    name: ClassVar[str] = ""
    cohesive_stress: float
    adhesion_range: float
    given: dict[str, float] = field(compare=False, repr=False)

    def __init__(
        self,
        *,
        work_of_adhesion: float | None = None,
        equilibrium_spacing: float | None = None,
        cohesive_stress: float | None = None,
        adhesion_range: float | None = None,
    ) -> None:
        s0, h = _adhesion(cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        given: dict[str, float] = {"cohesive_stress": s0, "adhesion_range": h}
        if work_of_adhesion is not None and equilibrium_spacing is not None:
            given = {
                "work_of_adhesion": float(work_of_adhesion),
                "equilibrium_spacing": float(equilibrium_spacing),
            }
        object.__setattr__(self, "cohesive_stress", s0)
        object.__setattr__(self, "adhesion_range", h)
        object.__setattr__(self, "given", given)

    @property
    def work_of_adhesion(self) -> float:
        r""":math:`w = \sigma_0 h` [J/m^2]."""
        return self.cohesive_stress * self.adhesion_range

    @property
    def equilibrium_spacing(self) -> float:
        r""":math:`z_0 = 16 h/(9 \sqrt 3)` [m] (the Maugis matching)."""
        return MAUGIS_STRENGTH * self.adhesion_range

    def same_adhesion(self, law: type[Law]) -> Law:
        """The same adhesion (the same Dugdale step) under ``law`` (:class:`Dugdale`, ...)."""
        out = law.__new__(law)
        for name in ("cohesive_stress", "adhesion_range", "given"):
            object.__setattr__(out, name, getattr(self, name))
        return out

    def __repr__(self) -> str:
        args = ", ".join(f"{k}={v!r}" for k, v in self.given.items())
        return f"{type(self).__name__}({args})"


class Dugdale(Law):
    r"""The Maugis--Dugdale step: tension :math:`\sigma_0` wherever the gap is below :math:`h`.

    Examples
    --------
    >>> Dugdale(cohesive_stress=1e9, adhesion_range=0.5e-9).work_of_adhesion
    0.5
    >>> law = Dugdale(work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)  # the Maugis matching
    >>> round(law.adhesion_range / 0.3e-9, 4)
    0.9743
    """

    name: ClassVar[str] = "dugdale"


class LennardJones(Law):
    r"""The Lennard-Jones law of Eq. (1), with work of adhesion :math:`w` and spacing :math:`z_0`.

    Its kernels take the groups of the Dugdale step of the same :math:`w` and peak tension
    (:mod:`linecontact.laws.lennard_jones`).

    Examples
    --------
    >>> law = LennardJones(0.1, 0.3e-9)
    >>> round(law.work_of_adhesion, 12), round(law.equilibrium_spacing / 1e-9, 12)
    (0.1, 0.3)
    """

    name: ClassVar[str] = "lennard-jones"

    def __init__(
        self,
        work_of_adhesion: float | None = None,
        equilibrium_spacing: float | None = None,
        **dugdale_step: float | None,
    ) -> None:
        # its own (w, z0) in order; the step (cohesive_stress, adhesion_range) as keywords
        super().__init__(
            work_of_adhesion=work_of_adhesion,
            equilibrium_spacing=equilibrium_spacing,
            **dugdale_step,
        )


#: The laws by name (the operations' ``law``).
LAWS: dict[str, Any] = {"dugdale": Dugdale, "lennard-jones": LennardJones}
