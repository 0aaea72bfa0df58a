"""Speed against accuracy of the gear solver: prints a table (not a test).

    .venv/bin/python benchmarks/bench_gears.py
"""
from __future__ import annotations

import math
import time

import numpy as np

from reportgen.gears.involute import inv, inv_inverse
from reportgen.gears.pair import solve_gear_pair
from reportgen.gears.profile import pair_teeth
from reportgen.gears.shifts import choose_shifts


def timed(fn, repeat=3):
    best = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def main() -> None:
    alpha = np.linspace(math.radians(0.5), math.radians(80), 200001)
    t, back = timed(lambda: inv_inverse(inv(alpha)))
    print(f"inverse involute, 2e5 angles 0.5…80°: {t * 1e3:.1f} ms, max |Δα| = {np.abs(back - alpha).max():.2e} rad")
    t, _ = timed(lambda: solve_gear_pair(13, 26, 9.0, 0.63, 0.67), 20)
    print(f"solve_gear_pair (given x): {t * 1e3:.2f} ms")
    print("\nrack-cutter simulation, seed pair z 13/26 m 9:")
    print(f"{'positions':>10}{'time, s':>10}{'|Δs| pitch, µm':>16}{'max |Δ| flank, µm':>20}")
    p = solve_gear_pair(13, 26, 9.0, 0.63, 0.67)
    for n in (61, 121, 241, 481, 961):
        t, (t1, t2) = timed(lambda n=n: pair_teeth(p, n), 1)
        ds = max(abs(t1.thickness(t1.r) - p.s1), abs(t2.thickness(t2.r) - p.s2))
        dev = 0.0
        for tt, rho_l, ra in ((t1, p.rho_l1, p.da1 / 2), (t2, p.rho_l2, p.da2 / 2)):
            r_l = math.hypot(tt.rb, rho_l)
            dev = max(dev, np.abs(tt.involute_deviation(np.linspace(r_l + 1e-3, ra * 0.999, 40))).max())
        print(f"{n:>10}{t:>10.3f}{ds * 1e3:>16.3f}{dev * 1e3:>20.3f}")
    print("\nautomatic shifts (blocking contour on an n × n grid):")
    print(f"{'z1/z2':>8}{'n':>6}{'time, s':>10}{'x1':>8}{'x2':>8}{'x1 exact':>10}{'x2 exact':>10}")
    for z1, z2 in ((13, 26), (9, 18), (20, 60)):
        for n in (81, 161, 321):
            t, ch = timed(lambda z1=z1, z2=z2, n=n: choose_shifts(z1, z2, 9.0, n=n), 1)
            print(f"{z1:>4}/{z2:<3}{n:>6}{t:>10.2f}{ch.x1:>8.2f}{ch.x2:>8.2f}{ch.x1_exact:>10.4f}{ch.x2_exact:>10.4f}")


if __name__ == "__main__":
    main()
