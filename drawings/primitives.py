"""Drawing primitives for scene modules: a :class:`Canvas` maps model coordinates to sheet mm.

Geometry (points, polylines, shapely shapes, vectors, dimensions) is given in *model units* of the
view (metres of a mechanism, millimetres of a plan, …) and mapped by the canvas's
:class:`Transform`; sizes of symbols and texts are always *sheet millimetres* (``…_mm``, ``height``),
so a hinge or a 5 mm letter look the same in every view. Every text registers its box with the
sheet's :class:`Annotations`, which the label placer uses to avoid overlaps and the layout check to
report them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Iterable, Sequence

import numpy as np
import shapely
from ezdxf.enums import TextEntityAlignment
from ezdxf.layouts import BaseLayout
from shapely import affinity
from shapely.geometry import LineString, Point, Polygon, box
from shapely.geometry.base import BaseGeometry

from reportgen.errors import ParameterError
from reportgen.numbers import plain, significant

from . import style

from reportgen.geometry import Vec2 as Vec
from reportgen.tolerances import ABS_ZERO, AREA_EPS_MM2, MM_EPS, MM_ROUNDOFF

#: Coordinates as the scenes pass them: a pair (or list) of floats, or a numpy array.
Coords = Sequence[float] | np.ndarray

# ---------------------------------------------------------------------------------------------
# numbers


def format_number(value: float, decimals: int = 2, *, strip: bool = True) -> str:
    """``value`` with the sheet language's decimal mark: ``format_number(0.0200) == "0,02"`` (ru/uk);
    ``-0`` becomes ``0``.

    ``strip`` drops trailing zeros (and a bare comma); ``decimals`` is the maximum kept. The
    rounding is the note's (:func:`reportgen.numbers.plain`).
    """
    if not math.isfinite(value):
        raise ParameterError("value", value, "a finite number to print")
    from .words import decimal_mark
    return plain(value, decimals, strip=strip, mark=decimal_mark())


def ratio_label(k: float) -> str:
    """A scale as written on a drawing from ``k`` sheet mm per real mm: 0.4 → "1:2,5", 2 → "2:1"."""
    if not (k > 0 and math.isfinite(k)):
        raise ParameterError("scale", k, "a positive number (sheet mm per real mm)")
    from .words import decimal_mark
    mark = decimal_mark()
    return f"{significant(k, 4, mark=mark)}:1" if k >= 1 else f"1:{significant(1.0 / k, 4, mark=mark)}"


def format_significant(value: float, digits: int = 3) -> str:
    """``value`` rounded to ``digits`` significant digits, the sheet language's decimal mark (``0,0123``)."""
    from .words import decimal_mark
    return significant(value, digits, mark=decimal_mark())


# ---------------------------------------------------------------------------------------------
# transform and annotation registry


@dataclass(frozen=True)
class Transform:
    """Model → sheet: ``sheet = at + scale · (model − origin)``; ``scale`` is sheet mm per model unit.

    A kinematic scheme in metres drawn with μl = 0,0025 м/мм has ``scale = 1/0.0025 = 400``.
    """
    scale: float = 1.0
    origin: Vec = (0.0, 0.0)
    at: Vec = (0.0, 0.0)

    def __post_init__(self) -> None:
        if not (self.scale > 0 and math.isfinite(self.scale)):
            raise ParameterError("scale", self.scale, "a positive finite number")

    def __call__(self, p: Coords) -> Vec:
        return (self.at[0] + self.scale * (float(p[0]) - self.origin[0]),
                self.at[1] + self.scale * (float(p[1]) - self.origin[1]))

    def points(self, pts: Iterable[Coords]) -> list[Vec]:
        return [self(p) for p in pts]

    def inverse(self, q: Coords) -> Vec:
        return (self.origin[0] + (float(q[0]) - self.at[0]) / self.scale,
                self.origin[1] + (float(q[1]) - self.at[1]) / self.scale)

    def geometry(self, geom: BaseGeometry) -> BaseGeometry:
        return affinity.affine_transform(
            geom, [self.scale, 0.0, 0.0, self.scale,
                   self.at[0] - self.scale * self.origin[0], self.at[1] - self.scale * self.origin[1]])


@dataclass(frozen=True)
class LabelRecord:
    """A label as drawn on a sheet: its text, the handles of its TEXT entities (a base and its
    indices), what it names (``anchor``: a point or a line, sheet mm) and the view (canvas) it
    belongs to. tests/labels reads the texts back from the DXF by these handles and checks that the
    label stays within :data:`reportgen.tolerances.LABEL_NEAR_MM` of what it names."""
    text: str
    handles: tuple[str, ...]
    anchor: BaseGeometry
    view: str


@dataclass
class Annotations:
    """Text boxes and drawn lines of one sheet (sheet mm), for placing labels and checking overlaps;
    ``labels`` what each label names (:class:`LabelRecord`)."""
    boxes: list[tuple[str, Polygon]] = field(default_factory=list)
    _obstacles: list[BaseGeometry] = field(default_factory=list)
    _tree: shapely.STRtree | None = None
    labels: list[LabelRecord] = field(default_factory=list)

    def add_box(self, name: str, poly: Polygon) -> None:
        self.boxes.append((name, poly))

    def add_label(self, record: LabelRecord) -> None:
        self.labels.append(record)

    def add_obstacle(self, geom: BaseGeometry) -> None:
        """A drawn line (or ring, or filled shape) labels keep off."""
        self._obstacles.append(geom)
        self._tree = None

    def hits_box(self, poly: Polygon) -> int:
        """How many registered text boxes ``poly`` overlaps (touching does not count)."""
        return sum(1 for _, b in self.boxes if poly.intersection(b).area > AREA_EPS_MM2)

    def crossings(self, poly: Polygon) -> int:
        """How many drawn lines ``poly`` crosses."""
        if not self._obstacles:
            return 0
        if self._tree is None:
            self._tree = shapely.STRtree(self._obstacles)
        return int(len(self._tree.query(poly, predicate="intersects")))


# ---------------------------------------------------------------------------------------------
# text placement helpers

_ALIGN = {
    (0, 0): TextEntityAlignment.BOTTOM_LEFT, (1, 0): TextEntityAlignment.BOTTOM_CENTER,
    (2, 0): TextEntityAlignment.BOTTOM_RIGHT, (0, 1): TextEntityAlignment.MIDDLE_LEFT,
    (1, 1): TextEntityAlignment.MIDDLE_CENTER, (2, 1): TextEntityAlignment.MIDDLE_RIGHT,
    (0, 2): TextEntityAlignment.TOP_LEFT, (1, 2): TextEntityAlignment.TOP_CENTER,
    (2, 2): TextEntityAlignment.TOP_RIGHT,
}
_ALIGN_NAMES = {
    "bottom-left": (0, 0), "bottom-center": (1, 0), "bottom-right": (2, 0),
    "middle-left": (0, 1), "center": (1, 1), "middle-right": (2, 1),
    "top-left": (0, 2), "top-center": (1, 2), "top-right": (2, 2),
}


#: Letters and signs that reach below the base line, by about DESCENT of the cap height.
DESCENDERS = frozenset("gjpqyрудфцщ(),;[]{}|")
DESCENT = 0.3


def descent(text: str, height: float) -> float:
    """How far (mm) ``text`` reaches below its base line: its descenders (р, у, (, …), or 0."""
    return DESCENT * height if any(ch in DESCENDERS for ch in text) else 0.0


def text_box(pos: Vec, text: str, height: float, align: str = "bottom-left",
             rotation: float = 0.0, pad: float = 0.5, descend: bool = False) -> Polygon:
    """The box (sheet mm) of a one-line text anchored at ``pos`` with ``align``, plus ``pad``;
    ``descend``: down to its descenders (a label's place is chosen with them)."""
    ax, ay = _ALIGN_NAMES[align]
    w = style.text_width(text, height)
    x0 = -w * ax / 2.0
    y0 = -height * ay / 2.0
    depth = descent(text, height) if descend else 0.0
    poly = box(x0 - pad, y0 - depth - pad, x0 + w + pad, y0 + height + pad)
    if rotation:
        poly = affinity.rotate(poly, rotation, origin=(0, 0))
    return affinity.translate(poly, pos[0], pos[1])


def _unit(angle_deg: float) -> Vec:
    a = math.radians(angle_deg)
    return (math.cos(a), math.sin(a))


# ---------------------------------------------------------------------------------------------
# the canvas


class Canvas:
    """Draws into an ezdxf layout through a model → sheet :class:`Transform`.

    ``name`` prefixes the names of text boxes in overlap reports.
    """

    def __init__(self, layout: BaseLayout, transform: Transform | None = None,
                 annotations: Annotations | None = None, name: str = "sheet") -> None:
        self.layout = layout
        self.transform = transform or Transform()
        self.annotations = annotations if annotations is not None else Annotations()
        self.name = name
        #: The handle of the last TEXT entity drawn (a label of several texts collects them).
        self.last_text_handle = ""

    # -- plain geometry ------------------------------------------------------------------------
    def _attrs(self, layer: str) -> dict:
        if layer not in style.LAYER_NAMES:
            raise ParameterError("layer", layer, f"one of {style.LAYER_NAMES}")
        return {"layer": layer}

    def _sheet_polyline(self, pts: Sequence[Vec], layer: str, closed: bool = False) -> None:
        if len(pts) < 2:
            return
        if len(pts) == 2 and not closed:
            self.layout.add_line(pts[0], pts[1], dxfattribs=self._attrs(layer))
        else:
            self.layout.add_lwpolyline(pts, close=closed, dxfattribs=self._attrs(layer))
        geom = LineString(list(pts) + ([pts[0]] if closed else []))
        if layer != "construction":
            self.annotations.add_obstacle(geom)

    def line(self, p: Coords, q: Coords, layer: str = "contour") -> None:
        """A segment between two model points."""
        self._sheet_polyline([self.transform(p), self.transform(q)], layer)

    def polyline(self, points: Iterable[Coords], layer: str = "contour",
                 closed: bool = False) -> None:
        """A polyline through model points."""
        self._sheet_polyline(self.transform.points(points), layer, closed)

    def segment(self, p: Coords, q: Coords, layer: str = "contour",
                trim_mm: tuple[float, float] = (0.0, 0.0)) -> None:
        """A segment shortened by ``trim_mm`` at its ends (to stop at hinge circles)."""
        a, b = self.transform(p), self.transform(q)
        d = math.dist(a, b)
        if d <= trim_mm[0] + trim_mm[1]:
            return
        ux, uy = (b[0] - a[0]) / d, (b[1] - a[1]) / d
        a2 = (a[0] + ux * trim_mm[0], a[1] + uy * trim_mm[0])
        b2 = (b[0] - ux * trim_mm[1], b[1] - uy * trim_mm[1])
        self._sheet_polyline([a2, b2], layer)

    def circle(self, center: Coords, radius: float, layer: str = "contour") -> None:
        """A circle of model ``radius``."""
        self.circle_mm(center, radius * self.transform.scale, layer)

    def circle_mm(self, center: Coords, radius_mm: float, layer: str = "contour") -> None:
        """A circle of ``radius_mm`` sheet millimetres at a model point."""
        c = self.transform(center)
        self.layout.add_circle(c, radius_mm, dxfattribs=self._attrs(layer))
        self.annotations.add_obstacle(Point(c).buffer(radius_mm).exterior)

    def arc(self, center: Coords, radius: float, start_deg: float, end_deg: float,
            layer: str = "contour") -> None:
        """A counter-clockwise arc of model ``radius`` from ``start_deg`` to ``end_deg``."""
        c = self.transform(center)
        r = radius * self.transform.scale
        self.layout.add_arc(c, r, start_deg, end_deg, dxfattribs=self._attrs(layer))
        sweep = (end_deg - start_deg) % 360.0 or 360.0
        n = max(int(sweep / 5.0), 2)
        pts = [(c[0] + r * math.cos(math.radians(start_deg + sweep * i / n)),
                c[1] + r * math.sin(math.radians(start_deg + sweep * i / n))) for i in range(n + 1)]
        self.annotations.add_obstacle(LineString(pts))

    def geometry(self, geom: BaseGeometry, layer: str = "contour") -> None:
        """Emit a shapely geometry (model units): lines as polylines, polygon rings closed."""
        if geom.is_empty:
            return
        kind = geom.geom_type
        if kind == "Point":
            self.circle_mm((geom.x, geom.y), 0.5, layer)
        elif kind in ("LineString", "LinearRing"):
            closed = kind == "LinearRing" or (geom.is_closed and len(geom.coords) > 3)
            coords = list(geom.coords)[:-1] if closed else list(geom.coords)
            self.polyline(coords, layer, closed=closed)
        elif kind == "Polygon":
            for ring in [geom.exterior, *geom.interiors]:
                self.polyline(list(ring.coords)[:-1], layer, closed=True)
        elif hasattr(geom, "geoms"):
            for part in geom.geoms:
                self.geometry(part, layer)
        else:  # pragma: no cover - shapely has no other kinds
            raise ParameterError("geometry", kind, "a shapely geometry")

    # -- text ----------------------------------------------------------------------------------
    def text_mm(self, pos: Vec, text: str, height: float = 3.5, align: str = "bottom-left",
                rotation: float = 0.0, layer: str = "text", register: bool = True,
                names: BaseGeometry | None = None) -> Polygon:
        """A one-line TEXT at a *sheet* point; returns its box. ``align`` e.g. "center";
        ``names``: what the text is the label of (sheet mm), recorded in :attr:`Annotations.labels`."""
        ent = self.layout.add_text(style.dxf_literal(text), height=height, rotation=rotation, dxfattribs={
            **self._attrs(layer), "style": style.TEXT_STYLE,
            "lineweight": style.text_lineweight(height)})
        ent.set_placement(pos, align=_ALIGN[_ALIGN_NAMES[align]])
        self.last_text_handle = str(ent.dxf.handle)
        if names is not None:
            self.annotations.add_label(LabelRecord(text, (self.last_text_handle,), names, self.name))
        poly = text_box(pos, text, height, align, rotation)
        if register:
            self.annotations.add_box(f"{self.name}: «{text}»", poly)
        return poly

    def text(self, pos: Coords, text: str, height: float = 3.5,
             align: str = "bottom-left", rotation: float = 0.0, layer: str = "text",
             names: Coords | None = None) -> Polygon:
        """A one-line TEXT at a model point (height in sheet mm); ``names``: the model point it is
        the label of."""
        named = None if names is None else Point(self.transform(names))
        return self.text_mm(self.transform(pos), text, height, align, rotation, layer, names=named)

    def label(self, point: Coords, text: str, height: float = 5.0, gap_mm: float = 1.5,
              prefer_deg: float = 45.0, layer: str = "text", names: BaseGeometry | None = None,
              others: Sequence[Coords] = ()) -> Polygon:
        """A point label (letter) next to a model point, placed where it overlaps nothing.

        Tries 16 directions starting from ``prefer_deg`` and two distances; takes the first box that
        overlaps no other text and crosses no drawn line, else the one with the fewest conflicts.
        ``names``: what the label names (sheet mm; default the point); ``others``: model points of
        the same kind (the other numbered points of a curve) — a box nearer to one of them than to
        its own point would name the wrong one and is taken last.
        """
        p = self.transform(point)
        rivals = [Point(self.transform(q)) for q in others]
        w = style.text_width(text, height)
        best: tuple[tuple[int, int, int], Vec] | None = None
        order = [prefer_deg + s * k * 22.5 for k in range(9) for s in ((1, -1) if k else (1,))]
        rank = 0
        for dist in (gap_mm, gap_mm + height):
            for ang in order[:16]:
                ux, uy = _unit(ang)
                # push the box centre out until its nearest edge is `dist` from the point
                t = min(((w / 2 + 0.5) / abs(ux)) if abs(ux) > ABS_ZERO else math.inf,
                        ((height / 2 + 0.5) / abs(uy)) if abs(uy) > ABS_ZERO else math.inf)
                c = (p[0] + ux * (t + dist), p[1] + uy * (t + dist))
                poly = text_box(c, text, height, "center", descend=True)
                own = poly.distance(Point(p))
                wrong = sum(1 for q in rivals if poly.distance(q) < own)
                score = (wrong + self.annotations.hits_box(poly), self.annotations.crossings(poly), rank)
                rank += 1
                if best is None or score < best[0]:
                    best = (score, c)
                if score[0] == 0 and score[1] == 0:
                    break
            if best is not None and best[0][:2] == (0, 0):
                break
        assert best is not None
        return self.text_mm(best[1], text, height, "center", layer=layer,
                            names=Point(p) if names is None else names)

    # -- vectors -------------------------------------------------------------------------------
    def arrowhead_mm(self, tip: Vec, direction: Vec, length: float = 5.0, width: float = 1.7,
                     layer: str = "vectors") -> None:
        """A filled arrowhead (SOLID) with its tip at a *sheet* point, pointing along ``direction``."""
        n = math.hypot(*direction)
        if n == 0:
            return
        ux, uy = direction[0] / n, direction[1] / n
        bx, by = tip[0] - ux * length, tip[1] - uy * length
        left = (bx - uy * width / 2, by + ux * width / 2)
        right = (bx + uy * width / 2, by - ux * width / 2)
        self.layout.add_solid([tip, left, right], dxfattribs=self._attrs(layer))
        self.annotations.add_obstacle(Polygon([tip, left, right]))

    def arrow(self, start: Coords, end: Coords, label: str | None = None,
              layer: str = "vectors", head_mm: float = 5.0, label_height: float = 5.0) -> None:
        """A vector start → end (model points) with a filled arrowhead and an optional tip label.

        ГОСТ-like proportions: head 5 mm long, 1/3 as wide. A vector shorter than its head is drawn
        with a head of its own length.
        """
        a, b = self.transform(start), self.transform(end)
        d = math.dist(a, b)
        if d < MM_ROUNDOFF:
            if label:
                self.label(end, label, label_height)
            return
        head = min(head_mm, d)
        ux, uy = (b[0] - a[0]) / d, (b[1] - a[1]) / d
        shaft_end = (b[0] - ux * head * 0.9, b[1] - uy * head * 0.9)
        if d - head * 0.9 > MM_EPS:
            self._sheet_polyline([a, shaft_end], layer)
        self.arrowhead_mm(b, (ux, uy), head, head / 3.0, layer)
        if label:
            self.label(end, label, label_height, prefer_deg=math.degrees(math.atan2(uy, ux)),
                       names=LineString([a, b]))

    # -- dimensions ----------------------------------------------------------------------------
    def dimension(self, p1: Coords, p2: Coords, offset_mm: float = 10.0,
                  unit_factor: float = 1.0, decimals: int = 1, text: str | None = None) -> float:
        """An aligned dimension between model points, its line ``offset_mm`` to the left of p1→p2.

        The value shown is the model distance × ``unit_factor`` (e.g. 1000 for a scheme in metres
        dimensioned in mm); ``dimlfac = unit_factor / scale`` makes CAD programs measure the same,
        and the text is written out with a decimal comma for readers that ignore overrides.
        Returns the value shown.
        """
        a, b = self.transform(p1), self.transform(p2)
        value = math.dist(p1, p2) * unit_factor
        shown = text if text is not None else format_number(value, decimals)
        dim = self.layout.add_aligned_dim(
            p1=a, p2=b, distance=offset_mm, text=shown, dimstyle=style.DIM_STYLE,
            override={"dimlfac": unit_factor / self.transform.scale},
            dxfattribs=self._attrs("dimensions"))
        dim.render()
        d = math.dist(a, b)
        if d > 0:
            nx, ny = -(b[1] - a[1]) / d, (b[0] - a[0]) / d
            mid = ((a[0] + b[0]) / 2 + nx * (offset_mm + 2.5), (a[1] + b[1]) / 2 + ny * (offset_mm + 2.5))
            angle = math.degrees(math.atan2(b[1] - a[1], b[0] - a[0]))
            if angle > 90.0 or angle <= -90.0:
                angle += 180.0
            self.annotations.add_box(f"{self.name}: dim «{shown}»",
                                     text_box(mid, shown, 3.5, "center", angle))
            for q in (a, b):
                self.annotations.add_obstacle(LineString([q, (q[0] + nx * offset_mm, q[1] + ny * offset_mm)]))
        return value

    # -- ГОСТ 2.770 kinematic symbols ----------------------------------------------------------
    def hatch_strokes_mm(self, p: Vec, q: Vec, side: float = -1.0, length: float = 3.0,
                         spacing: float = 2.5, layer: str = "thin") -> None:
        """Short 45° strokes along a *sheet* segment p→q, on its right (``side=-1``) or left (+1)."""
        d = math.dist(p, q)
        if d == 0:
            return
        ux, uy = (q[0] - p[0]) / d, (q[1] - p[1]) / d
        nx, ny = -uy * side, ux * side
        # stroke direction: 45° between the normal and the backward tangent
        sx, sy = (nx - ux) / math.sqrt(2), (ny - uy) / math.sqrt(2)
        n = max(int(d / spacing), 1)
        start = (d - (n - 1) * spacing) / 2 if n > 1 else d / 2
        for i in range(n):
            t = start + i * spacing + length / math.sqrt(2)
            x, y = p[0] + ux * t, p[1] + uy * t
            if t > d + MM_ROUNDOFF:
                break
            self._sheet_polyline([(x, y), (x + sx * length, y + sy * length)], layer)

    def hinge(self, point: Coords, radius_mm: float = 2.0, layer: str = "contour") -> None:
        """A revolute pair: a small circle."""
        self.circle_mm(point, radius_mm, layer)

    def fixed_pivot(self, point: Coords, direction_deg: float = -90.0,
                    radius_mm: float = 2.0, height_mm: float = 8.0, base_mm: float = 14.0,
                    layer: str = "contour") -> None:
        """A revolute pair on the frame: hinge circle, two legs to a hatched base.

        ``direction_deg`` points from the hinge to the base (−90 = base below).
        """
        c = self.transform(point)
        self.circle_mm(point, radius_mm, layer)
        ux, uy = _unit(direction_deg)
        tx, ty = -uy, ux
        base_c = (c[0] + ux * height_mm, c[1] + uy * height_mm)
        left = (base_c[0] + tx * base_mm / 2, base_c[1] + ty * base_mm / 2)
        right = (base_c[0] - tx * base_mm / 2, base_c[1] - ty * base_mm / 2)
        for foot in (left, right):
            d = math.dist(c, foot)
            fx, fy = (foot[0] - c[0]) / d, (foot[1] - c[1]) / d
            self._sheet_polyline([(c[0] + fx * radius_mm, c[1] + fy * radius_mm), foot], layer)
        ext = 3.0
        p = (left[0] + tx * ext, left[1] + ty * ext)
        q = (right[0] - tx * ext, right[1] - ty * ext)
        self._sheet_polyline([p, q], layer)
        # strokes on the far side of the base, away from the hinge: the side whose normal
        # (left normal of p→q times side) points along the hinge→base direction u
        dx, dy = q[0] - p[0], q[1] - p[1]
        side = 1.0 if (-dy * ux + dx * uy) > 0 else -1.0
        self.hatch_strokes_mm(p, q, side=side, layer="thin")

    def ground(self, p: Coords, q: Coords, side: float = -1.0,
               layer: str = "contour") -> None:
        """A frame line (guide) between model points, hatched on its right (−1) or left (+1)."""
        a, b = self.transform(p), self.transform(q)
        self._sheet_polyline([a, b], layer)
        self.hatch_strokes_mm(a, b, side=side)

    def slider(self, point: Coords, angle_deg: float = 0.0, length_mm: float = 14.0,
               height_mm: float = 7.0, guide_mm: float | None = 60.0, hinge_mm: float = 2.0,
               layer: str = "contour") -> None:
        """A slider (block) on a guide: rectangle along ``angle_deg`` centred on the point, a hinge
        in its middle, and (``guide_mm``) a hatched frame guide of that length under it."""
        c = self.transform(point)
        ux, uy = _unit(angle_deg)
        nx, ny = -uy, ux
        hl, hh = length_mm / 2, height_mm / 2
        corners = [(c[0] + sx * ux * hl + sy * nx * hh, c[1] + sx * uy * hl + sy * ny * hh)
                   for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        self._sheet_polyline(corners, layer, closed=True)
        if hinge_mm:
            self.circle_mm(point, hinge_mm, layer)
        if guide_mm:
            gl = guide_mm / 2
            g0 = (c[0] - ux * gl - nx * hh, c[1] - uy * gl - ny * hh)
            g1 = (c[0] + ux * gl - nx * hh, c[1] + uy * gl - ny * hh)
            self._sheet_polyline([g0, g1], layer)
            self.hatch_strokes_mm(g0, g1, side=-1.0)

    # -- scales and diagrams -------------------------------------------------------------------
    def scale_caption(self, pos: Coords, symbol: str, value: float, unit: str,
                      height: float = 5.0, digits: int = 4) -> Polygon:
        """«μv = 0,02 (м/с)/мм» at a model point; ``unit`` is the text after the number."""
        s = f"{symbol} = {format_significant(value, digits)} {unit}"
        return self.text(pos, s, height)

    def scale_bar(self, pos: Coords, length_mm: float, value: float, unit: str,
                  divisions: int = 5, height: float = 3.5) -> None:
        """A scale bar of ``length_mm`` standing for ``value`` ``unit``: ticks and end values."""
        x, y = self.transform(pos)
        self._sheet_polyline([(x, y), (x + length_mm, y)], "thin")
        for i in range(divisions + 1):
            xi = x + length_mm * i / divisions
            self._sheet_polyline([(xi, y), (xi, y + 2.0)], "thin")
        self.text_mm((x, y - 1.5), "0", height, "top-center")
        self.text_mm((x + length_mm, y - 1.5), f"{format_significant(value)} {unit}", height,
                     "top-center")

    def axes(self, origin: Coords, x_length_mm: float, y_up_mm: float,
             y_down_mm: float = 0.0, x_label: str = "", y_label: str = "",
             x_ticks: Sequence[tuple[float, str]] = (), y_ticks: Sequence[tuple[float, str]] = (),
             height: float = 3.5, tick_mm: float = 1.5) -> None:
        """Graph axes at a model point: x to the right, y up (and ``y_down_mm`` below the x axis),
        arrows at the positive ends, ticks at offsets in mm from the origin with their labels, and
        axis names at the arrows."""
        ox, oy = self.transform(origin)
        xe = (ox + x_length_mm, oy)
        ye = (ox, oy + y_up_mm)
        self._sheet_polyline([(ox, oy), (xe[0] - 3.0, oy)], "thin")
        self._sheet_polyline([(ox, oy - y_down_mm), (ox, ye[1] - 3.0)], "thin")
        self.arrowhead_mm(xe, (1.0, 0.0), 5.0, 1.7, "thin")
        self.arrowhead_mm(ye, (0.0, 1.0), 5.0, 1.7, "thin")
        for off, text in x_ticks:
            self._sheet_polyline([(ox + off, oy - tick_mm), (ox + off, oy + tick_mm)], "thin")
            if text:
                self.text_mm((ox + off, oy - tick_mm - 1.0), text, height, "top-center")
        for off, text in y_ticks:
            self._sheet_polyline([(ox - tick_mm, oy + off), (ox + tick_mm, oy + off)], "thin")
            if text:
                self.text_mm((ox - tick_mm - 1.0, oy + off), text, height, "middle-right")
        if x_label:
            self.text_mm((xe[0], oy + 2.0), x_label, height + 1.5, "bottom-right")
        if y_label:
            self.text_mm((ox + 2.5, ye[1]), y_label, height + 1.5, "top-left")

    def curve(self, xs: Coords, ys: Coords, layer: str = "contour") -> None:
        """A graph curve through model points (e.g. a diagram in its view's units)."""
        pts = np.column_stack([np.asarray(xs, float), np.asarray(ys, float)])
        self.polyline([tuple(p) for p in pts], layer)
