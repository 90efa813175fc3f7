"""Errors and warnings of linecontact."""

from __future__ import annotations


class ConvergenceError(RuntimeError):
    """A solver did not meet its tolerance; the message names the parameters."""


class NoEquilibriumError(ValueError):
    """The requested physical state does not exist (e.g. a load below the pull-off force)."""


class CouplingWarning(UserWarning):
    """The materials couple normal and tangential tractions (Dundurs beta not small).

    The solvers assume the uncoupled case (B = 0 in Eq. 6 of the paper).
    """
