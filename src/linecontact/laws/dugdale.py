"""The Maugis--Dugdale law: the functions of :mod:`linecontact.normal` under the law's name.

The Dugdale step (a constant tension ``sigma0`` up to a separation ``h``) is the law of the
paper and the default of the library; this module gives its ``pull_off``,
``contact_for_load`` and ``load_curve`` beside those of
:mod:`linecontact.laws.lennard_jones`, with the same names and argument order.
"""

from __future__ import annotations

from ..normal import LoadCurve, NormalContact, PullOff, contact_for_load, load_curve, pull_off

__all__ = [
    "LoadCurve",
    "NormalContact",
    "PullOff",
    "contact_for_load",
    "load_curve",
    "pull_off",
]
