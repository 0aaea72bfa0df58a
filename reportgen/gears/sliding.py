"""Specific sliding (удельное скольжение) along the line of action.

With ρ the distance of the contact point from N1 along N1N2 = g, the radii of curvature of the two
flanks are ρ1 = ρ and ρ2 = g − ρ, and (Артоболевский; Кудрявцев; the seed note, formulas of 4.1.3)
    λ1 = 1 − ρ2 / (ρ1 u),      λ2 = 1 − ρ1 u / ρ2,      u = z2 / z1.
λ1 → −∞ at N1, λ2 → −∞ at N2, both are 0 at the pole P. The most harmful values on the working
section ab are at its ends: λ1 at a (the lower point of the active profile of gear 1) and λ2 at b.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ..errors import ParameterError

from ..geometry import readonly

#: Points of the table between a and P and between P and b (the seed has 2 + 2).
DEFAULT_STEPS = 3


def lambda1(rho, g, u):
    """λ1 = 1 − (g − ρ) / (ρ u); −inf at ρ = 0."""
    rho = np.asarray(rho, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 1.0 - (g - rho) / (rho * u)


def lambda2(rho, g, u):
    """λ2 = 1 − ρ u / (g − ρ); −inf at ρ = g."""
    rho = np.asarray(rho, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 1.0 - rho * u / (g - rho)


@dataclass(frozen=True)
class SlidingRow:
    """One row of the table: point label ('N1', 'a', 'P', 'b', 'N2' or '' between), ρ = N1X in mm."""
    label: str
    rho: float
    lambda1: float
    lambda2: float


@dataclass(frozen=True)
class SlidingTable:
    g: float
    u: float
    rows: tuple[SlidingRow, ...]
    lambda1_a: float     # λ1 at a, the largest |λ1| on the working section
    lambda2_b: float     # λ2 at b, the largest |λ2| on the working section

    def curve(self, n: int = 201, clip: float = 0.02) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(ρ, λ1, λ2) over N1N2 for the graph, ρ from clip·g to (1 − clip)·g (λ is infinite at
        the ends). Read-only arrays."""
        rho = np.linspace(clip * self.g, (1.0 - clip) * self.g, n)
        out = (readonly(rho), readonly(lambda1(rho, self.g, self.u)), readonly(lambda2(rho, self.g, self.u)))
        return out


def sliding_table(g: float, u: float, n1a: float, n1p: float, n1b: float,
                  steps: int = DEFAULT_STEPS) -> SlidingTable:
    """The table at the course's points: N1, a, (steps − 1) points between a and P, P, (steps − 1)
    between P and b, b, N2. If P is not inside ab, ab is divided into ``2·steps`` equal parts."""
    if steps < 1:
        raise ParameterError("steps", steps, "≥ 1")
    pts: list[tuple[str, float]] = [("N1", 0.0)]
    if n1a < n1p < n1b:
        pts += [("a" if i == 0 else "", n1a + (n1p - n1a) * i / steps) for i in range(steps)]
        pts += [("P" if i == 0 else "", n1p + (n1b - n1p) * i / steps) for i in range(steps)]
        pts.append(("b", n1b))
    else:
        k = 2 * steps
        pts += [("a" if i == 0 else "", n1a + (n1b - n1a) * i / k) for i in range(k)]
        pts.append(("b", n1b))
        pts.append(("P", n1p))
    pts.append(("N2", g))
    pts.sort(key=lambda t: t[1])
    rows = tuple(SlidingRow(label, float(rho), float(lambda1(rho, g, u)), float(lambda2(rho, g, u)))
                 for label, rho in pts)
    return SlidingTable(g=float(g), u=float(u), rows=rows,
                        lambda1_a=float(lambda1(n1a, g, u)), lambda2_b=float(lambda2(n1b, g, u)))
