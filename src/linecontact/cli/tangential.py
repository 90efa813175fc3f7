"""Command-line subcommands for tangential loading: ``slide-init`` and ``roll``.

Registered on the ``linecontact`` parser by :func:`register` (called from
:func:`linecontact.cli.build_parser`); a thin shell over :mod:`linecontact.tangential`.

``--json`` contract: an array of records, one per value of ``--d-over-a`` (or of the given
tangential load), each with ``d_over_a`` and ``T_over_Ea`` (and ``creep_over_V`` for
``roll``), plus ``state`` (``"stick"``, ``"stick-slip"`` or ``"sliding"``: a load at or
above full slip is reported, not an error; ``d_over_a`` and ``creep_over_V`` are then
``null``), the friction law and the diagnostics. Bad input: one ``error:`` line on stderr,
exit status 2.
"""

from __future__ import annotations

import numpy as np

from .. import tangential as tg
from .._validation import non_negative
from ..cylinder import cylinder_sliding_initiation, cylinder_steady_rolling
from ..normal import contact_for_load
from . import _options as _cli

__all__ = ["register"]

_SI_KEYS = ("radius", "modulus", "E1", "nu1", "E2", "nu2", "sigma0", "h", "work_of_adhesion", "z0")
_ADHESION_KEYS = ("sigma0", "h", "work_of_adhesion", "z0")

_DESCRIPTION = {
    "slide-init": (
        "Initiation of sliding (paper Eqs 15-17): a tangential force T on a contact of "
        "half-width a; central stick zone |x| < d, slip zones d < |x| < a with shear stress "
        "tau0 (or mu p for --friction coulomb, Cattaneo-Mindlin). T >= 2 a tau0 (mu F) "
        "slides."
    ),
    "roll": (
        "Steady rolling of a driving cylinder (paper Eqs 23-29, Carter-type): rolling along "
        "+x, stick zone d < x < a at the leading edge, slip zone -a < x < d; T is the "
        "tractive force, creep_over_V = (V - omega R)/V (negative: the driving cylinder "
        "turns faster than it rolls)."
    ),
}


def register(sub) -> None:
    """Add ``slide-init`` and ``roll`` to the subparsers ``sub`` of ``linecontact``."""
    for name, helptext in (
        ("slide-init", "initiation of sliding under a tangential force (stick zone, T/(Ea))"),
        ("roll", "steady rolling of a driving cylinder (T/(Ea), creep)"),
    ):
        p = sub.add_parser(
            name,
            help=helptext,
            description=_DESCRIPTION[name],
            epilog="Give exactly one of --d-over-a, --T-over-Ea, --T-over-muF "
            "(Coulomb) or --tangential-load (SI).",
        )
        fr = p.add_argument_group("friction")
        fr.add_argument(
            "--friction",
            choices=("constant", "coulomb"),
            default="constant",
            help="constant friction stress tau0 (nano-scale, default) or Coulomb "
            "friction mu on the non-adhesive Hertz contact",
        )
        fr.add_argument("--tau0-over-E", type=float, help="friction stress over E, > 0")
        fr.add_argument("--tau0", type=float, help="friction stress [Pa] (SI mode)")
        fr.add_argument("--mu", type=float, help="friction coefficient (--friction coulomb)")
        st = p.add_argument_group("tangential state (exactly one)")
        lo = "[0, 1)" if name == "slide-init" else "(-1, 1)"
        st.add_argument(
            "--d-over-a", type=float, nargs="+", metavar="D", help=f"stick-zone end over a, in {lo}"
        )
        st.add_argument(
            "--T-over-Ea",
            type=float,
            nargs="+",
            metavar="T",
            help="tangential force per unit length over E a, >= 0",
        )
        st.add_argument(
            "--T-over-muF",
            type=float,
            nargs="+",
            metavar="T",
            help="tangential force over mu F (Coulomb), >= 0",
        )
        st.add_argument(
            "--tangential-load",
            type=float,
            nargs="+",
            metavar="T",
            help="tangential force per unit length [N/m] (SI mode)",
        )
        _cli._add_groups(p)
        nc = p.add_argument_group("normal contact (a from the normal problem)")
        nc.add_argument("--load", type=float, help="normal load F [N/m] (SI mode)")
        nc.add_argument(
            "--F-over-Eh",
            type=float,
            help="normal load over E h (with --R-over-h and --sigma0-over-E)",
        )
        nc.add_argument(
            "--a-over-R",
            type=float,
            help="contact half-width over R (Coulomb: the Hertz half-width)",
        )
        p.add_argument("--method", choices=("closed-form", "collocation"), default="closed-form")
        p.add_argument("--json", action="store_true", help="JSON array of records on stdout")
        p.set_defaults(func=_cmd_slide_init if name == "slide-init" else _cmd_roll)


def _cmd_slide_init(args) -> int:
    return _run(args, rolling=False)


def _cmd_roll(args) -> int:
    return _run(args, rolling=True)


def _given(args, *names) -> list[str]:
    return [n for n in names if getattr(args, n) is not None]


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def _normal_contact(args, coulomb: bool):
    """(a_over_R or None, F_over_Eh or None, Cylinder or None) from the normal inputs."""
    si = bool(_given(args, *_SI_KEYS))
    groups = bool(_given(args, "R_over_h", "sigma0_over_E"))
    if si:
        if args.a_over_R is not None or args.F_over_Eh is not None:
            raise ValueError(
                "--a-over-R and --F-over-Eh are nondimensional: in SI mode give "
                "the normal load with --load [N/m]"
            )
        if args.load is None:
            raise ValueError("SI inputs need the normal load --load [N/m]")
        if coulomb and not _given(args, *_ADHESION_KEYS):
            args.h = args.radius  # no adhesion: the range h only sets an unused length scale
        return None, None, _cli._cylinder(args)
    if args.load is not None:
        raise ValueError("--load [N/m] is an SI input: give --radius and the materials too")
    if groups:
        if args.a_over_R is not None:
            raise ValueError(
                "give either --a-over-R or the normal problem (--R-over-h, "
                "--sigma0-over-E, --F-over-Eh), not both"
            )
        _cli._cylinder(args)  # checks that both groups are given
        if args.F_over_Eh is None:
            raise ValueError("with --R-over-h and --sigma0-over-E give the normal load --F-over-Eh")
        if coulomb and args.sigma0_over_E != 0:
            raise ValueError(
                "Coulomb friction is the counterpart for the non-adhesive Hertz "
                "contact: use --sigma0-over-E 0 (or --friction constant)"
            )
        c = contact_for_load(args.F_over_Eh, args.R_over_h, args.sigma0_over_E)
        return c.a_over_R, args.F_over_Eh, None
    if args.F_over_Eh is not None:
        raise ValueError("--F-over-Eh needs --R-over-h and --sigma0-over-E")
    return args.a_over_R, None, None


def _run(args, rolling: bool) -> int:
    coulomb = args.friction == "coulomb"
    if coulomb:
        if _given(args, "tau0_over_E", "tau0"):
            raise ValueError(
                "--tau0-over-E and --tau0 are for --friction constant; Coulomb friction takes --mu"
            )
        if args.mu is None:
            raise ValueError("--friction coulomb needs the friction coefficient --mu")
    else:
        if args.mu is not None:
            raise ValueError("--mu is the Coulomb friction coefficient: add --friction coulomb")
        if args.T_over_muF is not None:
            raise ValueError("--T-over-muF is for --friction coulomb; use --T-over-Ea")
    states = _given(args, "d_over_a", "T_over_Ea", "T_over_muF", "tangential_load")
    if len(states) != 1:
        raise ValueError(
            "give exactly one of --d-over-a, --T-over-Ea, --T-over-muF "
            "(Coulomb) or --tangential-load [N/m] (SI)"
        )
    (state,) = states
    A, F_over_Eh, cyl = _normal_contact(args, coulomb)
    if cyl is None and state == "tangential_load":
        raise ValueError(
            "--tangential-load [N/m] is an SI input: give --radius, the "
            "materials and --load too, or use --T-over-Ea"
        )
    values = np.asarray(getattr(args, state), float)
    if state != "d_over_a":
        # checked before any conversion (T/(Ea) to T/(mu F), ...), so that the message names
        # the option given and its value
        non_negative(state, values)
    d = values if state == "d_over_a" else None
    kw = dict(method=args.method)

    if cyl is not None:
        E = cyl.modulus
        if coulomb:
            fr = dict(friction_coefficient=args.mu)
        else:
            if len(_given(args, "tau0", "tau0_over_E")) != 1:
                raise ValueError("give the friction stress as --tau0 [Pa] or --tau0-over-E")
            fr = dict(friction_stress=args.tau0 if args.tau0 is not None else args.tau0_over_E * E)
        fn = cylinder_steady_rolling if rolling else cylinder_sliding_initiation
        if state in ("T_over_Ea", "T_over_muF"):
            # the contact half-width first, to convert to [N/m]
            a_m = cyl.contact(load=args.load).contact_half_width
            T = values * E * a_m if state == "T_over_Ea" else values * args.mu * args.load
            res = fn(cyl, args.load, tangential_load=T, **fr, **kw)
        elif state == "tangential_load":
            res = fn(cyl, args.load, tangential_load=values, **fr, **kw)
        else:
            res = fn(cyl, args.load, d_over_a=d, **fr, **kw)
        r = res.nondimensional
        si = dict(
            a_m=res.contact_half_width,
            d_m=res.stick_zone_end,
            T_N_per_m=res.tangential_load,
            F_N_per_m=res.normal_load,
            T_full_slip_N_per_m=res.full_slip_load,
        )
        A = res.contact_half_width / cyl.radius
        header_si = (
            f", R = {cyl.radius:g} m, E = {E:g} Pa, F = {args.load:g} N/m, "
            f"a = {res.contact_half_width:.6g} m"
        )
    else:
        si = None
        header_si = "" if A is None else f", a/R = {float(A):g}"
        if coulomb:
            if A is None:
                raise ValueError(
                    "Coulomb friction needs the Hertz half-width: give --a-over-R "
                    "(or --R-over-h --sigma0-over-E 0 --F-over-Eh, or SI inputs)"
                )
            fn = tg.steady_rolling_coulomb if rolling else tg.sliding_initiation_coulomb
            if state == "T_over_Ea":
                values = values / ((np.pi / 4) * args.mu * A)
            r = fn(args.mu, A, d, T_over_muF=None if d is not None else values, **kw)
        else:
            if args.tau0 is not None:
                raise ValueError(
                    "--tau0 [Pa] is an SI input: give --radius, the materials and "
                    "--load too, or use --tau0-over-E"
                )
            if args.tau0_over_E is None:
                raise ValueError(
                    "give the friction stress --tau0-over-E (or --friction coulomb --mu)"
                )
            fn = tg.steady_rolling if rolling else tg.sliding_initiation
            r = fn(args.tau0_over_E, d, T_over_Ea=None if d is not None else values, **kw)

    recs = _records(r, rolling, coulomb, A, F_over_Eh, si)
    if args.json:
        print(_cli._dump_json(recs))
        return 0
    what = "steady rolling (driving cylinder)" if rolling else "initiation of sliding"
    law = (
        f"Coulomb mu = {args.mu:g}" if coulomb else f"tau0/E = {np.atleast_1d(r.tau0_over_E)[0]:g}"
    )
    print(f"# {what}, {law}{header_si} ({args.method})")
    keys = ["d_over_a", "T_over_Ea", "T_over_T_full_slip"]
    keys += ["creep_over_V"] if rolling else []
    keys += ["state"]
    keys += ["T_N_per_m"] if si is not None else []
    print(_cli._table(recs, keys))
    return 0


def _records(r, rolling: bool, coulomb: bool, A, F_over_Eh, si) -> list[dict]:
    base = r.to_records()
    out = []
    for i, rec in enumerate(base):
        o = {"d_over_a": rec["d_over_a"], "T_over_Ea": rec["T_over_Ea"]}
        if rolling:
            o["creep_over_V"] = rec["creep_over_V"]
        o["T_over_T_full_slip"] = rec["T_over_T_full_slip"]
        o["state"] = rec["state"]
        o["friction"] = "coulomb" if coulomb else "constant"
        if coulomb:
            o.update(mu=rec["mu"], T_over_muF=rec["T_over_muF"], a_over_R=rec["a_over_R"])
        else:
            o["tau0_over_E"] = rec["tau0_over_E"]
            if A is not None:
                o["a_over_R"] = float(np.atleast_1d(A)[0])
        if F_over_Eh is not None:
            o["F_over_Eh"] = F_over_Eh
        if si is not None:
            o.update(
                {k: float(np.atleast_1d(v)[i if np.size(v) > 1 else 0]) for k, v in si.items()}
            )
        o.update(
            method=r.method,
            n_collocation=rec["n_collocation"],
            residual_stick=rec["residual_stick"],
            residual_force=rec["residual_force"],
            error_estimate=rec["error_estimate"],
            converged=rec["converged"],
        )
        out.append(o)
    return out
