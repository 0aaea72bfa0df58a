"""Geometry of the external spur involute pair with profile shifts, by ГОСТ 16532-70 (table 1) for
the basic rack of ГОСТ 13755-81 (α = 20°, ha* = 1, c* = 0.25 by default, all configurable).

Formulas (ГОСТ 16532-70, table 1; the same in Кудрявцев «Зубчатые передачи» and in the seed note):
    inv αw = 2 xΣ tg α / (z1 + z2) + inv α
    a  = m (z1 + z2) / 2,             aw = a cos α / cos αw
    y  = (aw − a) / m,                Δy = xΣ − y
    d  = m z,  db = d cos α,  dw1 = 2 aw / (u + 1),  dw2 = 2 aw u / (u + 1),  u = z2 / z1
    da = d + 2 m (ha* + x − Δy)       (tip shortened by Δy to keep the radial clearance c* m)
    df = d − 2 m (ha* + c* − x)
    p = π m,  pb = π m cos α
    s  = m (π/2 + 2 x tg α)
    sa = da (s / d + inv α − inv αa),  cos αa = db / da
    chordal thickness s̄ = d sin(s/d), chordal height h̄a = (da − d)/2 + d (1 − cos(s/d)) / 2
    base tangent length W = m cos α [π (zw − 0.5) + 2 x tg α + z inv α],
        zw = round(z αx / π + 0.5), cos αx = d cos α / (d + 2 x m)   (ГОСТ 16532-70, table 4)
Line of action (Артоболевский, ch. «Эвольвентное зацепление»): N1N2 = aw sin αw; the tip circles cut it
at a (tip of gear 2) and b (tip of gear 1): N1b = √(ra1² − rb1²), N2a = √(ra2² − rb2²),
ab = N1b + N2a − N1N2, εα = ab / pb.

All the formulas are written once, for numpy arrays (:func:`pair_arrays`), so that the blocking
contour evaluates the very same expressions over a grid of (x1, x2).
"""
from __future__ import annotations

import math
from typing import Any
from dataclasses import dataclass, fields

import numpy as np

from ..errors import TaskError
from .involute import inv, inv_inverse

#: Basic rack of ГОСТ 13755-81.
ALPHA_DEG = 20.0
HA = 1.0
C = 0.25


def rack_tip_radius_factor(alpha: float, c: float) -> float:
    """ρf* of the generating rack: the largest tip-fillet radius that fits the clearance,
    ρf* = c* / (1 − sin α) (0.38 for α = 20°, c* = 0.25, as ГОСТ 13755-81 gives)."""
    return c / (1.0 - math.sin(alpha))


def pair_arrays(z1, z2, m, x1, x2, alpha, ha, c) -> dict[str, np.ndarray]:
    """Every quantity of the pair as arrays broadcast over x1, x2 (alpha in rad).

    Entries where inv αw ≤ 0 (a shift sum too negative for any working angle) are NaN.
    """
    x1 = np.asarray(x1, dtype=float)
    x2 = np.asarray(x2, dtype=float)
    x1, x2 = np.broadcast_arrays(x1, x2)
    tan_a, cos_a, sin_a = math.tan(alpha), math.cos(alpha), math.sin(alpha)
    inv_a = inv(alpha)
    x_sum = x1 + x2
    inv_aw = 2.0 * x_sum * tan_a / (z1 + z2) + inv_a
    ok = inv_aw > 0.0
    alpha_w = np.full(x_sum.shape, np.nan)
    if np.any(ok):
        alpha_w[ok] = inv_inverse(inv_aw[ok])
    u = z2 / z1
    a = m * (z1 + z2) / 2.0
    aw = a * cos_a / np.cos(alpha_w)
    y = (aw - a) / m
    dy = x_sum - y
    d1, d2 = m * z1, m * z2
    db1, db2 = d1 * cos_a, d2 * cos_a
    dw1 = 2.0 * aw / (u + 1.0)
    dw2 = 2.0 * aw * u / (u + 1.0)
    da1 = d1 + 2.0 * m * (ha + x1 - dy)
    da2 = d2 + 2.0 * m * (ha + x2 - dy)
    df1 = d1 - 2.0 * m * (ha + c - x1)
    df2 = d2 - 2.0 * m * (ha + c - x2)
    p = math.pi * m
    pb = p * cos_a
    s1 = m * (math.pi / 2.0 + 2.0 * x1 * tan_a)
    s2 = m * (math.pi / 2.0 + 2.0 * x2 * tan_a)
    alpha_a1 = np.arccos(np.clip(db1 / da1, -1.0, 1.0))
    alpha_a2 = np.arccos(np.clip(db2 / da2, -1.0, 1.0))
    sa1 = da1 * (s1 / d1 + inv_a - inv(alpha_a1))
    sa2 = da2 * (s2 / d2 + inv_a - inv(alpha_a2))
    ra1, ra2, rb1, rb2 = da1 / 2.0, da2 / 2.0, db1 / 2.0, db2 / 2.0
    g = aw * np.sin(alpha_w)                      # N1N2
    n1b = np.sqrt(np.maximum(ra1 * ra1 - rb1 * rb1, 0.0))
    n2a = np.sqrt(np.maximum(ra2 * ra2 - rb2 * rb2, 0.0))
    n1a = g - n2a
    n1p = rb1 * np.tan(alpha_w)
    ab = n1b + n2a - g
    eps_alpha = ab / pb
    # radii of curvature of the involute at the boundary point l, where the straight part of the
    # rack flank ends (height ha* m over the rack's datum line): ρl = r sin α − (ha* − x) m / sin α
    rho_l1 = d1 / 2.0 * sin_a - (ha - x1) * m / sin_a
    rho_l2 = d2 / 2.0 * sin_a - (ha - x2) * m / sin_a
    # lower points of the active profiles: gear 1 at a, gear 2 at b
    rho_p1 = n1a
    rho_p2 = g - n1b
    return dict(
        x1=x1, x2=x2, x_sum=x_sum, inv_alpha=np.full(x_sum.shape, inv_a), inv_alpha_w=inv_aw,
        alpha_w=alpha_w, u=np.full(x_sum.shape, u), a=np.full(x_sum.shape, a), aw=aw, y=y, dy=dy,
        d1=np.full(x_sum.shape, d1), d2=np.full(x_sum.shape, d2),
        db1=np.full(x_sum.shape, db1), db2=np.full(x_sum.shape, db2), dw1=dw1, dw2=dw2,
        da1=da1, da2=da2, df1=df1, df2=df2, p=np.full(x_sum.shape, p), pb=np.full(x_sum.shape, pb),
        s1=s1, s2=s2, alpha_a1=alpha_a1, alpha_a2=alpha_a2, sa1=sa1, sa2=sa2,
        g=g, n1a=n1a, n1b=n1b, n2a=n2a, n1p=n1p, ab=ab, eps_alpha=eps_alpha,
        rho_l1=rho_l1, rho_l2=rho_l2, rho_p1=rho_p1, rho_p2=rho_p2,
    )


@dataclass(frozen=True)
class GearGeometry:
    """The pair's geometry; sizes in mm, angles in rad (``*_deg`` in degrees).

    Gear 1 is the pinion of the task (z1), gear 2 the wheel. Every intermediate value of the
    formulas in the module docstring is a field, so that the note can print
    "formula = substituted numbers = result" from these fields alone.
    """
    z1: int
    z2: int
    m: float
    x1: float
    x2: float
    alpha: float
    ha: float
    c: float
    rho_f: float          # tip-fillet radius of the generating rack, mm
    x_sum: float
    inv_alpha: float
    inv_alpha_w: float
    alpha_w: float
    u: float
    a: float
    aw: float
    y: float
    dy: float
    d1: float
    d2: float
    db1: float
    db2: float
    dw1: float
    dw2: float
    da1: float
    da2: float
    df1: float
    df2: float
    ha1: float            # addendum (da − d)/2
    ha2: float
    hf1: float            # dedendum (d − df)/2
    hf2: float
    h1: float             # tooth height (da − df)/2
    h2: float
    p: float
    pb: float
    s1: float
    s2: float
    e1: float             # space width on the pitch circle, p − s
    e2: float
    alpha_a1: float
    alpha_a2: float
    inv_alpha_a1: float
    inv_alpha_a2: float
    sa1: float
    sa2: float
    sw1: float            # tooth thickness on the working pitch circle
    sw2: float
    chord_s1: float       # chordal thickness at the pitch circle
    chord_s2: float
    chord_h1: float       # chordal height to it
    chord_h2: float
    zw1: int              # teeth spanned by the base tangent length
    zw2: int
    w1: float             # base tangent length (длина общей нормали)
    w2: float
    g: float              # N1N2, length of the theoretical line of action
    n1a: float
    n1b: float
    n2a: float
    n1p: float
    ab: float
    eps_alpha: float
    rho_l1: float         # involute curvature at the boundary (transition) point
    rho_l2: float
    rho_p1: float         # involute curvature at the lower point of the active profile
    rho_p2: float

    @property
    def alpha_deg(self) -> float:
        return math.degrees(self.alpha)

    @property
    def alpha_w_deg(self) -> float:
        return math.degrees(self.alpha_w)

    @property
    def eps_alpha_angular(self) -> float:
        """εα by the angle form, [z1 (tg αa1 − tg αw) + z2 (tg αa2 − tg αw)] / 2π — an identity check."""
        tw = math.tan(self.alpha_w)
        return (self.z1 * (math.tan(self.alpha_a1) - tw)
                + self.z2 * (math.tan(self.alpha_a2) - tw)) / (2.0 * math.pi)

    def as_dict(self) -> dict[str, float]:
        return {f.name: getattr(self, f.name) for f in fields(self)}


def _validate(z1, z2, m, x1, x2, alpha_deg, ha, c) -> None:
    for key, z in (("z1", z1), ("z2", z2)):
        if isinstance(z, bool) or not isinstance(z, (int, np.integer)) or not 5 <= z <= 1000:
            raise TaskError(f"gears.{key}", f"tooth number {z!r} is not usable",
                            "an integer 5..1000, as in the task file")
    checks = (
        ("module", m, m > 0 and math.isfinite(m), "a module > 0 mm"),
        ("x1", x1, math.isfinite(x1) and abs(x1) <= 5, "a number in −5…5"),
        ("x2", x2, math.isfinite(x2) and abs(x2) <= 5, "a number in −5…5"),
        ("alpha_deg", alpha_deg, 5.0 <= alpha_deg <= 40.0, "a pressure angle in 5°…40°"),
        ("ha", ha, 0.3 <= ha <= 2.0, "an addendum coefficient in 0.3…2"),
        ("c", c, 0.0 < c <= 1.0, "a clearance coefficient in (0, 1]"),
    )
    for key, value, ok, expected in checks:
        if not ok:
            raise TaskError(f"gears.{key}", f"value {value!r} is out of range", expected)


def pair_geometry(z1: int, z2: int, module: float, x1: float, x2: float, alpha_deg: float = ALPHA_DEG,
                  ha: float = HA, c: float = C) -> GearGeometry:
    """The geometry of one pair (module docstring). Raises :class:`TaskError` for bad input."""
    _validate(z1, z2, module, x1, x2, alpha_deg, ha, c)
    alpha = math.radians(alpha_deg)
    r: dict[str, Any] = {k: float(v) for k, v in pair_arrays(z1, z2, module, x1, x2, alpha, ha, c).items()}
    if not math.isfinite(r["alpha_w"]):
        raise TaskError("gears.x1", f"the shift sum x1 + x2 = {x1 + x2:g} is so negative that "
                        f"inv αw = {r['inv_alpha_w']:.6g} ≤ 0",
                        f"x1 + x2 > {-(z1 + z2) * inv(alpha) / (2 * math.tan(alpha)):.4f}")
    for k in ("1", "2"):
        if r["da" + k] <= r["db" + k] or r["da" + k] <= r["df" + k]:
            raise TaskError(f"gears.x{k}", f"the tip circle da{k} = {r['da' + k]:.4f} mm lies inside "
                            f"the base or root circle", "a larger shift")
    tan_a = math.tan(alpha)
    extra: dict[str, Any] = {}
    for k, z, x in (("1", z1, x1), ("2", z2, x2)):
        d, da, df, s = r["d" + k], r["da" + k], r["df" + k], r["s" + k]
        dw = r["dw" + k]
        extra["ha" + k] = (da - d) / 2.0
        extra["hf" + k] = (d - df) / 2.0
        extra["h" + k] = (da - df) / 2.0
        extra["e" + k] = r["p"] - s
        extra["inv_alpha_a" + k] = inv(r["alpha_a" + k])
        extra["sw" + k] = dw * (s / d + r["inv_alpha"] - inv(r["alpha_w"]))
        extra["chord_s" + k] = d * math.sin(s / d)
        extra["chord_h" + k] = (da - d) / 2.0 + d * (1.0 - math.cos(s / d)) / 2.0
        cos_ax = d * math.cos(alpha) / (d + 2.0 * x * module)
        alpha_x = math.acos(min(cos_ax, 1.0))
        zw = max(1, int(round(z * alpha_x / math.pi + 0.5)))
        extra["zw" + k] = zw
        extra["w" + k] = module * math.cos(alpha) * (math.pi * (zw - 0.5) + 2.0 * x * tan_a
                                                     + z * r["inv_alpha"])
    for drop in ("x1", "x2"):
        r.pop(drop)
    return GearGeometry(z1=int(z1), z2=int(z2), m=float(module), x1=float(x1), x2=float(x2),
                        alpha=alpha, ha=float(ha), c=float(c),
                        rho_f=rack_tip_radius_factor(alpha, c) * module, **r, **extra)
