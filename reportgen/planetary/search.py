"""Tooth-number search: every coaxial, undercut-free set whose ratio is within the tolerance,
filtered by adjacency and the exact assembly condition, ranked by overall size.

Method. For two-row schemes, with D = 2a/m = z1 ± z2 fixed by (z1, z2), Willis' product
P = z2·z3/(z1·z2′) = (z2/z1)·(D/z2′ ± 1) is monotonic in z2′, so the ratio band maps to an interval
of z2′ solved in closed form on the whole (z1, z2) grid at once (numpy); every integer z2′ in it is
then checked exactly in integers. Sets are searched with every tooth number ≤ B for B = 128, 256, …
up to ``max_teeth``; only sets whose envelope is ≤ B are kept, so a pass sees every set of that
size and the ranking is exact (the envelope is ≥ every tooth number).

Ranking ("compact"): the envelope diameter max(z1, z3, 2a/m + max(z2, z2′)) (in modules: the
largest pitch diameter measured across the central axis), then the smaller |ratio deviation|,
then the larger K, then the tooth numbers in order.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from numbers import Real
from typing import Literal, cast

import numpy as np

from ..errors import PlanetarySynthesisError, TaskError
from .conditions import (DEFAULT_LIMITS, AdjacencyCheck, AssemblyCheck, CoaxialCheck, UndercutCheck, UndercutLimits,
                         check_adjacency, check_assembly, check_coaxial, check_undercut)
from .schemes import (DRIVERS, Driver, Scheme, envelope, expand, get_scheme, reducer_ratio,
                      willis_u13h, willis_u1h)
from ..tolerances import RTOL_EQUAL

AUTO_K_MAX = 6          # K = the largest that fits, up to 6, unless given
K_GIVEN_MAX = 12
FIRST_BOUND = 128
MAX_TEETH = 1000
NEAREST_BOUND = 120
EDGE = RTOL_EQUAL             # a ratio on the edge of the band (|deviation| = tolerance) is accepted


@dataclass(frozen=True)
class Candidate:
    """A set that meets every condition: ``ratio`` is the reducer ratio (signed), ``deviation``
    (|ratio| − |target|)/|target|, ``size`` the envelope diameter in modules."""
    z: tuple[int, ...]
    satellites: int
    ratio: float
    deviation: float
    size: int


@dataclass(frozen=True)
class RatioCheck:
    """u13^H, u1H = 1 − u13^H and the reducer ratio (u1H, or 1/u1H when the carrier drives),
    against the target: deviation = (|u| − |u_target|)/|u_target| within ±tolerance."""
    driver: str
    u13h: Fraction
    u1h: Fraction
    ratio: Fraction
    target: float | None
    tolerance: float
    deviation: float | None
    holds: bool


@dataclass(frozen=True)
class PlanetaryDesign:
    """A tooth set with every condition evaluated; ``alternatives`` are the next candidates of the
    search (empty when the set was given)."""
    scheme: Scheme
    driver: str
    z: tuple[int, ...]
    satellites: int
    satellites_auto: bool
    module: float | None
    limits: UndercutLimits
    ratio_check: RatioCheck
    coaxial: CoaxialCheck
    undercut: UndercutCheck
    adjacency: AdjacencyCheck
    assembly: AssemblyCheck
    size: int
    alternatives: tuple[Candidate, ...] = ()

    @property
    def ratio(self) -> float:
        return float(self.ratio_check.ratio)

    @property
    def valid(self) -> bool:
        return (self.coaxial.holds and self.undercut.holds and self.adjacency.holds
                and self.assembly.holds and self.ratio_check.holds)

    @property
    def reverses(self) -> bool:
        """True when the output turns against the input (negative ratio)."""
        return self.ratio_check.ratio < 0

    @property
    def diameters_mm(self) -> tuple[tuple[str, float], ...]:
        """Pitch diameters d = m·z per wheel label (empty without a module)."""
        if self.module is None:
            return ()
        return tuple((lab, self.module * zz) for lab, zz in zip(self.scheme.labels, self.z))

    @property
    def centre_distance_mm(self) -> float | None:
        """a = m·(z1 ± z2)/2."""
        return None if self.module is None else self.module * self.coaxial.left / 2


# ---------------------------------------------------------------------------------------------
# validation of the request

def _check_target(ratio: object) -> float:
    if isinstance(ratio, bool) or not isinstance(ratio, Real) or not math.isfinite(float(ratio)):
        raise TaskError("planetary.ratio", f"{ratio!r} is not a number", "a finite number or \"auto\"")
    value = float(ratio)
    if value == 0 or abs(value) > 1e4:
        raise TaskError("planetary.ratio", f"{value:g}", "0 < |ratio| ≤ 10000")
    return value


def _check_tolerance(tolerance: object) -> float:
    if isinstance(tolerance, bool) or not isinstance(tolerance, Real) or not 0 < float(tolerance) < 1:
        raise TaskError("planetary.tolerance", f"{tolerance!r}", "a relative error 0 < tolerance < 1, e.g. 0.05")
    return float(tolerance)


def _check_satellites(satellites: object) -> int | None:
    if satellites == "auto":
        return None
    if isinstance(satellites, bool) or not isinstance(satellites, int) or not 1 <= satellites <= K_GIVEN_MAX:
        raise TaskError("planetary.satellites", f"{satellites!r}", f"\"auto\" or an integer 1…{K_GIVEN_MAX}")
    return satellites


def _check_module(module: object) -> float | None:
    if module is None:
        return None
    if isinstance(module, bool) or not isinstance(module, Real) or not 0 < float(module) < 1000:
        raise TaskError("planetary.module", f"{module!r}", "a module in mm, 0 < m < 1000")
    return float(module)


def _check_driver(driver: object) -> Driver:
    if driver not in DRIVERS:
        raise TaskError("planetary.driver", f"{driver!r}", "wheel (wheel 1 drives, u1H) or carrier (uH1)")
    return cast(Driver, str(driver))


# ---------------------------------------------------------------------------------------------
# evaluation of one set

def _deviation(ratio: Fraction, target: float) -> float:
    return (abs(float(ratio)) - abs(target)) / abs(target)


def _sign_ok(ratio: float, target: float) -> bool:
    """A positive target is a magnitude (either sense of rotation); a negative one must be met."""
    return target > 0 or ratio < 0


def evaluate(scheme: str | Scheme, z: tuple[int, ...], satellites: int | Literal["auto"] = "auto", *,
             target: float | None = None, tolerance: float = 0.05, driver: Driver = "wheel",
             module: float | None = None, limits: UndercutLimits = DEFAULT_LIMITS, ha: float = 1.0,
             alternatives: tuple[Candidate, ...] = ()) -> PlanetaryDesign:
    """Every condition of the tooth set ``z`` with K ``satellites`` ("auto": the largest K ≤ 6 that
    meets adjacency and assembly; if none, the largest that meets adjacency)."""
    sch = scheme if isinstance(scheme, Scheme) else get_scheme(scheme)
    z = tuple(z)
    expand(sch, z)
    k_given = _check_satellites(satellites)
    driver = _check_driver(driver)
    tolerance = _check_tolerance(tolerance)
    module = _check_module(module)
    if target is not None:
        target = _check_target(target)
    if k_given is None:
        ks = range(AUTO_K_MAX, 1, -1)
        fits = [k for k in ks if check_adjacency(sch, z, k, ha).holds and check_assembly(sch, z, k).holds]
        adj = [k for k in ks if check_adjacency(sch, z, k, ha).holds]
        k = fits[0] if fits else (adj[0] if adj else 2)
    else:
        k = k_given
    coax = check_coaxial(sch, z)
    u_ratio = reducer_ratio(sch, z, driver) if willis_u1h(sch, z) != 0 or driver == "wheel" else Fraction(0)
    if target is None:
        dev, ok = None, True
    else:
        dev = _deviation(u_ratio, target)
        ok = abs(dev) <= tolerance * (1 + EDGE) and _sign_ok(float(u_ratio), target)
    rc = RatioCheck(driver, willis_u13h(sch, z), willis_u1h(sch, z), u_ratio, target, tolerance, dev, ok)
    return PlanetaryDesign(sch, driver, z, k, k_given is None, module, limits, rc, coax,
                           check_undercut(sch, z, limits), check_adjacency(sch, z, k, ha),
                           check_assembly(sch, z, k), envelope(sch, z), tuple(alternatives))


# ---------------------------------------------------------------------------------------------
# vectorised enumeration

@dataclass(frozen=True)
class _Sets:
    z1: np.ndarray
    z2: np.ndarray
    z2p: np.ndarray
    z3: np.ndarray
    ratio: np.ndarray


def _u_bands(target: float, lo_mag: float, hi_mag: float) -> list[tuple[float, float]]:
    """Signed intervals of the reducer ratio whose magnitude is in [lo_mag, hi_mag]."""
    lo_mag, hi_mag = lo_mag * (1 - EDGE), hi_mag * (1 + EDGE)
    bands = [(-hi_mag, -lo_mag)]
    if target > 0:
        bands.append((lo_mag, hi_mag))
    return bands


def _p_bands(sch: Scheme, driver: str, u_bands: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Intervals of P = z2·z3/(z1·z2′) > 0 that give the ratio bands (u1H = 1 − σ·P)."""
    out = []
    for a, b in u_bands:
        if driver == "carrier":
            a, b = 1 / b, 1 / a
        p1, p2 = (1 - a) / sch.sigma, (1 - b) / sch.sigma
        lo, hi = min(p1, p2), max(p1, p2)
        if hi > 0:
            out.append((max(lo, 0.0) * (1 - EDGE), hi * (1 + EDGE)))
    return out


def _ratio_of(sch: Scheme, driver: str, z1, z2, z2p, z3) -> tuple[np.ndarray, np.ndarray]:
    """Exact u1H as integers num/den, then the reducer ratio as floats (and a mask of num ≠ 0)."""
    num = z1 * z2p - sch.sigma * z2 * z3
    den = z1 * z2p
    ok = num != 0
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.where(ok, num / np.where(ok, den, 1), 0.0) if driver == "wheel" else \
            np.where(ok, den / np.where(ok, num, 1), np.inf)
    return r, ok


def _enumerate(sch: Scheme, driver: str, bound: int, u_bands: list[tuple[float, float]],
               limits: UndercutLimits) -> _Sets:
    """All coaxial, undercut-free sets with every z ≤ bound and the reducer ratio in ``u_bands``."""
    ext, inn, dif = limits.external_min, limits.internal_min, limits.internal_difference_min
    empty = np.zeros(0, dtype=np.int64)
    lo1 = inn if sch.row1 == "internal" else ext
    if bound < max(lo1, ext):
        return _Sets(empty, empty, empty, empty, np.zeros(0))
    g1, g2 = np.meshgrid(np.arange(lo1, bound + 1, dtype=np.int64),
                         np.arange(ext, bound + 1, dtype=np.int64), indexing="ij")
    z1g, z2g = g1.ravel(), g2.ravel()
    if not sch.two_row:
        z3g = z1g + 2 * z2g
        keep = (z3g <= bound) & (z3g >= inn) & (z3g - z2g >= dif)
        z1, z2, z3 = z1g[keep], z2g[keep], z3g[keep]
        z2p = z2
    else:
        d = z1g + z2g if sch.row1 == "external" else z1g - z2g
        base = d >= dif if sch.row1 == "internal" else d > 0
        s2 = -1 if sch.row2 == "external" else 1
        parts = []
        for plo, phi in _p_bands(sch, driver, u_bands):
            with np.errstate(divide="ignore", invalid="ignore"):
                qlo = plo * z1g / z2g - s2
                qhi = phi * z1g / z2g - s2
                zlo = np.where(qhi > 0, d / np.where(qhi > 0, qhi, 1), np.inf)
                zhi = np.where(qlo > 0, d / np.where(qlo > 0, qlo, 1), np.inf)
            lo = np.floor(np.minimum(zlo, 1e9)).astype(np.int64) - 1
            hi = np.ceil(np.minimum(zhi, 1e9)).astype(np.int64) + 1
            lo = np.maximum(lo, ext)
            hi = np.minimum(hi, bound)
            if sch.row2 == "external":      # z3 = d − z2′ in [ext, bound]
                hi = np.minimum(hi, d - ext)
                lo = np.maximum(lo, d - bound)
            else:                           # z3 = d + z2′ in [inn, bound], d ≥ dif
                hi = np.minimum(hi, bound - d)
                lo = np.maximum(lo, inn - d)
                base = base & (d >= dif)
            cnt = np.where(base & (hi >= lo), hi - lo + 1, 0)
            total = int(cnt.sum())
            if total == 0:
                continue
            idx = np.repeat(np.arange(cnt.size), cnt)
            offs = np.arange(total) - np.repeat(np.cumsum(cnt) - cnt, cnt)
            parts.append((z1g[idx], z2g[idx], lo[idx] + offs, d[idx]))
        if not parts:
            return _Sets(empty, empty, empty, empty, np.zeros(0))
        # the widened z2′ intervals of two bands may overlap: keep each set once
        stacked = np.unique(np.stack([np.concatenate([p[i] for p in parts]) for i in range(4)], axis=1), axis=0)
        z1, z2, z2p, dd = stacked[:, 0], stacked[:, 1], stacked[:, 2], stacked[:, 3]
        z3 = dd - z2p if sch.row2 == "external" else dd + z2p
    r, nz = _ratio_of(sch, driver, z1, z2, z2p, z3)
    inside = np.zeros(r.shape, dtype=bool)
    for a, b in u_bands:
        inside |= (r >= a) & (r <= b)
    inside &= nz
    return _Sets(z1[inside], z2[inside], z2p[inside], z3[inside], r[inside])


def _adjacent_vec(centre_sum: np.ndarray, planet_z: np.ndarray, k: int, ha: float) -> np.ndarray:
    """Vector form of conditions.adjacent (exact squares for K = 2, 3, 4, 6)."""
    if k == 1:
        return np.ones(centre_sum.shape, dtype=bool)
    right2 = planet_z + 2 * ha
    exact = {2: (1, 1), 3: (3, 4), 4: (1, 2), 6: (1, 4)}
    if k in exact and float(2 * ha).is_integer():
        n, dnm = exact[k]
        rr = (planet_z + int(2 * ha)).astype(np.int64)
        return (centre_sum > 0) & (centre_sum * centre_sum * n > rr * rr * dnm)
    return centre_sum * math.sin(math.pi / k) > right2


def _choose_k(sch: Scheme, s: _Sets, k_given: int | None, ha: float) -> tuple[np.ndarray, dict[str, int]]:
    """K per set (0 = none fits) and counts of rejections for the error message."""
    centre = s.z1 + s.z2 if sch.row1 == "external" else s.z1 - s.z2
    planet = np.maximum(s.z2, s.z2p)
    if sch.two_row:
        g = np.gcd(s.z2, s.z2p)
        num = s.z1 * s.z2p + s.z3 * s.z2 if sch.row1 != sch.row2 else np.abs(s.z1 * s.z2p - s.z3 * s.z2)
    else:
        g = np.ones_like(s.z1)
        num = s.z1 + s.z3
    ks = [k_given] if k_given is not None else list(range(AUTO_K_MAX, 1, -1))
    chosen = np.zeros(s.z1.shape, dtype=np.int64)
    any_adj = np.zeros(s.z1.shape, dtype=bool)
    for k in ks:
        adj = _adjacent_vec(centre, planet, k, ha)
        any_adj |= adj
        ok = adj & (num % (k * g) == 0) & (chosen == 0)
        chosen[ok] = k
    stats = {"in_band": int(s.z1.size), "adjacent": int(any_adj.sum()), "valid": int((chosen > 0).sum())}
    return chosen, stats


def _ranked(sch: Scheme, s: _Sets, k: np.ndarray, target: float, bound: int) -> list[Candidate]:
    keep = k > 0
    z1, z2, z2p, z3, r, kk = s.z1[keep], s.z2[keep], s.z2p[keep], s.z3[keep], s.ratio[keep], k[keep]
    centre = z1 + z2 if sch.row1 == "external" else z1 - z2
    env = np.maximum(np.maximum(z1, z3), centre + np.maximum(z2, z2p))
    small = env <= bound
    z1, z2, z2p, z3, r, kk, env = (a[small] for a in (z1, z2, z2p, z3, r, kk, env))
    dev = (np.abs(r) - abs(target)) / abs(target)
    order = np.lexsort((z3, z2p, z2, z1, -kk, np.abs(dev), env))
    out = []
    for i in order:
        z = (int(z1[i]), int(z2[i]), int(z2p[i]), int(z3[i])) if sch.two_row else \
            (int(z1[i]), int(z2[i]), int(z3[i]))
        out.append(Candidate(z, int(kk[i]), float(r[i]), float(dev[i]), int(env[i])))
    return out


def _search(sch: Scheme, target: float, tolerance: float, k_given: int | None, driver: str,
            limits: UndercutLimits, ha: float, count: int, max_teeth: int) -> tuple[list[Candidate], dict[str, int]]:
    """Growing bounds until ``count`` sets are found or ``max_teeth``; the last pass's statistics."""
    bands = _u_bands(target, abs(target) * (1 - tolerance), abs(target) * (1 + tolerance))
    bound = min(FIRST_BOUND, max_teeth)
    while True:
        sets = _enumerate(sch, driver, bound, bands, limits)
        k, stats = _choose_k(sch, sets, k_given, ha)
        found = _ranked(sch, sets, k, target, bound)
        if len(found) >= count or bound >= max_teeth:
            return found[:count], stats
        bound = min(2 * bound, max_teeth)


def search(scheme: str | Scheme, ratio: float, tolerance: float = 0.05,
           satellites: int | Literal["auto"] = "auto", *, driver: Driver = "wheel",
           limits: UndercutLimits = DEFAULT_LIMITS, ha: float = 1.0, count: int = 6,
           max_teeth: int = MAX_TEETH) -> tuple[Candidate, ...]:
    """The ``count`` most compact sets that meet every condition (fewer if fewer exist with an
    envelope ≤ ``max_teeth``); an empty tuple when none exists."""
    sch = scheme if isinstance(scheme, Scheme) else get_scheme(scheme)
    found, _ = _search(sch, _check_target(ratio), _check_tolerance(tolerance), _check_satellites(satellites),
                       _check_driver(driver), limits, ha, count, max_teeth)
    return tuple(found)


def nearest(scheme: str | Scheme, ratio: float, tolerance: float,
            satellites: int | Literal["auto"] = "auto", *, driver: Driver = "wheel",
            limits: UndercutLimits = DEFAULT_LIMITS, ha: float = 1.0,
            bound: int = NEAREST_BOUND) -> tuple[Candidate, ...]:
    """The valid sets (teeth ≤ ``bound``) with the nearest ratio below and above the band."""
    sch = scheme if isinstance(scheme, Scheme) else get_scheme(scheme)
    k_given = _check_satellites(satellites)
    m = abs(ratio)
    lo_edge, hi_edge = m * (1 - tolerance), m * (1 + tolerance)
    out: list[Candidate] = []
    for side in ("below", "above"):
        for g in (1.1, 1.3, 2.0, 5.0, 50.0, 1e4):
            band = (lo_edge / g, lo_edge) if side == "below" else (hi_edge, hi_edge * g)
            sets = _enumerate(sch, driver, bound, _u_bands(ratio, *band), limits)
            k, _ = _choose_k(sch, sets, k_given, ha)
            found = _ranked(sch, sets, k, ratio, 10 ** 9)
            if found:
                out.append(min(found, key=lambda c: (abs(abs(c.ratio) - m), c.size)))
                break
    return tuple(out)


def _why(st: dict[str, int], k_given: int | None, driver: str, limits: UndercutLimits,
         max_teeth: int) -> tuple[str, ...]:
    ks = f"K = {k_given}" if k_given is not None else f"any K = 2…{AUTO_K_MAX}"
    lim = (f"z ≥ {limits.external_min} external, z ≥ {limits.internal_min} internal, "
           f"z_internal − z_planet ≥ {limits.internal_difference_min}")
    if st["in_band"] == 0:
        return (f"no coaxial set free of undercut ({lim}) with every z ≤ {max_teeth} gives that ratio "
                f"with the {'carrier' if driver == 'carrier' else 'wheel 1'} driving",)
    reasons = [f"{st['in_band']} coaxial sets free of undercut give that ratio"]
    if st["in_band"] > st["adjacent"]:
        reasons.append(f"{st['in_band'] - st['adjacent']} of them fail adjacency for {ks}")
    if st["adjacent"]:
        reasons.append(f"{st['adjacent']} that fit fail the assembly condition for every K that fits")
    return tuple(reasons)


def synthesize(scheme: str, ratio: float, tolerance: float = 0.05,
               satellites: int | Literal["auto"] = "auto", module: float | None = None, *,
               driver: Driver = "wheel", limits: UndercutLimits = DEFAULT_LIMITS, ha: float = 1.0,
               alternatives: int = 5, max_teeth: int = MAX_TEETH) -> PlanetaryDesign:
    """The most compact tooth set for the target ratio, with every condition recorded and the next
    ``alternatives`` candidates; ``PlanetarySynthesisError`` (reasons, nearest ratios) if none."""
    sch = get_scheme(scheme)
    target = _check_target(ratio)
    tolerance = _check_tolerance(tolerance)
    k_given = _check_satellites(satellites)
    driver = _check_driver(driver)
    _check_module(module)
    if not isinstance(alternatives, int) or alternatives < 0:
        raise TaskError("planetary.alternatives", f"{alternatives!r}", "an integer ≥ 0")
    found, stats = _search(sch, target, tolerance, k_given, driver, limits, ha, alternatives + 1, max_teeth)
    if not found:
        near = nearest(sch, target, tolerance, satellites, driver=driver, limits=limits, ha=ha,
                       bound=min(NEAREST_BOUND, max_teeth))
        raise PlanetarySynthesisError(
            sch.name, target, tolerance, "auto" if k_given is None else k_given,
            _why(stats, k_given, driver, limits, max_teeth),
            tuple((c.ratio, c.z, c.satellites) for c in near))
    best = found[0]
    return evaluate(sch, best.z, best.satellites, target=target, tolerance=tolerance, driver=driver,
                    module=module, limits=limits, ha=ha, alternatives=tuple(found[1:]))
