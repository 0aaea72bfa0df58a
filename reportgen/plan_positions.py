"""Which positions get velocity and acceleration plans drawn in full (``[analysis] plan_positions``).

The course (seed 000, § 1.4: «Для положения на холостом ходе построение плана ускорений
аналогично») builds the plans of one position of the working stroke and one of the idle stroke; the
position of the force analysis is one of them (§ 2 carries its acceleration plan over from sheet 1).

Default rule (docs/task-format-notes.md): the position analysed in detail (``Project.analysed``)
first; then, when the output has extreme positions, the position of the *other* stroke whose crank
rotation from the start of that stroke is nearest its middle (a tie: the lower number). A position
on an extreme (the output at rest) belongs to neither stroke; when the analysed position is one,
the other plan is of the idle stroke.
"""
from __future__ import annotations

import math
from typing import Literal, Sequence

from .kinematics.extremes import Strokes
from .tolerances import RTOL_EQUAL

Stroke = Literal["working", "idle"]


def rotation_from_start(phi: float, strokes: Strokes, sign: float) -> float:
    """The crank's rotation from the start of the working stroke to ``phi``, rad in [0, 2π), in the
    direction of rotation (``sign`` = +1 counter-clockwise)."""
    return (sign * (phi - strokes.phi_start)) % (2 * math.pi)


def stroke_of(phi: float, strokes: Strokes | None, sign: float) -> Stroke | None:
    """``"working"`` or ``"idle"`` for a crank angle strictly inside that stroke; None on an extreme
    position (within ``RTOL_EQUAL`` of a turn) or when the output has no extreme positions."""
    if strokes is None:
        return None
    t = rotation_from_start(phi, strokes, sign)
    w = math.radians(strokes.working_deg)
    eps = 2 * math.pi * RTOL_EQUAL
    if eps < t < w - eps:
        return "working"
    if w + eps < t < 2 * math.pi - eps:
        return "idle"
    return None


def default_plan_positions(phi: Sequence[float], strokes: Strokes | None, sign: float,
                           analysed: int) -> tuple[int, ...]:
    """The default rule of the module docstring: ``(analysed, j)`` or ``(analysed,)``."""
    if strokes is None or len(phi) < 2:
        return (analysed,)
    own = stroke_of(float(phi[analysed]), strokes, sign)
    other: Stroke = "idle" if own in (None, "working") else "working"
    w = math.radians(strokes.working_deg)
    start, span = (0.0, w) if other == "working" else (w, 2 * math.pi - w)
    middle = start + span / 2
    best: tuple[float, int] | None = None
    for j, ph in enumerate(phi):
        if j == analysed or stroke_of(float(ph), strokes, sign) != other:
            continue
        d = abs(rotation_from_start(float(ph), strokes, sign) - middle)
        if best is None or d < best[0] - RTOL_EQUAL:
            best = (d, j)
    return (analysed,) if best is None else (analysed, best[1])
