"""Work and kinetic energy over the cycle (Артоболевский, «Теория механизмов и машин», the chapter on the motion of a machine; seed 000, section 3):

    A_red(θ) = ∫_0^θ M_red dθ              work of all loads but the drive (≤ 0 for a resistance)
    M_drive  = −A_red(2π) / 2π             constant driving moment balancing one cycle's work
    ΔE(θ)    = M_drive·θ + A_red(θ)        change of kinetic energy from position 0; ΔE(2π) = 0

The integrals are taken piecewise between the break angles (see ``quadrature``), so ΔE at any θ
is exact to the quadrature's precision wherever the grid falls.
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np
from ..roots import EXTREME_XTOL, extremes
from .cycle import TWO_PI, Cycle, moment_and_inertia
from .quadrature import DEFAULT_ORDER, cumulative, gauss_legendre, integrate_intervals, split_at


class EnergyProfile:
    """ΔE(θ) of a cycle: exact values at the nodes (grid ∪ break angles) and at any θ on demand."""

    def __init__(self, cycle: Cycle, grid: np.ndarray, order: int = DEFAULT_ORDER):
        self.cycle = cycle
        self.order = order
        nodes = np.union1d(np.asarray(grid, dtype=float), cycle.breaks)
        self.nodes = nodes[(nodes >= 0.0) & (nodes <= TWO_PI)]
        self._M = lambda t: moment_and_inertia(cycle, t).M
        self.A_nodes = cumulative(self._M, self.nodes, cycle.breaks, order)
        self.work_cycle = float(self.A_nodes[-1])
        self.M_drive = -self.work_cycle / TWO_PI

    def work_red(self, theta: np.ndarray) -> np.ndarray:
        """A_red(θ) for θ in [0, 2π]: the nearest node below plus the piecewise integral from it."""
        t = np.atleast_1d(np.asarray(theta, dtype=float))
        j = np.clip(np.searchsorted(self.nodes, t, side="right") - 1, 0, self.nodes.size - 1)
        rest = integrate_intervals(self._M, self.nodes[j], t, self.cycle.breaks, self.order)
        return self.A_nodes[j] + rest

    def delta_E(self, theta: np.ndarray) -> np.ndarray:
        t = np.atleast_1d(np.asarray(theta, dtype=float))
        return self.M_drive * t + self.work_red(t)

    def state(self, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(ΔE(θ), J_red(θ)) at any θ in [0, 2π], with one evaluation of the cycle."""
        t = np.atleast_1d(np.asarray(theta, dtype=float))
        j = np.clip(np.searchsorted(self.nodes, t, side="right") - 1, 0, self.nodes.size - 1)
        pl, pr, owner = split_at(self.nodes[j], t, self.cycle.breaks)
        x, w = gauss_legendre(self.order)
        half = 0.5 * (pr - pl)
        gl = (0.5 * (pr + pl))[:, None] + half[:, None] * x[None, :]
        r = moment_and_inertia(self.cycle, np.concatenate((gl.ravel(), t)))
        piece = half * (r.M[:gl.size].reshape(gl.shape) @ w)
        rest = np.zeros(t.size)
        np.add.at(rest, owner, piece)
        return self.M_drive * t + self.A_nodes[j] + rest, r.J[gl.size:]

    @property
    def delta_E_nodes(self) -> np.ndarray:
        return self.M_drive * self.nodes + self.A_nodes


def extreme(g: Callable[[np.ndarray], np.ndarray], nodes: np.ndarray, values: np.ndarray,
             kind: str) -> tuple[float, float]:
    """(θ, g(θ)) of the largest (``kind`` = "max") or smallest value of a continuous periodic g:
    the best node, then a vectorised search on each neighbouring interval (g is smooth inside an
    interval between nodes, since the break angles are nodes; see :func:`reportgen.roots.extremes`,
    which also serves several searches with one evaluation per round)."""
    return extremes(lambda t: (g(t),), nodes, [(lambda st: st[0], values, kind)])[0]


__all__ = ["EnergyProfile", "extreme", "extremes", "EXTREME_XTOL"]
