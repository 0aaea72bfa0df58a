"""Symbols of a kinematic scheme as scene entities (paper mm): hatching, a fixed pivot, a slider's
block (ГОСТ 2.770 proportions as the sheets draw them)."""
from __future__ import annotations

import math

from .scene import Circle, Entity, Point, Polyline, Segment
from ..tolerances import MM_ROUNDOFF


def _unit(angle_deg: float) -> Point:
    a = math.radians(angle_deg)
    return (math.cos(a), math.sin(a))


def hatch_strokes(id_: str, p: Point, q: Point, side: float = -1.0, length: float = 3.0,
                  spacing: float = 2.5) -> list[Segment]:
    """Short 45° strokes along p→q, on its right (``side=-1``) or left (+1)."""
    d = math.dist(p, q)
    if d == 0:
        return []
    ux, uy = (q[0] - p[0]) / d, (q[1] - p[1]) / d
    nx, ny = -uy * side, ux * side
    sx, sy = (nx - ux) / math.sqrt(2), (ny - uy) / math.sqrt(2)
    n = max(int(d / spacing), 1)
    start = (d - (n - 1) * spacing) / 2 if n > 1 else d / 2
    out = []
    for i in range(n):
        t = start + i * spacing + length / math.sqrt(2)
        if t > d + MM_ROUNDOFF:
            break
        x, y = p[0] + ux * t, p[1] + uy * t
        out.append(Segment(f"{id_}:h{i}", (x, y), (x + sx * length, y + sy * length), "thin"))
    return out


def ground(id_: str, p: Point, q: Point, side: float = -1.0) -> list[Entity]:
    """A frame line (guide) p→q hatched on its right (−1) or left (+1)."""
    return [Segment(id_, p, q, "contour"), *hatch_strokes(id_, p, q, side)]


def fixed_pivot(id_: str, c: Point, direction_deg: float = -90.0, radius: float = 2.0,
                height: float = 8.0, base: float = 14.0) -> list[Entity]:
    """A revolute pair on the frame: hinge circle, two legs to a hatched base (``direction_deg``
    from the hinge to the base)."""
    ux, uy = _unit(direction_deg)
    tx, ty = -uy, ux
    bc = (c[0] + ux * height, c[1] + uy * height)
    left = (bc[0] + tx * base / 2, bc[1] + ty * base / 2)
    right = (bc[0] - tx * base / 2, bc[1] - ty * base / 2)
    out: list[Entity] = [Circle(id_, c, radius, "contour", hinge=True)]
    for j, foot in enumerate((left, right)):
        d = math.dist(c, foot)
        fx, fy = (foot[0] - c[0]) / d, (foot[1] - c[1]) / d
        out.append(Segment(f"{id_}:leg{j}", (c[0] + fx * radius, c[1] + fy * radius), foot, "contour"))
    ext = 3.0
    p = (left[0] + tx * ext, left[1] + ty * ext)
    q = (right[0] - tx * ext, right[1] - ty * ext)
    out.append(Segment(f"{id_}:base", p, q, "contour"))
    dx, dy = q[0] - p[0], q[1] - p[1]
    side = 1.0 if (-dy * ux + dx * uy) > 0 else -1.0
    out += hatch_strokes(f"{id_}:base", p, q, side)
    return out


def block(id_: str, c: Point, angle_deg: float, length: float, height: float, kind: str,
          hinge: float = 0.0) -> list[Entity]:
    """A slider's block: a rectangle along ``angle_deg`` centred on ``c``, a hinge of radius
    ``hinge`` in its middle (none for 0)."""
    ux, uy = _unit(angle_deg)
    nx, ny = -uy, ux
    hl, hh = length / 2, height / 2
    corners = tuple((c[0] + sx * ux * hl + sy * nx * hh, c[1] + sx * uy * hl + sy * ny * hh)
                    for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1)))
    out: list[Entity] = [Polyline(id_, corners, kind, closed=True)]
    if hinge:
        out.append(Circle(f"{id_}:hinge", c, hinge, kind, hinge=True))
    return out
