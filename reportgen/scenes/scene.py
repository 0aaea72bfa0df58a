"""A scene: one construction (a plan, a polygon, a diagram) as pure geometry in millimetres of paper
at ONE scale, with its labels (each tied to the entity it names), its scale factors and the lengths
a student measures on it. The note (:mod:`latex_templates.figures.scene`) and the sheets
(:mod:`drawings.scenes.render`) draw the same scene, so they cannot disagree; the numbers the note
prints about a construction (its scale, its measured lengths and the values read back) are read
from the scene.

Nothing here imports a plotting or a DXF library (tests/test_layering.py checks it).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping, Union

from ..errors import NameLookupError
from ..geometry import Vec2 as Point  # a point of a scene, paper mm

#: Line kinds a renderer maps to its own pens (sheet layers, matplotlib widths).
LINE_KINDS = ("contour", "thin", "phantom", "axis", "hidden", "vectors", "construction")


@dataclass(frozen=True)
class Segment:
    """A straight line from ``a`` to ``b`` (mm); ``trim`` mm cut off at each end (hinge circles)."""
    id: str
    a: Point
    b: Point
    kind: str = "contour"
    trim: tuple[float, float] = (0.0, 0.0)

    @property
    def length(self) -> float:
        return math.dist(self.a, self.b)


@dataclass(frozen=True)
class Polyline:
    """A polyline through ``points`` (mm), closed if ``closed``."""
    id: str
    points: tuple[Point, ...]
    kind: str = "thin"
    closed: bool = False


@dataclass(frozen=True)
class Arrow:
    """A vector from ``a`` to ``b`` (mm) with its head at ``b``; ``style`` the component's kind
    (absolute, relative, normal, …) for colours in the note."""
    id: str
    a: Point
    b: Point
    style: str = "absolute"
    kind: str = "vectors"

    @property
    def length(self) -> float:
        return math.dist(self.a, self.b)


@dataclass(frozen=True)
class Circle:
    """A circle of radius ``r`` mm; ``filled`` a dot; ``hinge`` a hinge symbol (its radius is paper
    mm whatever the scale)."""
    id: str
    c: Point
    r: float
    kind: str = "contour"
    filled: bool = False
    hinge: bool = False


Entity = Union[Segment, Polyline, Arrow, Circle]


@dataclass(frozen=True)
class Label:
    """A text naming ``anchor`` (an entity id, or a point key of the scene). ``at`` is the point
    (mm) it belongs to — a plan point, the middle of a vector; the renderer places the text beside
    it. ``text`` uses TeX-like indices (``a^{n}_{BA}``, ``s_2``); ``role`` says what it names:
    "point" (a letter at a point), "vector" (a name along a vector), "number" (a position number),
    "link" (a link number)."""
    text: str
    anchor: str
    at: Point
    role: str = "point"
    along: tuple[Point, Point] | None = None     # for role "vector": the vector's ends
    leader: bool = False                         # too short to carry its name: a leader to it


@dataclass(frozen=True)
class Scale:
    """A scale factor of the scene: ``symbol`` (μl, μv…), value (SI units per mm), unit text, and for
    a drawing of the mechanism the ГОСТ 2.302 ratio text («1:2,5»)."""
    symbol: str
    value: float
    unit: str
    ratio: str = ""


@dataclass(frozen=True)
class Scene:
    """One construction in paper mm at one scale (see the module's docstring).

    ``values`` holds the lengths measured on it (mm, as a student reads them) and the values read
    back from them, by name; ``points`` named points (plan points, mechanism points of the analysed
    position) in mm."""
    name: str
    scales: tuple[Scale, ...]
    entities: tuple[Entity, ...]
    labels: tuple[Label, ...] = ()
    points: Mapping[str, Point] = field(default_factory=lambda: MappingProxyType({}))
    values: Mapping[str, float] = field(default_factory=lambda: MappingProxyType({}))

    def scale(self, symbol: str | None = None) -> Scale:
        """The scale of the scene (the one named ``symbol`` if it has several)."""
        if symbol is None:
            return self.scales[0]
        for s in self.scales:
            if s.symbol == symbol:
                return s
        raise NameLookupError("scale", symbol, tuple(s.symbol for s in self.scales))

    def entity(self, id_: str) -> Entity:
        for e in self.entities:
            if e.id == id_:
                return e
        raise NameLookupError("entity", id_, tuple(e.id for e in self.entities))

    def bounds(self) -> tuple[float, float, float, float]:
        """xmin, ymin, xmax, ymax of the drawn geometry (mm), labels' points included."""
        xs: list[float] = []
        ys: list[float] = []
        for e in self.entities:
            if isinstance(e, (Segment, Arrow)):
                pts: tuple[Point, ...] = (e.a, e.b)
            elif isinstance(e, Polyline):
                pts = e.points
            else:
                pts = ((e.c[0] - e.r, e.c[1] - e.r), (e.c[0] + e.r, e.c[1] + e.r))
            xs += [p[0] for p in pts]
            ys += [p[1] for p in pts]
        for lb in self.labels:
            xs.append(lb.at[0])
            ys.append(lb.at[1])
        if not xs:
            return (0.0, 0.0, 0.0, 0.0)
        return (min(xs), min(ys), max(xs), max(ys))

    def segments(self) -> dict[str, float]:
        """Lengths (mm) of the straight entities (segments and arrows), by id — what a test compares
        with the sheet."""
        return {e.id: e.length for e in self.entities if isinstance(e, (Segment, Arrow))}


def frozen(d: Mapping) -> Mapping:
    return MappingProxyType(dict(d))
