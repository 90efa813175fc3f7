"""``fit-friction``: the interfacial shear strength from friction forces (or widths).

Declared in :mod:`linecontact.operations.fit`.
"""

from __future__ import annotations

import math
import os
from typing import Any

import numpy as np

from .. import inverse as inv
from ..errors import ParameterError
from ..output import Table
from ._common import flags, positive
from ._fit_common import (
    _ESTIMATE,
    EXACT,
    _check_common,
    _modulus,
    _one_sd,
    _read,
    _record,
    _table,
    _uncertainty,
)

#: The largest shear strength [Pa] a measured width may give: a thousand times the stiffest
#: modulus there is (beyond, the inputs are in other units, and the draws would overflow).
_TAU_MAX = 1e15


# --------------------------------------------------------------------------------------------
# fit-friction


def _friction_from_width(args: Any) -> Table:
    """tau0 = (f - dw)/(2 a) from one friction force and one measured half-width (no model)."""
    if args.data is not None:
        raise ParameterError(
            "--half-width", "--half-width is one measured width: give it without --data"
        )
    if args.friction_force is None:
        raise ParameterError(
            "--half-width",
            "--half-width needs the friction force measured with it: --friction-force",
        )
    if not (math.isfinite(args.friction_force) and args.friction_force > 0):
        raise ParameterError(
            "--friction-force",
            f"--friction-force must be a finite number > 0, got {args.friction_force!r}",
        )
    positive("--half-width", args.half_width)
    if args.receding_work_of_adhesion is not None and args.work_of_adhesion is None:
        raise ParameterError(
            "--work-of-adhesion-receding",
            "--work-of-adhesion-receding needs the advancing --work-of-adhesion",
        )
    model = flags(
        args, "radius", "modulus", "E1", "E2", "z0", "cylinder_material", "substrate_material"
    ) + (["--contact"] if args.contact != "maugis-dugdale" else [])
    if model:
        raise ParameterError(
            model[0],
            f"{', '.join(model)}: not used with --half-width (a measured width needs no contact "
            "model)",
        )
    if (
        args.receding_work_of_adhesion is not None
        and args.receding_work_of_adhesion < args.work_of_adhesion
    ):
        raise ParameterError(
            "--work-of-adhesion-receding",
            "--work-of-adhesion-receding must be at least --work-of-adhesion (the hysteresis "
            "is not negative)",
        )
    dw = (
        args.receding_work_of_adhesion - args.work_of_adhesion
        if args.receding_work_of_adhesion is not None
        else 0.0
    )
    values = dict(friction_force=args.friction_force, half_width=args.half_width)
    tau = (args.friction_force - dw) / (2 * args.half_width)
    if not tau <= _TAU_MAX:  # drawing around it would overflow; no material is that strong
        raise ParameterError(
            "--friction-force",
            f"--friction-force {args.friction_force!r} N/m over --half-width "
            f"{args.half_width!r} m gives a shear strength of {tau:.3g} Pa, beyond any "
            f"material (above {_TAU_MAX:g} Pa): are they in N/m and m?",
        )
    sds = dict(
        friction_force=_one_sd(args, "friction_force", args.friction_force),
        half_width=_one_sd(args, "half_width", args.half_width),
    )
    est = inv.propagate(
        lambda friction_force, half_width: (friction_force - dw) / (2 * half_width),
        values,
        sds,
        n_samples=args.samples,
        seed=args.seed,
    )
    if est.value <= 0:
        raise ParameterError(
            "--friction-force",
            f"--friction-force {args.friction_force!r} N/m does not exceed the adhesion "
            f"hysteresis {dw:.6g} J/m^2: no positive shear strength",
        )
    given = [f"--{k.replace('_', '-')}-sd" for k, v in sds.items() if v]
    rec = {
        **_record(est, tuple((k, key.format("tau0") + "_Pa") for k, key in _ESTIMATE[:4])),
        "uncertainty": _uncertainty(given, args.samples),
        "half_width_m": args.half_width,
    }
    hide = ("tau0_sd_Pa", "tau0_ci95_Pa", "tau0_sd_linear_Pa") if not given else ()
    params: dict[str, Any] = dict(
        friction_force_N_per_m=args.friction_force,
        half_width_m=args.half_width,
        hysteresis_J_per_m2=dw,
        contact="measured width",
        samples=args.samples,
        seed=args.seed,
    )
    title = "interfacial shear strength from a measured contact width"
    return _table(args, rec, params, title, {"tau0_ci95_Pa": "Pa"}, hide)


def run_friction(args: Any) -> Table:
    _check_common(args)
    if args.half_width is not None:
        return _friction_from_width(args)
    if args.data is not None and args.friction_force_sd is not None:
        raise ParameterError(
            "--friction-force-sd",
            "--friction-force-sd is for one measurement: with --data give the uncertainties "
            "in the file, an sd column right after the friction forces",
        )
    E, mat = _modulus(args)
    params: dict[str, Any] = dict(mat)
    if args.radius is None or args.work_of_adhesion is None or args.z0 is None:
        raise ParameterError(
            "--radius",
            "the contact width needs the cylinder: give --radius, --work-of-adhesion and --z0 "
            "(with the modulus or the materials)",
        )
    positive("--length", args.length)
    if args.data is not None:
        if args.friction_force is not None or args.normal_load is not None:
            raise ParameterError(
                "--data", "give either --data FILE or one measurement (--load, ...)"
            )
        data = _read(args, "friction")
        F, f = data["normal_load"], data["friction_force"]
        f_sd = data.get("friction_force_sd", np.zeros_like(f))
        lines = data["line"]
        n = F.size
    else:
        if args.friction_force is None or args.normal_load is None:
            raise ParameterError(
                "--data", "give --data FILE, or one measurement: --load and --friction-force"
            )
        F, f = np.array([args.normal_load]), np.array([args.friction_force])
        lines = np.array([0])
        f_sd = np.array([_one_sd(args, "friction_force", args.friction_force)])
        n = 1
    w_sd = _one_sd(args, "work_of_adhesion", args.work_of_adhesion)
    R_sd = _one_sd(args, "radius", args.radius)
    E_sd = _one_sd(args, "modulus", E)
    z_sd = _one_sd(args, "z0", args.z0)
    common = dict(
        radius=args.radius,
        modulus=E,
        work_of_adhesion=args.work_of_adhesion,
        equilibrium_spacing=args.z0,
    )

    def tau_fn(contact, **kw):
        def fn(friction_force, normal_load, radius, modulus, work_of_adhesion, equilibrium_spacing):
            return inv.shear_strength_from_friction(
                friction_force,
                normal_load,
                radius,
                modulus,
                work_of_adhesion,
                equilibrium_spacing,
                contact=contact,
                **kw,
            )

        return fn

    kw = {}
    if args.receding_work_of_adhesion is not None:
        kw["receding_work_of_adhesion"] = args.receding_work_of_adhesion
    fn = tau_fn(args.contact, **kw)
    try:
        tau = np.asarray(fn(f, F, **common), float)
    except ValueError as exc:
        if args.data is None:
            raise
        for i in range(n):  # name the row that fails
            try:
                fn(f[i], F[i], **common)
            except ValueError as one:
                raise ParameterError(
                    "--data", f"--data {args.data!r}, row {int(lines[i])}: {one}"
                ) from None
        raise exc
    ests = [
        inv.propagate(
            fn,
            dict(friction_force=f[i], normal_load=F[i], **common),
            dict(
                friction_force=f_sd[i],
                radius=R_sd,
                modulus=E_sd,
                work_of_adhesion=w_sd,
                equilibrium_spacing=z_sd,
            ),
            n_samples=args.samples,
            seed=args.seed + i,
        )
        for i in range(n)
    ]
    sd = np.array([e.sd for e in ests])
    combined = inv.fit_shear_strength(
        fn,
        f,
        F,
        f_sd,
        common,
        dict(radius=R_sd, modulus=E_sd, work_of_adhesion=w_sd, equilibrium_spacing=z_sd),
        args.samples,
        args.seed,
    )
    others: dict[str, list[float]] = {}
    for c in ("jkr", "dmt", "hertz"):  # point by point: a model may have no contact at one
        others[c] = []
        for i in range(n):
            try:
                others[c].append(float(tau_fn(c)(f[i], F[i], **common)))
            except ValueError:
                others[c].append(math.nan)
    rec: dict[str, Any] = {
        **_record(
            combined,
            (
                ("tau0", "tau0_Pa"),
                ("tau0_sd", "tau0_sd_Pa"),
                ("tau0_ci95", "tau0_ci95_Pa"),
                ("birge_ratio", "birge_ratio"),
            ),
        ),
        "uncertainty": _friction_uncertainty(args, f_sd, n, (R_sd, E_sd, w_sd, z_sd)),
        "n_points": n,
        "normal_load_N_per_m": F.tolist(),
        "friction_force_N_per_m": f.tolist(),
        "tau0_per_point_Pa": tau.tolist(),
        "tau0_per_point_sd_Pa": sd.tolist(),
        "tau0_per_point_ci95_Pa": [list(e.ci95) for e in ests],
        "tau0_jkr_Pa": others["jkr"],
        "tau0_dmt_Pa": others["dmt"],
        "tau0_hertz_Pa": others["hertz"],
    }
    params.update(
        radius_m=args.radius,
        work_of_adhesion_J_per_m2=args.work_of_adhesion,
        z0_m=args.z0,
        contact=args.contact,
        samples=args.samples,
        seed=args.seed,
    )
    if args.data is not None:
        params["data"] = os.fspath(args.data)
    if args.receding_work_of_adhesion is not None:
        params["receding_work_of_adhesion_J_per_m2"] = args.receding_work_of_adhesion
    # the figure, drawn by the shell that has a file for it (--plot)
    others_ = {k.upper() if k != "hertz" else "Hertz": np.asarray(v) for k, v in others.items()}
    args.drawing = (
        "draw_friction_fit",
        (F, f, tau, np.array([e.ci95 for e in ests]), others_),
        {"friction_sd": f_sd, "combined": (combined.tau0, combined.tau0_ci95)},
    )
    units = {"n_points": "1", "birge_ratio": "1", "tau0_per_point_ci95_Pa": "Pa"}
    hide = ("tau0_sd_Pa", "tau0_ci95_Pa", "birge_ratio") if rec["uncertainty"] == EXACT else ()
    return _table(
        args,
        rec,
        params,
        f"interfacial shear strength from {n} friction force(s) ({args.contact} contact)",
        units,
        hide,
    )


def _friction_uncertainty(args, f_sd: np.ndarray, n: int, shared: tuple[float, ...]) -> str:
    """Where the uncertainty of a fitted tau0 comes from: the sds given, the scatter, or none."""
    given = [
        flag
        for flag, v in (
            ("--friction-force-sd" if args.data is None else "the friction forces' sd", f_sd),
            ("--radius-sd", shared[0]),
            ("--modulus-sd", shared[1]),
            ("--work-of-adhesion-sd", shared[2]),
            ("--z0-sd", shared[3]),
        )
        if np.any(np.asarray(v) > 0)
    ]
    if given:
        return _uncertainty(given, args.samples)
    if n < 2:
        return EXACT
    return f"the scatter of the {n} points (no uncertainty given): Student's t"
