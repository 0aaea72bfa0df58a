"""Kinetostatics: solve time over N crank positions (reactions group by group, Zhukovsky's lever),
the agreement of the two methods, the equilibrium residual, and the graphical replica's deviations
at the task's force position, per example.

Run: .venv/bin/python benchmarks/bench_kinetostatics.py   (prints tables; not a test)
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from reportgen.bench.tables import best_time as shortest_time
from reportgen.kinetostatics import kinetostatics_at, solve_reactions, zhukovsky_lever
from reportgen.project import Project
from reportgen.taskfile import load_task

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
NAMES = ("press", "crank-slider", "shaper", "conveyor", "class3")


def best_time(fn, repeat: int = 5) -> float:
    """The shortest wall time of ``repeat`` calls of ``fn``, s."""
    return shortest_time(fn, repeat)[0]


def main() -> None:
    print(f"{'example':<14}{'N':>6}{'kin+loads, ms':>15}{'reactions, ms':>15}{'lever, ms':>11}"
          f"{'|ΔM|/max|M|':>14}{'max resid/ΣF':>14}")
    for name in NAMES:
        p = Project(load_task(EXAMPLES / name / "task.toml"))
        for N in (12, 360, 3600):
            phi = np.linspace(0, 2 * math.pi, N, endpoint=False)
            t_kin = best_time(lambda p=p, phi=phi: p.loads_at(p.kinematics_at(phi)), repeat=3)
            kin = p.kinematics_at(phi)
            loads = p.loads_at(kin)
            t_r = best_time(lambda p=p, kin=kin, loads=loads: solve_reactions(p.linkage, p.structure, kin, loads))
            t_z = best_time(lambda p=p, kin=kin, loads=loads: zhukovsky_lever(p.linkage, kin, loads))
            r = solve_reactions(p.linkage, p.structure, kin, loads)
            z = zhukovsky_lever(p.linkage, kin, loads)
            dm = np.abs(r.balancing_moment - z.balancing_moment).max() / np.abs(r.balancing_moment).max()
            fs = sum(np.hypot(*np.asarray(f.vector).T) for f in loads.forces)
            worst = 0.0
            for k in p.linkage.moving:
                F, M = r.residuals(k)
                worst = max(worst, float((np.hypot(*F.T) / fs).max()))
            print(f"{name:<14}{N:>6}{t_kin * 1e3:>15.2f}{t_r * 1e3:>15.2f}{t_z * 1e3:>11.2f}{dm:>14.1e}{worst:>14.1e}")
    print()
    print(f"{'example':<14}{'φ1, °':>8}{'M_ур, N·m':>12}{'exact Δ, %':>12}{'graph. Δ, %':>13}"
          f"{'max |dev| of reactions > 20 mm, %':>36}{'t, ms':>8}")
    for name in NAMES:
        p = Project(load_task(EXAMPLES / name / "task.toml"))
        t = best_time(lambda p=p: kinetostatics_at(p), repeat=3)
        ks = kinetostatics_at(p)
        g = ks.graphical
        devs = [abs(v.deviation_percent) for poly in [gg.polygon for gg in g.groups] + [g.crank.polygon]
                for v in poly.vectors + poly.extra if not v.known and v.length_mm > 20]
        print(f"{name:<14}{ks.phi_deg:>8.2f}{ks.balancing_moment:>12.4f}{ks.discrepancy_percent:>12.1e}"
              f"{g.discrepancy_percent:>13.4f}{max(devs):>36.3f}{t * 1e3:>8.1f}")


if __name__ == "__main__":
    main()
