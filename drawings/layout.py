"""Placing views in the free field of a sheet, and checking that nothing overlaps.

:func:`pack` puts rectangles one by one into a region (a shapely polygon: the frame minus the
title block), each as near to its preferred corner as it fits, without touching the others.
:func:`find_overlaps` reports pairs of named shapes (view extents, text boxes) that overlap.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Iterable, Literal, Sequence

import shapely
from shapely.geometry import box
from shapely.geometry.base import BaseGeometry

from reportgen.errors import BuildError

Corner = Literal["top-left", "top-right", "bottom-left", "bottom-right", "center"]
CORNERS: tuple[str, ...] = ("top-left", "top-right", "bottom-left", "bottom-right", "center")


@dataclass(frozen=True)
class Rect:
    """An axis-parallel rectangle in sheet millimetres."""
    x0: float
    y0: float
    x1: float
    y1: float

    def __post_init__(self) -> None:
        if not (self.x1 >= self.x0 and self.y1 >= self.y0):
            raise ValueError(f"degenerate rectangle {self}")

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
    x0, y0, x1, y1 = region.bounds
    return {
        "top-left": (x0, y1), "top-right": (x1, y1),
        "bottom-left": (x0, y0), "bottom-right": (x1, y0),
        "center": ((x0 + x1) / 2.0, (y0 + y1) / 2.0),
    }[corner]


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
    for req in requests:
        if req.preferred not in CORNERS:
            raise ValueError(f"preferred must be one of {CORNERS}, not {req.preferred!r}")
        tx, ty = _corner_target(region, req.preferred)
        best: tuple[float, Rect] | None = None
        for cx, cy in _candidates(region, done, req.width, req.height, gap):
            rect = Rect.from_size(cx, cy, req.width, req.height)
            if not region.buffer(1e-6).contains(rect.polygon()):
                continue
            if any(rect.overlaps(p.expanded(gap - 1e-6)) for p in done):
                continue
            rx, ry = rect.center if req.preferred == "center" else _corner_target(
                rect.polygon(), req.preferred)
            d = (rx - tx) ** 2 + (ry - ty) ** 2
            if best is None or d < best[0] - 1e-9:
                best = (d, rect)
        if best is None:
            free = region.area - sum(r.width * r.height for r in done)
            raise BuildError(
                "sheet layout",
                f"view '{req.name}' ({req.width:.0f}×{req.height:.0f} mm) does not fit in the free "
                f"field of the sheet (about {free:.0f} mm² left); reduce its scale or move views "
                f"to another sheet")
        done.append(best[1])
        out.append(best[1])
    return out


@dataclass(frozen=True)
class Overlap:
    """Two named shapes that overlap by ``area`` mm²."""
    first: str
    second: str
    area: float

    def __str__(self) -> str:
        return f"{self.first} overlaps {self.second} ({self.area:.1f} mm²)"


def find_overlaps(items: Sequence[tuple[str, BaseGeometry]], *,
                  tolerance: float = 1e-6) -> list[Overlap]:
    """All pairs of ``(name, geometry)`` whose interiors overlap by more than ``tolerance`` mm²."""
    if len(items) < 2:
        return []
    geoms = [g for _, g in items]
    tree = shapely.STRtree(geoms)
    left, right = tree.query(geoms, predicate="intersects")
    found: list[Overlap] = []
    for i, j in sorted(zip(left.tolist(), right.tolist())):
        if i >= j:
            continue
        area = geoms[i].intersection(geoms[j]).area
        if area > tolerance:
            found.append(Overlap(items[i][0], items[j][0], area))
    return found
