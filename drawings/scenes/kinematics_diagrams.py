"""Sheet 1, the kinematic diagrams of the output: s(φ), v(φ), a(φ) one above the other, the φ axis
divided into the n intervals of :func:`reportgen.diagrams.build_diagrams`, the chords of s, the
steps of each replica and the curve through them, the rays from the poles P1, P2 at H1, H2, the
exact curves thin, and the scales."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from drawings.primitives import format_number, format_significant
from drawings.sheet import Sheet, View
from drawings.scenes import kinematics_labels as rl
from reportgen.diagrams import Diagrams
from reportgen.tolerances import MM_EPS, MM_ROUNDOFF
from ..words import tr, unit

#: Space above a diagram's largest ordinate (title, dimensions) and between diagrams, mm.
TOP_MM = 32.0
GAP_MM = 8.0
RIGHT_MM = 28.0


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


def _x_nodes(d: Diagrams) -> np.ndarray:
    return np.asarray(d.nodes) / d.mu_phi


def _dense_x(d: Diagrams) -> np.ndarray:
    return np.asarray(d.dense_offset) / d.mu_phi


def _v_steps(d: Diagrams) -> list[tuple[float, float, float]]:
    """(x0, x1, y) of the velocity steps: over each interval."""
    x = _x_nodes(d)
    return [(float(x[i]), float(x[i + 1]), float(d.v_chord_mm[i])) for i in range(d.n)]


def _a_steps(d: Diagrams) -> list[tuple[float, float, float]]:
    """(x0, x1, y) of the acceleration steps: between the middles of the velocity steps; the last
    one wraps round to the start of the axis (the motion is periodic)."""
    x = _x_nodes(d)
    dx = d.axis_mm / d.n
    out = []
    for j in range(d.n):
        x0, x1 = float(x[j] + dx / 2), float(x[j] + 3 * dx / 2)
        if x1 <= d.axis_mm + MM_ROUNDOFF:
            out.append((x0, x1, float(d.a_chord_mm[j])))
        else:
            out.append((x0, d.axis_mm, float(d.a_chord_mm[j])))
            out.append((0.0, x1 - d.axis_mm, float(d.a_chord_mm[j])))
    return out


def _ranges(d: Diagrams) -> list[tuple[float, float]]:
    """(up, down) ordinates in mm of the three diagrams (both ≥ 0)."""
    s = np.concatenate([np.asarray(d.s) / d.mu_s, d.s_nodes_mm])
    v = np.concatenate([np.asarray(d.v) / d.mu_v, d.v_chord_mm])
    a = np.concatenate([np.asarray(d.a) / d.mu_a, d.a_chord_mm])
    return [(max(float(arr.max()), 10.0) + 4.0, max(-float(arr.min()), 0.0) + 4.0) for arr in (s, v, a)]


def size(d: Diagrams) -> tuple[float, float]:
    left = max(d.H1, d.H2) + 22.0
    w = left + d.axis_mm + RIGHT_MM + 6.0
    h = sum(up + down + TOP_MM + GAP_MM for up, down in _ranges(d)) + 6.0
    return w, h


def add_diagrams_view(sheet: Sheet, d: Diagrams, positions: int, start_deg: float, working_deg: float,
                      preferred: str) -> View:
    w, h = size(d)
    view = sheet.add_view("diagrams", w, h, preferred=preferred)
    draw_diagrams(view, d, positions, start_deg, working_deg)
    return view


def draw_diagrams(view: View, d: Diagrams, positions: int, start_deg: float, working_deg: float) -> None:
    """The three diagrams; the working stroke starts ``start_deg`` after position 0 and lasts
    ``working_deg`` of the crank."""
    nm = names(d)
    left = max(d.H1, d.H2) + 22.0
    ranges = _ranges(d)
    x0 = left                                  # view coordinates: mm from its lower-left corner
    top = view.rect.height - 2.0
    origins = []
    for up, down in ranges:
        oy = top - TOP_MM - up
        origins.append((x0, oy))
        top = oy - down - GAP_MM
    xs = _x_nodes(d)
    dense_x = _dense_x(d)
    # ---- s(φ)
    o = origins[0]
    _axes(view, o, d, ranges[0], nm.s, numbered=True, positions=positions)
    view.curve(o[0] + dense_x, o[1] + np.asarray(d.s) / d.mu_s, "thin")
    view.polyline([(o[0] + x, o[1] + y) for x, y in zip(xs, d.s_nodes_mm)], "contour")
    for x, y in zip(xs, d.s_nodes_mm):
        view.circle_mm((o[0] + x, o[1] + y), 0.7, "contour")
    ytop = o[1] + ranges[0][0] + 12.0                # above the arrow of the y axis
    _strokes(view, o, d.axis_mm, ytop, start_deg, working_deg)
    _title(view, o, ranges[0], f"{nm.titles[0]}, {nm.symbols[0]} = {format_significant(d.mu_s, 4)} {nm.mu_s}")
    # ---- v(φ)
    o = origins[1]
    _axes(view, o, d, ranges[1], nm.v, numbered=False, positions=positions)
    _pole(view, o, d.H1, d.v_chord_mm, "P", "1")
    view.curve(o[0] + dense_x, o[1] + np.asarray(d.v) / d.mu_v, "thin")
    steps = _v_steps(d)
    _steps(view, o, steps)
    mids = [((a + b) / 2, y) for a, b, y in steps]
    ends = [(0.0, (mids[0][1] + mids[-1][1]) / 2)] + mids + [(d.axis_mm, (mids[0][1] + mids[-1][1]) / 2)]
    view.polyline([(o[0] + x, o[1] + y) for x, y in ends], "contour")
    _title(view, o, ranges[1], f"{nm.titles[1]}, {nm.symbols[1]} = {format_significant(d.mu_v, 4)} {nm.mu_v}")
    # ---- a(φ)
    o = origins[2]
    _axes(view, o, d, ranges[2], nm.a, numbered=False, positions=positions)
    _pole(view, o, d.H2, d.a_chord_mm, "P", "2")
    view.curve(o[0] + dense_x, o[1] + np.asarray(d.a) / d.mu_a, "thin")
    a_steps = _a_steps(d)
    _steps(view, o, a_steps)
    pts = sorted(((a + b) / 2 if b - a > d.axis_mm / d.n / 2 else (a if a > 0 else b), y)
                 for a, b, y in a_steps if b - a > d.axis_mm / d.n / 2)
    pts = [(0.0, d.a_chord_mm[-1])] + pts + [(d.axis_mm, d.a_chord_mm[-1])]
    view.polyline([(o[0] + x, o[1] + y) for x, y in pts], "contour")
    _title(view, o, ranges[2], f"{nm.titles[2]}, {nm.symbols[2]} = {format_significant(d.mu_a, 4)} {nm.mu_a}")


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
    view.text((o[0] + 30.0, o[1] + rng[0] + TOP_MM - 7.0), text, 5.0, "bottom-left")


def _axes(view: View, o: tuple[float, float], d: Diagrams, rng: tuple[float, float], y_label: str,
          numbered: bool, positions: int) -> None:
    ticks = [(float(x), "") for x in _x_nodes(d)]
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
    for y in sorted(set(float(v) for v in ordinates)):
        view.line(p, (o[0], o[1] + y), "construction")
    view.circle_mm(p, 0.8, "contour")
    rich = rl.Rich(name, "", index)
    sp = view.transform(p)
    rl.place_rich(view, rl.around(sp, rich, 5.0, 180.0), rich, 5.0)
    low = min(min(float(v) for v in ordinates), 0.0)
    y = o[1] + low - 4.0
    view.dimension((p[0], y), (o[0], y), offset_mm=-4.0,
                   text=f"H{index} = {format_number(H, 1)}")
    view.line(p, (p[0], y - 4.0), "thin")


def _steps(view: View, o: tuple[float, float], steps: list[tuple[float, float, float]]) -> None:
    """The steps of a replica: horizontal segments and the verticals joining them."""
    prev = None
    for a, b, y in sorted(steps):
        if prev is not None and abs(prev[0] - a) < MM_EPS:
            view.line((o[0] + a, o[1] + prev[1]), (o[0] + a, o[1] + y), "thin")
        view.line((o[0] + a, o[1] + y), (o[0] + b, o[1] + y), "thin")
        prev = (b, y)
