"""The ``planetary`` block of results.json (RESULTS_FORMAT.md) as a plain dict.

Contract keys: scheme, z, satellites, ratio, ratio_target, ratio_graphical, checks {coaxial,
adjacent, assembly}. Added keys: driver, u1h, deviation, tolerance, checks.undercut, checks.ratio,
size_modules, module, diameters_mm, centre_distance_mm, conditions (the numbers of each check),
candidates (the next sets of the search), drive, velocity.
"""
from __future__ import annotations

from typing import Any

from .drive import DriveCheck
from .search import PlanetaryDesign
from .velocity import VelocityTriangle


def _pt(p: tuple[float, float]) -> list[float]:
    return [float(p[0]), float(p[1])]


def conditions_dict(design: PlanetaryDesign) -> dict[str, Any]:
    """Every condition with its numbers."""
    c, u, adj, asm, rc = design.coaxial, design.undercut, design.adjacency, design.assembly, design.ratio_check
    return {
        "coaxial": {"formula": c.formula, "left": c.left, "right": c.right, "holds": c.holds},
        "undercut": [{"what": i.what, "kind": i.kind, "value": i.value, "limit": i.limit, "holds": i.holds}
                     for i in u.items],
        "adjacency": {"satellites": adj.satellites, "centre_sum": adj.centre_sum,
                      "planet": adj.planet_label, "planet_z": adj.planet_z, "ha": adj.ha,
                      "sin_pi_over_K": adj.sin_term, "left": adj.left, "right": adj.right,
                      "k_limit": adj.k_limit, "k_max": adj.k_max, "holds": adj.holds},
        "assembly": {"satellites": asm.satellites, "formula": asm.formula, "sign": asm.sign,
                     "numerator": asm.numerator, "gcd": asm.g, "divisor": asm.divisor,
                     "quotient": float(asm.quotient), "holds": asm.holds},
        "ratio": {"driver": rc.driver, "u13h": float(rc.u13h), "u1h": float(rc.u1h),
                  "ratio": float(rc.ratio), "target": rc.target, "tolerance": rc.tolerance,
                  "deviation": rc.deviation, "holds": rc.holds},
    }


def planetary_block(design: PlanetaryDesign, triangle: VelocityTriangle | None = None,
                    drive: DriveCheck | None = None) -> dict[str, Any]:
    """The ``planetary`` block; ``triangle`` and ``drive`` add their keys when given."""
    rc = design.ratio_check
    out: dict[str, Any] = {
        "scheme": design.scheme.name,
        "z": list(design.z),
        "satellites": design.satellites,
        "ratio": float(rc.ratio),
        "ratio_target": rc.target,
        "ratio_graphical": None if triangle is None else triangle.ratio_graphical,
        "checks": {"coaxial": design.coaxial.holds, "adjacent": design.adjacency.holds,
                   "assembly": design.assembly.holds, "undercut": design.undercut.holds,
                   "ratio": rc.holds},
        "driver": design.driver,
        "u1h": float(rc.u1h),
        "deviation": rc.deviation,
        "tolerance": rc.tolerance,
        "satellites_auto": design.satellites_auto,
        "size_modules": design.size,
        "module": design.module,
        "conditions": conditions_dict(design),
        "candidates": [{"z": list(c.z), "satellites": c.satellites, "ratio": c.ratio,
                        "deviation": c.deviation, "size_modules": c.size} for c in design.alternatives],
        "limits": {"external_min": design.limits.external_min, "internal_min": design.limits.internal_min,
                   "internal_difference_min": design.limits.internal_difference_min},
    }
    if design.module is not None:
        out["diameters_mm"] = {lab: d for lab, d in design.diameters_mm}
        out["centre_distance_mm"] = design.centre_distance_mm
    if drive is not None:
        r = drive.required
        out["drive"] = {"motor_rpm": r.motor_rpm, "omega_motor": r.omega_motor,
                        "z_open": [r.z1_open, r.z2_open], "open_ratio": r.open_ratio,
                        "order": r.order, "omega_crank_target": r.omega_crank,
                        "ratio_required": r.required, "total_ratio": drive.total_ratio,
                        "omega_crank": drive.omega_crank_achieved, "deviation": drive.deviation}
    if triangle is not None:
        t = triangle
        out["velocity"] = {
            "scale": t.scale_label, "length_scale": t.length_scale, "omega1": t.omega1,
            "radii_mm": {k: v for k, v in t.radii_mm}, "points_mm": {k: _pt(p) for k, p in t.points},
            "v_a": t.v_a, "vector_mm": t.vector_mm, "mu_v": t.mu_v, "v_b_mm": t.v_b_mm_read,
            "reading_mm": t.reading_mm, "v_b": t.v_b, "omega_h": t.omega_h,
            "ratio_graphical": t.ratio_graphical, "difference_percent": t.difference_percent,
            "plan": {"h_mm": t.plan.h_mm, "cuts_mm": {k: x for k, x in t.plan.cuts},
                     "mu_omega": t.plan.mu_omega, "ratio": t.plan.ratio_read},
        }
    return out
