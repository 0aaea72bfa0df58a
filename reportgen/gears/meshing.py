"""The meshing picture (картина зацепления) as pure geometry, in mm, in the gear-pair frame:
O1 = (0, 0), O2 = (0, aw), the pole P = (0, rw1) on the line of centres. Gear 1 turns clockwise and
drives; the line of action runs from N1 (left, tangent point on the base circle of gear 1) up to
N2; the tip circle of gear 2 cuts it at a (start of contact), the tip circle of gear 1 at b (end).

Construction (seed 000, 4.1.2; Артоболевский, ch. «Построение картины зацепления»): one pair of
teeth touches at P, the neighbours follow at one angular pitch; each tooth is the rack-generated
tooth of :mod:`reportgen.gears.profile` (true fillet and undercut). Along ab the number of tooth
pairs in contact changes where a point is one base pitch pb from a or from b, which gives the
zones of single and double contact.

The drawing scale is a separate matter: :func:`suggest_scale` picks a ГОСТ 2.302 scale for a
window of the sheet; the geometry here is always at 1:1.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np
from shapely.geometry import LineString

from ..numbers import plain
from .profile import DEFAULT_POSITIONS, half_thickness_angle, pair_teeth
from .. import gost_scales
from ..geometry import readonly as _ro, vec2
from ..errors import GeometryError, ParameterError

from ..geometry import Vec2 as Point
from ..tolerances import TOOTH_SIMPLIFY_REL

#: ГОСТ 2.302-68 scales (enlargement > 1, reduction < 1).
GOST_SCALES = tuple(gost_scales.factor(s) for s in gost_scales.scales(largest=10.0, smallest=1 / 10))


@dataclass(frozen=True)
class Circle:
    name: str          # e.g. "ra1"
    gear: int
    kind: str          # pitch | base | tip | root | working
    centre: Point
    radius: float


@dataclass(frozen=True)
class Label:
    text: str
    point: Point


@dataclass(frozen=True)
class Zone:
    """A stretch of ab with ``pairs`` tooth pairs in contact (0 means a gap: εα < 1)."""
    start: Point
    end: Point
    pairs: int


@dataclass(frozen=True)
class Dimension:
    """A linear dimension from ``start`` to ``end`` with its value in mm and its text."""
    name: str
    start: Point
    end: Point
    value: float
    text: str


@dataclass(frozen=True)
class MeshingPicture:
    circles: tuple[Circle, ...]
    teeth1: tuple[np.ndarray, ...]       # polylines (n, 2), read-only
    teeth2: tuple[np.ndarray, ...]
    points: Mapping[str, Point]          # O1, O2, P, N1, N2, a, b
    segments: Mapping[str, tuple[Point, Point]]   # N1N2, ab, O1O2, tangent (common tangent at P)
    zones: tuple[Zone, ...]
    labels: tuple[Label, ...]
    dimensions: tuple[Dimension, ...]
    ab_drawn: float                      # |ab| measured between the constructed points a and b
    eps_alpha_drawn: float               # ab_drawn / pb
    view: tuple[float, float, float, float]   # xmin, ymin, xmax, ymax that holds the drawn teeth


def _placed(pts: np.ndarray, ang: float, shift: Point = (0.0, 0.0)) -> np.ndarray:
    """A polyline (n, 2) turned by ``ang`` about the origin, then moved by ``shift``."""
    c, s = math.cos(ang), math.sin(ang)
    return _ro(np.asarray(pts) @ np.array([[c, s], [-s, c]]) + np.asarray(shift))


def _line_circle(p0: np.ndarray, u: np.ndarray, centre: np.ndarray, radius: float) -> tuple[float, float]:
    """Parameters t of the points p0 + t u (|u| = 1) on the circle."""
    w = p0 - centre
    b = w @ u
    disc = b * b - (w @ w - radius * radius)
    if disc < 0:
        raise GeometryError("the line", f"misses the circle r = {radius}")
    root = math.sqrt(disc)
    return -b - root, -b + root


def contact_zones(ab: float, pb: float) -> list[tuple[float, float, int]]:
    """(start, end, pairs) along ab measured from a: pairs = number of integers k with
    0 ≤ s + k pb ≤ ab, constant between the breakpoints k pb and ab − k pb."""
    cut_set = {0.0, ab}
    k = 1
    while k * pb < ab:
        cut_set.update((k * pb, ab - k * pb))
        k += 1
    cuts = sorted(cut_set)
    zones: list[tuple[float, float, int]] = []
    for s0, s1 in zip(cuts[:-1], cuts[1:]):
        mid = (s0 + s1) / 2
        n = math.floor((ab - mid) / pb) + math.floor(mid / pb) + 1
        if zones and zones[-1][2] == n:
            zones[-1] = (zones[-1][0], s1, n)
        else:
            zones.append((s0, s1, n))
    if ab < pb:  # εα < 1: the gap where no pair is in contact, between b and the next a
        zones.append((ab, pb, 0))
    return zones


def suggest_scale(extent_mm: float, window_mm: float) -> float:
    """The largest ГОСТ 2.302 scale at which ``extent_mm`` fits ``window_mm``."""
    for k in GOST_SCALES:
        if extent_mm * k <= window_mm:
            return k
    return GOST_SCALES[-1]


def meshing_picture(pair, n_teeth: int = 3, positions: int = DEFAULT_POSITIONS,
                    simplify: float | None = None) -> MeshingPicture:
    """The picture of a solved pair (:class:`reportgen.gears.pair.GearPair`) with ``n_teeth``
    (≥ 3, odd numbers centre the pair at P) teeth of each gear. ``simplify``: a tolerance in mm
    for the tooth polylines (default 2e-4·m)."""
    if n_teeth < 1:
        raise ParameterError("n_teeth", n_teeth, "≥ 1")
    g = pair.geometry
    tooth1, tooth2 = pair_teeth(pair, positions)
    tol = simplify if simplify is not None else TOOTH_SIMPLIFY_REL * g.m
    rw1, rw2 = g.dw1 / 2, g.dw2 / 2
    o1, o2 = np.array([0.0, 0.0]), np.array([0.0, g.aw])
    psi_w1 = float(half_thickness_angle(rw1, g.db1 / 2, g.s1, g.d1, g.alpha))
    psi_w2 = float(half_thickness_angle(rw2, g.db2 / 2, g.s2, g.d2, g.alpha))
    ks = [k - (n_teeth - 1) // 2 for k in range(n_teeth)]

    def teeth(tooth, base_angle, step, centre):
        line = np.asarray(LineString(tooth.outline).simplify(tol).coords) if tol > 0 else tooth.outline
        return tuple(_placed(line, base_angle + k * step, centre) for k in ks)

    # gear 1 turns clockwise (teeth to the left of P follow); gear 2 counter-clockwise
    teeth1 = teeth(tooth1, psi_w1, 2 * math.pi / g.z1, (0.0, 0.0))
    teeth2 = teeth(tooth2, math.pi + psi_w2, 2 * math.pi / g.z2, (0.0, g.aw))
    sw, cw = math.sin(g.alpha_w), math.cos(g.alpha_w)
    rb1, rb2 = g.db1 / 2, g.db2 / 2
    p = np.array([0.0, rw1])
    n1 = np.array([-rb1 * sw, rb1 * cw])
    n2 = o2 + np.array([rb2 * sw, -rb2 * cw])
    u = (n2 - n1) / np.linalg.norm(n2 - n1)
    # a: tip circle of gear 2 on N1N2 (the crossing nearer N1); b: tip circle of gear 1 (nearer N2)
    ta = _line_circle(n1, u, o2, g.da2 / 2)[0]
    tb = _line_circle(n1, u, o1, g.da1 / 2)[1]
    a, b = n1 + ta * u, n1 + tb * u
    ab = float(np.linalg.norm(b - a)) * (1.0 if tb >= ta else -1.0)
    pts = {"O1": o1, "O2": o2, "P": p, "N1": n1, "N2": n2, "a": a, "b": b}
    points = MappingProxyType({k: (float(v[0]), float(v[1])) for k, v in pts.items()})
    t = np.array([cw, sw])  # along N1N2 (unit), for zones
    zones = tuple(Zone(vec2(a + s0 * u), vec2(a + s1 * u), n)
                  for s0, s1, n in contact_zones(max(ab, 0.0), g.pb))
    del t
    half_tan = 1.2 * max(g.g, 2 * g.pb)
    segments = MappingProxyType({
        "N1N2": (points["N1"], points["N2"]),
        "ab": (points["a"], points["b"]),
        "O1O2": (points["O1"], points["O2"]),
        "tangent": ((-half_tan, float(p[1])), (half_tan, float(p[1]))),
    })
    circles = []
    for gear, centre, d, db, dw, da, df in ((1, (0.0, 0.0), g.d1, g.db1, g.dw1, g.da1, g.df1),
                                            (2, (0.0, float(g.aw)), g.d2, g.db2, g.dw2, g.da2, g.df2)):
        for kind, name, dia in (("pitch", "r", d), ("base", "rb", db), ("working", "rw", dw),
                                ("tip", "ra", da), ("root", "rf", df)):
            circles.append(Circle(f"{name}{gear}", gear, kind, centre, float(dia / 2)))
    labels = tuple(Label(k, points[k]) for k in ("O1", "O2", "P", "N1", "N2", "a", "b"))
    dims = (
        Dimension("aw", points["O1"], points["O2"], float(g.aw), f"aw = {plain(g.aw, 3)}"),
        Dimension("ab", points["a"], points["b"], ab, f"ab = {plain(ab, 3)}"),
        Dimension("pb", vec2(p), vec2(p + g.pb * u), float(g.pb),
                  f"pb = {plain(g.pb, 3)}"),
        Dimension("N1N2", points["N1"], points["N2"], float(g.g), f"N1N2 = {plain(g.g, 3)}"),
    )
    allpts = np.vstack(teeth1 + teeth2 + tuple(np.array([v]) for v in pts.values() if v is not o2 and v is not o1))
    margin = g.m
    view = (float(allpts[:, 0].min() - margin), float(allpts[:, 1].min() - margin),
            float(allpts[:, 0].max() + margin), float(allpts[:, 1].max() + margin))
    return MeshingPicture(circles=tuple(circles), teeth1=teeth1, teeth2=teeth2, points=points,
                          segments=segments, zones=zones, labels=labels, dimensions=dims,
                          ab_drawn=ab, eps_alpha_drawn=ab / g.pb, view=view)
