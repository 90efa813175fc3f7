"""Errors and warnings of linecontact."""

from __future__ import annotations


class ConvergenceError(RuntimeError):
    """A solver did not meet its tolerance; the message names the parameters."""


class NoEquilibriumError(ValueError):
    """The requested physical state does not exist (e.g. a load below the pull-off force)."""


class ModelValidityWarning(UserWarning):
    """An input lies where the model is doubtful, or looks like a value in the wrong units.

    Issued for a contact half-width beyond the small-strain (half-plane) range of the
    solvers (``a/R`` above :data:`linecontact.normal.A_OVER_R_SMALL_STRAIN`), and by the SI
    layer for a radius, modulus, work of adhesion or adhesion range (``z0``) outside the
    ranges of :data:`linecontact.cylinder.PLAUSIBLE`, and for an SI contact half-width that is
    no physical width (below :data:`linecontact.cylinder.WIDTH_MIN`, 1e-15 m, or above the
    radius); as :class:`CouplingWarning`, for materials whose Dundurs beta is not small. The
    numbers are still computed.
    """


class CouplingWarning(ModelValidityWarning):
    """The materials couple normal and tangential tractions (Dundurs beta not small).

    The solvers assume the uncoupled case (B = 0 in Eq. 6 of the paper): a model note, so a
    :class:`ModelValidityWarning` (silencing that silences this too; the command line's
    ``--quiet`` does).
    """


class UnitsWarning(ModelValidityWarning):
    """An input or a result that looks like a value in the wrong units ("is the ... in m?").

    A :class:`ModelValidityWarning` (its catchers catch it too); the command line prints it
    even with ``--quiet``, which silences the model notes (coupling, small strain) only.
    """


class ParameterError(ValueError):
    """An input refused, with the name of the parameter it was given as.

    ``parameter`` is the name as the caller spelled it (a keyword, an HTTP field, a query
    key); each shell says it in its own spelling (``--radius`` on the command line, the
    field on a page).
    """

    def __init__(self, parameter: str, message: str) -> None:
        super().__init__(message)
        self.parameter = parameter
