"""The public entry point: a solved gear pair (geometry + checks + specific sliding [+ the shift
choice when x is "auto"]). The note, the sheet and ``reportgen gear`` all start here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from ..errors import NameLookupError, TaskError
from .checks import EPS_MIN, SA_MIN_FACTOR, Check, pair_checks
from .geometry import ALPHA_DEG, C, HA, GearGeometry, pair_arrays, pair_geometry
from .shifts import ShiftChoice, choose_shifts
from .sliding import DEFAULT_STEPS, SlidingTable, sliding_table

Shift = float | Literal["auto"]


@dataclass(frozen=True)
class GearPair:
    """A solved pair. Attributes of :class:`GearGeometry` are also readable directly
    (``pair.aw`` is ``pair.geometry.aw``)."""
    geometry: GearGeometry
    checks: tuple[Check, ...]
    sliding: SlidingTable
    sa_min_factor: float
    eps_min: float
    shift_choice: ShiftChoice | None = None   # set when x1, x2 were "auto"

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.geometry, name)

    @property
    def all_passed(self) -> bool:
        return all(c.passed for c in self.checks)

    def check(self, name: str) -> Check:
        for c in self.checks:
            if c.name == name:
                return c
        raise NameLookupError("gear check", name, tuple(c.name for c in self.checks))


def _is_auto(x) -> bool:
    return isinstance(x, str) and x.strip().lower() == "auto"


def solve_gear_pair(z1: int, z2: int, module: float, x1: Shift = 0.0, x2: Shift = 0.0,
                    alpha_deg: float = ALPHA_DEG, ha: float = HA, c: float = C,
                    sa_min_factor: float = SA_MIN_FACTOR, eps_min: float = EPS_MIN,
                    sliding_steps: int = DEFAULT_STEPS, rounding: float | None = 0.01) -> GearPair:
    """Solve the pair. ``x1``/``x2`` are numbers, or both ``"auto"`` (chosen on the blocking
    contour, :mod:`reportgen.gears.shifts`; rounded to ``rounding``). Bad input raises
    :class:`reportgen.errors.TaskError` with the key ``gears.<name>``; failed checks do not raise."""
    if not (sa_min_factor >= 0 and math.isfinite(sa_min_factor)):
        raise TaskError("gears.sa_min", f"value {sa_min_factor!r} is out of range", "a number ≥ 0")
    if not (eps_min > 0 and math.isfinite(eps_min)):
        raise TaskError("gears.eps_min", f"value {eps_min!r} is out of range", "a number > 0")
    choice = None
    if _is_auto(x1) or _is_auto(x2):
        if not (_is_auto(x1) and _is_auto(x2)):
            key = "gears.x2" if _is_auto(x1) else "gears.x1"
            raise TaskError(key, "only one shift is \"auto\"", "both x1 and x2 \"auto\", or both numbers")
        geometry_probe = pair_geometry(z1, z2, module, 0.0, 0.0, alpha_deg, ha, c)  # validates input
        del geometry_probe
        choice = choose_shifts(z1, z2, module, alpha_deg, ha, c, sa_min_factor, eps_min, rounding)
        x1, x2 = choice.x1, choice.x2
    for key, x in (("gears.x1", x1), ("gears.x2", x2)):
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            raise TaskError(key, f"value {x!r} is not a number", "a number or \"auto\"")
    geo = pair_geometry(z1, z2, module, float(x1), float(x2), alpha_deg, ha, c)
    arr = pair_arrays(geo.z1, geo.z2, geo.m, geo.x1, geo.x2, geo.alpha, geo.ha, geo.c)
    checks = pair_checks(arr, geo.z1, geo.z2, geo.m, geo.alpha, geo.ha, sa_min_factor, eps_min)
    sliding = sliding_table(geo.g, geo.u, geo.n1a, geo.n1p, geo.n1b, sliding_steps)
    return GearPair(geometry=geo, checks=checks, sliding=sliding, sa_min_factor=float(sa_min_factor),
                    eps_min=float(eps_min), shift_choice=choice)


def from_task(gears, **options) -> GearPair:
    """Solve the ``[gears]`` section of a task (:class:`reportgen.task.Gears`) with its limits
    (``eps_min``, ``sa_min``); ``options`` go to :func:`solve_gear_pair` (sliding_steps, rounding, or
    limits that override the task's)."""
    eps_min = float(options.pop("eps_min", getattr(gears, "eps_min", EPS_MIN)))
    sa_min = float(options.pop("sa_min_factor", getattr(gears, "sa_min", SA_MIN_FACTOR)))
    return solve_gear_pair(gears.z1, gears.z2, gears.module, gears.x1, gears.x2,
                           alpha_deg=gears.alpha_deg, ha=gears.ha, c=gears.c, sa_min_factor=sa_min,
                           eps_min=eps_min, **options)


def passing_alternative(pair: GearPair, rounding: float | None = 0.01) -> GearPair | None:
    """When a pair with *given* shifts fails a check: the pair with the shifts chosen on the blocking
    contour under the same limits (:func:`reportgen.gears.shifts.choose_shifts`), which passes every
    check; None when the given pair passes, the shifts were chosen already, or no point of the
    contour passes (then the teeth numbers or the limits must change)."""
    if pair.all_passed or pair.shift_choice is not None:
        return None
    g = pair.geometry
    try:
        alt = solve_gear_pair(g.z1, g.z2, g.m, "auto", "auto", alpha_deg=g.alpha_deg, ha=g.ha, c=g.c,
                              sa_min_factor=pair.sa_min_factor, eps_min=pair.eps_min, rounding=rounding)
    except TaskError:
        return None
    return alt if alt.all_passed else None
