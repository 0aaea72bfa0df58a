"""The flywheel's hub as a student draws it on the sketch: the bore for the crank shaft and its
keyway. Nothing of it enters J or the mass (the calculation counts the disk or rim, as the course
does); it only makes the sketch a part that can be fitted on a shaft.

* The shaft's diameter by the preliminary (torsion-only) estimate of machine-part courses,
  d ≥ ∛(T / (0,2·[τ])), with T the driving moment M_дв the shaft carries and the lowered allowable
  stress [τ] = 20 МПа that covers the bending left out; rounded up to the normal linear sizes of
  ГОСТ 6636-69 (series Ra 40), at least 20 mm.
* The keyway of a prismatic key by ГОСТ 23360-78: b × h of the key and the depth t2 of the hub's
  slot for the shaft's diameter range.
* The hub's outer diameter 1,6·d (a steel hub), not larger than the disk.

Sources the tables were checked against (issue 12), row by row:

* :data:`KEYS` — ГОСТ 23360-78, table 1 (d over … up to, b × h, t1, t2): every row from 12–17 to
  440–500 mm agrees with two independent copies of the table: a shaft-key lookup typed from the
  standard (gist.github.com/kelevara/6204878, «ГОСТ 23360-78», rows 6–8 … 75–85 mm) and the table of
  GB/T 1095-1979, whose sizes are the same (blog.csdn.net/weixin_39519072/article/
  details/111860237, «普通平键规格尺寸表»: d, b × h, shaft depth t, hub depth t1, 6–8 … 440–500 mm).
  Nothing needed fixing. The rows under 12 mm (2 × 2 … 4 × 4) are left out: the bore is ≥ 20 mm.
* :data:`RA40` — ГОСТ 6636-69 (text: omegametall.ru/Data2/1/4294823/4294823017.htm) rounds the
  preferred numbers of ГОСТ 8032-84 / ISO 3; its series Ra 40 is R40 rounded (1,06 → 1,05; 1,18 →
  1,2 in the decade 100…1000, where 115 is not a normal size; 2,12 → 2,1; 3,15 → 3,2 …). The R40
  mantissas (ISO 3, as tabulated in the ``renard`` package, github.com/rob-smallshire/renard) check
  the table: 40 sizes a decade, each within 2 % of its R40 value (tests/labels/test_flywheel_hub.py).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import ParameterError
from ..tolerances import RTOL_ROUNDOFF

#: Allowable shear stress of the preliminary shaft estimate, Pa.
TAU_ALLOWED = 20e6
#: ГОСТ 6636-69 normal linear sizes, series Ra 40 (mm), from 20 to 500.
RA40 = (20, 21, 22, 24, 25, 26, 28, 30, 32, 34, 36, 38, 40, 42, 45, 48, 50, 53, 56, 60, 63, 67, 71, 75,
        80, 85, 90, 95, 100, 105, 110, 120, 125, 130, 140, 150, 160, 170, 180, 190, 200, 210, 220, 240,
        250, 260, 280, 300, 320, 340, 360, 380, 400, 420, 450, 480, 500)
#: ГОСТ 23360-78, prismatic keys: (d over, d up to, b, h, t1 shaft, t2 hub), mm.
KEYS = ((12, 17, 5, 5, 3.0, 2.3), (17, 22, 6, 6, 3.5, 2.8), (22, 30, 8, 7, 4.0, 3.3),
        (30, 38, 10, 8, 5.0, 3.3), (38, 44, 12, 8, 5.0, 3.3), (44, 50, 14, 9, 5.5, 3.8),
        (50, 58, 16, 10, 6.0, 4.3), (58, 65, 18, 11, 7.0, 4.4), (65, 75, 20, 12, 7.5, 4.9),
        (75, 85, 22, 14, 9.0, 5.4), (85, 95, 25, 14, 9.0, 5.4), (95, 110, 28, 16, 10.0, 6.4),
        (110, 130, 32, 18, 11.0, 7.4), (130, 150, 36, 20, 12.0, 8.4), (150, 170, 40, 22, 13.0, 9.4),
        (170, 200, 45, 25, 15.0, 10.4), (200, 230, 50, 28, 17.0, 11.4), (230, 260, 56, 32, 20.0, 12.4),
        (260, 290, 63, 32, 20.0, 12.4), (290, 330, 70, 36, 22.0, 14.4), (330, 380, 80, 40, 25.0, 15.4),
        (380, 440, 90, 45, 28.0, 17.4), (440, 500, 100, 50, 31.0, 19.5))


def key_row(d: float) -> tuple[float, float, float, float, float, float]:
    """The row of :data:`KEYS` for a shaft of ``d`` mm: «свыше d0 до d1» is d0 < d ≤ d1; beyond the
    table its last (or first) row."""
    if d > KEYS[-1][1]:
        return KEYS[-1]
    return next((k for k in KEYS if k[0] < d <= k[1]), KEYS[0])


#: The hub's outer diameter in bore diameters.
HUB_RATIO = 1.6


@dataclass(frozen=True)
class Hub:
    """d_min (mm, the estimate), d (mm, the bore), the hub's diameter, the key b × h and the depth
    t2 of the hub's slot (mm), the torque T (N·m) and [τ] (Pa) the estimate used."""
    torque: float
    tau: float
    d_min: float
    d: float
    hub_d: float
    key_b: float
    key_h: float
    t2: float


def hub_of(torque: float, outer_diameter_mm: float, tau: float = TAU_ALLOWED) -> Hub:
    """The hub of a flywheel of ``outer_diameter_mm`` on a shaft carrying ``torque`` (N·m)."""
    if not (math.isfinite(torque) and math.isfinite(outer_diameter_mm) and outer_diameter_mm > 0):
        raise ParameterError("torque, diameter", (torque, outer_diameter_mm), "finite, the diameter > 0")
    d_min = 1000.0 * (abs(torque) / (0.2 * tau)) ** (1.0 / 3.0)
    d = float(next((x for x in RA40 if x >= d_min * (1 - RTOL_ROUNDOFF)), RA40[-1]))   # d_min on a size: that size
    key = key_row(d)
    hub_d = min(HUB_RATIO * d, outer_diameter_mm)
    return Hub(float(torque), tau, d_min, d, hub_d, float(key[2]), float(key[3]), float(key[5]))


#: A web (the disk between a rim and its hub) this many times the rim's width thick.
WEB_RATIO = 0.3

Rect = tuple[float, float, float, float]          # x0, y0, x1, y1 (mm)


def section_rects(radius_mm: float, inner_mm: float, width_mm: float, hub: Hub) -> list[Rect]:
    """The axial section through the keyway (x along the axis from 0 to the width, y radial; the
    keyway up): the solid parts as rectangles. A disk: from the bore (its slot above) to R; a rim:
    the rim, a web of WEB_RATIO·b in the middle and the hub, each side."""
    R, b = radius_mm, width_mm
    top, bottom = hub.d / 2 + hub.t2, -hub.d / 2
    if inner_mm <= 0:
        return [(0.0, top, b, R), (0.0, -R, b, bottom)]
    r, h = inner_mm, hub.hub_d / 2
    s = WEB_RATIO * b
    out = [(0.0, r, b, R), (0.0, -R, b, -r)]
    if h < r:
        out += [(b / 2 - s / 2, h, b / 2 + s / 2, r), (b / 2 - s / 2, -r, b / 2 + s / 2, -h)]
    out += [(0.0, top, b, max(h, top)), (0.0, -max(h, -bottom), b, bottom)]
    return [q for q in out if q[3] > q[1] and q[2] > q[0]]


def bore_outline(hub: Hub, n: int = 48) -> list[tuple[float, float]]:
    """The bore with its keyway (the front view, mm, centred on the axis, the slot up): a closed
    polyline — the circle of d broken by the slot b wide reaching d/2 + t2."""
    r, hb = hub.d / 2, hub.key_b / 2
    if hb >= r:
        hb = 0.5 * r
    a = math.asin(hb / r)
    pts = [(hb, hub.d / 2 + hub.t2), (-hb, hub.d / 2 + hub.t2)]
    for k in range(n + 1):              # from the slot's left edge round to its right edge
        t = math.pi / 2 + a + (2 * math.pi - 2 * a) * k / n
        pts.append((r * math.cos(t), r * math.sin(t)))
    return pts
