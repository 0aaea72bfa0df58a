"""Solve time of positions, velocities and accelerations over N crank positions, per example.

Run: .venv/bin/python benchmarks/bench_kinematics.py   (prints a table; not a test)
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from reportgen.bench.tables import best_time as shortest_time
from reportgen.kinematics import build_model
from reportgen.taskfile import load_task

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def best_time(fn, repeat: int = 7) -> float:
    """The shortest wall time of ``repeat`` calls of ``fn``, s."""
    return shortest_time(fn, repeat)[0]


def main() -> None:
    print(f"{'example':<14}{'N':>6}{'build, ms':>12}{'positions, ms':>15}{'+ v, a, ms':>13}{'total, ms':>12}")
    for name in ("press", "crank-slider", "shaper", "conveyor", "class3"):
        mech = load_task(EXAMPLES / name / "task.toml").mechanism
        t_build = best_time(lambda mech=mech: build_model(mech), repeat=3)
        m = build_model(mech)
        for N in (12, 360, 3600):
            if name == "class3" and N > 360:
                continue
            phi = np.linspace(0, 2 * math.pi, N, endpoint=False)
            t_pos = best_time(lambda m=m, phi=phi: m.positions(phi), repeat=3 if name == "class3" else 7)
            t_all = best_time(lambda m=m, phi=phi: m.solve(phi), repeat=3 if name == "class3" else 7)
            print(f"{name:<14}{N:>6}{t_build * 1e3:>12.2f}{t_pos * 1e3:>15.2f}{(t_all - t_pos) * 1e3:>13.2f}{t_all * 1e3:>12.2f}")


if __name__ == "__main__":
    main()
