"""Benchmark of tangential load histories: speed, and agreement of the two solvers.

Run: ``PYTHONPATH=src python benchmarks/history.py [--seed 0] [--histories 8]``.

Prints:

1. the time of ``cyclic_loss`` for 10,000 amplitudes (closed form), both friction laws;
2. the time of a 1,000-step history (closed form): a random walk with reversals, and a
   decaying oscillation (every reversal nested in the last: 999 turning points held);
3. the worst disagreement of the Masing states (closed form) with the incremental
   collocation solver over ``--histories`` random histories of 12 steps per law (reversals
   of at least 5 % of the full-slip load): stick zone, traction, slip, displacement, energy;
4. the worst disagreement of the closed-form loss per cycle with the loop area by adaptive
   quadrature of the closed-form displacements, and with the incremental solver's friction
   work, over amplitudes from 0.01 to 0.999 of full slip; and the log-log slope of the
   loss between 1e-3 and 1e-2 of full slip.
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np
from scipy.integrate import quad

from _common import best_of
from linecontact import (
    cyclic_loss,
    cyclic_loss_coulomb,
    tangential_history,
    tangential_history_coulomb,
)
from linecontact.tangential.history import _LAWS

T0, MU, A = 0.01, 0.3, 0.01


def law_calls(law):
    if law == "constant":
        return (
            lambda r, **k: tangential_history(T0, 2 * T0 * np.asarray(r), **k),
            lambda r, **k: cyclic_loss(T0, 2 * T0 * np.asarray(r), **k),
            T0,
        )
    return (
        lambda r, **k: tangential_history_coulomb(MU, A, r, **k),
        lambda r, **k: cyclic_loss_coulomb(MU, A, r, **k),
        MU * A / 2,
    )


def random_history(rng, n=12, min_step=0.05):
    """Loads over the full-slip load in [-0.97, 0.97], steps of at least ``min_step``."""
    loads, t = [], 0.0
    while len(loads) < n:
        nxt = float(np.clip(t + rng.normal(0, 0.4), -0.97, 0.97))
        if abs(nxt - t) >= min_step:
            loads.append(nxt)
            t = nxt
    return loads


def loop_area(law, r):
    warnings.simplefilter("ignore")  # quad's round-off note at small amplitude
    g, Tf = _LAWS[law].displacement, _LAWS[law].T_full
    f = lambda t: float(2 * g(r) - 2 * g((r - t) / 2) - 2 * g((t + r) / 2))  # noqa: E731
    return Tf * quad(f, -r, r, epsabs=0, epsrel=1e-12, limit=400)[0]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--histories", type=int, default=8)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)

    print("1. cyclic_loss, 10,000 amplitudes (closed form)")
    amps = rng.uniform(1e-4, 1.2, 10_000)
    for law in ("constant", "coulomb"):
        _, loss, _ = law_calls(law)
        t, w = best_of(lambda loss=loss: loss(amps))
        print(f"   {law:9s} {t * 1e3:8.2f} ms   ({np.isnan(w.W_over_Ea2).sum()} sliding)")

    print("2. a 1,000-step history (closed form)")
    walk = np.clip(np.cumsum(rng.normal(0, 0.25, 1000)), -1.1, 1.1)
    decay = 0.95 * np.cos(np.pi * np.arange(1000)) * np.exp(-np.arange(1000) / 300)
    for name, loads in (("random walk", walk), ("decaying oscillation", decay)):
        for law in ("constant", "coulomb"):
            hist, _, _ = law_calls(law)
            t, h = best_of(lambda hist=hist, loads=loads: hist(loads))
            print(
                f"   {name:21s} {law:9s} {t * 1e3:8.1f} ms   memory up to {h.memory.max()}, "
                f"{(h.state == 'sliding').sum()} sliding steps"
            )

    print(f"3. closed form vs incremental collocation, {args.histories} histories x 12 steps")
    x = np.sin(np.linspace(-1.5, 1.5, 201)) * 1.001
    for law in ("constant", "coulomb"):
        hist, _, scale = law_calls(law)
        worst = dict.fromkeys(("c", "q", "s", "D", "W"), 0.0)
        t_inc = 0.0
        n_max = 0
        for _ in range(args.histories):
            loads = random_history(rng)
            m = hist(loads)
            t1 = time.perf_counter()
            i = hist(loads, method="incremental")
            t_inc += time.perf_counter() - t1
            n_max = max(n_max, int(i.n_collocation.max()))
            ok = m.state != "sliding"
            worst["c"] = max(worst["c"], np.max(np.abs(m.c_over_a - i.c_over_a)[ok]))
            worst["q"] = max(worst["q"], np.max(np.abs(m.traction(x) - i.traction(x))) / scale)
            worst["s"] = max(worst["s"], np.nanmax(np.abs(m.slip(x) - i.slip(x))) / scale)
            dD = np.abs(m.displacement_over_a - i.displacement_over_a)[ok]
            worst["D"] = max(worst["D"], np.max(dD) / scale)
            wm, wi = m.dissipation_over_Ea2[ok], i.dissipation_over_Ea2[ok]
            worst["W"] = max(worst["W"], np.max(np.abs(wm - wi) / np.max(wm)))
        print(
            f"   {law:9s} |dc/a| {worst['c']:.1e}  |dq|/scale {worst['q']:.1e}  "
            f"|ds|/(a scale/E) {worst['s']:.1e}  |dD|/(a scale/E) {worst['D']:.1e}  "
            f"|dW|/max W {worst['W']:.1e}   incremental {t_inc / args.histories:.2f} s "
            f"per history, n up to {n_max}"
        )

    print("4. loss per cycle: closed form vs loop area (quadrature) and friction work")
    r = np.array([1e-3, 1e-2, 0.1, 0.3, 0.6, 0.9, 0.999])
    for law in ("constant", "coulomb"):
        _, loss, scale = law_calls(law)
        w = loss(r).W_over_Ea2
        # the loop-area integrand cancels to ~r^4 from terms ~r: quad from r = 0.01 on
        big = r >= 0.01
        area = np.array([loop_area(law, ri) for ri in r[big]]) * scale**2
        inc_r = r[r >= 0.01]
        t1 = time.perf_counter()
        inc = loss(inc_r, method="incremental").W_over_Ea2
        t_inc = time.perf_counter() - t1
        e_area = np.max(np.abs(area / w[big] - 1))
        e_inc = np.max(np.abs(inc / w[r >= 0.01] - 1))
        print(
            f"   {law:9s} vs loop area (r >= 0.01) {e_area:.1e}   vs friction work "
            f"{e_inc:.1e} ({t_inc:.1f} s)"
        )
        print(f"   {'':9s} small-amplitude slope {np.log(w[1] / w[0]) / np.log(10):.6f}")


if __name__ == "__main__":
    main()
