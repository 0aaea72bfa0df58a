"""Moment of inertia of the flywheel from the energy–mass (Wittenbauer) diagram ΔE(J_red), exactly,
and by Мерцалов's method.

Exact (the analytic equivalent of the tangents, NOTES.md; Артоболевский, гл. 15): with
ω_max,min = ω_m(1 ± δ/2) the speed stays in [ω_min, ω_max] iff, for the kinetic energy T0 at
position 0, T0 + ΔE(θ) ≤ ½(J_red + J_fly)·ω_max² and ≥ ½(J_red + J_fly)·ω_min² for every θ; both
tight give

    J_fly = [max_θ(ΔE − J_red·ω_max²/2) − min_θ(ΔE − J_red·ω_min²/2)] / (ω_m²·δ),

the flywheel to be ADDED to J_red (which already holds the crank and its rotor). The two maxima are
the intercepts of the tangents at ψmax, ψmin with the ΔE axis (points K and L of the diagram).

Мерцалов (Кожевников, «Теория механизмов и машин»; Артоболевский): the variable part J_v = J_red − J_const
is taken to move at ω_m, T_II = J_v·ω_m²/2; the first group (crank, rotor, flywheel) then has
T_I = ΔE − T_II + const and needs J_I = (max T_I − min T_I)/(ω_m²·δ); the flywheel is
J_I − J_const. Freezing ω in T_II overestimates J_fly by about (J_max − J_min)/2 when J_red varies
strongly.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..roots import extremes
from .cycle import Cycle, moment_and_inertia
from .energy import EnergyProfile


@dataclass(frozen=True)
class WittenbauerExact:
    """The exact tangents: K = max(ΔE − J·ω_max²/2) at θ_K, L = min(ΔE − J·ω_min²/2) at θ_L (J);
    the tangent points (J, ΔE) on the curve; J_fly (kg·m²)."""
    delta: float
    omega_m: float
    omega_max: float
    omega_min: float
    K: float
    L: float
    theta_K: float
    theta_L: float
    point_K: tuple[float, float]
    point_L: tuple[float, float]
    J_fly: float


@dataclass(frozen=True)
class Merzalov:
    """Мерцалов's method: T_I = ΔE − J_v·ω_m²/2, its extremes (J) at θ, the first group's J_I and
    the flywheel J_fly = J_I − J_const (kg·m²)."""
    J_const: float
    T_max: float
    T_min: float
    theta_max: float
    theta_min: float
    J_first_group: float
    J_fly: float


def wittenbauer_and_merzalov(cycle: Cycle, profile: EnergyProfile, delta: float) -> tuple[WittenbauerExact, Merzalov]:
    """Both flywheels; their four extremes (K, L; max and min of T_I) are searched together, one
    evaluation of the cycle per round (:func:`reportgen.roots.extremes`)."""
    wm = cycle.omega_m
    w_hi, w_lo = wm * (1.0 + delta / 2.0), wm * (1.0 - delta / 2.0)
    nodes = profile.nodes
    E = profile.delta_E_nodes
    J = moment_and_inertia(cycle, nodes).J

    def T(st):
        E_t, J_t = st
        return E_t - (J_t - cycle.J_const) * wm * wm / 2.0

    vals = E - (J - cycle.J_const) * wm * wm / 2.0
    (tK, K), (tL, L), (t_hi, T_hi), (t_lo, T_lo) = extremes(profile.state, nodes, [
        (lambda st: st[0] - st[1] * w_hi * w_hi / 2.0, E - J * w_hi ** 2 / 2.0, "max"),
        (lambda st: st[0] - st[1] * w_lo * w_lo / 2.0, E - J * w_lo ** 2 / 2.0, "min"),
        (T, vals, "max"), (T, vals, "min")])
    (EK, EL), (JK, JL) = profile.state(np.array([tK, tL]))
    pK, pL = (float(JK), float(EK)), (float(JL), float(EL))
    witt = WittenbauerExact(delta, wm, w_hi, w_lo, K, L, tK, tL, pK, pL, (K - L) / (wm * wm * delta))
    J1 = (T_hi - T_lo) / (wm * wm * delta)
    return witt, Merzalov(cycle.J_const, T_hi, T_lo, t_hi, t_lo, J1, J1 - cycle.J_const)


def wittenbauer_exact(cycle: Cycle, profile: EnergyProfile, delta: float) -> WittenbauerExact:
    """J_fly from the exact analytic equivalent of the Wittenbauer tangents."""
    return wittenbauer_and_merzalov(cycle, profile, delta)[0]


def merzalov(cycle: Cycle, profile: EnergyProfile, delta: float) -> Merzalov:
    """J_fly by Мерцалов's method (the kinetic energy of the variable links at ω_m)."""
    return wittenbauer_and_merzalov(cycle, profile, delta)[1]
