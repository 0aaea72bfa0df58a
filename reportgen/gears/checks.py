"""Quality checks of the pair. A failed check is a finding for the student, not an error.

Each check is written as a margin that is ≥ 0 when the check holds, evaluated on the arrays of
:func:`reportgen.gears.geometry.pair_arrays`, so that one function serves a single pair and the
blocking contour alike.

- Undercut (подрезание), Кудрявцев; ГОСТ 16532-70 appendix: x ≥ x_min = ha* − z sin²α / 2
  (the end of the straight part of the rack flank must not pass beyond N, i.e. ρl ≥ 0).
- Sharpening (заострение): sa ≥ k m, k = 0.25 by default (the seed uses 0.2; Болотовский
  recommends 0.25…0.3 for hardened teeth).
- Contact ratio: εα ≥ εmin, 1.2 by default (Болотовский, «Справочник…», § blocking contours).
- Interference with the fillet of the mating gear (интерференция с переходной кривой): the lower
  point p of the active profile must lie on the involute, above its boundary point l:
  ρp1 = N1a ≥ ρl1 and ρp2 = N2b ≥ ρl2, ρl = r sin α − (ha* − x) m / sin α (Болотовский).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..tolerances import RTOL_EQUAL

SA_MIN_FACTOR = 0.25
EPS_MIN = 1.2

#: Names of the checks, in report order.
CHECK_NAMES = ("undercut1", "undercut2", "sharpening1", "sharpening2", "contact_ratio",
               "interference1", "interference2")


@dataclass(frozen=True)
class Check:
    """One check: ``value`` compared with ``limit`` by ``relation`` ('≥'); ``margin`` = value − limit
    (in ``unit``); ``passed`` = margin ≥ 0 up to a relative 1e-9."""
    name: str
    title: str
    symbol: str
    value: float
    limit: float
    unit: str
    passed: bool
    relation: str = "≥"

    @property
    def margin(self) -> float:
        return self.value - self.limit

    def as_dict(self) -> dict:
        return {"name": self.name, "title": self.title, "symbol": self.symbol, "value": self.value,
                "limit": self.limit, "relation": self.relation, "unit": self.unit,
                "passed": self.passed}


def x_min(z, alpha: float, ha: float):
    """Least shift without undercut, x_min = ha* − z sin²α / 2."""
    return ha - np.asarray(z, dtype=float) * np.sin(alpha) ** 2 / 2.0


def margins(arr: dict[str, np.ndarray], z1: int, z2: int, m: float, alpha: float, ha: float,
            sa_min_factor: float = SA_MIN_FACTOR, eps_min: float = EPS_MIN
            ) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each check as (value, limit) arrays, keyed by :data:`CHECK_NAMES`."""
    ones = np.ones_like(arr["x1"])
    return {
        "undercut1": (arr["x1"], x_min(z1, alpha, ha) * ones),
        "undercut2": (arr["x2"], x_min(z2, alpha, ha) * ones),
        "sharpening1": (arr["sa1"], sa_min_factor * m * ones),
        "sharpening2": (arr["sa2"], sa_min_factor * m * ones),
        "contact_ratio": (arr["eps_alpha"], eps_min * ones),
        "interference1": (arr["rho_p1"], arr["rho_l1"]),
        "interference2": (arr["rho_p2"], arr["rho_l2"]),
    }


_TITLES = {
    "undercut1": ("no undercut of gear 1", "x1", ""),
    "undercut2": ("no undercut of gear 2", "x2", ""),
    "sharpening1": ("tip thickness of gear 1", "sa1", "mm"),
    "sharpening2": ("tip thickness of gear 2", "sa2", "mm"),
    "contact_ratio": ("transverse contact ratio", "εα", ""),
    "interference1": ("no interference of the tip of gear 2 with the fillet of gear 1", "ρp1", "mm"),
    "interference2": ("no interference of the tip of gear 1 with the fillet of gear 2", "ρp2", "mm"),
}


def passes(value, limit):
    """value ≥ limit up to a relative 1e-9 of the larger magnitude (NaN fails)."""
    value = np.asarray(value, dtype=float)
    limit = np.asarray(limit, dtype=float)
    tol = RTOL_EQUAL * np.maximum(1.0, np.maximum(np.abs(value), np.abs(limit)))
    return value >= limit - tol


def pair_checks(arr: dict[str, np.ndarray], z1: int, z2: int, m: float, alpha: float, ha: float,
                sa_min_factor: float = SA_MIN_FACTOR, eps_min: float = EPS_MIN) -> tuple[Check, ...]:
    """The checks of one pair (arrays of shape ()) as :class:`Check` records."""
    out = []
    for name, (value, limit) in margins(arr, z1, z2, m, alpha, ha, sa_min_factor, eps_min).items():
        title, symbol, unit = _TITLES[name]
        out.append(Check(name=name, title=title, symbol=symbol, value=float(value),
                         limit=float(limit), unit=unit, passed=bool(passes(value, limit))))
    return tuple(out)
