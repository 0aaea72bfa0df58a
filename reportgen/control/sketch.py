"""The sketch of a control-work variant: every point of the reconstructed scheme at the printed φ.

Closed forms only (circle–circle and circle–line intersections); a variant whose dimensions cannot
form the mechanism at φ gets the violated condition with its numbers instead of a sketch.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from ..errors import ReportgenInputError
from .tables import Scheme, Variant, evaluate

from ..geometry import Vec2 as Point


class VariantGeometryError(ReportgenInputError):
    """The variant's dimensions cannot form the mechanism at its φ (``condition`` with numbers)."""

    def __init__(self, table: int, variant: int, condition: str) -> None:
        self.table = table
        self.variant = variant
        self.condition = condition
        super().__init__(f"table {table}, variant {variant}: the mechanism cannot be assembled: {condition}")


class _Unassembled(ReportgenInputError):
    """A closure condition of the scheme fails (internal: becomes VariantGeometryError)."""


@dataclass(frozen=True)
class Sketch:
    points: Mapping[str, Point]
    lengths: Mapping[str, float]          # l_XY of every link side the scheme uses


def _circles(p: Point, r1: float, q: Point, r2: float, side: int, what: str) -> Point:
    """The intersection of circles (p, r1), (q, r2) on the side ``side`` (+1 left) of p→q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = math.hypot(dx, dy)
    if not (abs(r1 - r2) <= d <= r1 + r2) or d == 0.0:
        raise _Unassembled(f"{what}: |{r1:.4g} − {r2:.4g}| ≤ {d:.4g} ≤ {r1:.4g} + {r2:.4g} m fails")
    x = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(max(r1 * r1 - x * x, 0.0))
    ex, ey = dx / d, dy / d
    return (p[0] + x * ex - side * h * ey, p[1] + x * ey + side * h * ex)


def _on_line(p: Point, r: float, through: Point, angle: float, side: int, what: str) -> Point:
    """The point of the line (through, angle) at distance r from p; ``side`` +1: the one further along."""
    ux, uy = math.cos(angle), math.sin(angle)
    wx, wy = p[0] - through[0], p[1] - through[1]
    t0 = wx * ux + wy * uy
    h = abs(wx * uy - wy * ux)                  # distance of p from the line
    if h > r:
        raise _Unassembled(f"{what}: the distance {h:.4g} m of the point from the guide exceeds {r:.4g} m")
    s = math.sqrt(r * r - h * h)
    t = t0 + side * s
    return (through[0] + t * ux, through[1] + t * uy)


def link4_key(scheme: Scheme) -> str:
    """The table's key of link 4's length (l_EF, or l_CE when link 4 joins C to the slider E)."""
    return "l_" + "".join(sorted(scheme.f_from + scheme.slider))


def sketch(scheme: Scheme, v: Variant, phi_deg: float | None = None) -> Sketch:
    """Every point at the crank angle ``phi_deg`` (default: the variant's φ)."""
    val = dict(v.values)
    ev = lambda e: evaluate(e, val)  # noqa: E731
    ph = math.radians(v.phi_deg if phi_deg is None else phi_deg)
    A = (0.0, 0.0)
    B = (val["l_AB"] * math.cos(ph), val["l_AB"] * math.sin(ph))
    D = (ev(scheme.D[0]), ev(scheme.D[1]))
    val.setdefault("l_AD", math.hypot(*D))
    pts: dict[str, Point] = {"A": A, "B": B, "D": D}
    try:
        pts["C"] = _circles(B, val["l_BC"], D, val["l_CD"], scheme.c_side, "C from B and D")
        if scheme.e_kind == "bar":
            p, q = pts[scheme.e_from], pts[scheme.e_toward]
            d = math.hypot(q[0] - p[0], q[1] - p[1])
            t = ev(scheme.e_distance) / d
            pts["E"] = (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
        elif scheme.e_kind == "triangle":
            p, q = pts[scheme.e_from], pts[scheme.e_toward]
            r1, r2 = (ev(x) for x in scheme.e_distances)
            pts["E"] = _circles(p, r1, q, r2, scheme.e_side, f"the triangle {scheme.e_from}{scheme.e_toward}E")
        through = (ev(scheme.guide_through[0]), ev(scheme.guide_through[1]))
        start = pts[scheme.f_from]
        l4 = val[link4_key(scheme)]
        pts[scheme.slider] = _on_line(start, l4, through, math.radians(scheme.guide_angle_deg), scheme.f_side,
                            f"F on the guide from {scheme.f_from}")
    except _Unassembled as exc:
        raise VariantGeometryError(v.table, v.number, str(exc)) from None
    return Sketch(MappingProxyType(pts), MappingProxyType({k: x for k, x in val.items() if k.startswith("l_")}))
