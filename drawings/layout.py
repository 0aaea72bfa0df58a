"""Placing views in the free field of a sheet, and checking that nothing overlaps.

The packing is the core's (:mod:`reportgen.scenes.packing`, re-exported here): :func:`pack` puts
rectangles one by one into a region (a shapely polygon: the frame minus the title block), each as
near to its preferred corner as it fits, without touching the others.
:func:`find_overlaps` reports pairs of named shapes (view extents, text boxes) that overlap.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import shapely
from shapely.geometry.base import BaseGeometry

# the packing is pure geometry and lives in the core (the core arranges sheet 1's views to choose the
# scale of the plan of positions, issue 12); the sheets import it from here as before
from reportgen.scenes.packing import (CORNERS, LAYOUT_LIMIT, Rect, Request, clearance, grow, pack,  # noqa: F401
                                      room, spread, try_pack, walls)
from reportgen.tolerances import MM_EPS


@dataclass(frozen=True)
class Overlap:
    """Two named shapes that overlap by ``area`` mm²."""
    first: str
    second: str
    area: float

    def __str__(self) -> str:
        return f"{self.first} overlaps {self.second} ({self.area:.1f} mm²)"


def find_overlaps(items: Sequence[tuple[str, BaseGeometry]], *,
                  tolerance: float = MM_EPS) -> list[Overlap]:
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


