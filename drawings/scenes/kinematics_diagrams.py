"""Sheet 1, the kinematic diagrams of the output: s(φ), v(φ), a(φ) one above the other, the φ axis
divided into the n intervals of :func:`reportgen.diagrams.build_diagrams`, the chords of s, the
steps of each replica and the curve through them, the rays from the poles P1, P2 at H1, H2, the
exact curves thin, and the scales."""
from __future__ import annotations

from dataclasses import dataclass


from drawings import style
from drawings.primitives import format_number, format_significant
from drawings.sheet import Sheet, View
from drawings.scenes import kinematics_labels as rl
from reportgen.diagrams import Diagrams
from reportgen.scenes import output_diagrams as od
from reportgen.scenes.scene import Scene
from reportgen.tolerances import MM_ROUNDOFF
from .render import draw_entities
from ..words import tr, unit

#: Room right of the φ axis (its arrow and name), mm.
RIGHT_MM = od.RIGHT_MM


@dataclass(frozen=True)
class Names:
    s: str
    v: str
    a: str
    mu_s: str
    mu_v: str
    mu_a: str
    symbols: tuple[str, str, str]       # the scales' symbols
    titles: tuple[str, str, str]        # the diagrams' titles


def names(d: Diagrams) -> Names:
    """Axis names, units of the scales, their symbols and the titles: a slider's s, V, a or a
    rocker's ψ, ω, ε."""
    if d.unit == "м":
        return Names(tr("sheets.kd04"), tr("sheets.kd05"), tr("sheets.kd06"), unit("м/мм"), unit("(м/с)/мм"), unit("(м/с²)/мм"), ("μs", "μv", "μa"),
                     (tr("sheets.kd10"), tr("sheets.kd11"), tr("sheets.kd12")))
    return Names(tr("sheets.kd01"), tr("sheets.kd02"), tr("sheets.kd03"), unit("рад/мм"), unit("(рад/с)/мм"), unit("(рад/с²)/мм"), ("μψ", "μω", "με"),
                 (tr("sheets.kd07"), tr("sheets.kd08"), tr("sheets.kd09")))


def size(d: Diagrams) -> tuple[float, float]:
    return od.size(d)


def add_diagrams_view(sheet: Sheet, d: Diagrams, scene: Scene, positions: int, start_deg: float, working_deg: float,
                      preferred: str) -> View:
    w, h = size(d)
    view = sheet.add_view("diagrams", w, h, preferred=preferred)
    draw_diagrams(view, d, scene, positions, start_deg, working_deg)
    return view


def draw_diagrams(view: View, d: Diagrams, scene: Scene, positions: int, start_deg: float, working_deg: float) -> None:
    """The three diagrams of ``scene`` (:func:`reportgen.scenes.output_diagrams.output_diagrams_scene`,
    in this view's mm) with the sheet's axes, titles, position numbers, pole letters and dimensions;
    the working stroke starts ``start_deg`` after position 0 and lasts ``working_deg`` of the crank."""
    nm = names(d)
    ranges = od.ranges(d)
    draw_entities(view, [e for e in scene.entities if ":axis:" not in e.id and not e.id.endswith(":pole")])
    sc = [scene.scale(sym) for sym in nm.symbols]
    # ---- s(φ)
    o = scene.points["o_s"]
    _axes(view, o, d, ranges[0], nm.s, numbered=True, positions=positions)
    ytop = o[1] + ranges[0][0] + 12.0                # above the arrow of the y axis
    _strokes(view, o, d.axis_mm, ytop, start_deg, working_deg)
    _title(view, o, ranges[0], f"{nm.titles[0]}, {nm.symbols[0]} = {format_significant(sc[0].value, 4)} {nm.mu_s}")
    # ---- v(φ)
    o = scene.points["o_v"]
    _axes(view, o, d, ranges[1], nm.v, numbered=False, positions=positions)
    _pole(view, o, scene.values["H1"], d.v_chord_mm, "P", "1")
    _title(view, o, ranges[1], f"{nm.titles[1]}, {nm.symbols[1]} = {format_significant(sc[1].value, 4)} {nm.mu_v}")
    # ---- a(φ)
    o = scene.points["o_a"]
    _axes(view, o, d, ranges[2], nm.a, numbered=False, positions=positions)
    _pole(view, o, scene.values["H2"], d.a_chord_mm, "P", "2")
    _title(view, o, ranges[2], f"{nm.titles[2]}, {nm.symbols[2]} = {format_significant(sc[2].value, 4)} {nm.mu_a}")


def _spans(a: float, b: float, length: float) -> list[tuple[float, float]]:
    """The interval a → b (mm) on a periodic axis of ``length``, split where it wraps round."""
    a, b = a % length, b % length
    if b > a + MM_ROUNDOFF:
        return [(a, b)]
    return [(x, y) for x, y in ((a, length), (0.0, b)) if y - x > MM_ROUNDOFF]


def _strokes(view: View, o: tuple[float, float], length: float, y: float, start_deg: float,
             working_deg: float) -> None:
    """Vertical lines at the extreme positions and the spans φр.х., φх.х. above the s diagram."""
    xs = start_deg / 360.0 * length
    xe = (start_deg + working_deg) / 360.0 * length
    for x in {round(xs % length, 9), round(xe % length, 9)}:
        view.line((o[0] + x, o[1]), (o[0] + x, y + 4.0), "axis")
    for (a, b), text in [(span, tr("sheets.kd13")) for span in _spans(xs, xe, length)] + \
                        [(span, tr("sheets.kd14")) for span in _spans(xe, xs + length, length)]:
        view.dimension((o[0] + a, y), (o[0] + b, y), offset_mm=4.0,
                       text=text if b - a > 14.0 else "")


def _title(view: View, o: tuple[float, float], rng: tuple[float, float], text: str) -> None:
    """The diagram's title and scale, 30 mm right of its origin; a title longer than the room left
    in the view (a scale of many digits: class3 with its lengths × 47 and its crank 50 times slower
    wrote «με = 0,0007234 …» over the frame) starts at the view's left edge, then drops to 3.5 mm."""
    x, y = view.transform((o[0] + 30.0, o[1] + rng[0] + od.TOP_MM - 7.0))
    r = view.rect
    height = 5.0
    if x + style.text_width(text, height) > r.x1:
        x = r.x0 + 2.0
        if x + style.text_width(text, height) > r.x1:
            height = 3.5
    view.text_mm((x, y), text, height, "bottom-left")


def _axes(view: View, o: tuple[float, float], d: Diagrams, rng: tuple[float, float], y_label: str,
          numbered: bool, positions: int) -> None:
    ticks = [(float(x), "") for x in od.x_nodes(d)]
    view.axes(o, d.axis_mm + RIGHT_MM - 6.0, rng[0] + 10.0, rng[1], x_label="φ", y_label=y_label,
              x_ticks=ticks)
    if numbered:
        # the mechanism's positions along the φ axis (the last one is position 0 again)
        y = o[1] - max(rng[1] - 4.0, 0.0) - 2.5        # under the curve where it dips below the axis
        for j in range(positions + 1):
            x = o[0] + d.axis_mm * j / positions
            view.text((x, y), str(j % positions), 3.5, "top-center")


def _pole(view: View, o: tuple[float, float], H: float, ordinates, name: str, index: str) -> None:
    """The pole at H left of the origin, its rays to the ordinates on the y axis, its letter and
    the dimension H."""
    p = (o[0] - H, o[1])
    view.circle_mm(p, od.POLE_MM, "contour")           # its rays are the scene's
    rich = rl.Rich(name, "", index)
    sp = view.transform(p)
    rl.place_rich(view, rl.around(sp, rich, 5.0, 180.0), rich, 5.0)
    low = min(min(float(v) for v in ordinates), 0.0)
    y = o[1] + low - 4.0
    view.dimension((p[0], y), (o[0], y), offset_mm=-4.0,
                   text=f"H{index} = {format_number(H, 1)}")
    view.line(p, (p[0], y - 4.0), "thin")
