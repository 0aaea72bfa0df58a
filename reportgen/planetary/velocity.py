"""Kutzbach's velocity triangle and the angular-velocity plan as pure geometry (drawing mm).

Construction (Артоболевский, «Теория механизмов и машин», графический метод Кутцбаха): the
kinematic scheme is drawn at the length scale k (drawing mm per real mm); a vertical line through the
central axis carries the mesh points and the planet axis at their heights y = k·r, r = m·z/2:
    A: wheel 1 with planet 2, y_A = k·m·z1/2;   B: planet axis, y_B = k·a, a = m·(z1 ± z2)/2;
    C: planet 2′ with the fixed wheel 3, y_C = k·m·z3/2 (v_C = 0: the planet's instantaneous centre).
v_A = ω1·r1 is drawn as a horizontal vector of ``vector_mm`` (scale μ_v = v_A/vector_mm, m/s per mm).
The planet's velocity line runs through C and the tip a of v_A; at the height of B it gives v_B,
    x_b = x_a·(y_B − y_C)/(y_A − y_C),
read off to ``reading_mm``; then ω_H = v_B/a and the ratio u1H = ω1/ω_H from the construction.
Angular-velocity plan: from a pole P, rays parallel to each link's velocity line cut a line at the
distance h; the cut lengths are proportional to the angular velocities, ω_i = μ_ω·x_i, so
u1H = x_1/x_H.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from numbers import Real

from ..errors import TaskError
from .search import PlanetaryDesign
from .schemes import expand

from ..geometry import Vec2 as Point

# ГОСТ 2.302 scales (drawing : real), largest first.
GOST_SCALES: tuple[tuple[str, float], ...] = (
    ("10:1", 10.0), ("5:1", 5.0), ("4:1", 4.0), ("2.5:1", 2.5), ("2:1", 2.0), ("1:1", 1.0),
    ("1:2", 1 / 2), ("1:2.5", 1 / 2.5), ("1:4", 1 / 4), ("1:5", 1 / 5), ("1:10", 1 / 10),
    ("1:15", 1 / 15), ("1:20", 1 / 20), ("1:25", 1 / 25), ("1:40", 1 / 40), ("1:50", 1 / 50),
    ("1:75", 1 / 75), ("1:100", 1 / 100))


@dataclass(frozen=True)
class Segment:
    label: str
    start: Point
    end: Point

    @property
    def length(self) -> float:
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])


@dataclass(frozen=True)
class AngularVelocityPlan:
    """Pole at (0, 0), the cutting line y = h_mm; ``cuts`` are (label, x mm as read); ω = μ_ω·x."""
    h_mm: float
    rays: tuple[Segment, ...]
    cuts: tuple[tuple[str, float], ...]
    mu_omega: float
    ratio_read: float


@dataclass(frozen=True)
class VelocityTriangle:
    """The construction in drawing mm (origin: the central axis on the scheme's vertical line)."""
    module: float
    scale_label: str
    length_scale: float                 # drawing mm per real mm
    omega1: float                       # wheel 1, rad/s (the sign of the drawing: v_A to +x)
    radii_mm: tuple[tuple[str, float], ...]   # real radii: r1, a (planet axis), r3, r2, r2′
    points: tuple[tuple[str, Point], ...]     # O, A, B, C, a (tip of v_A), b (tip of v_B)
    lines: tuple[Segment, ...]          # velocity lines: wheel 1 (O–a), planet (C–a), carrier (O–b)
    v_a: float                          # m/s
    vector_mm: float                    # drawn length of v_A
    mu_v: float                         # (m/s)/mm
    v_b_mm_exact: float
    v_b_mm_read: float
    reading_mm: float
    v_b: float                          # m/s, from the read length
    omega_h: float                      # rad/s, from the construction
    ratio_graphical: float              # reducer ratio from the construction (ω_in/ω_out)
    ratio_analytic: float
    difference_percent: float           # 100·(graphical − analytic)/analytic
    plan: AngularVelocityPlan

    def point(self, label: str) -> Point:
        return dict(self.points)[label]


def choose_scale(radius_mm: float, max_radius_mm: float) -> tuple[str, float]:
    """The largest ГОСТ 2.302 scale that draws ``radius_mm`` within ``max_radius_mm``."""
    for label, k in GOST_SCALES:
        if radius_mm * k <= max_radius_mm:
            return label, k
    return GOST_SCALES[-1]


def _round_to(x: float, step: float) -> float:
    return round(round(x / step) * step, 12) if step > 0 else x


def velocity_triangle(design: PlanetaryDesign, omega_in: float, module: float | None = None, *,
                      vector_mm: float = 100.0, length_scale: float | None = None,
                      max_radius_mm: float = 150.0, reading_mm: float = 0.01,
                      h_mm: float | None = None, plan_mm: float = 100.0) -> VelocityTriangle:
    """Kutzbach's triangle for ``design`` with the driving member at ``omega_in`` rad/s and module
    ``module`` mm (default: the design's). ``length_scale`` None: the largest ГОСТ 2.302 scale that
    keeps the envelope radius within ``max_radius_mm``. ``h_mm`` None: the pole distance (whole mm)
    that makes the longest cut of the angular-velocity plan about ``plan_mm``."""
    m = design.module if module is None else module
    if isinstance(m, bool) or not isinstance(m, Real) or not m > 0:
        raise TaskError("planetary.module", f"{m!r}", "a module in mm > 0 (needed for the velocity triangle)")
    for path, v in (("omega_in", omega_in), ("vector_mm", vector_mm), ("plan_mm", plan_mm),
                    ("h_mm", 1.0 if h_mm is None else h_mm)):
        if isinstance(v, bool) or not isinstance(v, Real) or not math.isfinite(v) or v == 0:
            raise TaskError(f"planetary.velocity.{path}", f"{v!r}", "a finite number ≠ 0")
    sch = design.scheme
    z1, z2, z2p, z3 = expand(sch, design.z)
    u1h = float(design.ratio_check.u1h)
    w_in = abs(float(omega_in))
    omega1 = w_in if design.driver == "wheel" else w_in * u1h
    r1, r3 = m * z1 / 2, m * z3 / 2
    a = m * design.coaxial.left / 2
    if length_scale is None:
        scale_label, k = choose_scale(m * design.size / 2, max_radius_mm)
    else:
        scale_label, k = f"{length_scale:g}", float(length_scale)
    ya, yb, yc = k * r1, k * a, k * r3
    v_a = abs(omega1) * r1 / 1000.0                      # m/s
    sgn = 1.0 if omega1 >= 0 else -1.0
    xa = sgn * vector_mm
    mu_v = v_a / vector_mm
    xb = xa * (yb - yc) / (ya - yc)                       # planet line C–a at the height of B
    xb_read = _round_to(xb, reading_mm)
    v_b = xb_read * mu_v                                  # signed along +x
    omega_h = v_b / (a / 1000.0)
    omega1_signed = xa * mu_v / (r1 / 1000.0)
    u1h_graph = omega1_signed / omega_h if omega_h != 0 else math.inf
    ratio_graph = u1h_graph if design.driver == "wheel" else 1.0 / u1h_graph
    analytic = design.ratio
    pts = (("O", (0.0, 0.0)), ("A", (0.0, ya)), ("B", (0.0, yb)), ("C", (0.0, yc)),
           ("a", (xa, ya)), ("b", (xb_read, yb)))
    lines = (Segment("1", (0.0, 0.0), (xa, ya)), Segment("2", (0.0, yc), (xa, ya)),
             Segment("H", (0.0, 0.0), (xb_read, yb)))
    # angular-velocity plan: rays parallel to the velocity lines, cut at y = h
    slopes = [abs((s.end[0] - s.start[0]) / (s.end[1] - s.start[1])) for s in lines]
    if h_mm is None:
        h_mm = max(1.0, float(round(abs(plan_mm) / max(slopes))))
    rays, cuts = [], []
    for seg in lines:
        dx, dy = seg.end[0] - seg.start[0], seg.end[1] - seg.start[1]
        x = _round_to(h_mm * dx / dy, reading_mm)
        rays.append(Segment(seg.label, (0.0, 0.0), (x, h_mm)))
        cuts.append((seg.label, x))
    x1, xh = cuts[0][1], cuts[2][1]
    mu_omega = omega1_signed / x1
    plan_u1h = x1 / xh if xh != 0 else math.inf
    plan = AngularVelocityPlan(h_mm, tuple(rays), tuple(cuts), mu_omega,
                               plan_u1h if design.driver == "wheel" else 1.0 / plan_u1h)
    radii = (("r1", r1), ("a", a), ("r3", r3), ("r2", m * z2 / 2), ("r2′", m * z2p / 2))
    return VelocityTriangle(float(m), scale_label, k, omega1, radii, pts, lines, v_a, float(vector_mm),
                            mu_v, xb, xb_read, reading_mm, v_b, omega_h, ratio_graph, analytic,
                            100.0 * (ratio_graph - analytic) / analytic, plan)
