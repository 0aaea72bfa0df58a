"""The involute function and its inverse.

inv α = tan α − α  (Артоболевский, «Теория механизмов и машин», § on the involute; ГОСТ 16532-70,
table 1). The inverse is solved by Newton's method on f(α) = tan α − α − v, f′(α) = tan²α. On
(0, π/2) f is increasing and convex, so Newton started to the right of the root decreases
monotonically onto it. Both starting guesses used here lie to the right of the root:
α0 = (3v)^(1/3), because tan α − α ≥ α³/3, and α0 = atan(v + π/2), because tan α = v + α < v + π/2
at the root. The smaller of the two is taken.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import ReportgenInputError
from ..tolerances import INV_INVERSE_TOL

#: Below this angle (rad) inv is evaluated by its Taylor series, which avoids the cancellation in
#: tan α − α: inv α = α³/3 + 2α⁵/15 + 17α⁷/315 + 62α⁹/2835 + …
_SERIES_LIMIT = 0.02

#: Largest involute value the inverse accepts (α ≈ 89.4°); beyond it no gear geometry exists.
INV_MAX = 100.0


class InvoluteDomainError(ReportgenInputError):
    """The inverse involute was asked for a value outside (0, INV_MAX]."""

    def __init__(self, value: float) -> None:
        self.value = value
        super().__init__(f"inverse involute of {value!r}: the involute function takes only values "
                         f"in (0, {INV_MAX}] on the useful range 0 < α < 89.4°")


def inv(alpha):
    """inv α = tan α − α (rad). Accepts a float or an array; series below 0.02 rad."""
    a = np.asarray(alpha, dtype=float)
    a2 = a * a
    series = a * a2 * (1.0 / 3.0 + a2 * (2.0 / 15.0 + a2 * (17.0 / 315.0 + a2 * 62.0 / 2835.0)))
    with np.errstate(invalid="ignore"):
        direct = np.tan(a) - a
    out = np.where(np.abs(a) < _SERIES_LIMIT, series, direct)
    return float(out) if out.ndim == 0 else out


def inv_inverse(value, *, tol: float = INV_INVERSE_TOL, max_iter: int = 60):
    """α with inv α = value (rad), by monotone Newton iteration (module docstring).

    Accurate to about 1e-15 rad relative for 1e-9 ≤ value ≤ 100; accepts a float or an array.
    Raises :class:`InvoluteDomainError` for a value ≤ 0 or > INV_MAX (or NaN).
    """
    v = np.asarray(value, dtype=float)
    if not np.all((v > 0.0) & (v <= INV_MAX)):
        bad = v[~((v > 0.0) & (v <= INV_MAX))].ravel()
        raise InvoluteDomainError(float(bad[0]))
    alpha = np.minimum(np.cbrt(3.0 * v), np.arctan(v + math.pi / 2.0))
    for _ in range(max_iter):
        t = np.tan(alpha)
        step = (inv(alpha) - v) / (t * t)
        alpha = alpha - step
        if np.all(np.abs(step) <= tol * alpha):
            break
    return float(alpha) if alpha.ndim == 0 else alpha
