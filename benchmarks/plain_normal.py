"""A plain NumPy closed-form script: the baseline that ``benchmarks/cli.py`` times the CLI against.

Run: ``python benchmarks/plain_normal.py R_over_h sigma0_over_E START STOP NUM > out.json``.

It does the work of ``linecontact normal --R-over-h ... --a-over-R-range START STOP NUM
--json`` the way a user would write it without linecontact: the Maugis--Dugdale line contact
(Baney & Hui 1997; Johnson & Greenwood 2008) by a vectorised bisection on the separation
condition in ``m = c/a``, the load by equilibrium, the stability by a difference of the load,
and the same JSON document (the provenance block and one dict per record, ``json.dumps``).
It imports nothing from linecontact.
"""

from __future__ import annotations

import json
import sys

import numpy as np


def closed_form(A, rho, s):
    """c/R, F/(Eh) and the separation residual for contact half-widths A = a/R."""
    kap = (4 / np.pi) * s * np.sqrt(2 * rho)
    ab = A * np.sqrt(rho / 2)

    def residual(u):  # abar^2 f1(u) + kappa abar f2(u) - 1, increasing in u
        f1 = np.sinh(u) * np.cosh(u) - u
        f2 = u * np.sinh(u) - np.cosh(u) * np.log(np.cosh(u))
        return ab * ab * f1 + kap * ab * f2 - 1

    lo = np.full(A.shape, 1e-9)
    hi = np.full(A.shape, 50.0)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        up = residual(mid) > 0
        hi = np.where(up, mid, hi)
        lo = np.where(up, lo, mid)
    u = 0.5 * (lo + hi)
    C = A * np.cosh(u)
    F = np.pi / 4 * A * A * rho - 2 * s * rho * np.sqrt(C * C - A * A)
    return C, F, np.abs(residual(u))


def main() -> None:
    rho, s, start, stop, num = map(float, sys.argv[1:6])
    A = np.linspace(start, stop, int(num))
    C, F, res = closed_form(A, rho, s)
    eps = 1e-7 * A
    _, F2, _ = closed_form(A + eps, rho, s)
    stable = F2 > F
    kap = (4 / np.pi) * s * np.sqrt(2 * rho)
    lam = 4 / np.pi ** (2 / 3) * s ** (2 / 3) * rho ** (1 / 3)
    records = [
        {
            "a_over_R": a,
            "c_over_R": c,
            "F_over_Eh": f,
            "n_collocation": 0,
            "residual_separation": r,
            "residual_consistency": 0.0,
            "error_estimate": 0.0,
            "converged": True,
            "stable": st,
            "c_over_a": c / a,
            "state": "contact",
            "reason": None,
        }
        for a, c, f, r, st in zip(
            A.tolist(), C.tolist(), F.tolist(), res.tolist(), stable.tolist(), strict=True
        )
    ]
    names = (
        "a_over_R",
        "c_over_R",
        "F_over_Eh",
        "n_collocation",
        "residual_separation",
        "residual_consistency",
        "error_estimate",
        "c_over_a",
    )
    doc = {
        "linecontact": {"version": "baseline"},
        "command": sys.argv,
        "parameters": {
            "R_over_h": rho,
            "sigma0_over_E": s,
            "kappa": kap,
            "maugis_parameter": lam,
            "method": "closed-form",
        },
        "units": {
            k: "1" for k in ("R_over_h", "sigma0_over_E", "kappa", "maugis_parameter", *names)
        },
        "results": records,
    }
    # one write: json.dump(doc, sys.stdout) writes piece by piece and takes ten times longer
    sys.stdout.write(json.dumps(doc, separators=(",", ":")) + "\n")


if __name__ == "__main__":
    main()
