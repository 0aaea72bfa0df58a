"""Dynamics: solve time, the error of the work integral by rule and grid, and the flywheel by the
three methods — with the δ that each method's flywheel really gives when the motion is integrated.

Run: .venv/bin/python benchmarks/bench_dynamics.py   (prints tables; not a test)
"""
from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from reportgen.dynamics import EnergyProfile, ProjectCycle, graphical_replica, solve_dynamics, steady_motion
from reportgen.project import Project
from reportgen.taskfile import load_task
from reportgen.scenes.boxes import DEFAULT as DEFAULT_BOXES

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
NAMES = ("press", "conveyor", "crank-slider", "shaper")


def law_area(law) -> float:
    xs, ys = np.array([p[0] for p in law]), np.array([p[1] for p in law])
    return float(np.sum(np.diff(xs) * (ys[:-1] + ys[1:]) / 2))


def main() -> None:
    print("Solve time (n = 360, everything: exact, Мерцалов, replica, motion)")
    print(f"{'example':<14}{'time, s':>9}")
    projects = {}
    results = {}
    for name in NAMES:
        p = Project(load_task(EXAMPLES / name / "task.toml"))
        t0 = time.perf_counter()
        r = solve_dynamics(p)
        dt = time.perf_counter() - t0
        projects[name], results[name] = p, r
        print(f"{name:<14}{dt:>9.2f}")

    print("\nRelative error of one cycle's work against −F·s·∫law (gravity is conservative)")
    print(f"{'example':<14}{'rule':<26}{'n=36':>10}{'n=360':>10}{'n=361':>10}")
    for name in NAMES:
        p, r = projects[name], results[name]
        exact = -sum(ld.force * p.strokes.stroke * law_area(ld.law) for ld in p.task.mechanism.loads
                     if ld.kind == "resistance")
        cyc = ProjectCycle(p)
        row = {}
        for n in (36, 360, 361):
            t = np.arange(n + 1) * 2 * math.pi / n
            M = cyc.reduced(t).M
            row.setdefault("periodic trapezoid", []).append(np.sum((M[:-1] + M[1:]) / 2 * np.diff(t)))
            for k in (1, 2, 4, 8):
                row.setdefault(f"piecewise Gauss–Legendre {k}", []).append(EnergyProfile(cyc, t[:-1], k).work_cycle)
        for rule, vals in row.items():
            print(f"{name:<14}{rule:<26}" + "".join(f"{abs(v / exact - 1):>10.1e}" for v in vals))

    print("\nFlywheel by method; δ achieved when the motion is integrated with that flywheel")
    print(f"{'example':<14}{'method':<16}{'J_fly, kg·m²':>14}{'vs exact':>10}{'δ achieved':>12}{'δ target':>10}")
    for name in NAMES:
        p, r = projects[name], results[name]
        cyc = ProjectCycle(p)
        prof = EnergyProfile(cyc, r.theta)
        methods = [("exact", r.exact.J_fly), ("Мерцалов", r.merzalov.J_fly)]
        for n in (8, 12, 24, 48):
            methods.append((f"graphical {n}", graphical_replica(cyc, r.delta_target, n, layout=DEFAULT_BOXES.diagrams).J_fly))
        for label, J in methods:
            d = steady_motion(cyc, prof, J, r.theta, r.delta_target).delta
            print(f"{name:<14}{label:<16}{J:>14.4f}{J / r.exact.J_fly - 1:>+10.2%}{d:>12.5f}{r.delta_target:>10.3f}")
        print(f"{'':<14}{'(replica accuracy estimate at 12 positions: ±' + format(r.graphical.accuracy, '.3g') + ' kg·m²)'}")


if __name__ == "__main__":
    main()
