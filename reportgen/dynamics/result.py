"""The result of the dynamics stage and its ``dynamics`` block of results.json (RESULTS_FORMAT.md;
added keys documented in docs/dynamics.md)."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .flywheel import FlywheelSize
from .graphical import GraphicalReplica
from .motion import SteadyMotion
from .wittenbauer import Merzalov, WittenbauerExact


@dataclass(frozen=True)
class MethodComparison:
    """J_fly by one method and its difference from the exact value (kg·m² and relative)."""
    method: str
    J_fly: float
    difference: float
    relative: float


@dataclass(frozen=True)
class DynamicsResult:
    """Everything of the flywheel calculation; arrays (n,) over the grid θ_i = i·2π/n from position 0.

    theta: rotation from position 0 in the crank's sense (rad); phi: the crank angle φ1 (rad);
    M_red (N·m), J_red (kg·m²), dJ_red (kg·m²/rad); work_resistance = ∫M_red dθ, work_drive =
    M_drive·θ, delta_E = their sum (J). breaks: θ where the loads switch or kink (rad);
    switching: crank angles φ1 where the resistance switches on and off (rad).
    """
    theta: np.ndarray
    phi: np.ndarray
    M_red: np.ndarray
    J_red: np.ndarray
    dJ_red: np.ndarray
    work_resistance: np.ndarray
    work_drive: np.ndarray
    delta_E: np.ndarray
    M_drive: float
    work_cycle: float
    omega_m: float
    delta_target: float
    crank_inertia: float
    J_const: float
    breaks: np.ndarray
    switching: tuple[float, ...]
    exact: WittenbauerExact
    merzalov: Merzalov
    graphical: GraphicalReplica
    comparison: tuple[MethodComparison, ...]
    J_flywheel: float
    flywheel: FlywheelSize
    motion: SteadyMotion

    @property
    def delta_achieved(self) -> float:
        return self.motion.delta

    @property
    def phi_deg(self) -> np.ndarray:
        return np.mod(np.degrees(self.phi), 360.0)


def compare(exact: float, others: dict[str, float]) -> tuple[MethodComparison, ...]:
    rows = [MethodComparison("exact", exact, 0.0, 0.0)]
    for name, J in others.items():
        d = J - exact
        rows.append(MethodComparison(name, J, d, d / exact if exact != 0 else math.inf))
    return tuple(rows)


def dynamics_block(r: DynamicsResult) -> dict[str, Any]:
    """The ``dynamics`` block: the contract's keys first, then the added ones."""
    g, ex, mz, mo, fw = r.graphical, r.exact, r.merzalov, r.motion, r.flywheel
    return {
        "phi_deg": r.phi_deg,
        "M_red": r.M_red,
        "J_red": r.J_red,
        "work_resistance": r.work_resistance,
        "work_drive": r.work_drive,
        "delta_E": r.delta_E,
        "M_drive": r.M_drive,
        "J_flywheel": r.J_flywheel,
        "delta_target": r.delta_target,
        "delta_achieved": r.delta_achieved,
        "flywheel": {"shape": fw.shape, "radius": fw.radius, "width": fw.width, "mass": fw.mass,
                     "inner_radius": fw.inner_radius, "thickness": fw.thickness,
                     "density": fw.density, "width_ratio": fw.width_ratio, "J": fw.J},
        # -- added keys (docs/dynamics.md) --
        "rotation_deg": np.degrees(r.theta),
        "dJ_red": r.dJ_red,
        "omega": mo.omega,
        "omega_m": r.omega_m,
        "omega_band": list(mo.band),
        "work_cycle": r.work_cycle,
        "crank_inertia": r.crank_inertia,
        "J_const": r.J_const,
        "break_rotation_deg": np.degrees(r.breaks),
        "switching_phi_deg": [math.degrees(p) % 360.0 for p in r.switching],
        "motion": {"omega0": mo.omega0, "omega_max": mo.omega_max, "omega_min": mo.omega_min,
                   "rotation_max_deg": math.degrees(mo.theta_max), "rotation_min_deg": math.degrees(mo.theta_min),
                   "omega_mean": mo.omega_mean},
        "wittenbauer": {"omega_max": ex.omega_max, "omega_min": ex.omega_min, "K": ex.K, "L": ex.L,
                        "rotation_K_deg": math.degrees(ex.theta_K), "rotation_L_deg": math.degrees(ex.theta_L),
                        "point_K": list(ex.point_K), "point_L": list(ex.point_L), "J_flywheel": ex.J_fly},
        "merzalov": {"J_const": mz.J_const, "T_max": mz.T_max, "T_min": mz.T_min,
                     "rotation_max_deg": math.degrees(mz.theta_max), "rotation_min_deg": math.degrees(mz.theta_min),
                     "J_first_group": mz.J_first_group, "J_flywheel": mz.J_fly},
        "graphical": {"mu_phi": g.mu_phi, "mu_M": g.mu_M, "H_mm": g.H, "mu_A": g.mu_A,
                      "enlargement": g.enlargement, "mu_E": g.mu_E, "mu_J": g.mu_J,
                      "psi_max_deg": g.psi_max_deg, "psi_min_deg": g.psi_min_deg,
                      "rotation_deg": np.degrees(g.theta), "x_mm": g.x, "M_mm": g.M_mm,
                      "mid_x_mm": g.mid_x, "mid_mm": g.mid_mm, "a_mm": g.a_mm, "drive_mm": g.drive_mm,
                      "e_mm": g.e_mm, "j_mm": g.j_mm, "K_mm": g.K_mm, "L_mm": g.L_mm, "KL_mm": g.KL_mm,
                      "KL_read_mm": g.KL_read_mm,
                      "index_K": g.index_K, "index_L": g.index_L, "J_flywheel": g.J_fly,
                      "accuracy": g.accuracy},
        "comparison": [{"method": c.method, "J_flywheel": c.J_fly, "difference": c.difference,
                        "relative": c.relative} for c in r.comparison],
    }
