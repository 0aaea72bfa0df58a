"""The output link, its extreme positions (dead centres), the working and idle strokes.

The output is the last attached link that has a pair with the frame: a slider (its displacement
along the guide) or a rocker (its angle). Its extreme positions are the roots of its velocity
v(φ) = 0, bracketed on a grid of ``GRID`` crank angles and refined by Brent's method to
``ROOT_XTOL`` rad. The working stroke is the stroke that takes the larger crank angle (the slow
stroke of a quick-return mechanism, as in the course's presses and shapers) unless the task asks
for the other one; position 0 (``start = "extreme"``) is the start of the working stroke.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ReportgenError
from ..roots import brent_root, brent_roots
from .constraints import rot, world
from .solve import KinematicModel
from ..tolerances import CONSTRUCTION_TOL, ROOT_XTOL, RTOL_EQUAL, TINY

GRID = 720


class NoExtremesError(ReportgenError, ValueError):
    """The output link turns fully: it has no extreme positions."""


@dataclass(frozen=True)
class Output:
    """The output link: ``kind`` "slider" (coordinate in m) or "rocker" (angle in rad)."""
    link: int
    kind: str
    point: str | None          # the slider's point on the guide
    slide: int = -1


@dataclass(frozen=True)
class Strokes:
    output: Output
    phi_start: float           # crank angle at the start of the working stroke, rad
    phi_end: float             # at its end, rad
    working_deg: float         # crank angle of the working stroke
    idle_deg: float
    stroke: float              # travel of the output between its extremes (m or rad)
    direction: float           # +1 if the output coordinate grows along the working stroke
    time_ratio: float          # K = working / idle (coefficient of the average speed change)


def find_output(model: KinematicModel) -> Output:
    lk = model.linkage
    for g in reversed(model.structure.groups[1:]):
        for k in reversed(g.links):
            for s in lk.slides:
                if s.link == k and s.guide == 0:
                    return Output(k, "slider", s.point, s.index)
        for k in reversed(g.links):
            for j in lk.joints:
                if 0 in j.bodies and k in j.bodies:
                    return Output(k, "rocker", j.name)
    d = lk.drive_link
    return Output(d, "rocker", lk.drive_axis)


def output_coordinate(model: KinematicModel, out: Output, q: np.ndarray, qd: np.ndarray | None = None):
    """The output's coordinate (m along the guide, or rad) and, with ``qd``, its velocity."""
    lk = model.linkage
    if out.kind == "slider":
        s = lk.slides[out.slide]
        u = np.asarray(s.line_dir)
        p = world(q, out.link, s.point_local)
        x = p @ u
        if qd is None:
            return x
        Rp = rot(q[:, out.link, 2], s.point_local)
        v = qd[:, out.link, :2] + qd[:, out.link, 2][:, None] * np.stack((-Rp[:, 1], Rp[:, 0]), -1)
        return x, v @ u
    # the rocker's angle measured from its sketch angle, in (−π, π]: continuous over its swing
    ref = model.linkage.bodies[out.link].sketch_pose[2]
    x = np.remainder(q[:, out.link, 2] - ref + math.pi, 2 * math.pi) - math.pi
    return x if qd is None else (x, qd[:, out.link, 2])


def _velocities_at(model: KinematicModel, out: Output, phi: np.ndarray) -> np.ndarray:
    """The output's velocity at the crank angles ``phi`` (one solve)."""
    q, _ = model.positions(np.asarray(phi, dtype=float))
    qd = model.velocities(q)
    return output_coordinate(model, out, q, qd)[1]


def _velocity_at(model: KinematicModel, out: Output, phi: float) -> float:
    return float(_velocities_at(model, out, np.array([phi]))[0])


def _roots_of_velocity(model: KinematicModel, out: Output, grid: np.ndarray, v: np.ndarray, sgn: float
                       ) -> list[float]:
    """The crank angles where the output's velocity is zero: each sign change on the grid refined by
    Brent's method. A model that solves every position on its own is evaluated at all brackets at
    once (the ends together, then the searches in lockstep: the same steps and bits as one by one)."""
    found: list[float | None] = []
    brackets: list[tuple[int, float, float]] = []
    for i in range(GRID):
        j = (i + 1) % GRID
        a, b = grid[i], grid[i] + sgn * 2 * math.pi / GRID
        if v[i] == 0.0:
            found.append(grid[i])
        elif v[i] * v[j] < 0:
            lo, hi = (a, b) if a < b else (b, a)
            brackets.append((len(found), lo, hi))
            found.append(None)
    if not brackets:
        return [float(r) for r in found if r is not None]
    if model.positions_independent:
        ends = _velocities_at(model, out, np.array([x for _, lo, hi in brackets for x in (lo, hi)]))
        f_ends = [(float(ends[2 * k]), float(ends[2 * k + 1])) for k in range(len(brackets))]
    else:
        f_ends = [(_velocity_at(model, out, lo), _velocity_at(model, out, hi)) for _, lo, hi in brackets]
    search = [k for k, (flo, fhi) in enumerate(f_ends) if flo * fhi < 0]
    for k, (flo, fhi) in enumerate(f_ends):
        if k not in search:   # a grid point sits on the dead centre itself (|v| at rounding level)
            _, lo, hi = brackets[k]
            found[brackets[k][0]] = lo if abs(flo) <= abs(fhi) else hi
    if model.positions_independent:
        refined = brent_roots(lambda ph: _velocities_at(model, out, ph), [brackets[k][1:] for k in search],
                              xtol=ROOT_XTOL, known=[f_ends[k] for k in search])
    else:
        refined = [brent_root(lambda ph: _velocity_at(model, out, ph), *brackets[k][1:], xtol=ROOT_XTOL)
                   for k in search]
    for k, r in zip(search, refined):
        found[brackets[k][0]] = r
    return [float(r) for r in found if r is not None]


def _extreme_indices(roots, rx: np.ndarray, sgn: float) -> tuple[int, int]:
    """Indices of the largest and the smallest output coordinate among the roots of v(φ).

    An output can reach its largest (or smallest) value twice a turn, equal by construction (class3:
    the rocker reaches its upper extreme at φ1 = 10.8° and 61.2°, dipping 0.3° between them): argmax
    then chose by round-off, and the same mechanism scaled × 0.1 had its working stroke 206.2° instead
    of 204.2° and position 0 half a turn away. Of equal extremes (within RTOL_EQUAL of the stroke) the
    one taken is the last before the other extreme in the direction of rotation, where the output
    leaves for it (the choice round-off made for the examples)."""
    rx = np.asarray(rx, dtype=float)
    tol = RTOL_EQUAL * max(float(rx.max() - rx.min()), TINY)
    i_max, i_min = int(np.argmax(rx)), int(np.argmin(rx))

    def before(candidates, target: float) -> int:
        # the crank angle from each candidate to the target, in the direction of rotation: the smallest
        return min(candidates, key=lambda i: ((sgn * (target - roots[i])) % (2 * math.pi), i))

    tied_max = [i for i in range(len(rx)) if rx[i] >= rx[i_max] - tol]
    tied_min = [i for i in range(len(rx)) if rx[i] <= rx[i_min] + tol]
    i_max = before(tied_max, roots[i_min])
    i_min = before(tied_min, roots[i_max])
    return i_max, i_min


def find_strokes(model: KinematicModel, working: str = "slow") -> Strokes:
    """Extreme positions by root finding; ``working`` = "slow" (default) or "fast"."""
    out = find_output(model)
    sgn = 1.0 if model.omega >= 0 else -1.0
    phi0 = model.linkage.sketch_phi()
    grid = phi0 + sgn * np.linspace(0.0, 2 * math.pi, GRID, endpoint=False)
    q, _ = model.positions(grid)
    qd = model.velocities(q)
    x, v = output_coordinate(model, out, q, qd)
    roots = _roots_of_velocity(model, out, grid, v, sgn)
    if len(roots) < 2:
        raise NoExtremesError("the output link has no extreme positions (it turns fully)")
    rq, _ = model.positions(np.array(roots))
    rx = output_coordinate(model, out, rq)
    i_max, i_min = _extreme_indices(roots, rx, sgn)
    phi_max, phi_min = roots[i_max], roots[i_min]
    # crank angle from max to min in the direction of rotation
    a_max_to_min = math.degrees((sgn * (phi_min - phi_max)) % (2 * math.pi))
    a_min_to_max = 360.0 - a_max_to_min
    slow_from_max = a_max_to_min >= a_min_to_max
    from_max = slow_from_max if working == "slow" else not slow_from_max
    if from_max:
        start, end, work, idle, direction = phi_max, phi_min, a_max_to_min, a_min_to_max, -1.0
    else:
        start, end, work, idle, direction = phi_min, phi_max, a_min_to_max, a_max_to_min, 1.0
    stroke = float(rx[i_max] - rx[i_min])
    return Strokes(out, start % (2 * math.pi), end % (2 * math.pi), work, idle, stroke, direction, work / idle)


# ------------------------------------------------------------------------------ the course's construction


@dataclass(frozen=True)
class ExtremeConstruction:
    """How the course finds the extreme positions graphically, checked on the solved ones.

    ``kind`` "in-line": the crank O–A and the coupler A–B lie on one line (``positions`` give, per
    extreme, φ1 in degrees, "extended" |OB| = l_AB + l_OA or "folded" |OB| = l_AB − l_OA, and |OB| in
    m); "perpendicular": the crank is perpendicular to the slotted link that carries its pin's
    block (the slotted link touches the crank pin's circle; |OB| is then the distance of the slotted
    link's pivot B from O, the same for both)."""
    kind: str
    axis: str
    pin: str
    far: str
    coupler: int
    crank_length: float
    coupler_length: float
    positions: tuple[tuple[float, str, float], ...]


def extreme_construction(model: KinematicModel, strokes: Strokes) -> ExtremeConstruction | None:
    """The construction of the two extreme positions found by :func:`find_strokes`, or None when
    neither applies (the output is not driven through the crank's coupler in one of these ways)."""
    lk = model.linkage
    O, A = lk.drive_axis, lk.drive_tip
    phis = np.array([strokes.phi_start, strokes.phi_end])
    kin = model.solve(phis)
    pos = {n: np.asarray(m.pos) for n, m in kin.points.items()}
    joint = next((j for j in lk.joints if j.name == A and lk.drive_link in j.bodies), None)
    if joint is None:
        return None
    for c in joint.bodies:
        if c in (0, lk.drive_link):
            continue
        for B in lk.bodies[c].points:
            if B == A or B not in pos or not any(j.name == B for j in lk.joints):
                continue
            out = []
            for i, ph in enumerate(phis):
                oa, ab = pos[A][i] - pos[O][i], pos[B][i] - pos[A][i]
                sin = abs(oa[0] * ab[1] - oa[1] * ab[0]) / (np.hypot(*oa) * np.hypot(*ab))
                if sin > CONSTRUCTION_TOL:
                    break
                out.append((math.degrees(float(ph)) % 360.0, "extended" if float(oa @ ab) > 0 else "folded",
                            float(np.hypot(*(pos[B][i] - pos[O][i])))))
            else:
                return ExtremeConstruction("in-line", O, A, B, c, float(np.hypot(*(pos[A][0] - pos[O][0]))),
                                           float(np.hypot(*(pos[B][0] - pos[A][0]))), tuple(out))
    # a block on the crank pin sliding along a slotted link pivoted at the frame
    for s in lk.slides:
        blocks = {b for b in joint.bodies if b not in (0, lk.drive_link)}
        if s.link not in blocks or s.guide == 0:
            continue
        pivot = next((j.name for j in lk.joints if 0 in j.bodies and s.guide in j.bodies), None)
        if pivot is None:
            continue
        out = []
        for i, ph in enumerate(phis):
            oa, ba = pos[A][i] - pos[O][i], pos[A][i] - pos[pivot][i]
            cos = abs(float(oa @ ba)) / (np.hypot(*oa) * np.hypot(*ba))
            if cos > CONSTRUCTION_TOL:
                break
            out.append((math.degrees(float(ph)) % 360.0, "tangent", float(np.hypot(*(pos[pivot][i] - pos[O][i])))))
        else:
            return ExtremeConstruction("perpendicular", O, A, pivot, s.guide,
                                       float(np.hypot(*(pos[A][0] - pos[O][0]))), 0.0, tuple(out))
    return None
