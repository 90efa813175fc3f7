r"""The sliding contact that carries a given load (:func:`sliding_contact_for_load`).

The inverse of :func:`~linecontact.sliding.sliding_contact`, solved per point on the closed
form in ``ln(a)`` on the stable side of the load minimum (or below it, on the unstable side).
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from numpy.typing import ArrayLike

from .. import _numerics as _num
from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import (
    FailurePolicy,
    first_point,
    point_text,
)
from ..errors import NoEquilibriumError
from ..sie import _in_chunks
from ._checks import _broadcast_state, _check_state_inputs, _flat_points
from .contact import SlidingContact, _pack, _solve_closed_form, _solve_split
from .pulloff import _LAB_DEEP, _phi_at, _pulloff_flat, _zero_width


def _pulloff_end(r, s, kap):
    r"""The load-free part of :func:`_lower_end`: ``(lab_lo, phi_po)`` of the adhesive points.

    The lower end (ln abar) of the stable branch and its load (the pull-off load); without
    adhesion ``_LAB_DEEP`` and 0 (:func:`_lower_end` then starts below Hertz's width). Flat
    arrays or NumPy scalars; depends on :math:`(R/h_2, h_1/h_2, \sigma_0/E)` only, so a caller that
    solves several loads at the same points computes it once (:func:`_sliding_ends`).
    """
    adh = s > 0
    if not isinstance(s, np.ndarray):
        phi_po, lab_lo = np.float64(0.0), np.float64(_LAB_DEEP)
        if adh:
            d = _pulloff_flat(kap, r)
            phi_po = d["phi_min"]
            lab_lo = _num._where(d["interior"], d["lab_min"], lab_lo)
        return lab_lo, phi_po
    lab_lo = np.full(s.shape, _LAB_DEEP)
    phi_po = np.zeros(s.shape)
    if adh.any():
        d = _pulloff_flat(kap[adh], r[adh])
        phi_po[adh] = d["phi_min"]
        lab_lo[adh] = np.where(d["interior"], d["lab_min"], _LAB_DEEP)
    return lab_lo, phi_po


def _sliding_ends(rho, r, s, F=None):
    """Check kappa and compute :func:`_pulloff_end` once, on flat checked arrays.

    For :func:`_sliding_for_load` called many times at the same points (``push``'s tip);
    the arrays are indexed by the caller like the points.

    ``F`` (like the points; NaN: any load) where the caller knows the only load it will
    ask for: a point whose load lies above its zero-width load (the pull-off force is at
    most that) needs no pull-off search. Its ends are those of a minimum at zero width,
    ``_LAB_DEEP`` and the zero-width load: the load there is below the target everywhere
    below the stable root (it falls from the zero-width load to its minimum, then rises),
    so the bracket holds the same root (``push``: the search was half its time).
    """
    _cf._check_kappa(rho, s, "R_over_h2")
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        kap = _cf._kappa(rho, s)
        if F is None:
            return _pulloff_end(r, s, kap)
        X1, X2, _ = _zero_width(kap, r)
        phi0 = -0.5 * kap * (X1 + X2)
        F0 = (np.pi / 2) * phi0
        # (strictly above, by more than the search's own round-off: at the zero-width load
        # itself the two ends differ in which width they report)
        above = (s > 0) & (F > F0 + 1e-9 * abs(F0))
        if not isinstance(s, np.ndarray):
            return (np.float64(_LAB_DEEP), phi0) if above else _pulloff_end(r, s, kap)
        lab_lo = np.full(s.shape, _LAB_DEEP)
        phi_po = np.where(above, phi0, 0.0)
        need = ~above
        if need.any():
            lab_lo[need], phi_po[need] = _pulloff_end(r[need], s[need], kap[need])
        return lab_lo, phi_po


def _lower_end(F, rho, r, s, kap, phi_t, report: bool = False, ends=None):
    """Lower end (ln abar) of the stable branch; below the pull-off, NoEquilibriumError.

    Flat arrays or NumPy scalars; the pull-off search runs on the adhesive points only.
    With ``report`` the points below the pull-off force (or at a load <= 0 without
    adhesion) are not an error: they are marked ``missing`` and their target load is moved
    to one that a contact carries. ``ends`` is :func:`_pulloff_end`'s result where the
    caller has it. Returns ``(lab_lo, phi_t, missing, phi_po)``, the last the load at the
    lower end (the pull-off load; 0 without adhesion).

    Where the minimum sits at zero width the branch starts at ``abar -> 0``: the bracket
    starts at ``abar = e**-300`` (a load within round-off of the zero-width one); without
    adhesion just below the width that carries the target (``Phi = abar^2``).
    """
    adh = s > 0
    lab_lo, phi_po = _pulloff_end(r, s, kap) if ends is None else ends
    below = adh & (F < (np.pi / 2) * phi_po)  # as the pull-off force is reported
    nonpos = ~adh & (phi_t <= 0)
    missing = below | nonpos
    # without adhesion the load is Hertz's, Phi = abar^2, down to any width: start the
    # bracket below the width that carries the target (F = 1e-300 needs abar ~ 1e-150)
    hertz_lo = 0.5 * np.log(_num._maximum(phi_t, 1e-300)) - 1.0
    lab_lo = _num._where(~adh, hertz_lo, lab_lo)
    if report:
        # a load that a contact carries stands in (the values are NaN in the result)
        phi_t = _num._where(below, phi_po, _num._where(nonpos, 1.0, phi_t))
        return lab_lo, phi_t, missing, phi_po
    if np.any(below):
        _, at = first_point(
            below,
            F_over_Eh2=F,
            F_po=np.pi / 2 * phi_po,
            R_over_h2=rho,
            h1_over_h2=r,
            sigma0_over_E=s,
        )
        raise NoEquilibriumError(
            f"no steadily sliding contact carries F_over_Eh2={at.pop('F_over_Eh2')!r}: it is "
            f"below the pull-off force F_pulloff_over_Eh2={at.pop('F_po')!r} "
            f"({point_text(at)}); the cylinder has pulled off"
        )
    if np.any(nonpos):
        _, at = first_point(nonpos, F_over_Eh2=F, R_over_h2=rho, h1_over_h2=r)
        raise NoEquilibriumError(
            f"no contact carries F_over_Eh2={at.pop('F_over_Eh2')!r} without adhesion "
            f"(sigma0_over_E=0, {point_text(at)}): the pull-off force is 0 and the load must "
            "be > 0"
        )
    return lab_lo, phi_t, missing, phi_po


def _double_step(lab, ph, dph, u1, u2, du1, du2, phi_t, kap, r):
    """Double abar until the load at it exceeds the target (the upper end of the bracket).

    The state is :func:`_phi_at`'s at ``lab`` (each point solved from the tangent at the
    last).
    """
    nxt = lab + np.log(2.0)
    ph, dph, u1, u2, du1, du2 = _phi_at(nxt, kap, r, (lab, u1, u2, du1, du2))
    return (nxt, ph, dph, u1, u2, du1, du2), ~(ph < phi_t)


def _load_step(lab, ph, dph, u1, u2, du1, du2, lo, hi, phi_t, pmin, kap, r):
    """One bracketed Newton step in ln abar of Phi(abar) = phi_t along the stable branch.

    Newton on ``ln(Phi - pmin) = ln(phi_t - pmin)`` (``pmin`` the load at the lower end),
    which is exact for Hertz (``Phi = abar^2``) and takes loads many decades above the
    lower end in a few steps; on ``Phi - phi_t`` where a difference is not positive.
    The state holds :func:`_phi_at`'s solution at ``lab`` (Phi, its slope, u1, u2 and their
    slopes): a point that is done keeps it, so u1, u2 belong to the returned ln abar;
    the others are solved at the next ln abar from the tangent there (the points still
    active only).
    """
    where = _num._where
    mx = _num._maximum
    fx = ph - phi_t
    up = fx > 0
    hi = where(up, lab, hi)
    lo = where(up, lo, lab)
    ab = np.exp(lab)
    d, dt = ph - pmin, phi_t - pmin
    logs = (d > 0) & (dt > 0)
    nxt = where(
        logs,
        lab - np.log(where(logs, d / dt, 1.0)) * d / (dph * ab),
        lab - fx / (dph * ab),
    )
    nxt = where((abs(nxt) < np.inf) & (nxt > lo) & (nxt < hi), nxt, 0.5 * (lo + hi))
    # at the noise of Phi's terms (Hertz's abar^2, the adhesive rest), relative at any scale
    ab2 = np.exp(2 * lab)
    done = (
        (abs(fx) <= 4e-16 * mx(mx(abs(phi_t), ab2), abs(ph - ab2)))
        | (abs(nxt - lab) <= 1e-15 * mx(1.0, abs(lab)))
        | (hi - lo <= 1e-15 * mx(1.0, abs(hi)))
    )
    state = [lab, ph, dph, u1, u2, du1, du2]
    if not isinstance(done, np.ndarray):
        if not done:
            state = [nxt, *_phi_at(nxt, kap, r, tuple(state[i] for i in (0, 3, 4, 5, 6)))]
    else:
        go = np.flatnonzero(~done)
        if go.size:
            state = [np.array(v) for v in state]
            start = tuple(state[i][go] for i in (0, 3, 4, 5, 6))
            new = (nxt[go], *_phi_at(nxt[go], kap[go], r[go], start))
            for v, w in zip(state, new, strict=True):
                v[go] = w
    return (*state, lo, hi), done


def _at_domain_end(near, a_min, rho, kap, r):
    """Phi, u1, u2 at the domain's end ``a/R = a_min``, at the points ``near`` (NaN elsewhere).

    Flat arrays or NumPy scalars (``near`` a bool then).
    """
    lab = np.log(a_min * np.sqrt(rho / 2))
    if not isinstance(near, np.ndarray):
        if not near:
            return np.float64(np.nan), np.float64(np.nan), np.float64(np.nan)
        ph, _, u1, u2, _, _ = _phi_at(lab, kap, r)
        return ph, u1, u2
    out = np.full((3, near.size), np.nan)
    i = np.flatnonzero(near)
    if i.size:
        ph, _, u1, u2, _, _ = _phi_at(lab[i], kap[i], r[i])
        out[:, i] = ph, u1, u2
    return out[0], out[1], out[2]


def sliding_contact_for_load(
    F_over_Eh2: ArrayLike,
    R_over_h2: ArrayLike,
    h1_over_h2: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    tau0_over_E: ArrayLike | None = None,
    method: Literal["closed-form", "collocation"] = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = "raise",
) -> SlidingContact:
    r"""The steadily sliding contact carrying a given normal load (stable branch).

    Solves :math:`F(a) = F` for the contact half-width on the branch with :math:`dF/da > 0` (stable
    under load control) with the closed form, then computes the state at that width with
    ``method``; with ``tau0_over_E`` the friction force :math:`2 a \tau_0` is reported as
    ``T_over_Eh2``. A load within 1e-12 of the zero-width load, where the stable branch
    starts at zero width, gives the zero-width state at the domain's end :math:`a/R = 10^{-20}`
    (every narrower width carries it to round-off), by the closed form under either method
    (``n_collocation`` 0; docs/sliding.md, "Loads at the zero-width end").

    Parameters
    ----------
    F_over_Eh2 : array_like
        Normal load per unit length over ``E h2``, compressive positive.
    R_over_h2, h1_over_h2, sigma0_over_E, tau0_over_E, method, n, tol
        As in :func:`sliding_contact` (the closed form by default).
    on_failure : {"raise", "report"}
        For a load below the pull-off force, or a state that misses its tolerance: raise
        :class:`~linecontact.errors.NoEquilibriumError` or
        :class:`~linecontact.errors.ConvergenceError` (``"raise"``, default), or report the
        point (``"report"``: below the pull-off force ``state == "no-equilibrium"``, NaN
        values (the load kept), ``converged`` and ``stable`` False; a miss flagged in
        ``converged``); README, "Conventions".

    Returns
    -------
    SlidingContact

    Raises
    ------
    NoEquilibriumError
        If the load is below the pull-off force of steady sliding (:func:`sliding_pull_off`),
        naming it.

    Examples
    --------
    >>> r = sliding_contact_for_load(0.5, 100.0, 2.0, 0.01, tau0_over_E=0.005)
    >>> abs(r.F_over_Eh2 - 0.5) < 1e-10, bool(r.stable)
    (True, True)
    """
    F = _domain.check("F_over_Eh2", F_over_Eh2)
    rho, r, s, tau, policy = _check_state_inputs(
        R_over_h2, h1_over_h2, sigma0_over_E, tau0_over_E, method, n, tol, on_failure
    )
    scalar, F, rho, r, s, tau = _broadcast_state("F_over_Eh2", F, rho, r, s, tau)
    shape = F.shape
    # with scalar inputs the search runs on NumPy scalars (see _numerics._where)
    F, rho, r, s, tau = _flat_points(scalar, F, rho, r, s, tau)
    return _sliding_for_load(F, rho, r, s, tau, method, n, tol, policy, shape, scalar)


def _sliding_for_load(F, rho, r, s, tau, method, n, tol, policy, shape, scalar, ends=None):
    """The kernel of :func:`sliding_contact_for_load`: checked inputs, no check again.

    Flat float arrays (or NumPy scalars with ``scalar``) of the broadcast inputs, kappa
    within range; ``ends`` the lower end of the stable branch at these points
    (:func:`_sliding_ends`, indexed like them) where the caller has it, else it is searched
    here. Returns the :class:`SlidingContact` of shape ``shape``. The closed forms work on
    chunks of points (:func:`linecontact.sie._in_chunks`: bounded memory).
    """
    report = policy == "report"
    lo_end, po_end = (None, None) if ends is None else ends
    args = (F, rho, r, s, report, lo_end, po_end)
    A, u1, u2, missing = _widths(*args) if scalar else _in_chunks(_widths, F.size, *args)
    if not scalar or method != "closed-form":  # the collocation works on arrays
        A, rho, r, s, tau, u1, u2, F, missing = (
            np.reshape(v, -1) for v in (A, rho, r, s, tau, u1, u2, F, missing)
        )
    _domain.check_widths(
        np.where(missing, np.nan, A), F, "F_over_Eh2", "sliding_a_over_R", narrow=True
    )
    _cf._warn_wide(np.where(missing, np.nan, A))
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # see sliding_contact
        if method == "closed-form":
            dd = _in_chunks(_solve_closed_form, np.size(A), A, rho, r, s, u1, u2)
        else:
            # the zero-width states (A at the domain's end, above) are the closed form's:
            # no collocation resolves a contact 1e20 times narrower than its adhesive zones
            a_min = _domain.DOMAIN["sliding_a_over_R"][0]
            dd = _solve_split(A, rho, r, s, n, tol, (A <= a_min) & (s > 0), (u1, u2))
        return _pack(
            dd,
            A,
            rho,
            r,
            s,
            tau,
            method,
            shape,
            scalar,
            policy,
            "sliding_contact_for_load",
            missing,
            F,
        )


def _widths(F, rho, r, s, report, lo_end=None, po_end=None):
    """The half-widths that carry the loads ``F``, by the closed form: ``A, u1, u2, missing``.

    Flat arrays (a chunk of the points) or NumPy scalars; ``lo_end, po_end`` are
    :func:`_pulloff_end`'s result at these points where the caller has it (else None).
    ``missing`` marks the loads below the pull-off force (with ``report``; else they raise).
    """
    kap = _cf._kappa(rho, s)
    phi_t = F * (2 / np.pi)
    ends = None if lo_end is None else (lo_end, po_end)
    # as in sliding_pull_off: far from h1 = h2 the search overflows on the way; the
    # convergence check of the state found reports a failure
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        # lower end of the stable branch and its load
        lab_lo, phi_t, missing, phi_lo = _lower_end(F, rho, r, s, kap, phi_t, report, ends)
        # upper end: where Phi exceeds the target (Hertz: Phi >= abar^2 - kappa abar sinh ...)
        lab_hi = np.log(np.sqrt(_num._maximum(phi_t, 0.0)) + 2.0 + 2.0 * kap)
        at_hi = (lab_hi, *_phi_at(lab_hi, kap, r))
        at_hi, _ = _num._iterate(_double_step, at_hi, (phi_t, kap, r), 60, done=~(at_hi[1] < phi_t))
        # bracketed Newton in ln abar on [lab_lo, lab_hi], where Phi increases, from lab_hi
        state = (*at_hi, lab_lo + 0.0 * at_hi[0], at_hi[0])
        (lab, _, _, u1, u2, _, _, _, _), _ = _num._iterate(
            _load_step, state, (phi_t, phi_lo, kap, r), 200
        )
        A = np.exp(lab) * np.sqrt(2 / rho)
        # narrower than the domain of sliding_contact: the load there is the zero-width one
        # to round-off (kept at the domain's end), or the point is refused (A = 0 below).
        # Where the stable branch starts at zero width (or at a minimum within 1e-12 of the
        # zero-width load), a load that the domain's end already carries to 1e-12 is the
        # zero-width state too: the load rises like a^2 from there, so the width that Newton
        # finds for it (anywhere below ~1e-7 R) is set by the last bits of the load, which
        # differ between machines, and the collocation cannot resolve such widths. The state
        # at the domain's end is the answer on every machine (docs/sliding.md, "Loads at the
        # zero-width end").
        a_min = _domain.DOMAIN["sliding_a_over_R"][0]
        scale = _num._maximum(abs(phi_t), abs(phi_lo))
        # the state at the domain's end, where it can matter: below it, or at a target
        # within 2e-12 of the lower end's load (ok & zero_end below imply that)
        near = (A < a_min) | ((s > 0) & (abs(phi_t - phi_lo) <= 2e-12 * scale))
        ph_f, u1f, u2f = _at_domain_end(near, a_min, rho, kap, r)
        ok = abs(ph_f - phi_t) <= 1e-12 * scale
        zero_end = (s > 0) & (abs(ph_f - phi_lo) <= 1e-12 * scale)
        narrow = ((A < a_min) | (ok & zero_end)) & ~missing
        if np.any(narrow):
            where = _num._where
            # (without adhesion the width found is Hertz's and is said; else it is < a_min)
            A = where(narrow, where(ok, a_min, where(s == 0, A, 0.0)), A)
            u1, u2 = where(narrow, u1f, u1), where(narrow, u2f, u2)
    return A, u1, u2, missing
