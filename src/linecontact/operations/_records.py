"""The records every operation gives: a result's table with the call's command line.

Beside the result's own columns, its SI columns (:func:`si_shown`), the state and reason of
each point of a contact (:func:`convergence`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..output import Table, table_from_result
from ._common import null_missing, si_columns


def records(
    args: Any,
    result: Any,
    params: dict[str, Any],
    columns: dict[str, Any],
    title: str,
    show: Sequence[str],
    *,
    contact: tuple[np.ndarray, np.ndarray, str] | None = None,
    **how: Any,
) -> Table:
    """The records of ``result`` for the call ``args``, with its command line.

    ``params`` and ``columns`` (beside the result's own) as in
    :func:`~linecontact.output.table_from_result`, with the ``title`` and the columns to
    ``show``; ``how`` the rest (``drop``, ``scales``). ``contact``, for contacts one per
    point: ``(state, reason, given)``, each point's state and why it has none (columns; the
    state shown where a point has no contact, whose values are then missing, but for its
    input ``given``, its state and its reason: :func:`null_missing`).
    """
    if contact is not None:
        state, reason, given = contact
        if np.any(state != "contact"):
            show = [*show, "state"]
        columns = {**columns, "state": state, "reason": reason}
    table = table_from_result(
        result,
        columns=columns,
        parameters=params,
        command=args.command_line(),
        title=title,
        show=show,
        **how,
    )
    if contact is None:
        return table
    return null_missing(table, state != "contact", keep=(given, "state", "reason"))


def convergence(result: Any, method: str, estimate: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The state of each given half-width, ``contact`` or ``not-converged``, and why not.

    The reason names the solver ``method`` and the point's ``a_over_R`` (with ``estimate``,
    the result's error estimate too).
    """
    ok = np.asarray(result.converged, bool).reshape(-1)
    state = np.where(ok, "contact", "not-converged")
    reason = np.full(ok.shape, None, dtype=object)
    A_over_R = np.reshape(result.a_over_R, -1)
    for i in np.flatnonzero(~ok):
        reason[i] = f"the {method} solver did not converge at a_over_R={float(A_over_R[i])!r}"
        if estimate:
            error = float(np.reshape(result.error_estimate, -1)[i])
            reason[i] += f" (error estimate {error:.3g})"
    return state, reason


def si_shown(
    args: Any, result: Any, names: dict[str, str], totals: dict[str, str], shown: Sequence[str]
) -> tuple[dict[str, Any], list[str]]:
    """The SI columns of ``result`` and those to show.

    The columns are :func:`~linecontact.operations._common.si_columns`' (with the totals over
    ``--length``); those to show are ``shown``, then the totals where the length is given.
    """
    columns = si_columns(result, names, totals=totals, length=args.length)
    return columns, [*shown, *(totals.values() if args.length is not None else ())]
