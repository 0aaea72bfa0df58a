"""Scenes of the crane sheets: the polyspast reeving scheme, the kinematic schemes of the hoist and
of the trolley travel (symbols after ГОСТ 2.770-68: shafts as thick lines, spur gears as rectangles
across their shafts touching at the pitch line, couplings as facing strokes, the shoe brake as a
pulley with two hatched shoes, the motor as a rectangle with «М»), and the parameter tables.

Kinematic schemes are not to scale (ГОСТ 2.703): every size here is in sheet millimetres.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from drawings.layout import Rect
from drawings.primitives import Transform
from drawings.sheet import Sheet, View
from drawings.words import tr
from reportgen.tolerances import MM_ROUNDOFF

ROW_MM = 8.0          # table rows
TEXT_MM = 3.5         # table and label text
TITLE_MM = 5.0        # view titles
BRANCH_MM = 13.0      # distance between rope branches in the reeving scheme


# ----------------------------------------------------------------------------------------- tables
LINE_PITCH = 1.6      # of a wrapped cell, × text height


def _row_lines(row: Sequence[str], widths: tuple[float, ...]) -> list[list[str]]:
    from drawings.sheet import _wrap        # the sheet's word wrap (one home for it)
    return [_wrap(cell, TEXT_MM, w - 4.0, 1.0) for cell, w in zip(row, widths)]


def _row_height(lines: list[list[str]]) -> float:
    n = max(len(c) for c in lines)
    return ROW_MM + (n - 1) * TEXT_MM * LINE_PITCH


def table_size(rows: Sequence[Sequence[str]], widths: tuple[float, ...]) -> tuple[float, float]:
    """Width and height of :func:`draw_table`'s table with its title, mm."""
    return sum(widths), sum(_row_height(_row_lines(r, widths)) for r in rows) + TITLE_MM + 5.0


def draw_table(sheet: Sheet, name: str, rect: Rect, title: str, rows: Sequence[Sequence[str]],
               widths: tuple[float, ...]) -> View:
    """A table (first row = header, centred) under its title, in ``rect`` from its top; long cells
    wrap onto more lines (the row grows)."""
    view = sheet.place_view(name, rect, Transform(1.0, (0.0, 0.0), (rect.x0, rect.y0)))
    tw = sum(widths)
    top = rect.height - TITLE_MM - 5.0
    view.text((tw / 2, top + 2.5), title, TITLE_MM, "bottom-center")
    y = top
    for i, row in enumerate(rows):
        lines = _row_lines(row, widths)
        h = _row_height(lines)
        x = 0.0
        for w, cell in zip(widths, lines):
            first = y - h / 2 + (len(cell) - 1) * TEXT_MM * LINE_PITCH / 2
            for k, text in enumerate(cell):
                yy = first - k * TEXT_MM * LINE_PITCH
                if i == 0:
                    view.text((x + w / 2, yy), text, TEXT_MM, "center")
                else:
                    view.text((x + 2.0, yy), text, TEXT_MM, "middle-left")
            x += w
        view.line((0.0, y), (tw, y), "contour" if i in (0, 1) else "thin")
        y -= h
    view.line((0.0, y), (tw, y), "contour")
    x = 0.0
    for j in range(len(widths) + 1):
        view.line((x, top), (x, y), "contour")
        if j < len(widths):
            x += widths[j]
    return view


# ------------------------------------------------------------------------------- reeving scheme
@dataclass(frozen=True)
class Reeving:
    """Branch positions (x, mm from the scheme's middle) and the sheaves of a polyspast."""
    ratio: int
    branches: int          # rope branches wound on the drum: 1 or 2 (a double polyspast)

    def half(self, side: int) -> list[float]:
        """x of the branches of one half, from the drum branch (0) inwards; side −1 left, +1 right."""
        s = BRANCH_MM
        if self.branches == 1:
            return [(i - (self.ratio - 1) / 2) * s for i in range(self.ratio)]
        return [side * (s / 2 + (self.ratio - 1 - i) * s) for i in range(self.ratio)]

    @property
    def width(self) -> float:
        return (2 * self.ratio if self.branches == 2 else self.ratio) * BRANCH_MM

def draw_reeving(view: View, rv: Reeving, height: float) -> dict[str, tuple[float, float]]:
    """The reeving scheme with its middle at x = 0, the hook sheaves at y = 0 and the top sheaves at
    ``height``; returns anchor points of its parts (sheet-independent model mm)."""
    s = BRANCH_MM
    r = s / 2
    y_top, y_bot = height, 0.0
    y_drum = height + 28.0
    sides = (-1, 1) if rv.branches == 2 else (1,)
    xs_all: list[float] = []
    for side in sides:
        xs = rv.half(side)
        xs_all += xs
        for i, x in enumerate(xs):
            start = y_drum - 8.0 if i == 0 else y_top
            view.line((x, start), (x, y_bot), "contour")
        for i in range(0, rv.ratio - 1, 2):          # hook sheaves join (0,1), (2,3) …
            cx = (xs[i] + xs[i + 1]) / 2
            view.circle((cx, y_bot), r, "contour")
            view.circle_mm((cx, y_bot), 0.8, "contour")
        for i in range(1, rv.ratio - 1, 2):          # fixed sheaves join (1,2), (3,4) …
            cx = (xs[i] + xs[i + 1]) / 2
            view.circle((cx, y_top), r, "contour")
            view.circle_mm((cx, y_top), 0.8, "contour")
        last = rv.ratio - 1
        if last % 2 == 0:                             # an odd ratio: the end is fixed on the hook block
            view.polyline([(xs[last] - 2.5, y_bot - 3.0), (xs[last] + 2.5, y_bot - 3.0), (xs[last], y_bot)],
                          "contour", closed=True)
        elif rv.branches == 1:                        # an even single polyspast: fixed at the top
            view.line((xs[last] - 4.0, y_top), (xs[last] + 4.0, y_top), "contour")
            for k in range(3):
                x0 = xs[last] - 4.0 + 3.0 * k
                view.line((x0, y_top), (x0 + 2.0, y_top + 2.0), "thin")
    anchors = {}
    if rv.branches == 2 and rv.ratio % 2 == 0:
        view.circle((0.0, y_top), r, "contour")       # the equalizing sheave
        view.circle_mm((0.0, y_top), 0.8, "contour")
        anchors["equalizer"] = (0.0, y_top + r)
    # the drum over the branches
    x0, x1 = min(xs_all) - 10.0, max(xs_all) + 10.0
    view.polyline([(x0, y_drum - 8.0), (x1, y_drum - 8.0), (x1, y_drum + 8.0), (x0, y_drum + 8.0)],
                  "contour", closed=True)
    view.line((x0 - 8.0, y_drum), (x1 + 8.0, y_drum), "axis")
    # the hook block and the hook
    hx0 = min(xs_all) - r - 4.0
    hx1 = max(xs_all) + r + 4.0
    view.polyline([(hx0, y_bot - r - 6.0), (hx1, y_bot - r - 6.0), (hx1, y_bot + r + 4.0),
                   (hx0, y_bot + r + 4.0)], "thin", closed=True)
    hook_top = y_bot - r - 6.0
    view.line((0.0, hook_top), (0.0, hook_top - 10.0), "contour")
    view.arc((4.0, hook_top - 16.0), 6.0, 180.0, 360.0, "contour")
    view.line((10.0, hook_top - 16.0), (10.0, hook_top - 12.0), "contour")
    view.arc((4.0, hook_top - 16.0), 6.0, 90.0, 180.0, "contour")
    anchors.update(drum=(x1, y_drum + 8.0), hook_block=(hx1, y_bot + r + 4.0),
                   top=(max(xs_all) + r, y_top), hook=(10.0, hook_top - 16.0))
    return anchors


# --------------------------------------------------------------------------- kinematic symbols
def shaft(view: View, p: tuple[float, float], q: tuple[float, float]) -> None:
    view.line(p, q, "contour")


def gear(view: View, x: float, y: float, radius: float, width: float = 6.0) -> None:
    """A spur gear on a shaft along x at (x, y): a rectangle across the shaft, radius to its pitch line."""
    view.polyline([(x - width / 2, y - radius), (x + width / 2, y - radius), (x + width / 2, y + radius),
                   (x - width / 2, y + radius)], "contour", closed=True)


def coupling(view: View, x: float, y: float, h: float = 10.0) -> None:
    """A coupling on a shaft along x (ГОСТ 2.770, general sign): two facing strokes with a gap."""
    for dx in (-1.5, 1.5):
        view.line((x + dx, y - h / 2), (x + dx, y + h / 2), "contour")
    for sy in (-1, 1):
        view.line((x - 1.5, y + sy * h / 2), (x - 4.0, y + sy * h / 2), "contour")
        view.line((x + 1.5, y + sy * h / 2), (x + 4.0, y + sy * h / 2), "contour")


def brake(view: View, x: float, y: float, radius: float = 10.0) -> None:
    """A shoe brake on a shaft along x: the pulley (a rectangle across the shaft) and two shoes."""
    view.polyline([(x - 5.0, y - radius), (x + 5.0, y - radius), (x + 5.0, y + radius), (x - 5.0, y + radius)],
                  "contour", closed=True)
    for sy in (-1, 1):
        yy = y + sy * (radius + 1.5)
        view.line((x - 6.0, yy), (x + 6.0, yy), "contour")
        for k in range(4):
            xx = x - 6.0 + 4.0 * k
            view.line((xx, yy), (xx + 2.0, yy + sy * 2.5), "thin")


def motor(view: View, x0: float, y: float, w: float = 40.0, h: float = 26.0) -> float:
    """The motor (a rectangle with «М» and its feet) whose shaft leaves at the right, at height y;
    returns x of the shaft's exit."""
    view.polyline([(x0, y - h / 2), (x0 + w, y - h / 2), (x0 + w, y + h / 2), (x0, y + h / 2)], "contour",
                  closed=True)
    view.text((x0 + w / 2, y), tr("crane.sheet.motor_letter"), 5.0, "center")
    return x0 + w


def bearing(view: View, x: float, y: float) -> None:
    """A radial bearing on a shaft along x: short strokes above and below the shaft."""
    for sy in (-1, 1):
        view.line((x - 2.0, y + sy * 3.0), (x + 2.0, y + sy * 3.0), "contour")
        view.line((x, y + sy * 3.0), (x, y + sy * 0.7), "contour")


def callout(view: View, point: tuple[float, float], to: tuple[float, float], number: int) -> None:
    """A position number on a leader line (ГОСТ 2.109 style: number over a shelf)."""
    view.line(point, to, "thin")
    view.circle_mm(point, 0.6, "contour")
    view.line(to, (to[0] + 8.0, to[1]), "thin")
    view.text((to[0] + 4.0, to[1] + 0.8), str(number), 5.0, "bottom-center")


def draw_hoist_drive(view: View, open_gear: bool) -> dict[str, tuple[float, float]]:
    """Motor – coupling – brake – two-stage reducer – (open gear) – drum, plan view. Returns the
    anchor of each numbered part."""
    y_in = 20.0
    x = motor(view, 0.0, y_in)
    shaft(view, (x, y_in), (150.0, y_in))
    coupling(view, 72.0, y_in)
    brake(view, 98.0, y_in)
    # reducer: box, input, intermediate, output shafts
    bx0, bx1, by0, by1 = 120.0, 215.0, -5.0, 130.0
    view.polyline([(bx0, by0), (bx1, by0), (bx1, by1), (bx0, by1)], "thin", closed=True)
    y_mid, y_out = 50.0, 90.0
    shaft(view, (bx0 + 5.0, y_mid), (bx1 - 5.0, y_mid))
    gear(view, 150.0, y_in, 8.0)
    gear(view, 150.0, y_mid, 22.0)
    gear(view, 190.0, y_mid, 8.0)
    gear(view, 190.0, y_out, 32.0)
    for xb in (bx0 + 5.0, bx1 - 5.0):
        bearing(view, xb, y_mid)
    bearing(view, bx0 + 5.0, y_in)
    anchors = {"motor": (20.0, y_in + 13.0), "coupling": (72.0, y_in + 5.0), "brake": (98.0, y_in + 11.5),
               "reducer": (bx0 + 20.0, by1)}
    if open_gear:
        shaft(view, (175.0, y_out), (262.0, y_out))
        bearing(view, bx1 - 5.0, y_out)
        bearing(view, 255.0, y_out)
        gear(view, 240.0, y_out, 10.0)
        y_drum = y_out + 10.0 + 40.0
        gear(view, 240.0, y_drum, 40.0, 8.0)
        dx0, dx1 = 248.0, 430.0
        anchors["open_gear"] = (240.0, y_out + 10.0)
    else:
        shaft(view, (175.0, y_out), (250.0, y_out))
        bearing(view, bx1 - 5.0, y_out)
        coupling(view, 232.0, y_out)
        y_drum = y_out
        dx0, dx1 = 245.0, 420.0
    r_drum = 30.0
    shaft(view, (dx0 - 8.0, y_drum), (dx1 + 10.0, y_drum))
    view.polyline([(dx0, y_drum - r_drum), (dx1, y_drum - r_drum), (dx1, y_drum + r_drum),
                   (dx0, y_drum + r_drum)], "contour", closed=True)
    # grooves: right- and left-hand halves
    mid = (dx0 + dx1) / 2
    for k in range(9):
        xa = dx0 + 12.0 + 8.0 * k
        view.line((xa, y_drum - r_drum), (xa + 6.0, y_drum + r_drum), "thin")
        xb = dx1 - 12.0 - 8.0 * k
        view.line((xb, y_drum - r_drum), (xb - 6.0, y_drum + r_drum), "thin")
    view.line((mid, y_drum - r_drum - 6.0), (mid, y_drum + r_drum + 6.0), "axis")
    bearing(view, dx1 + 4.0, y_drum)
    anchors["drum"] = (dx1 - 20.0, y_drum + r_drum)
    return anchors


def draw_trolley_drive(view: View, driven: int, wheels: int, gauge_mm: float = 300.0,
                       base_mm: float = 220.0) -> dict[str, tuple[float, float]]:
    """Central drive of the trolley, plan view: the motor, the coupling and the brake on the input
    shaft of a two-stage reducer in the middle; its slow shaft runs to both rails through couplings
    to the driven wheels; the other wheels idle. Wheel axles along x, rails along y."""
    half = gauge_mm / 2
    y_in, y_mid, y_out = 44.0, 22.0, 0.0
    for sx in (-1, 1):                                 # rails (centre lines)
        view.line((sx * half, -base_mm / 2 - 35.0), (sx * half, base_mm / 2 + 35.0), "axis")
    view.polyline([(-25.0, -22.0), (25.0, -22.0), (25.0, 56.0), (-25.0, 56.0)], "thin", closed=True)
    x_m = motor(view, -125.0, y_in, 40.0, 24.0)
    shaft(view, (x_m, y_in), (-2.0, y_in))
    coupling(view, -70.0, y_in)
    brake(view, -46.0, y_in, 9.0)
    shaft(view, (-20.0, y_mid), (20.0, y_mid))
    gear(view, -8.0, y_in, 6.0, 5.0)
    gear(view, -8.0, y_mid, 16.0, 5.0)
    gear(view, 10.0, y_mid, 6.0, 5.0)
    gear(view, 10.0, y_out, 16.0, 5.0)
    wheel_r, wheel_w = 20.0, 8.0
    n_axles = max(wheels // 2, 2)
    ys = [(i - (n_axles - 1) / 2) * base_mm / (n_axles - 1) for i in range(n_axles)]
    drive_axles = min(max(driven // 2, 1), 2)
    if drive_axles == 1:                               # the driven axle on the slow shaft's line,
        ys = [0.6 * base_mm * k / (n_axles - 1) for k in range(n_axles)]   # the idle ones above it
        driven_ys = [0.0]
        x_end = half + 16.0
    else:                                              # two driven axles: a spur train on each side
        d = min(abs(y) for y in ys)
        driven_ys = [-d, d]
        x_end = half - 30.0
    shaft(view, (-x_end, y_out), (x_end, y_out))
    for sx in (-1, 1):
        coupling(view, sx * (half - 60.0), y_out)
        if drive_axles == 2:
            xg = sx * (half - 30.0)
            gear(view, xg, y_out, d / 2, 5.0)
            for yd in driven_ys:
                gear(view, xg, yd, d / 2, 5.0)
                shaft(view, (xg, yd), (sx * (half + 16.0), yd))
    for y in ys:
        for sx in (-1, 1):
            x = sx * half
            view.polyline([(x - wheel_w / 2, y - wheel_r), (x + wheel_w / 2, y - wheel_r),
                           (x + wheel_w / 2, y + wheel_r), (x - wheel_w / 2, y + wheel_r)], "contour", closed=True)
            if not any(abs(y - yd) < MM_ROUNDOFF for yd in driven_ys):
                view.line((x - 14.0, y), (x + 14.0, y), "contour")
            bearing(view, x - 10.0 * sx, y)
    return {"motor": (-105.0, y_in + 12.0), "coupling": (-70.0, y_in + 5.0), "brake": (-46.0, y_in + 10.5),
            "reducer": (0.0, 56.0), "shaft_coupling": (half - 60.0, y_out + 5.0),
            "wheel": (half + wheel_w / 2, driven_ys[0] + wheel_r), "idle_wheel": (half + wheel_w / 2, max(ys) + wheel_r)}
