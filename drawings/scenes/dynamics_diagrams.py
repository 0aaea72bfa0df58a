"""Sheet 3, the flywheel calculation drawn as the course draws it, from
:class:`reportgen.dynamics.GraphicalReplica` (every length in mm is the replica's own):

* M_red(φ) at μM with the mid-interval ordinates (steps), the pole P at H and its rays;
* the work of resistance A_с by chords (each parallel to its ray) and the straight line of A_дв;
* ΔE(φ) at μE;
* the Wittenbauer diagram ΔE(J) with the tangents at ψmax, ψmin, the points K, L and KL dimensioned;
* J_red(φ) turned (φ downwards) under it, sharing its J axis.

Views are placed at explicit rectangles (:func:`layout`) so that ΔE(φ) and the Wittenbauer diagram
share their ΔE level and the Wittenbauer diagram and J_red(φ) share their J axis.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from drawings import style
from drawings.layout import LAYOUT_LIMIT, Rect
from drawings.primitives import Transform, format_number, format_significant
from drawings.sheet import Sheet, View
from reportgen.dynamics.graphical import KL_DECIMALS
from reportgen.errors import BuildError
from reportgen.tolerances import ABS_ZERO, MM_EPS
from reportgen.scenes import dynamics as ds
from reportgen.scenes.scene import Polyline, Scene, Segment
from .render import draw_entities
from ..words import tr

#: Room around a diagram: above (title, scale), below (position numbers), mm.
TOP_MM = 22.0
BOTTOM_MM = 12.0
#: Room right of the φ axis (its arrow and name) and left of the ordinate axis (its ticks), mm.
RIGHT_MM = 24.0
LEFT_MM = 14.0
GAP_MM = 8.0
#: The diagrams of the column are spread over its height, at most this far apart, mm.
MAX_GAP_MM = 30.0
#: The column of M, A, ΔE is at least this wide (its titles), mm.
MIN_WIDTH_MM = 250.0
#: The J_red(φ) view: room above the J axis (the axis name) and below the φ axis's end.
J_TOP_MM = 12.0
J_BOTTOM_MM = 16.0
#: Radius of the arcs marking ψmax, ψmin at K and L (at least ARC_MIN_MM), mm.
ARC_MM = 22.0
ARC_MIN_MM = 10.0


@dataclass(frozen=True)
class Span:
    """Ordinates of a diagram, mm: how far it goes above and below its φ axis (both ≥ 0), and the
    room under it (position numbers, the names of the break positions)."""
    up: float
    down: float
    bottom: float = BOTTOM_MM

    @staticmethod
    def of(*arrays, bottom: float = BOTTOM_MM) -> "Span":
        v = np.concatenate([np.atleast_1d(np.asarray(a, dtype=float)) for a in arrays])
        return Span(max(float(v.max()), 0.0) + 4.0, max(-float(v.min()), 0.0) + 4.0, bottom)

    @property
    def height(self) -> float:
        return TOP_MM + self.up + self.down + self.bottom


@dataclass(frozen=True)
class Layout:
    """The rectangles of the five views and the origins of their diagrams (sheet mm)."""
    moment: Rect
    work: Rect
    energy: Rect
    wittenbauer: Rect
    inertia: Rect
    o_moment: tuple[float, float]
    o_work: tuple[float, float]
    o_energy: tuple[float, float]
    o_wittenbauer: tuple[float, float]
    o_inertia: tuple[float, float]
    omega: Rect | None = None

    @property
    def right(self) -> float:
        return max(self.wittenbauer.x1, self.inertia.x1)


def spans(g, labels: list[str] | None = None) -> dict[str, Span]:
    chord_line = np.array([0.0, float(g.drive_mm[-1])])       # A_дв rises to −A_с(2π)
    tangents = np.array([g.K_mm, g.L_mm])
    names = [n for n in (labels or []) if not n.isdigit()]
    bottom_m = BOTTOM_MM + (max(len(n) for n in names) * 2.6 + 6.0 if names else 0.0)
    return {"M": Span.of(g.M_mm, g.mid_mm, bottom=bottom_m), "A": Span.of(g.a_mm, chord_line), "E": Span.of(g.e_mm),
            "W": Span.of(g.e_mm, tangents, _tangent_ends(g))}


def _construction(scene: Scene):
    """The scene's entities but its axes and break lines (the sheet draws its own, with arrows,
    ticks and the breaks' names)."""
    return [e for e in scene.entities if not e.id.startswith(("axis:", "break:"))]


def _tangent_ends(g) -> np.ndarray:
    """Ordinates of the two tangents at the right end of the J axis."""
    x = _j_length(g)
    return np.array([g.K_mm + x * math.tan(math.radians(g.psi_max_deg)),
                     g.L_mm + x * math.tan(math.radians(g.psi_min_deg))])


def _j_length(g) -> float:
    """Length of the drawn tangents and of the J axis up to its arrow, mm."""
    return ds.j_length(g)


def layout(g, labels: list[str], x0: float, y_top: float, y_bottom: float, omega_h: float = 0.0) -> Layout:
    """Column of M, A, ΔE and ω(φ) (``omega_h`` high) from (x0, y_top) down to y_bottom, the room left
    spread between them (at most MAX_GAP_MM apart); the Wittenbauer diagram right of ΔE at its level,
    J_red(φ) turned under it (if J_red(φ) would not fit there, both go to the top of their column)."""
    sp = spans(g, labels)
    phi_len = float(g.x[-1])
    left = g.H + LEFT_MM + 8.0
    width = max(left + phi_len + RIGHT_MM, MIN_WIDTH_MM)
    heights = [sp[key].height for key in ("M", "A", "E")] + ([omega_h] if omega_h > 0 else [])
    spare = (y_top - y_bottom) - sum(heights) - GAP_MM * (len(heights) - 1)
    gap = GAP_MM + min(max(spare, 0.0) / max(len(heights) - 1, 1), MAX_GAP_MM - GAP_MM)
    rects, origins = [], []
    top = y_top
    for key, h in zip(("M", "A", "E", "ω"), heights):
        r = Rect(x0, top - h, x0 + width, top)
        rects.append(r)
        if key != "ω":
            origins.append((x0 + left, top - TOP_MM - sp[key].up))
        top = r.y0 - gap
    sw = sp["W"]
    xw = x0 + width + GAP_MM
    ww = LEFT_MM + 8.0 + _j_length(g) + RIGHT_MM
    j_height = J_TOP_MM + phi_len + J_BOTTOM_MM
    # the Wittenbauer diagram at the level of ΔE(φ) (same ΔE axis); if J_red(φ) would not fit under
    # it, both go to the top of their column
    oy_w = origins[2][1]
    if oy_w - sw.down - BOTTOM_MM - GAP_MM - j_height < y_bottom:
        oy_w = y_top - TOP_MM - sw.up
    wit = Rect(xw, oy_w - sw.down - BOTTOM_MM, xw + ww, oy_w + sw.up + TOP_MM)
    o_w = (xw + LEFT_MM + 8.0, oy_w)
    inertia_top = wit.y0 - GAP_MM
    inertia = Rect(xw, inertia_top - j_height, xw + ww, inertia_top)
    o_j = (o_w[0], inertia_top - J_TOP_MM)
    if inertia.y0 < y_bottom or wit.y1 > y_top:
        raise BuildError("dynamics sheet layout", "the Wittenbauer and J_red(φ) diagrams do not fit one under the other "
                         f"(tangents at ψ = {g.psi_max_deg:.1f}°, {g.psi_min_deg:.1f}°); " + LAYOUT_LIMIT)
    omega = rects[3] if omega_h > 0 else None
    return Layout(rects[0], rects[1], rects[2], wit, inertia, origins[0], origins[1], origins[2], o_w, o_j, omega)


def _view(sheet: Sheet, name: str, rect: Rect, origin: tuple[float, float]) -> View:
    """A view whose model units are the diagram's mm, model (0, 0) at ``origin``."""
    return sheet.place_view(name, rect, Transform(1.0, (0.0, 0.0), origin))


def _title(view: View, text: str, scale: str) -> None:
    r = view.rect
    view.text_mm((r.x0 + 4.0, r.y1 - 6.5), text, 5.0, "bottom-left")
    view.text_mm((r.x0 + 4.0, r.y1 - 13.0), scale, 3.5, "bottom-left")


def _phi_axes(view: View, g, span: Span, y_label: str, labels: list[str], numbers: bool) -> None:
    ticks = [(float(x), "") for x in g.x]
    view.axes((0.0, 0.0), float(g.x[-1]) + RIGHT_MM - 6.0, span.up + 4.0, span.down, x_label="φ",
              y_label=y_label, x_ticks=ticks)
    if numbers:
        y = -span.down - 1.0
        for x, name in zip(g.x, labels):
            if name.isdigit():
                view.text((float(x), y), name, 3.5, "top-center")


def _break_lines(view: View, g, span: Span, labels: list[str]) -> None:
    """Thin verticals at the break positions, their names turned under the position numbers."""
    for x, name in zip(g.x, labels):
        if name.isdigit():
            continue
        view.line((float(x), -span.down), (float(x), span.up), "thin")
        view.text((float(x), -span.down - 7.0), name, 3.5, "middle-right", rotation=90.0)


def draw_moment(sheet: Sheet, lay: Layout, g, labels: list[str], scene: Scene) -> View:
    """M_red(φ) (``scene``, :func:`reportgen.scenes.dynamics.moment_scene`): the points, the curve
    through them, the steps of the mid ordinates carried to the M axis and joined to the pole."""
    sp = spans(g, labels)["M"]
    v = _view(sheet, "moment", lay.moment, lay.o_moment)
    _title(v, tr("sheets.dd01"), tr("sheets.dd02", v1=format_significant(scene.scale(ds.MU_M).value, 4),
                                    v2=format_significant(scene.scale(ds.MU_PHI).value, 4)))
    _phi_axes(v, g, sp, tr("sheets.dd03"), labels, numbers=True)
    _break_lines(v, g, sp, labels)
    draw_entities(v, _construction(scene))
    pole = scene.points["P"]
    v.text((pole[0], 2.0), "P", 5.0, "bottom-center")
    y_dim = -sp.down - 7.0
    v.dimension((pole[0], y_dim), (0.0, y_dim), offset_mm=0.0, text=f"H = {format_number(g.H, 0)}")
    v.line(pole, (pole[0], y_dim - 1.0), "thin")
    return v


def draw_work(sheet: Sheet, lay: Layout, g, labels: list[str], scene: Scene) -> View:
    """A_с by chords and the straight line of A_дв = −A_с(2π)·φ/2π (from the origin to the end of
    A_с mirrored: the note's convention ΔE = A_дв + A_с)."""
    sp = spans(g)["A"]
    v = _view(sheet, "work", lay.work, lay.o_work)
    _title(v, tr("sheets.dd04"), tr("sheets.dd05", v1=format_significant(scene.scale(ds.MU_A).value, 4)))
    _phi_axes(v, g, sp, "A", labels, numbers=False)
    draw_entities(v, _construction(scene))
    curve = scene.entity("curve")
    assert isinstance(curve, Polyline)
    pts = list(curve.points)
    drive = scene.entity("drive")
    assert isinstance(drive, Segment)
    end = drive.b
    i_mid = len(pts) // 2
    v.label(pts[i_mid], tr("sheets.dd06"), 5.0, prefer_deg=-60.0)
    v.label((end[0] * 0.5, end[1] * 0.5), tr("sheets.dd07"), 5.0, prefer_deg=120.0)
    return v


def draw_energy(sheet: Sheet, lay: Layout, g, labels: list[str], scene: Scene) -> View:
    """ΔE(φ) = A_дв + A_с at μE, by subtracting the line from the chords."""
    sp = spans(g)["E"]
    v = _view(sheet, "energy", lay.energy, lay.o_energy)
    k = (tr("sheets.dd08", v1=g.enlargement) if g.enlargement > 1
         else tr("sheets.dd16", v1=format_significant(1.0 / g.enlargement, 4), v2=1.0 / g.enlargement)
         if g.enlargement < 1 else "")
    _title(v, tr("sheets.dd09"), tr("sheets.dd10", v1=format_significant(scene.scale(ds.MU_E).value, 4), k=k))
    _phi_axes(v, g, sp, "ΔE", labels, numbers=True)
    draw_entities(v, _construction(scene))
    return v


def draw_wittenbauer(sheet: Sheet, lay: Layout, g, labels: list[str], scene: Scene) -> tuple[View, float]:
    """ΔE(J) through the positions, the tangents at ψmax, ψmin, K, L (``scene``,
    :func:`reportgen.scenes.dynamics.wittenbauer_scene`) and the dimension KL (its value is returned:
    the distance between K and L measured on the sheet, mm)."""
    sp = spans(g)["W"]
    v = _view(sheet, "wittenbauer", lay.wittenbauer, lay.o_wittenbauer)
    _title(v, tr("sheets.dd11"), tr("sheets.dd12", v1=format_significant(scene.scale(ds.MU_E).value, 4),
                                    v2=format_significant(scene.scale(ds.MU_J).value, 4)))
    x_len = scene.values["j_length"]
    v.axes((0.0, 0.0), x_len + RIGHT_MM - 6.0, sp.up + 4.0, sp.down, x_label="J", y_label="ΔE")
    # the segment KL is the dimension's (below); the points K, L are drawn with their letters
    draw_entities(v, [e for e in _construction(scene) if e.id != "KL"])
    curve = scene.entity("curve")
    assert isinstance(curve, Polyline)
    pts = list(curve.points)
    K_mm, L_mm = scene.values["K_mm"], scene.values["L_mm"]
    # the arcs of ψ stop short of the curve where it comes close to the ΔE axis (shaper)
    r_arc = min(ARC_MM, max(ARC_MIN_MM, 0.6 * float(np.min(g.j_mm))))
    for y0, psi, name in ((K_mm, scene.values["psi_max_deg"], "ψmax"), (L_mm, scene.values["psi_min_deg"], "ψmin")):
        v.line((0.0, y0), (r_arc + 4.0, y0), "thin")
        v.arc((0.0, y0), r_arc, 0.0, psi, "thin")
        mid = math.radians(psi / 2)
        v.label((r_arc * math.cos(mid), y0 + r_arc * math.sin(mid)), name, 3.5, gap_mm=1.0, prefer_deg=-20.0)
    nodes = pts[:-1]
    numbered = [(p, name) for p, name in zip(nodes, labels[:-1]) if name.isdigit()]
    number_labels(v, numbered, nodes)
    v.circle_mm((0.0, K_mm), 0.8, "contour")
    v.circle_mm((0.0, L_mm), 0.8, "contour")
    v.text((-2.0, K_mm + 1.0), "K", 5.0, "bottom-right")
    v.text((-2.0, L_mm - 1.0), "L", 5.0, "top-right")
    kl = v.dimension((0.0, L_mm), (0.0, K_mm), offset_mm=LEFT_MM + 2.0, decimals=KL_DECIMALS)
    return v, kl


#: The positions' numbers on the Wittenbauer curve: letter height, the distances tried beside the
#: node (sheet mm, from the node to the number's padded box) and the leaders' lengths where the
#: curve crowds its nodes (class3 with 24 positions: «23» on «0», «12» on «13»).
NUMBER_H = 3.5
NUMBER_GAPS = (1.0, 2.5)
NUMBER_LEADERS = (6.0, 9.0, 12.0, 16.0, 21.0)


def number_labels(v: View, numbered, nodes) -> None:
    """Each position's number beside its node (model points): the first of 16 directions — from
    the one away from the curve's middle — and NUMBER_GAPS where the number's box overlaps no text
    (the padded boxes keep 1 mm between letters), crosses no drawn line and is nearer to its own
    node than to any other; else on a thin leader from the node (NUMBER_LEADERS), its box clear of
    the texts and lines, the leader crossing no text and the fewest lines; else where
    :meth:`drawings.primitives.Canvas.label` puts it."""
    from shapely.geometry import LineString, Point

    from drawings.primitives import text_box
    sheet_nodes = [v.transform(q) for q in nodes]
    mid = (sum(q[0] for q in sheet_nodes) / len(sheet_nodes), sum(q[1] for q in sheet_nodes) / len(sheet_nodes))
    ann = v.annotations
    for p, name in numbered:
        P = v.transform(p)
        rivals = [Point(q) for q in sheet_nodes if math.dist(q, P) > MM_EPS]
        away = math.degrees(math.atan2(P[1] - mid[1], P[0] - mid[0])) if math.dist(P, mid) > MM_EPS else 45.0
        order = [away + sgn * i * 22.5 for i in range(9) for sgn in ((1, -1) if i else (1,))][:16]
        w = style.text_width(name, NUMBER_H)
        placed = False
        for gap in NUMBER_GAPS:
            for ang in order:
                ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
                t = min((w / 2 + 0.5) / abs(ux) if abs(ux) > ABS_ZERO else math.inf,
                        (NUMBER_H / 2 + 0.5) / abs(uy) if abs(uy) > ABS_ZERO else math.inf)
                c = (P[0] + ux * (t + gap), P[1] + uy * (t + gap))
                poly = text_box(c, name, NUMBER_H, "center", descend=True)
                own = poly.distance(Point(P))
                if ann.hits_box(poly) or ann.crossings(poly) or any(poly.distance(q) < own for q in rivals):
                    continue
                v.text_mm(c, name, NUMBER_H, "center", names=Point(P))
                placed = True
                break
            if placed:
                break
        if placed:
            continue
        best = None
        for rank, (L, ang) in enumerate((L, a) for L in NUMBER_LEADERS for a in order):
            ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
            end = (P[0] + ux * L, P[1] + uy * L)
            t = min((w / 2 + 0.5) / abs(ux) if abs(ux) > ABS_ZERO else math.inf,
                    (NUMBER_H / 2 + 0.5) / abs(uy) if abs(uy) > ABS_ZERO else math.inf)
            c = (end[0] + ux * (t + 0.5), end[1] + uy * (t + 0.5))
            poly = text_box(c, name, NUMBER_H, "center", descend=True)
            leader = LineString([(P[0] + ux * 1.2, P[1] + uy * 1.2), end])
            if ann.hits_box(poly) or ann.crossings(poly) or any(leader.intersects(b) for _, b in ann.boxes):
                continue
            score = (ann.crossings(leader), rank)
            if best is None or score < best[0]:
                best = (score, c, end)
            if score[0] == 0:
                break
        if best is None:
            v.label(p, name, NUMBER_H, gap_mm=1.0, others=[q for q in nodes if q != p])
            continue
        _, c, end = best
        v.line(p, (end[0] - P[0] + p[0], end[1] - P[1] + p[1]), "thin")
        v.text_mm(c, name, NUMBER_H, "center", names=LineString([P, end]))


def draw_inertia(sheet: Sheet, lay: Layout, g, labels: list[str], scene: Scene) -> View:
    """J_red(φ) turned: J to the right (the Wittenbauer diagram's J axis), φ downwards."""
    v = _view(sheet, "inertia", lay.inertia, lay.o_inertia)
    phi_len = float(g.x[-1])
    x_len = _j_length(g)
    # J axis to the right, φ axis downwards (arrows at the positive ends)
    v.line((0.0, 0.0), (x_len + 4.0, 0.0), "thin")
    v.arrowhead_mm(v.transform((x_len + 7.0, 0.0)), (1.0, 0.0), 5.0, 1.7, "thin")
    v.text((x_len + 7.0, 2.0), "J", 5.0, "bottom-right")
    v.line((0.0, 0.0), (0.0, -phi_len - 4.0), "thin")
    v.arrowhead_mm(v.transform((0.0, -phi_len - 7.0)), (0.0, -1.0), 5.0, 1.7, "thin")
    v.text((2.5, -phi_len - 7.0), "φ", 5.0, "bottom-left")
    for x, name in zip(g.x, labels):
        y = -float(x)
        v.line((-1.5, y), (1.5, y), "thin")
        if name.isdigit():
            v.text((-2.5, y), name, 3.5, "middle-right")
    draw_entities(v, [e for e in _construction(scene) if not e.id.startswith("tick:")])
    r = v.rect
    v.text_mm((r.x0 + 4.0, r.y0 + 2.0), tr("sheets.dd13", v1=format_significant(scene.scale(ds.MU_J).value, 4)),
              3.5, "bottom-left")
    return v


def omega_span(scene: Scene) -> Span:
    """The span of ω − ω_m on the sheet (band included), from the scene of ω(φ)."""
    curve = scene.entity("curve")
    assert isinstance(curve, Polyline)
    band = [scene.entity(k) for k in ("band:max", "band:min")]
    return Span.of([p[1] for p in curve.points], [b.a[1] for b in band if isinstance(b, Segment)])


def omega_height(scene: Scene) -> float:
    return omega_span(scene).height


def draw_omega(sheet: Sheet, rect: Rect, scene: Scene, g) -> View:
    """ω(φ) of the steady motion with the flywheel (``scene``,
    :func:`reportgen.scenes.dynamics.omega_scene`): the φ axis at ω_m, the band ω_m(1 ± δ/2)."""
    sp = omega_span(scene)
    mu = scene.scale(ds.MU_OMEGA).value
    w_m, w_max, w_min = (scene.values[k] for k in ("omega_m", "omega_max", "omega_min"))
    left = g.H + LEFT_MM + 8.0
    v = _view(sheet, "omega", rect, (rect.x0 + left, rect.y1 - TOP_MM - sp.up))
    _title(v, tr("sheets.dd14"), tr("sheets.dd15", v1=format_significant(mu, 4), v2=format_significant(w_m, 4)))
    ticks = [((w_max - w_m) / mu, format_significant(w_max, 4)), ((w_min - w_m) / mu, format_significant(w_min, 4))]
    view_len = float(g.x[-1])
    v.axes((0.0, 0.0), view_len + RIGHT_MM - 6.0, sp.up + 4.0, sp.down, x_label="φ", y_label="ω",
           x_ticks=[(float(x), "") for x in g.x], y_ticks=ticks)
    draw_entities(v, _construction(scene))
    v.text((view_len + 1.5, ticks[0][0]), "ωmax", 3.5, "middle-left")
    v.text((view_len + 1.5, ticks[1][0]), "ωmin", 3.5, "middle-left")
    return v
