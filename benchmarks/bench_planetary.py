"""Speed of the planetary tooth-number search: wall time per target ratio and scheme (K auto,
tolerance 5 %), best of 3 runs. Prints a table; not a test.

    .venv/bin/python benchmarks/bench_planetary.py
"""
from __future__ import annotations

import time

from reportgen.errors import PlanetarySynthesisError
from reportgen.planetary import SCHEMES, synthesize

TARGETS = (3.0, 5.0, 8.0, 12.272, 20.0, 30.0, 40.0)


def _time(scheme: str, target: float, driver: str) -> tuple[float, str]:
    best = float("inf")
    result = ""
    for _ in range(3):
        t0 = time.perf_counter()
        try:
            d = synthesize(scheme, target, 0.05, "auto", driver=driver)
            result = f"{'/'.join(map(str, d.z))} K={d.satellites} u={d.ratio:.3f}"
        except PlanetarySynthesisError as exc:
            result = f"none ({len(exc.nearest)} nearest)"
        best = min(best, time.perf_counter() - t0)
    return best, result


def main() -> None:
    print(f"{'scheme':18} {'driver':8} {'target':>7} {'time, ms':>9}  result")
    for driver in ("wheel", "carrier"):
        for scheme in SCHEMES:
            for target in TARGETS:
                t, res = _time(scheme, target, driver)
                print(f"{scheme:18} {driver:8} {target:7.3f} {t * 1000:9.1f}  {res}")


if __name__ == "__main__":
    main()
