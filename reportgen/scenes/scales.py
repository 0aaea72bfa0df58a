"""Scale factors of the drawings — one rule, one place.

A scale factor μ (SI units per mm of paper) is *round*: a mantissa of a series times 10^k, the
smallest such μ that draws ``value`` within ``max_mm`` (so the drawing is between about half and
all of ``max_mm``). The series differs by construction, as the course's manuals take them:

- :data:`PLAN_SERIES` (1, 2, 2.5, 4, 5): velocity and acceleration plans, Zhukovsky's lever (the
  velocity plan turned), the s–v–a diagrams, the diagrams of section 3 (seed 000, § 1.3; ГОСТ 2.302
  ratios 1:2, 1:2,5, 1:4, 1:5);
- :data:`FORCE_SERIES` (1, 2, 2.5, 5): force polygons, the lever's forces, the scheme of section 2
  (seed 001, §§ 5–6).

A drawing of the mechanism itself is at a ГОСТ 2.302 scale (:data:`GOST_SCALES`):
:func:`gost_scale` picks the largest that fits a box.
"""
from __future__ import annotations

import math

from .. import gost_scales
from ..tolerances import RTOL_ROUNDOFF

#: Mantissas of round scale factors (see the module's docstring).
PLAN_SERIES = (1.0, 2.0, 2.5, 4.0, 5.0)
FORCE_SERIES = (1.0, 2.0, 2.5, 5.0)

#: ГОСТ 2.302 scales as (paper, real), largest first: 1:2,5 is (1, 2.5) — the list of
#: :mod:`reportgen.gost_scales` (the one home of the standard's scales).
GOST_SCALES: tuple[tuple[float, float], ...] = gost_scales.scales()


def round_up(x: float, series: tuple[float, ...] = PLAN_SERIES) -> float:
    """The smallest m·10^k ≥ x with m in ``series`` (1.0 for a non-positive or infinite x)."""
    if x <= 0 or not math.isfinite(x):
        return 1.0
    k = math.floor(math.log10(x)) - 1
    while True:
        for m in series:
            mu = float(f"{m * 10.0 ** k:.12g}")
            if mu >= x * (1 - RTOL_ROUNDOFF):
                return mu
        k += 1


def round_scale(value: float, max_mm: float, series: tuple[float, ...] = PLAN_SERIES) -> float:
    """The smallest round μ (``series``) that draws ``value`` within ``max_mm``: value/μ ≤ max_mm."""
    if not (value > 0 and math.isfinite(value)):
        return 1.0
    return round_up(value / max_mm, series)


def gost_scale(width_m: float, height_m: float, max_w_mm: float, max_h_mm: float) -> tuple[float, str]:
    """The largest ГОСТ 2.302 scale at which width × height (m) fits max_w × max_h (mm); returns
    (paper mm per metre, «1:2,5»). The smallest scale of the list if none fits."""
    s = gost_scales.largest_fitting(_needed(width_m, height_m, max_w_mm, max_h_mm))
    return 1000.0 * gost_scales.factor(s), gost_scales.label(s)


def _needed(width_m: float, height_m: float, max_w_mm: float, max_h_mm: float) -> float:
    """The largest factor (drawing per real) with which a width × height (m) fits max_w × max_h (mm)."""
    fits = [m / (1000.0 * e) for e, m in ((width_m, max_w_mm), (height_m, max_h_mm)) if e > 0]
    return min(fits) if fits else math.inf


def gost_scales_from(k: float) -> list[tuple[float, str]]:
    """The ГОСТ 2.302 scales (paper mm per metre, ratio text) not larger than ``k``, largest first."""
    return [(1000.0 * gost_scales.factor(s), gost_scales.label(s)) for s in gost_scales.fitting(k / 1000.0)]
