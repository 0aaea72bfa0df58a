"""The graphical replica of the flywheel calculation as the student draws it on sheet 3 (seed 000,
section 3; Артоболевский), kept in millimetres so that it can be drawn and printed:

1. M_red(φ) at scale μM (N·m/mm) over a φ axis of μφ (rad/mm).
2. Graphical integration by chords: on each interval between positions the ordinate at its middle,
   y_i (mm), is carried to the M axis and joined to the pole P at distance H (mm); the chord of the
   work diagram on that interval is parallel to that ray: a_{i+1} = a_i + y_i·Δx_i / H.
   Scale of work: μA = μM·μφ·H (J/mm).
3. A_drive is the straight line from the origin to the end of A_red's diagram; ΔE = A_drive + A_red
   is redrawn at μE = μA / k (k the enlargement, J/mm).
4. J_red(φ) at μJ (kg·m²/mm); the Wittenbauer diagram ΔE(J) from the positions (x = J/μJ from J = 0).
5. Tangents at ψmax,min = arctg[μJ·(1 ± δ)·ω_m² / (2·μE)] (the course's formula, seed 000; the exact
   (1 ± δ/2)² differs by δ²/4) cut the ΔE axis at K and L; J_fly = KL·μE / (ω_m²·δ).

The positions are the [analysis] positions plus the angles where the resistance switches or kinks
(seed 000 adds the end of the working stroke, «крх»). Its drawing accuracy: the chords and the
polygon through the positions err as h²; Richardson's estimate 4/3·|J(h) − J(h/2)| from the replica
repeated with every interval halved (at the same scales), plus reading KL to READING_MM.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..scenes.boxes import GraphLayout
from ..scenes.dynamics import J_BEYOND_MM
from ..scenes.scales import PLAN_SERIES, round_up
from .cycle import TWO_PI, Cycle, moment_and_inertia
from ..geometry import readonly as _ro
from ..numbers import decimal_text
from ..tolerances import RTOL_EQUAL, RTOL_ROUNDOFF

#: Reading accuracy of a length measured on the sheet, mm.
READING_MM = 0.5
#: KL is dimensioned on sheet 3 to this many decimals (0,1 mm) and read as printed: the note's
#: formula for J_fly and the replica's J_fly use that value (one quantity, one rounding).
KL_DECIMALS = 1
#: Mantissas of the scale factors (ГОСТ 2.302-like round values; 10 closes the decade).
NICE = (*PLAN_SERIES, 10.0)
#: Enlargements allowed from the work diagram to the ΔE diagram (μE = μA / k).
ENLARGE = (1, 2, 4, 5, 10)
#: A step past a round scale factor to the next one of the series (whose steps are ≥ 25 %).
NEXT_ROUND = 0.01
#: At most this many steps to a coarser μM (five a decade: a column 10^20 times too tall; a NaN
#: ordinate, which never fits, stops here instead of looping).
COARSER_STEPS = 100


def nice_ceil(x: float) -> float:
    """The smallest round scale factor ≥ x (:func:`reportgen.scenes.scales.round_up`)."""
    return round_up(x, PLAN_SERIES)


@dataclass(frozen=True)
class GraphicalReplica:
    """Every intermediate of the construction (lengths in mm, scales in SI per mm).

    theta: the positions (rad, from position 0, the last = 2π); x: their abscissae;
    M_mm: M_red at the positions; mid_x, mid_mm: the middle ordinates used for the chords;
    a_mm: the work of the loads A_red by chords; drive_mm: A_drive; e_mm: ΔE at μE; j_mm: J_red;
    K_mm, L_mm: intercepts on the ΔE axis; KL_mm (as constructed); index_K, index_L: the tangent
    positions; KL_read_mm: KL as sheet 3 dimensions it and the student reads it (KL_DECIMALS);
    J_fly = KL_read·μE / (ω_m²·δ).
    """
    mu_phi: float
    mu_M: float
    H: float
    mu_A: float
    enlargement: float           # k of μE = μA / k: an int ≥ 1 (ENLARGE), or 1/n (a reduction)
    mu_E: float
    mu_J: float
    psi_max_deg: float
    psi_min_deg: float
    theta: np.ndarray
    x: np.ndarray
    M_mm: np.ndarray
    mid_x: np.ndarray
    mid_mm: np.ndarray
    a_mm: np.ndarray
    drive_mm: np.ndarray
    e_mm: np.ndarray
    j_mm: np.ndarray
    K_mm: float
    L_mm: float
    KL_mm: float
    index_K: int
    index_L: int
    J_fly: float
    accuracy: float               # estimated drawing accuracy of J_fly, kg·m²
    KL_read_mm: float             # KL as dimensioned on sheet 3 and read, mm


def work_scale(mu_M: float, mu_phi: float, H: float) -> float:
    """μA = μM·μφ·H, J/mm (seed 000: 25·0.032725·60 = 49.088)."""
    return mu_M * mu_phi * H


def tangent_slopes(mu_J: float, mu_E: float, omega_m: float, delta: float) -> tuple[float, float]:
    """tg ψmax,min = μJ·(1 ± δ)·ω_m² / (2·μE) (seed 000, section 3)."""
    base = mu_J * omega_m * omega_m / (2.0 * mu_E)
    return base * (1.0 + delta), base * (1.0 - delta)


def flywheel_from_KL(KL_mm: float, mu_E: float, omega_m: float, delta: float) -> float:
    """J_fly = KL·μE / (ω_m²·δ), kg·m² (seed 000: 102.418·24.544/(18²·0.05) = 155.17)."""
    return KL_mm * mu_E / (omega_m * omega_m * delta)


def replica_positions(cycle: Cycle, positions: int) -> np.ndarray:
    """θ of the [analysis] positions from position 0, the break angles, and 2π (sorted)."""
    th = np.arange(positions) * TWO_PI / positions
    return np.union1d(np.union1d(th, cycle.breaks), [TWO_PI])


def wittenbauer_height(e: np.ndarray, jx: np.ndarray, t_max: float, t_min: float) -> float:
    """Height of the Wittenbauer construction, mm: the curve ΔE(J), the ΔE axis from 0, the points K
    and L where the tangents cut it and the tangents' ends at the end of the J axis (as
    :func:`reportgen.scenes.dynamics.wittenbauer_scene` draws them)."""
    K, L = float(np.max(e - jx * t_max)), float(np.min(e - jx * t_min))
    x_end = float(np.max(jx)) + J_BEYOND_MM
    ys = np.concatenate((e, [0.0, K, L, K + x_end * t_max, L + x_end * t_min]))
    return float(ys.max() - ys.min())


def _enlargement(e_A: np.ndarray, jx: np.ndarray, mu_J: float, mu_A: float, omega_m: float, delta: float,
                 layout: GraphLayout) -> float:
    """k of μE = μA / k: the largest of ENLARGE that draws the span of ΔE within ``layout.e_height``
    (1 if none), made smaller where the whole Wittenbauer construction would not fit
    ``layout.w_height``: k = 1/n, n the smallest round reduction (1, 2, 2.5, 4, 5 × 10^j) that fits.

    Every ordinate of that construction — ΔE, K, L, the tangents' ends — is ∝ 1/μE (tg ψ ∝ μJ/μE at a
    fixed μJ), so its height at k is k times its height at k = 1. K and L stand about J_red·ω_m²/(2μE)
    below the curve: a machine whose J_red·ω_m²/2 (or its variation) dwarfs ΔE (the press with its
    lengths × 100 and its masses kept: ψ ≈ 86°) put them metres below the ΔE axis at μE = μA."""
    span = float(e_A.max() - e_A.min())
    t_max, t_min = tangent_slopes(mu_J, mu_A, omega_m, delta)      # at k = 1
    height = wittenbauer_height(e_A, jx, t_max, t_min)
    fits = [k for k in ENLARGE if k * span <= layout.e_height and k * height <= layout.w_height]
    if fits:
        return max(fits)
    if height <= layout.w_height:
        return 1
    return 1.0 / round_up(height / layout.w_height, PLAN_SERIES)


def _span(*arrays) -> float:
    """From the lowest to the highest ordinate, 0 included (the diagram's axis), mm."""
    v = np.concatenate([np.atleast_1d(np.asarray(a, dtype=float)) for a in arrays] + [np.zeros(1)])
    return float(v.max() - v.min())


def _construct(cycle: Cycle, theta: np.ndarray, delta: float, layout: GraphLayout,
               scales: dict | None = None) -> dict:
    wm = cycle.omega_m
    mid = 0.5 * (theta[:-1] + theta[1:])
    r = moment_and_inertia(cycle, np.concatenate((theta, mid)))
    M, Mmid = r.M[:theta.size], r.M[theta.size:]
    J = r.J[:theta.size]
    s = dict(scales or {})
    mu_phi = s.setdefault("mu_phi", TWO_PI / layout.phi_axis)
    # a machine without load (M_red ≈ 0) still gets a finite scale: a floor of 1e-9·J·ω² (N·m)
    m_ref = max(float(np.abs(np.concatenate((M, Mmid))).max()), RTOL_EQUAL * float(J.max()) * wm * wm)
    x = theta / mu_phi
    mu_J = s.setdefault("mu_J", nice_ceil(float(J.max()) / layout.j_width))
    jx = J / mu_J
    choose = "mu_M" not in s
    s.setdefault("mu_M", nice_ceil(m_ref / layout.m_height))
    for _coarser in range(COARSER_STEPS + 1):
        mu_M = s["mu_M"]
        y_mid = Mmid / mu_M
        steps = y_mid * np.diff(x)                       # = a_{i+1}·H − a_i·H
        a_H = np.concatenate(([0.0], np.cumsum(steps)))  # a·H, mm²
        if "H" not in s:
            need = float(np.abs(a_H).max()) / layout.a_height
            s["H"] = max(layout.pole_step, layout.pole_step * math.ceil(need / layout.pole_step - RTOL_ROUNDOFF))
        H = s["H"]
        a = a_H / H
        mu_A = work_scale(mu_M, mu_phi, H)
        drive = -a[-1] * x / x[-1]
        e_A = a + drive
        k = s["enlargement"] if "enlargement" in s else _enlargement(e_A, jx, mu_J, mu_A, wm, delta, layout)
        # sheet 3's column holds M, A and ΔE one under the other: each filling its own box, they
        # could overflow it together (conveyor with its lengths × 0.37 and its force × 8.5); then μM
        # is the next round value, H kept (M and A shrink, ΔE keeps its own enlargement rule)
        column = _span(M / mu_M, y_mid) + _span(a, [drive[-1]]) + _span(e_A * k)
        if not choose or column <= layout.column_height or _coarser == COARSER_STEPS:
            break
        s["mu_M"] = nice_ceil(mu_M * (1.0 + NEXT_ROUND))
    s.setdefault("enlargement", k)
    mu_E = mu_A / k
    e = e_A * k
    t_max, t_min = tangent_slopes(mu_J, mu_E, wm, delta)
    up, lo = e - jx * t_max, e - jx * t_min
    iK, iL = int(np.argmax(up)), int(np.argmin(lo))
    KL = float(up[iK] - lo[iL])
    return dict(mu_phi=mu_phi, mu_M=mu_M, H=H, mu_A=mu_A, enlargement=k, mu_E=mu_E, mu_J=mu_J,
                psi_max_deg=math.degrees(math.atan(t_max)), psi_min_deg=math.degrees(math.atan(t_min)),
                theta=theta, x=x, M_mm=M / mu_M, mid_x=mid / mu_phi, mid_mm=y_mid, a_mm=a, drive_mm=drive,
                e_mm=e, j_mm=jx, K_mm=float(up[iK]), L_mm=float(lo[iL]), KL_mm=KL, index_K=iK, index_L=iL,
                J_fly=flywheel_from_KL(KL, mu_E, wm, delta), scales=s)


def graphical_replica(cycle: Cycle, delta: float, positions: int = 12, *, layout: GraphLayout) -> GraphicalReplica:
    """The sheet's construction at ``positions`` equal steps (plus the break angles), its scales
    chosen for the room ``layout`` (``project.boxes.diagrams``: the caller passes it, the solver
    holds no sheet's boxes)."""
    theta = replica_positions(cycle, positions)
    c = _construct(cycle, theta, delta, layout)
    scales = c.pop("scales")
    fine = np.union1d(theta, 0.5 * (theta[:-1] + theta[1:]))
    c2 = _construct(cycle, fine, delta, layout, scales)
    wm = cycle.omega_m
    # Chords and polygon err as h²: Richardson's estimate of the error at h is 4/3·|J(h) − J(h/2)|.
    accuracy = 4.0 / 3.0 * abs(c["J_fly"] - c2["J_fly"]) + READING_MM * c["mu_E"] / (wm * wm * delta)
    # the student reads KL off the sheet as it is dimensioned there, and J_fly follows from that
    kl_read = float(decimal_text(c["KL_mm"], KL_DECIMALS))
    c["J_fly"] = flywheel_from_KL(kl_read, c["mu_E"], wm, delta)
    arrays = ("theta", "x", "M_mm", "mid_x", "mid_mm", "a_mm", "drive_mm", "e_mm", "j_mm")
    fields_: dict[str, Any] = {k: (_ro(v) if k in arrays else v) for k, v in c.items()}
    return GraphicalReplica(**fields_, accuracy=accuracy, KL_read_mm=kl_read)
