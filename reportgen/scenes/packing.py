"""Placing rectangles (the views of a sheet) in a free field, pure geometry in sheet mm: the core
chooses the scale of the plan of positions from the arrangement of the sheet's views
(:mod:`reportgen.scenes.arrangement`), and the sheets (``drawings.layout`` re-exports these) pack
their other views with the same functions.

:func:`pack` puts rectangles one by one into a region (a shapely polygon: the frame minus the
title block), each as near to its preferred corner as it fits, without touching the others;
:func:`try_pack` does the same without raising; :func:`room`, :func:`spread` and :func:`grow` share
out the room left round them.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Iterable, Sequence

import numpy as np
from shapely.geometry import box
from shapely.geometry.base import BaseGeometry

from ..errors import BuildError, GeometryError, ParameterError
from ..tolerances import AREA_EPS_MM2, MM_EPS, MM_ROUNDOFF

CORNERS: tuple[str, ...] = ("top-left", "top-right", "bottom-left", "bottom-right", "center")


#: What a layout failure tells the user: no option sets a sheet's scales, so nothing for them to change.
LAYOUT_LIMIT = ("a limit of reportgen's sheet layout, not an error in the task (no option sets the "
                "sheets' scales); please report it with the task file, or build with --no-sheets")


@dataclass(frozen=True)
class Rect:
    """An axis-parallel rectangle in sheet millimetres."""
    x0: float
    y0: float
    x1: float
    y1: float

    def __post_init__(self) -> None:
        if not (self.x1 >= self.x0 and self.y1 >= self.y0):
            raise GeometryError(f"rectangle {self}", "degenerate (x1 < x0 or y1 < y0)")

    @classmethod
    def from_size(cls, x0: float, y0: float, width: float, height: float) -> "Rect":
        return cls(x0, y0, x0 + width, y0 + height)

    @property
    def width(self) -> float:
        return self.x1 - self.x0

    @property
    def height(self) -> float:
        return self.y1 - self.y0

    @property
    def center(self) -> tuple[float, float]:
        return ((self.x0 + self.x1) / 2.0, (self.y0 + self.y1) / 2.0)

    def polygon(self) -> BaseGeometry:
        return box(self.x0, self.y0, self.x1, self.y1)

    def expanded(self, d: float) -> "Rect":
        return Rect(self.x0 - d, self.y0 - d, self.x1 + d, self.y1 + d)

    def overlaps(self, other: "Rect") -> bool:
        """True if the interiors intersect (touching edges do not count)."""
        return (self.x0 < other.x1 and other.x0 < self.x1
                and self.y0 < other.y1 and other.y0 < self.y1)


@dataclass(frozen=True)
class Request:
    """A view to place: ``width`` × ``height`` mm, as near to ``preferred`` as it fits."""
    name: str
    width: float
    height: float
    preferred: str = "top-left"


def _corner_target(region: BaseGeometry, corner: str) -> tuple[float, float]:
    x0, y0, x1, y1 = _bounds(region)
    return {
        "top-left": (x0, y1), "top-right": (x1, y1),
        "bottom-left": (x0, y0), "bottom-right": (x1, y0),
        "center": ((x0 + x1) / 2.0, (y0 + y1) / 2.0),
    }[corner]


def _rect_corner(rect: Rect, corner: str) -> tuple[float, float]:
    """:func:`_corner_target` of a rectangle, without making it a polygon."""
    return {"top-left": (rect.x0, rect.y1), "top-right": (rect.x1, rect.y1),
            "bottom-left": (rect.x0, rect.y0), "bottom-right": (rect.x1, rect.y0)}[corner]


def _candidates(region: BaseGeometry, placed: Sequence[Rect], w: float, h: float,
                gap: float) -> Iterable[tuple[float, float]]:
    """Lower-left corners worth trying: flush with the region's bounds or next to placed views."""
    x0, y0, x1, y1 = region.bounds
    xs = {x0, x1 - w}
    ys = {y0, y1 - h}
    # inner corners of a non-rectangular region (e.g. the notch of the title block)
    for x, y in region.exterior.coords:
        xs.update((x, x - w))
        ys.update((y, y - h))
    for r in placed:
        xs.update((r.x1 + gap, r.x0 - gap - w, r.x0, r.x1 - w))
        ys.update((r.y1 + gap, r.y0 - gap - h, r.y0, r.y1 - h))
    return itertools.product(sorted(xs), sorted(ys))


def pack(region: BaseGeometry, requests: Sequence[Request], *, gap: float = 10.0,
         placed: Sequence[Rect] = ()) -> list[Rect]:
    """Place ``requests`` in order inside ``region`` (a polygon in sheet mm).

    Each rectangle goes to the free position nearest to its preferred corner, at least ``gap`` mm
    from every rectangle already placed (``placed`` plus the earlier requests). Raises
    :class:`BuildError` naming the view that does not fit.
    """
    done: list[Rect] = list(placed)
    out: list[Rect] = []
    grown = region.buffer(MM_EPS)          # once: buffering per candidate cost most of a control sheet's scale choice
    for req in requests:
        if req.preferred not in CORNERS:
            raise ParameterError("preferred", req.preferred, f"one of {CORNERS}")
        tx, ty = _corner_target(region, req.preferred)
        best: tuple[float, Rect] | None = None
        bx0, by0, bx1, by1 = grown.bounds
        for cx, cy in _candidates(region, done, req.width, req.height, gap):
            rect = Rect.from_size(cx, cy, req.width, req.height)
            # the cheap tests first (the outcome is the same: a rect must pass them all)
            if rect.x0 < bx0 or rect.y0 < by0 or rect.x1 > bx1 or rect.y1 > by1:
                continue                       # outside the bounds: not inside the region
            rx, ry = rect.center if req.preferred == "center" else _rect_corner(rect, req.preferred)
            d = (rx - tx) ** 2 + (ry - ty) ** 2
            if best is not None and d >= best[0] - MM_ROUNDOFF:
                continue
            if any(rect.overlaps(p.expanded(gap - MM_EPS)) for p in done):
                continue
            if not grown.contains(rect.polygon()):
                continue
            best = (d, rect)
        if best is None:
            free = region.area - sum(r.width * r.height for r in done)
            raise BuildError(
                "sheet layout",
                f"view '{req.name}' ({req.width:.0f}×{req.height:.0f} mm) does not fit in the free "
                f"field of the sheet (about {free:.0f} mm² left) at any scale tried; " + LAYOUT_LIMIT)
        done.append(best[1])
        out.append(best[1])
    return out


# ---------------------------------------------------------------------------------------------
# trial packing and spreading (additive helpers for sheets that try several arrangements)


def try_pack(region: BaseGeometry, requests: Sequence[Request], *, gap: float = 10.0,
             placed: Sequence[Rect] = ()) -> list[Rect] | None:
    """Like :func:`pack` but returns None when a view does not fit, and fast enough to try many
    arrangements: a rectangle is inside ``region`` when it is inside its bounds and clear of its
    :func:`walls` (exact for a rectilinear region such as the free field of a sheet, cautious
    otherwise). The candidates of a view are tested at once (numpy arrays, the same arithmetic as
    one by one): of those inside the bounds and clear of the others, the first in the candidates'
    order whose distance to the preferred corner no later one undercuts by ``MM_ROUNDOFF``."""
    bx0, by0, bx1, by1 = _bounds(region)
    notches = walls(region)
    corners_x, corners_y = _exterior(region)
    done: list[Rect] = list(placed)
    out: list[Rect] = []
    eps = MM_EPS
    fixed = np.array([(b.x0, b.y0, b.x1, b.y1) for b in (n.expanded(-eps) for n in notches)], float).reshape(-1, 4)
    for req in requests:
        if req.preferred not in CORNERS:
            raise ParameterError("preferred", req.preferred, f"one of {CORNERS}")
        tx, ty = _corner_target(region, req.preferred)
        fx = {"top-left": 0.0, "bottom-left": 0.0, "top-right": 1.0, "bottom-right": 1.0}.get(req.preferred, 0.5)
        fy = {"top-left": 1.0, "top-right": 1.0, "bottom-left": 0.0, "bottom-right": 0.0}.get(req.preferred, 0.5)
        w, h = req.width, req.height
        xs = {bx0, bx1 - w, *corners_x, *(x - w for x in corners_x)}
        ys = {by0, by1 - h, *corners_y, *(y - h for y in corners_y)}
        for r in done:
            xs.update((r.x1 + gap, r.x0 - gap - w, r.x0, r.x1 - w))
            ys.update((r.y1 + gap, r.y0 - gap - h, r.y0, r.y1 - h))
        # the candidates as _candidates orders them (x, then y), inside the bounds
        ax = np.array(sorted(xs), float)
        ay = np.array(sorted(ys), float)
        ax = ax[(ax >= bx0 - eps) & (ax + w <= bx1 + eps)]
        ay = ay[(ay >= by0 - eps) & (ay + h <= by1 + eps)]
        if not len(ax) or not len(ay):
            return None
        cx = np.repeat(ax, len(ay))
        cy = np.tile(ay, len(ax))
        d = (cx + fx * w - tx) ** 2 + (cy + fy * h - ty) ** 2
        blocked = np.array([(b.x0, b.y0, b.x1, b.y1) for b in (p.expanded(gap - eps) for p in done)],
                           float).reshape(-1, 4)
        blocked = np.vstack([blocked, fixed])
        x1, y1 = cx + w, cy + h
        hit = ((cx[:, None] < blocked[:, 2]) & (blocked[:, 0] < x1[:, None])
               & (cy[:, None] < blocked[:, 3]) & (blocked[:, 1] < y1[:, None])).any(axis=1)
        free = np.flatnonzero(~hit)
        if not len(free):
            return None
        dist = d[free]
        k = 0                                    # the record scan of the one-by-one loop
        while True:
            later = np.flatnonzero(dist[k + 1:] < dist[k] - MM_ROUNDOFF)
            if not len(later):
                break
            k += 1 + int(later[0])
        rect = Rect.from_size(float(cx[free[k]]), float(cy[free[k]]), w, h)
        done.append(rect)
        out.append(rect)
    return out


@lru_cache(maxsize=64)
def _bounds(region: BaseGeometry) -> tuple[float, float, float, float]:
    """``region.bounds``, once per region (a shapely call per request cost a tenth of sheet 1's
    scale choice)."""
    return tuple(region.bounds)


@lru_cache(maxsize=32)
def _exterior(region: BaseGeometry) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The x and y of the corners of ``region``'s exterior, once per region."""
    coords = list(region.exterior.coords)
    return tuple(x for x, _ in coords), tuple(y for _, y in coords)


def walls(region: BaseGeometry) -> list[Rect]:
    """The parts of ``region``'s bounding box outside it (the notches of the title block and
    graph 26), as rectangles (bounding boxes of the parts)."""
    return list(_walls(region))


@lru_cache(maxsize=32)
def _walls(region: BaseGeometry) -> tuple[Rect, ...]:
    """:func:`walls`, once per region (shapely geometries are immutable and hash by value): sheet 1
    tries some 500 arrangements in one free field."""
    rest = box(*region.bounds).difference(region)
    return tuple(Rect(*g.bounds) for g in getattr(rest, "geoms", [rest]) if not g.is_empty and g.area > AREA_EPS_MM2)


def clearance(region: BaseGeometry, rect: Rect, others: Sequence[Rect],
              notches: Sequence[Rect] | None = None) -> tuple[float, float, float, float]:
    """Free room (mm) left, below, right and above ``rect`` before ``others`` or the edge of
    ``region`` (the others as given: expand them by a gap first if one is wanted); ``notches``
    are :func:`walls` of the region if already known."""
    x0, y0, x1, y1 = region.bounds
    stops = [*others, *(walls(region) if notches is None else notches)]
    left, below, right, above = rect.x0 - x0, rect.y0 - y0, x1 - rect.x1, y1 - rect.y1
    for b in stops:
        if b.y0 < rect.y1 and rect.y0 < b.y1:            # in the same row
            if b.x1 <= rect.x0 + MM_EPS:
                left = min(left, rect.x0 - b.x1)
            elif b.x0 >= rect.x1 - MM_EPS:
                right = min(right, b.x0 - rect.x1)
        if b.x0 < rect.x1 and rect.x0 < b.x1:            # in the same column
            if b.y1 <= rect.y0 + MM_EPS:
                below = min(below, rect.y0 - b.y1)
            elif b.y0 >= rect.y1 - MM_EPS:
                above = min(above, b.y0 - rect.y1)
    return max(left, 0.0), max(below, 0.0), max(right, 0.0), max(above, 0.0)


def room(region: BaseGeometry, rects: Sequence[Rect], *, gap: float = 10.0,
         placed: Sequence[Rect] = ()) -> float:
    """The free room each of ``rects`` would have on either side once centred in it: the smallest
    over the rects and the two axes of half the room along the axis (mm)."""
    notches = walls(region)
    worst = math.inf
    for i, r in enumerate(rects):
        others = [o.expanded(gap) for o in [*placed, *rects[:i], *rects[i + 1:]]]
        left, below, right, above = clearance(region, r, others, notches)
        worst = min(worst, (left + right) / 2, (below + above) / 2)
    return worst


def spread(region: BaseGeometry, rects: Sequence[Rect], *, gap: float = 10.0,
           placed: Sequence[Rect] = (), rounds: int = 12,
           weights: Sequence[tuple[float, float]] | None = None) -> list[Rect]:
    """Move ``rects`` (sizes kept) so that the free room is shared out: each in turn goes to the
    middle of the room it can slide in along x, then along y, at least ``gap`` mm from the others
    and ``placed`` and inside ``region``; a few rounds. ``weights`` (per rect, x and y, 0…1) put
    a rect at that fraction of its room instead of the middle (0: left/bottom, 1: right/top)."""
    notches = walls(region)
    out = list(rects)
    ws = list(weights) if weights is not None else [(0.5, 0.5)] * len(out)
    for _ in range(rounds):
        moved = 0.0
        for i, r in enumerate(out):
            others = [o.expanded(gap) for o in [*placed, *out[:i], *out[i + 1:]]]
            left, _, right, _ = clearance(region, r, others, notches)
            dx = ws[i][0] * (left + right) - left
            r = Rect(r.x0 + dx, r.y0, r.x1 + dx, r.y1)
            _, below, _, above = clearance(region, r, others, notches)
            dy = ws[i][1] * (below + above) - below
            r = Rect(r.x0, r.y0 + dy, r.x1, r.y1 + dy)
            moved = max(moved, abs(dx), abs(dy))
            out[i] = r
        if moved < 0.05:
            break
    return out


def grow(region: BaseGeometry, rects: Sequence[Rect], index: int, *, gap: float = 10.0,
         placed: Sequence[Rect] = (), share: float = 0.5, max_grow: tuple[float, float] = (math.inf, math.inf)
         ) -> list[Rect]:
    """Enlarge ``rects[index]`` about its centre into ``share`` of the room it has on its
    narrower side along each axis (at most ``max_grow`` mm in width and height), keeping ``gap``
    mm from the others and ``placed`` and staying inside ``region``."""
    out = list(rects)
    r = out[index]
    others = [o.expanded(gap) for o in [*placed, *out[:index], *out[index + 1:]]]
    notches = walls(region)
    left, _, right, _ = clearance(region, r, others, notches)
    ex = min(min(left, right) * share, max_grow[0] / 2)
    r = Rect(r.x0 - ex, r.y0, r.x1 + ex, r.y1)
    _, below, _, above = clearance(region, r, others, notches)
    ey = min(min(below, above) * share, max_grow[1] / 2)
    out[index] = Rect(r.x0, r.y0 - ey, r.x1, r.y1 + ey)
    return out
