"""Automatic profile shifts from a computed blocking contour (блокирующий контур).

The blocking contour of a pair z1/z2 is the region of the (x1, x2) plane where every check of
:mod:`reportgen.gears.checks` holds (Болотовский, Гурьев, Смирнов, Шендерей, «Справочник по
геометрическому расчёту эвольвентных зубчатых и червячных передач», blocking contours, where they
are given as printed charts for selected z1/z2). Here it is computed for any pair: every check's
margin is evaluated on a grid with the formulas of :mod:`reportgen.gears.geometry`, its zero line is
traced by marching squares, and the line of equal maximal specific sliding λ1(a) = λ2(b) is traced
the same way.

Rule for "auto" (documented and justified in docs/gears.md):
1. Take the part of the equal-sliding line that lies inside the contour, and on it the point with
   the largest shift sum x1 + x2 (found by bisection of the boundary crossing). Equal maximal
   sliding equalises the wear of the two flanks; the largest sum gives the largest working angle αw,
   hence the largest radii of curvature at the pole (contact strength) and the thickest roots
   (bending strength), as far as the sharpening, contact-ratio and interference limits allow.
2. If that line misses the contour, take the feasible grid point with the smallest |λ1(a) − λ2(b)|
   (ties: the larger sum).
3. Round to ``rounding`` (0.01 by default) to the nearest rounded point that still passes every
   check, searched among the 3 × 3 rounded neighbours; keep the exact point if none does.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..errors import TaskError
from .checks import EPS_MIN, SA_MIN_FACTOR, margins, passes, x_min
from .contours import zero_lines
from .geometry import pair_arrays
from .sliding import lambda1, lambda2
from ..geometry import readonly as _ro
from ..tolerances import SHIFT_BISECT_TOL, SHIFT_FD_STEP, SHIFT_SECANT_TOL

RULE_EQUAL_SLIDING = "equal maximal specific sliding λ1(a) = λ2(b) at the largest feasible x1 + x2"
RULE_LEAST_IMBALANCE = "no feasible point has equal sliding: smallest |λ1(a) − λ2(b)|, then largest x1 + x2"


@dataclass(frozen=True)
class BlockingContour:
    """Grid data and curves of the blocking contour of one pair.

    ``curves`` maps a check name (:data:`CHECK_NAMES`) or ``"equal_sliding"`` or ``"eps_1"``
    (εα = 1) to its zero lines, each an (n, 2) array of (x1, x2). ``feasible[i, j]`` says whether
    every check holds at (x1[i], x2[j]).
    """
    z1: int
    z2: int
    x1: np.ndarray
    x2: np.ndarray
    feasible: np.ndarray
    curves: Mapping[str, tuple[np.ndarray, ...]]
    sa_min_factor: float
    eps_min: float


@dataclass(frozen=True)
class ShiftChoice:
    """The chosen shifts: ``x1``, ``x2`` as used, ``x1_exact``, ``x2_exact`` before rounding,
    ``rule`` in words, and the contour they were chosen on."""
    x1: float
    x2: float
    x1_exact: float
    x2_exact: float
    rule: str
    lambda1_a: float
    lambda2_b: float
    contour: BlockingContour


class _Evaluator:
    def __init__(self, z1, z2, m, alpha, ha, c, sa_min_factor, eps_min):
        self.args = (z1, z2, m, alpha, ha, c)
        self.z1, self.z2, self.m, self.alpha, self.ha = z1, z2, m, alpha, ha
        self.sa_min_factor, self.eps_min = sa_min_factor, eps_min

    def arrays(self, x1, x2):
        z1, z2, m, alpha, ha, c = self.args
        with np.errstate(invalid="ignore", divide="ignore"):
            return pair_arrays(z1, z2, m, x1, x2, alpha, ha, c)

    def margins(self, arr):
        return margins(arr, self.z1, self.z2, self.m, self.alpha, self.ha,
                       self.sa_min_factor, self.eps_min)

    def feasible(self, x1, x2):
        arr = self.arrays(x1, x2)
        ok = np.isfinite(arr["alpha_w"])
        for value, limit in self.margins(arr).values():
            ok &= passes(value, limit)
        return ok

    def sliding_gap(self, arr):
        """λ1(a) − λ2(b); NaN where a or b is off the segment N1N2."""
        g, u = arr["g"], arr["u"]
        with np.errstate(invalid="ignore", divide="ignore"):
            gap = lambda1(arr["n1a"], g, u) - lambda2(arr["n1b"], g, u)
        bad = ~((arr["n1a"] > 0) & (arr["n1b"] < g) & (arr["n1a"] < arr["n1b"]))
        return np.where(bad, np.nan, gap)


def _grid_range(ev: _Evaluator, z: int, which: int) -> tuple[float, float]:
    """From a little below the undercut limit (at least −1.5) up to where this gear's tooth alone
    (the other shift 0) would be pointed, plus 0.2 (at most 3)."""
    lo = max(float(x_min(z, ev.alpha, ev.ha)) - 0.4, -1.5)
    xs = np.linspace(lo, 3.0, 361)
    zeros = np.zeros_like(xs)
    arr = ev.arrays(xs, zeros) if which == 1 else ev.arrays(zeros, xs)
    sa = arr["sa1" if which == 1 else "sa2"]
    pointed = np.nonzero(np.isfinite(sa) & (sa <= 0))[0]
    hi = xs[pointed[0]] + 0.2 if pointed.size else 3.0
    return lo, float(min(max(hi, lo + 0.5), 3.0))


def blocking_contour(z1: int, z2: int, module: float = 1.0, alpha_deg: float = 20.0, ha: float = 1.0,
                     c: float = 0.25, sa_min_factor: float = SA_MIN_FACTOR, eps_min: float = EPS_MIN,
                     n: int = 161, x1_range: tuple[float, float] | None = None,
                     x2_range: tuple[float, float] | None = None) -> BlockingContour:
    """The blocking contour on an n × n grid (module docstring). Module-free except through
    sa ≥ k·m, which scales with m, so the contour does not depend on m."""
    ev = _Evaluator(z1, z2, module, math.radians(alpha_deg), ha, c, sa_min_factor, eps_min)
    return _contour(ev, n, x1_range, x2_range)


def _contour(ev: _Evaluator, n: int, x1_range, x2_range) -> BlockingContour:
    r1 = x1_range or _grid_range(ev, ev.z1, 1)
    r2 = x2_range or _grid_range(ev, ev.z2, 2)
    xs1, xs2 = np.linspace(r1[0], r1[1], n), np.linspace(r2[0], r2[1], n)
    X1, X2 = np.meshgrid(xs1, xs2, indexing="ij")
    arr = ev.arrays(X1, X2)
    feasible = np.isfinite(arr["alpha_w"])
    curves: dict[str, tuple[np.ndarray, ...]] = {}
    for name, (value, limit) in ev.margins(arr).items():
        margin = value - limit
        feasible &= passes(value, limit)
        curves[name] = zero_lines(xs1, xs2, margin)
    curves["eps_1"] = zero_lines(xs1, xs2, arr["eps_alpha"] - 1.0)
    curves["equal_sliding"] = zero_lines(xs1, xs2, ev.sliding_gap(arr))
    feasible = _ro(feasible, dtype=bool)
    return BlockingContour(z1=ev.z1, z2=ev.z2, x1=_ro(xs1), x2=_ro(xs2), feasible=feasible,
                           curves=MappingProxyType(curves), sa_min_factor=ev.sa_min_factor,
                           eps_min=ev.eps_min)


def _refine_on_line(ev: _Evaluator, p_in: np.ndarray, p_out: np.ndarray) -> np.ndarray:
    """Bisection between a feasible and an infeasible point of the equal-sliding line; each trial
    point is first moved onto λ1(a) = λ2(b) along x2 (secant steps)."""
    def project(p):
        x1, x2 = float(p[0]), float(p[1])
        h = SHIFT_FD_STEP
        for _ in range(30):
            f0 = float(ev.sliding_gap(ev.arrays(x1, x2)))
            f1 = float(ev.sliding_gap(ev.arrays(x1, x2 + h)))
            if not (math.isfinite(f0) and math.isfinite(f1)) or f1 == f0:
                break
            step = -f0 * h / (f1 - f0)
            x2 += step
            if abs(step) < SHIFT_SECANT_TOL:
                break
        return np.array([x1, x2])

    lo, hi = np.array(p_in, float), np.array(p_out, float)
    best = project(lo) if ev.feasible(*project(lo)) else lo
    for _ in range(60):
        mid = project((lo + hi) / 2.0)
        if bool(ev.feasible(*mid)):
            lo, best = (lo + hi) / 2.0, mid
        else:
            hi = (lo + hi) / 2.0
        if np.hypot(*(hi - lo)) < SHIFT_BISECT_TOL:
            break
    return best


def _densify(line: np.ndarray, step: float) -> np.ndarray:
    pts = [line[0]]
    for p, q in zip(line[:-1], line[1:]):
        k = max(1, int(math.ceil(np.hypot(*(q - p)) / step)))
        pts += [p + (q - p) * t for t in np.linspace(0, 1, k + 1)[1:]]
    return np.array(pts)


def choose_shifts(z1: int, z2: int, module: float, alpha_deg: float = 20.0, ha: float = 1.0,
                  c: float = 0.25, sa_min_factor: float = SA_MIN_FACTOR, eps_min: float = EPS_MIN,
                  rounding: float | None = 0.01, n: int = 161) -> ShiftChoice:
    """x1, x2 by the rule of the module docstring. Raises :class:`TaskError` (key gears.x1) when
    no grid point of the contour passes every check."""
    ev = _Evaluator(z1, z2, module, math.radians(alpha_deg), ha, c, sa_min_factor, eps_min)
    contour = _contour(ev, n, None, None)
    if not contour.feasible.any():
        raise TaskError("gears.x1", f"no profile shifts (x1, x2) satisfy every check for z1 = {z1}, "
                        f"z2 = {z2} (εα ≥ {eps_min}, sa ≥ {sa_min_factor}·m, no undercut, no "
                        f"interference)", "explicit x1 and x2, or a smaller eps_min / sa_min, "
                        "or more teeth")
    h = float(contour.x1[1] - contour.x1[0])
    best = None
    for line in contour.curves["equal_sliding"]:
        pts = _densify(np.asarray(line), h / 4.0)
        ok = ev.feasible(pts[:, 0], pts[:, 1])
        for k in np.nonzero(ok)[0]:
            cand = pts[k]
            # walk to the neighbour with the larger sum; refine if it leaves the contour
            for j in (k - 1, k + 1):
                if 0 <= j < len(pts) and not ok[j] and pts[j].sum() > cand.sum():
                    cand = _refine_on_line(ev, pts[k], pts[j])
            if best is None or cand.sum() > best.sum():
                best = np.array(cand)
    if best is not None:
        rule = RULE_EQUAL_SLIDING
    else:
        rule = RULE_LEAST_IMBALANCE
        X1, X2 = np.meshgrid(contour.x1, contour.x2, indexing="ij")
        gap = np.abs(ev.sliding_gap(ev.arrays(X1, X2)))
        gap = np.where(contour.feasible & np.isfinite(gap), gap, np.inf)
        if not np.isfinite(gap).any():
            gap = np.where(contour.feasible, 0.0, np.inf)
        order = np.lexsort((-(X1 + X2).ravel(), gap.ravel()))
        i, j = np.unravel_index(order[0], X1.shape)
        best = np.array([X1[i, j], X2[i, j]])
    x1e, x2e = float(best[0]), float(best[1])
    x1r, x2r = x1e, x2e
    if rounding:
        cands = [(round(x1e / rounding) * rounding + di * rounding,
                  round(x2e / rounding) * rounding + dj * rounding)
                 for di in (-1, 0, 1) for dj in (-1, 0, 1)]
        cands = [(round(a, 10), round(b, 10)) for a, b in cands]
        good = [p for p in cands if bool(ev.feasible(*p))]
        if good:
            x1r, x2r = min(good, key=lambda p: math.hypot(p[0] - x1e, p[1] - x2e))
    arr = ev.arrays(x1r, x2r)
    return ShiftChoice(x1=x1r, x2=x2r, x1_exact=x1e, x2_exact=x2e, rule=rule,
                       lambda1_a=float(lambda1(arr["n1a"], arr["g"], arr["u"])),
                       lambda2_b=float(lambda2(arr["n1b"], arr["g"], arr["u"])), contour=contour)
