"""Sizes of the flywheel from its moment of inertia.

Disk (seed 000, section 3; Кожевников): a solid disk of radius R and width b = ψ·R,
J = m·R²/2, m = ρ·π·R²·b  ⇒  R = (2·J / (π·ρ·ψ))^(1/5).

Rim (chosen model, hub and spokes neglected): an annulus of outer radius R, radial thickness
h = k·R (k = RIM_THICKNESS_RATIO = 0.15, within the usual 0.1…0.2) and width b = ψ·h:
m = ρ·b·π·(R² − r²), J = m·(R² + r²)/2 = ρ·π·ψ·k·R⁵·[1 − (1 − k)⁴]/2 with r = (1 − k)·R
⇒  R = (2·J / (π·ρ·ψ·k·[1 − (1 − k)⁴]))^(1/5).  For k = 1 this is the disk.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import DynamicsInputError
from ..errors import ParameterError

#: Radial thickness of a rim over its outer radius.
RIM_THICKNESS_RATIO = 0.15


@dataclass(frozen=True)
class FlywheelSize:
    """shape "disk" | "rim"; J (kg·m²); radius = outer radius R, inner_radius (0 for a disk),
    width b, thickness (radial, = R for a disk), mass (m, kg, SI); density ρ, width_ratio ψ."""
    shape: str
    J: float
    radius: float
    inner_radius: float
    width: float
    thickness: float
    mass: float
    density: float
    width_ratio: float


def flywheel_size(J: float, shape: str = "disk", density: float = 7860.0, width_ratio: float = 1.0,
                  rim_thickness_ratio: float = RIM_THICKNESS_RATIO) -> FlywheelSize:
    """Radius, width and mass of a disk or rim flywheel of moment of inertia ``J``."""
    if shape not in ("disk", "rim"):
        raise DynamicsInputError("dynamics.flywheel.shape", f"unknown shape {shape!r}", '"disk" or "rim"')
    if not (density > 0 and math.isfinite(density)):
        raise DynamicsInputError("dynamics.flywheel.density", f"{density!r} is not a density", "a number > 0, kg/m³")
    if not (width_ratio > 0 and math.isfinite(width_ratio)):
        raise DynamicsInputError("dynamics.flywheel.width_ratio", f"{width_ratio!r} is not a ratio", "a number > 0")
    if not (0 < rim_thickness_ratio <= 1):
        raise ParameterError("rim_thickness_ratio", rim_thickness_ratio, "a ratio in (0, 1]")
    J = max(float(J), 0.0)
    k = 1.0 if shape == "disk" else rim_thickness_ratio
    shape_factor = k * (1.0 - (1.0 - k) ** 4)
    R = (2.0 * J / (math.pi * density * width_ratio * shape_factor)) ** 0.2
    h = k * R
    r = R - h
    b = width_ratio * h
    m = density * b * math.pi * (R * R - r * r)
    return FlywheelSize(shape, J, R, r, b, h, m, density, width_ratio)
