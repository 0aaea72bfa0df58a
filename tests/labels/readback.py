"""What a reader sees of the labels, read back from the outputs.

Sheets: every TEXT of the DXF's modelspace (and the MTEXT of each DIMENSION's block) as a box in
sheet mm, computed from the entity alone — insert or align point, alignment, height, width factor,
rotation and the text's advance in the sheet's measuring font (:data:`drawings.style.MEASURE_FONT`,
whose advance is LibreCAD's ГОСТ type B within a few per cent; without the placer's safety margin).
What each label names comes from the sheet (:attr:`drawings.primitives.Annotations.labels`: the
handles of its texts and its anchor), never guessed from the geometry.

Note figures: every text of a matplotlib figure with its window extent (the renderer's own metrics),
in mm of the figure; what it names from ``reportgen_names`` (:mod:`latex_templates.figures.labels`)
or, for an annotation, the point it annotates."""
from __future__ import annotations

import math
from dataclasses import dataclass

from shapely import affinity
from shapely.geometry import LineString, Point, Polygon, box
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union

from drawings import style
from drawings.primitives import descent

#: Boxes are shrunk by this much (mm) on each side before testing overlap: two texts set edge to
#: edge in a table or a label written tight against its neighbour only touch.
TOUCH_MM = 0.25


@dataclass(frozen=True)
class TextBox:
    handle: str
    text: str
    box: Polygon


def _width(text: str, height: float, factor: float) -> float:
    return style.text_width(text, height) / style.WIDTH_MARGIN * factor


def text_box(e) -> Polygon:
    """The box (sheet mm) of a DXF TEXT: its cap height over the base line, its advance wide."""
    h = float(e.dxf.height)
    text = e.plain_text()
    w = _width(text, h, float(e.dxf.get("width", 1.0)))
    halign, valign = int(e.dxf.get("halign", 0)), int(e.dxf.get("valign", 0))
    p = e.dxf.insert if (halign, valign) == (0, 0) or halign in (3, 5) else e.dxf.get("align_point", e.dxf.insert)
    x0 = {0: 0.0, 1: -w / 2, 2: -w, 4: -w / 2}.get(halign, 0.0)
    y0 = {0: 0.0, 1: 0.0, 2: -h / 2, 3: -h}.get(valign, 0.0)
    if halign == 4:                       # MIDDLE: centred both ways
        y0 = -h / 2
    depth = descent(text, h)
    y0 -= depth
    h += depth
    poly = box(x0, y0, x0 + w, y0 + h)
    rot = float(e.dxf.get("rotation", 0.0))
    if rot:
        poly = affinity.rotate(poly, rot, origin=(0, 0))
    return affinity.translate(poly, float(p[0]), float(p[1]))


def mtext_box(e) -> Polygon:
    """The box of a one-line MTEXT (a dimension's value): attachment point, char height, advance."""
    h = float(e.dxf.char_height)
    text = e.plain_text()
    w = _width(text, h, 1.0)
    ap = int(e.dxf.get("attachment_point", 1))
    col, row = (ap - 1) % 3, (ap - 1) // 3
    x0 = -w * col / 2
    y0 = -h * (2 - row) / 2
    poly = box(x0, y0, x0 + w, y0 + h)
    rot = math.degrees(math.atan2(*reversed(tuple(e.dxf.get("text_direction", (1, 0, 0)))[:2]))) \
        if e.dxf.hasattr("text_direction") else float(e.dxf.get("rotation", 0.0))
    if rot:
        poly = affinity.rotate(poly, rot, origin=(0, 0))
    p = e.dxf.insert
    return affinity.translate(poly, float(p[0]), float(p[1]))


def sheet_texts(doc) -> list[TextBox]:
    """Every text a reader sees on the sheet, with its box."""
    out = []
    msp = doc.modelspace()
    for e in msp.query("TEXT"):
        if e.plain_text().strip():
            out.append(TextBox(str(e.dxf.handle), e.plain_text(), text_box(e)))
    for d in msp.query("DIMENSION"):
        for v in d.virtual_entities():
            if v.dxftype() == "MTEXT" and v.plain_text().strip():
                out.append(TextBox(f"{d.dxf.handle}/dim", v.plain_text(), mtext_box(v)))
    return out


def sheet_names(doc) -> list[TextBox]:
    """:func:`sheet_texts` with every name lettered with indices joined into one (``r`` with its
    smaller ``b1`` → «rb1», its box the union): an index is a smaller TEXT set where its base's
    advance ends (drawings.lettering; ``draw_rich``), level with the base or raised or lowered."""
    msp = doc.modelspace()
    plain = [e for e in msp.query("TEXT") if e.plain_text().strip() and not e.dxf.get("rotation", 0.0)
             and int(e.dxf.get("halign", 0)) == 0 and int(e.dxf.get("valign", 0)) in (0, 1)]   # left, on the base line
    index_of: dict[str, list] = {}
    taken: set[str] = set()
    for base in plain:
        hb, xb, yb = float(base.dxf.height), base.dxf.insert.x, base.dxf.insert.y
        end = xb + style.text_width(base.plain_text(), hb)
        for e in plain:
            h = float(e.dxf.height)
            if h < 0.9 * hb and e.dxf.get("valign", 0) == base.dxf.get("valign", 0) \
                    and abs(e.dxf.insert.x - end) < 0.02 and abs(e.dxf.insert.y - yb) < 0.6 * hb:
                index_of.setdefault(str(base.dxf.handle), []).append(e)
                taken.add(str(e.dxf.handle))
    out = []
    for t in sheet_texts(doc):
        if t.handle in taken:
            continue
        parts = sorted(index_of.get(t.handle, []), key=lambda e: -e.dxf.insert.y)   # raised, then lowered
        if parts:
            joined = t.box.union(unary_union([text_box(e) for e in parts])).envelope
            t = TextBox(t.handle, t.text + "".join(e.plain_text() for e in parts), joined)
        out.append(t)
    return out


def overlap(a: Polygon, b: Polygon, touch: float = TOUCH_MM) -> bool:
    return a.buffer(-touch, join_style=2).intersects(b.buffer(-touch, join_style=2))


@dataclass(frozen=True)
class Found:
    """A defect a teacher would mark: ``what`` and where."""
    what: str
    first: str
    second: str = ""
    mm: float = 0.0

    def __str__(self) -> str:
        return f"{self.what}: «{self.first}»" + (f" / «{self.second}»" if self.second else "") + \
            (f" ({self.mm:.1f} mm)" if self.mm else "")


#: Views whose vectors' names are checked against the other named vectors (issue 12: force polygons
#: and their details, Zhukovsky's lever, the groups' and the crank's free-body views of sheet 2, the
#: velocity and acceleration plans of sheet 1 and of the control work's sheet).
VECTOR_VIEWS = ("polygon ", "lever", "group ", "crank", "plan_v", "plan_a")


def check_sheet(doc, records, near_mm: float, vector_views: tuple[str, ...] = VECTOR_VIEWS) -> list[Found]:
    """Labels on a sheet read back from its DXF ``doc``: no two texts overlap (the texts of one label
    — a base and its indices — count as one), each recorded label is within ``near_mm`` of what it
    names, no other point labelled in the same view is nearer to it than its own and, in the views
    named ``vector_views…``, no other named vector (not lying along its own) is nearer to a vector's
    name than its own vector."""
    texts = sheet_texts(doc)
    by_handle = {t.handle: t for t in texts}
    owner: dict[str, int] = {}
    for k, r in enumerate(records):
        for h in r.handles:
            owner[h] = k
    found: list[Found] = []
    import shapely
    polys = [t.box.buffer(-TOUCH_MM, join_style=2) for t in texts]
    tree = shapely.STRtree(polys)
    for i, t in enumerate(texts):
        for j in tree.query(polys[i], predicate="intersects"):
            j = int(j)
            if j <= i:
                continue
            u = texts[j]
            oi, oj = owner.get(t.handle, -1 - i), owner.get(u.handle, -1 - j)
            if oi == oj:
                continue
            found.append(Found("texts overlap", t.text, u.text))
    points = {}
    lines: dict = {}
    for k, r in enumerate(records):
        if isinstance(r.anchor, Point):
            points.setdefault(r.view, []).append((k, r.anchor))
        elif isinstance(r.anchor, LineString):
            lines.setdefault(r.view, []).append((k, r.anchor))
    for k, r in enumerate(records):
        boxes = [by_handle[h].box for h in r.handles if h in by_handle]
        if not boxes:
            found.append(Found("label not in the DXF", r.text))
            continue
        shape = shapely.union_all(boxes)
        d = shape.distance(r.anchor)
        if d > near_mm:
            found.append(Found(f"label far from what it names (view {r.view})", r.text, mm=d))
        if isinstance(r.anchor, Point):
            for j, q in points.get(r.view, ()):
                if j != k and not q.equals(r.anchor) and shape.distance(q) + 0.5 < d:
                    found.append(Found(f"label nearer to another labelled point (view {r.view})", r.text,
                                       records[j].text, d))
                    break
        elif isinstance(r.anchor, LineString) and str(r.view).startswith(vector_views):
            other = _nearer_vector(shape, r.anchor, d, [(records[j].text, q) for j, q in lines.get(r.view, ()) if j != k])
            if other is not None:
                found.append(Found(f"vector's name nearer to another named vector (view {r.view})", r.text, other, d))
    return found


def _nearer_vector(shape, own, d: float, others) -> str | None:
    """The name of a vector (``others``: (name, line)) nearer to the label ``shape`` than its own
    vector ``own`` at distance ``d`` — by more than half a millimetre, and not one lying along its
    own (two vectors drawn on one line share their names' room: the first name beside them is as
    near to both). A leader belongs to its label: a label on a leader (``own`` has more than two
    points, the leader's foot first) is measured along the leader."""
    for text, q in others:
        if q.equals(own):
            continue
        if shape.distance(q) + 0.5 < d and not _collinear(own, q):
            return text
    return None


def _collinear(a, b) -> bool:
    """Do the last segments of ``a`` and ``b`` (the vectors) lie on one line, overlapping?"""
    (ax, ay), (bx, by) = list(a.coords)[-2:]
    (cx, cy), (dx, dy) = list(b.coords)[-2:]
    ux, uy = bx - ax, by - ay
    n = math.hypot(ux, uy)
    if n == 0:
        return False
    off = max(abs((cx - ax) * uy - (cy - ay) * ux), abs((dx - ax) * uy - (dy - ay) * ux)) / n
    return off < 0.5 and a.distance(b) < 0.5


# -- note figures -------------------------------------------------------------------------------

@dataclass(frozen=True)
class FigureText:
    text: str
    box: Polygon            # mm of the figure
    names: BaseGeometry | None
    drawn: bool = True      # False: an annotation of a point outside its axes (matplotlib leaves it out)


def figure_texts(fig) -> list[FigureText]:
    """Every visible, non-empty text of ``fig`` (its axes' texts and annotations, the figure's own)
    with its window extent in mm and what it names (figure mm), if known."""
    renderer = fig.canvas.get_renderer()
    k = 25.4 / fig.dpi
    out = []
    artists = list(fig.texts)
    for ax in fig.axes:
        artists += [(t, ax) for t in ax.texts]
    for item in artists:
        t, ax = item if isinstance(item, tuple) else (item, None)
        if not t.get_visible() or not t.get_text().strip():
            continue
        if hasattr(t, "xy") and ax is not None and getattr(t, "xycoords", "data") == "data" \
                and t.get_annotation_clip() is not False \
                and not ax.bbox.expanded(1.001, 1.001).contains(*ax.transData.transform(t.xy)):
            out.append(FigureText(t.get_text(), box(0, 0, 0, 0), None, drawn=False))
            continue
        bb = t.get_window_extent(renderer)
        patch = t.get_bbox_patch()
        if patch is not None:                    # a circled number: the circle is part of it
            t.update_bbox_position_size(renderer)
            pb = patch.get_window_extent(renderer)
            bb = bb.union([bb, pb])
        poly = box(bb.x0 * k, bb.y0 * k, bb.x1 * k, bb.y1 * k)
        names = getattr(t, "reportgen_names", None)
        geom = None
        trans = (ax.transData if ax is not None else None)
        if names is not None and trans is not None:
            pts = [tuple(trans.transform(p) * k) for p in names]
            geom = Point(pts[0]) if len(pts) == 1 else LineString(pts)
        elif hasattr(t, "xy") and trans is not None and getattr(t, "xycoords", "data") == "data":
            geom = Point(tuple(trans.transform(t.xy) * k))
        out.append(FigureText(t.get_text(), poly, geom))
    return out


def check_figure(fig, near_mm: float, vectors: bool = False) -> list[Found]:
    """No two texts of a note figure overlap; each text that names something is within ``near_mm``
    of it (figure mm) and no other named point is nearer to it than its own; with ``vectors`` (the
    force polygons and the lever: issue 12), no other named vector (not lying along it) is nearer to
    a vector's name than its own vector. A name on a leader names the leader and its vector."""
    found: list[Found] = [Found("label not drawn (what it names is outside the axes)", t.text)
                          for t in figure_texts(fig) if not t.drawn]
    texts = [t for t in figure_texts(fig) if t.drawn]
    for i, a in enumerate(texts):
        for b in texts[i + 1:]:
            if overlap(a.box, b.box):
                found.append(Found("texts overlap", a.text, b.text))
    pts = [(i, t.names) for i, t in enumerate(texts) if isinstance(t.names, Point)]
    for i, t in enumerate(texts):
        if t.names is None:
            continue
        d = t.box.distance(t.names)
        if d > near_mm:
            found.append(Found("label far from what it names", t.text, mm=d))
        if isinstance(t.names, Point):
            for j, q in pts:
                if j != i and q.distance(t.names) > 0.5 and t.box.distance(q) + 0.5 < d:
                    found.append(Found("label nearer to another labelled point", t.text, texts[j].text, d))
                    break
        elif vectors and isinstance(t.names, LineString) and len(t.names.coords) == 2:
            other = _nearer_vector(t.box, t.names, d, [(u.text, u.names) for j, u in enumerate(texts) if j != i
                                                       and isinstance(u.names, LineString)
                                                       and len(u.names.coords) == 2])
            if other is not None:
                found.append(Found("vector's name nearer to another named vector", t.text, other, d))
    return found


# -- lines crossing labels (issue 12: «Fур», «FMи4(D)» crossed by other vectors on the lever) -----

#: A line counts as a label's own (its vector, the vector's arrowhead, its leader) when it lies
#: within this many mm of what the label names: an arrowhead is a third of its length wide.
OWN_LINE_MM = 1.5


def entity_geometry(e):
    """The drawn shape of one DXF entity (sheet mm): a line, polyline, circle or arc as a line, an
    arrowhead (SOLID) as its triangle, a TEXT as its letters' box (:func:`text_box`); None for
    anything else."""
    from shapely.geometry import Polygon as _Polygon
    kind = e.dxftype()
    if kind == "LINE":
        a, b = e.dxf.start, e.dxf.end
        if math.dist((a[0], a[1]), (b[0], b[1])) > 0.0:
            return LineString([(a[0], a[1]), (b[0], b[1])])
    elif kind == "LWPOLYLINE":
        pts = [(p[0], p[1]) for p in e.get_points("xy")]
        if e.closed and len(pts) > 2:
            pts.append(pts[0])
        if len(pts) >= 2:
            return LineString(pts)
    elif kind == "CIRCLE":
        c = e.dxf.center
        return Point(c[0], c[1]).buffer(float(e.dxf.radius), 32).exterior
    elif kind == "ARC":
        c, r = e.dxf.center, float(e.dxf.radius)
        a0, a1 = float(e.dxf.start_angle), float(e.dxf.end_angle)
        sweep = (a1 - a0) % 360.0 or 360.0
        n = max(int(sweep / 5.0), 2)
        return LineString([(c[0] + r * math.cos(math.radians(a0 + sweep * i / n)),
                            c[1] + r * math.sin(math.radians(a0 + sweep * i / n))) for i in range(n + 1)])
    elif kind == "SOLID":
        pts = [(float(e.dxf.get(f"vtx{i}")[0]), float(e.dxf.get(f"vtx{i}")[1])) for i in range(3)]
        poly = _Polygon(pts)
        if poly.area > 0.0:
            return poly
    elif kind == "TEXT" and e.plain_text().strip():
        return text_box(e)
    return None


def drawn_shapes(e, touch: float = 0.0) -> list:
    """Every shape one entity puts on the sheet (sheet mm): :func:`entity_geometry`'s, and for a
    DIMENSION (or a block INSERT, a dimension's tick) the lines, ticks and value (its MTEXT's box)
    of the block it shows; a text's box shrunk by ``touch`` on each side (texts set edge to edge
    only touch)."""
    kind = e.dxftype()
    if kind in ("DIMENSION", "INSERT"):
        return [g for v in e.virtual_entities() for g in drawn_shapes(v, touch)]
    if kind == "MTEXT":
        shapes = [mtext_box(e)] if e.plain_text().strip() else []
    else:
        g = entity_geometry(e)
        shapes = [] if g is None else [g]
    if kind in ("TEXT", "MTEXT") and touch:
        shapes = [s.buffer(-touch, join_style=2) for s in shapes]
    return [s for s in shapes if not s.is_empty]


def _dxf_lines(doc) -> list:
    """Every drawn line of the sheet's modelspace as a shapely geometry (sheet mm): lines,
    polylines, circles, arcs and the arrowheads (SOLID, filled)."""
    out = []
    for e in doc.modelspace():
        if e.dxftype() != "TEXT":
            g = entity_geometry(e)
            if g is not None:
                out.append(g)
    return out


def _own(line, anchor, own_mm: float = OWN_LINE_MM) -> bool:
    """Does ``line`` belong to what the label names (``anchor``: its vector, and its leader)?"""
    return anchor is not None and not isinstance(anchor, Point) and line.within(anchor.buffer(own_mm))


def crossed_labels(texts, lines, touch: float = TOUCH_MM, strict: bool = True) -> list[Found]:
    """Labels whose letters are crossed by a drawn line that is not their own: ``texts`` (name,
    letters' box, what it names), ``lines`` the drawn lines (sheet or figure mm)."""
    import shapely
    found: list[Found] = []
    if not lines:
        return found
    tree = shapely.STRtree(lines)
    for name, shape, anchor in texts:
        inner = shape.buffer(-touch, join_style=2)
        if inner.is_empty:
            continue
        hits = [lines[int(j)] for j in tree.query(inner, predicate="intersects")]
        if strict:
            foreign = hits
        else:
            foreign = [g for g in hits if not _own(g, anchor)]
        if foreign:
            found.append(Found("label crossed by a line", name, mm=len(foreign)))
    return found


def check_sheet_crossings(doc, records, views: tuple[str, ...] = VECTOR_VIEWS) -> list[Found]:
    """Every label recorded in the views named ``views…`` read back from the DXF ``doc``: no drawn
    line other than its own (its vector with its arrowhead, its leader) crosses its letters."""
    import shapely
    by_handle = {t.handle: t for t in sheet_texts(doc)}
    texts = []
    for r in records:
        if not str(r.view).startswith(views):
            continue
        boxes = [by_handle[h].box for h in r.handles if h in by_handle]
        if boxes:
            texts.append((f"{r.view}: {r.text}", shapely.union_all(boxes), r.anchor))
    return crossed_labels(texts, _dxf_lines(doc))


def _figure_lines(fig) -> list:
    """Every drawn line of a figure's axes (lines, patch outlines; filled patches as areas), in mm
    of the figure."""
    from shapely.geometry import Polygon as _Polygon
    k = 25.4 / fig.dpi
    out = []
    for ax in fig.axes:
        for ln in ax.lines:
            if not ln.get_visible():
                continue
            xy = ax.transData.transform(list(zip(ln.get_xdata(), ln.get_ydata()))) * k if len(ln.get_xdata()) else []
            if len(xy) >= 2:
                out.append(LineString([tuple(p) for p in xy]))
        for p in ax.patches:
            if not p.get_visible():
                continue
            path = p.get_path().transformed(p.get_transform())
            for poly in path.to_polygons(closed_only=False):
                pts = [tuple(q * k) for q in poly]
                if len(pts) < 2:
                    continue
                if p.get_fill() and len(pts) >= 3 and p.get_facecolor()[3] > 0 \
                        and tuple(p.get_facecolor()[:3]) != (1.0, 1.0, 1.0):
                    g = _Polygon(pts)
                    out.append(g if g.is_valid else g.buffer(0))
                else:
                    out.append(LineString(pts))
    return [g for g in out if not g.is_empty]


def check_figure_crossings(fig) -> list[Found]:
    """No drawn line of a note figure other than a label's own (its vector, its arrowhead, its
    leader) crosses the label's text (window extent)."""
    texts = [(t.text, t.box, t.names) for t in figure_texts(fig) if t.drawn and t.names is not None]
    return crossed_labels(texts, _figure_lines(fig))
