"""The steady motion of the machine with the flywheel fitted, from the equation of motion in energy
form (exact for a machine with one degree of freedom; Артоболевский, «Теория механизмов и машин»):

    ½·J(θ)·ω(θ)² = ½·J(0)·ω0² + ΔE(θ),   J = J_red + J_fly,

which is periodic because ΔE(2π) = 0. ω0 is chosen so that the mean speed, taken as in the course
as ω_m = (ω_max + ω_min)/2, equals the nominal crank speed; then δ = (ω_max − ω_min)/ω_m. The
extremes of ω are searched between the grid nodes, not only at them.

``integrate_ivp`` is an independent cross-check: dω/dθ = (M_drive + M_red − ½·J′·ω²)/(J·ω), the
differential form of the same equation, integrated with scipy's DOP853 piecewise between breaks.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..geometry import readonly
from .cycle import Cycle, moment_and_inertia
from ..roots import brent_root, extremes
from .energy import EnergyProfile
from .errors import DynamicsInputError
from ..errors import ComputationError
from ..tolerances import IVP_RTOL, MEAN_SPEED_REFINE, MEAN_SPEED_RTOL, MEAN_SPEED_XREL


@dataclass(frozen=True)
class SteadyMotion:
    """ω at the grid angles (rad/s, (n,)); ω0 at position 0; the extremes and where they are;
    ω_m = (ω_max + ω_min)/2; δ achieved; the band ω_m(1 ± δ_target/2) for the plot; J_fly used."""
    theta: np.ndarray
    omega: np.ndarray
    omega0: float
    omega_max: float
    omega_min: float
    theta_max: float
    theta_min: float
    omega_mean: float
    delta: float
    band: tuple[float, float]
    J_fly: float


def _omega(u: float, E: np.ndarray, J: np.ndarray) -> np.ndarray:
    return np.sqrt(np.maximum(u + 2.0 * E, 0.0) / J)


def steady_motion(cycle: Cycle, profile: EnergyProfile, J_fly: float, grid: np.ndarray,
                  delta_target: float) -> SteadyMotion:
    """ω(θ) of the steady cycle with mean speed ω_m = (ω_max + ω_min)/2 = the nominal crank speed."""
    wm = cycle.omega_m
    nodes, E = profile.nodes, profile.delta_E_nodes
    J = moment_and_inertia(cycle, nodes).J + J_fly
    u_lo = -2.0 * float(E.min())

    def mean_speed(u: float, En: np.ndarray, Jn: np.ndarray) -> float:
        w = _omega(u, En, Jn)
        return 0.5 * (w.max() + w.min()) - wm

    if mean_speed(u_lo, E, J) > 0:
        raise DynamicsInputError("dynamics.delta", "the machine would stop within the cycle at the nominal "
                                 "mean speed (the flywheel is too small)", "a larger flywheel / smaller δ")
    u_hi = max(u_lo, 1.0) + float(J.max()) * wm * wm
    while mean_speed(u_hi, E, J) < 0:
        u_hi *= 2.0
    u = brent_root(mean_speed, u_lo, u_hi, args=(E, J), xtol=MEAN_SPEED_XREL * u_hi, rtol=MEAN_SPEED_RTOL)
    # Refine: the extremes of ω lie between nodes; solve again on the refined extreme points.
    for _ in range(4):
        def w_of(st, u=u):
            return _omega(u, st[0], st[1] + J_fly)
        vals = _omega(u, E, J)
        (t_hi, _), (t_lo, _) = extremes(profile.state, nodes, [(w_of, vals, "max"), (w_of, vals, "min")])
        tt = np.array([t_hi, t_lo])
        Ex, Jx = profile.state(tt)
        Jx = Jx + J_fly
        u_new = brent_root(lambda v, Ex=Ex, Jx=Jx: 0.5 * (_omega(v, Ex, Jx).sum()) - wm, u_lo, u_hi, xtol=MEAN_SPEED_XREL * u_hi, rtol=MEAN_SPEED_RTOL)
        done = abs(u_new - u) <= MEAN_SPEED_REFINE * abs(u_new)
        u = u_new
        if done:
            break
    w_hi, w_lo = (float(x) for x in _omega(u, Ex, Jx))
    grid = np.asarray(grid, dtype=float)
    Eg, Jg = profile.state(grid)
    w_grid = readonly(_omega(u, Eg, Jg + J_fly))
    g = readonly(grid)
    J0 = float(moment_and_inertia(cycle, np.array([0.0])).J[0]) + J_fly
    mean = 0.5 * (w_hi + w_lo)
    return SteadyMotion(g, w_grid, math.sqrt(u / J0), w_hi, w_lo, t_hi, t_lo, mean, (w_hi - w_lo) / mean,
                        (wm * (1 - delta_target / 2), wm * (1 + delta_target / 2)), J_fly)


def integrate_ivp(cycle: Cycle, M_drive: float, J_fly: float, omega0: float, theta_out: np.ndarray,
                  rtol: float = IVP_RTOL) -> np.ndarray:
    """ω at ``theta_out`` (within [0, 2π]) from dω/dθ = (M_drive + M_red − ½·J′·ω²)/(J·ω), ω(0) = ω0,
    integrated piecewise between the cycle's break angles (DOP853)."""
    from scipy.integrate import solve_ivp

    def rhs(t, y):
        r = cycle.reduced(np.array([t]))
        w = y[0]
        return [(M_drive + r.M[0] - 0.5 * r.dJ[0] * w * w) / ((r.J[0] + J_fly) * w)]

    theta_out = np.asarray(theta_out, dtype=float)
    out = np.full(theta_out.size, np.nan)
    w = float(omega0)
    br = cycle.breaks
    for a, b in zip(br[:-1], br[1:]):
        inside = (theta_out >= a) & (theta_out <= b)
        t_eval = np.union1d(theta_out[inside], [b])
        sol = solve_ivp(rhs, (a, b), [w], method="DOP853", rtol=rtol, atol=rtol * abs(omega0), t_eval=t_eval)
        if not sol.success:
            raise ComputationError("the equation of motion (solve_ivp)", f"failed on θ ∈ [{a}, {b}]: {sol.message}")
        out[inside] = np.interp(theta_out[inside], sol.t, sol.y[0])   # exact: the same points
        w = float(sol.y[0, -1])
    return out
