"""Loads on the links at the analysed positions: production resistance, gravity, constant forces and
moments (the task's), and d'Alembert inertia loads (from the kinematics).

Every force is given with its point of application, at every position, so that the equilibrium of
each link can be re-checked. Names follow RESULTS_FORMAT.md: ``Fпс`` (resistance force), ``Mпс``
(resistance moment), ``G2`` (weight of link 2), ``Fи2``/``Mи2`` (inertia force and moment of link
2), ``F5``/``M3`` (constant task loads on links 5 and 3; a second one on the same link gets a
suffix ``F5.2``).

Production resistance (TASK_FORMAT.md): it acts on its link during the stroke(s) named, against the
motion; its magnitude follows ``law`` = (fraction of the stroke travelled, fraction of the maximum),
linear in between. The fraction of the stroke is measured on the loaded link's own coordinate
(displacement along its guide, or angle) from its value at the start of that stroke; the direction
is against the motion of that stroke (constant over it, so that it does not flicker where v → 0).
Inertia (course manual, seed 001): Fи = −m·a_S at the centre of mass, Mи = −J_S·ε.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import TaskError
from .kinematics import KinematicsResult
from .kinematics.constraints import world
from .kinematics.extremes import Strokes
from .linkage import Linkage
from .task import Mechanism
from .geometry import dot as _dot, frozen, readonly as _ro, shared
from .tolerances import ABS_ROUNDOFF


@dataclass(frozen=True)
class Force:
    """A force on ``link`` at ``point`` (N, 2), vector (N, 2) in N; ``where`` names the point
    (a point name, ``S2`` for a centre of mass)."""
    name: str
    link: int
    where: str
    point: np.ndarray
    vector: np.ndarray
    kind: str            # "resistance" | "gravity" | "inertia" | "force"


@dataclass(frozen=True)
class Moment:
    """A couple on ``link``, N·m, positive counter-clockwise, (N,)."""
    name: str
    link: int
    value: np.ndarray
    kind: str            # "resistance" | "inertia" | "moment"


@dataclass(frozen=True)
class LoadSet:
    forces: tuple[Force, ...]
    moments: tuple[Moment, ...]

    def on_link(self, k: int) -> tuple[tuple[Force, ...], tuple[Moment, ...]]:
        return (tuple(f for f in self.forces if f.link == k), tuple(m for m in self.moments if m.link == k))

    def __add__(self, other: "LoadSet") -> "LoadSet":
        return LoadSet(self.forces + other.forces, self.moments + other.moments)


def law_value(law: tuple[tuple[float, float], ...], frac: np.ndarray) -> np.ndarray:
    """The resistance law (piecewise linear through its points; 0 outside [first, last])."""
    xs = np.array([p[0] for p in law], dtype=float)
    ys = np.array([p[1] for p in law], dtype=float)
    return np.interp(frac, xs, ys, left=0.0, right=0.0)


def link_coordinate(linkage: Linkage, link: int, q: np.ndarray) -> tuple[np.ndarray, str]:
    """The loaded link's own coordinate: displacement along its frame guide (m) or its angle (rad)."""
    for s in linkage.slides:
        if s.link == link and s.guide == 0:
            return world(q, link, s.point_local) @ np.asarray(s.line_dir), "slider"
    return q[:, link, 2], "rocker"


@dataclass(frozen=True)
class StrokeWindow:
    """Crank angles of the working stroke (start → end in the direction of rotation), rad."""
    phi_start: float
    phi_end: float
    sign: float          # +1 if the crank angle grows (ω > 0)

    def on_working(self, phi: np.ndarray) -> np.ndarray:
        span = (self.sign * (self.phi_end - self.phi_start)) % (2 * math.pi)
        off = (self.sign * (np.asarray(phi) - self.phi_start)) % (2 * math.pi)
        # round-off either side of both ends: an angle 1e-16 before the start (the same position
        # computed another way, e.g. a scaled task's) is the start, not the end of the idle stroke
        return (off <= span + ABS_ROUNDOFF) | (off >= 2 * math.pi - ABS_ROUNDOFF)

    def switching_angles(self) -> tuple[float, float]:
        return (self.phi_start, self.phi_end)


def resistance_loads(mech: Mechanism, linkage: Linkage, model, kin: KinematicsResult,
                     strokes: Strokes | None) -> LoadSet:
    """Production resistance at the analysed positions (zero where its stroke is not on)."""
    forces, moments = [], []
    if strokes is None:
        return LoadSet((), ())
    win = StrokeWindow(strokes.phi_start, strokes.phi_end, 1.0 if linkage.omega >= 0 else -1.0)
    q = np.asarray(kin.q)
    working = win.on_working(kin.phi)
    ends_q = model.positions_kept((strokes.phi_start, strokes.phi_end))
    for i, ld in enumerate(mech.loads):
        if ld.kind != "resistance":
            continue
        x, kind = link_coordinate(linkage, ld.link, q)
        xe, _ = link_coordinate(linkage, ld.link, ends_q)
        if kind == "rocker":
            x = xe[0] + np.mod(x - xe[0] + math.pi, 2 * math.pi) - math.pi
        x0, x1 = float(xe[0]), float(xe[1])
        travel = x1 - x0
        mag = np.zeros_like(x)
        direction = np.zeros_like(x)     # the sign of the coordinate's motion on the stroke
        if abs(travel) > 0:
            fw = np.clip((x - x0) / travel, 0.0, 1.0)          # fraction of the working stroke
            fi = np.clip((x1 - x) / travel, 0.0, 1.0)          # fraction of the idle stroke
            if ld.stroke in ("working", "both"):
                mag = np.where(working, law_value(ld.law, fw), mag)
                direction = np.where(working, math.copysign(1.0, travel), direction)
            if ld.stroke in ("idle", "both"):
                mag = np.where(~working, law_value(ld.law, fi), mag)
                direction = np.where(~working, -math.copysign(1.0, travel), direction)
        if ld.force is not None:
            s = next(s for s in linkage.slides if s.link == ld.link and s.guide == 0) \
                if kind == "slider" else None
            if s is None:
                raise TaskError(f"mechanism.load[{i}].force",
                                f"a resistance force on link {ld.link}, which is not a slider on a frame guide",
                                "a force on a slider that runs on a guide of the frame, or a moment "
                                "(`moment = …`) on a rocker")
            u = np.asarray(s.line_dir)
            vec = (-(ld.force * mag * direction))[:, None] * u[None, :]
            pt = world(q, ld.link, s.point_local)
            forces.append(Force("Fпс", ld.link, s.point, frozen(pt), frozen(vec), "resistance"))
        else:
            moments.append(Moment("Mпс", ld.link, frozen(-(ld.moment or 0.0) * mag * direction), "resistance"))
    return LoadSet(tuple(forces), tuple(moments))


def gravity_loads(linkage: Linkage, kin: KinematicsResult) -> LoadSet:
    """G_k = m_k·g, downwards, at the centre of mass of every link with a mass."""
    forces = []
    if linkage.g == 0:
        return LoadSet((), ())
    for k in linkage.moving:
        m = linkage.bodies[k].mass
        if m <= 0:
            continue
        pt = kin.coms[k].pos
        vec = np.zeros_like(pt)
        vec[:, 1] = -m * linkage.g
        forces.append(Force(f"G{k}", k, f"S{k}", shared(pt), frozen(vec), "gravity"))
    return LoadSet(tuple(forces), ())


def constant_loads(mech: Mechanism, kin: KinematicsResult) -> LoadSet:
    """The task's constant forces (at a point or the centre of mass) and couples."""
    forces, moments = [], []
    count: dict[str, int] = {}

    def name(base: str) -> str:
        count[base] = count.get(base, 0) + 1
        return base if count[base] == 1 else f"{base}.{count[base]}"

    N = kin.phi.size
    for ld in mech.loads:
        if ld.kind == "force":
            if ld.com or ld.point is None:
                pt, where = kin.coms[ld.link].pos, f"S{ld.link}"
            else:
                pt, where = kin.points[ld.point].pos, ld.point
            vec = np.broadcast_to(np.asarray(ld.vector, dtype=float), (N, 2))
            forces.append(Force(name(f"F{ld.link}"), ld.link, where, shared(pt), _ro(vec), "force"))
        elif ld.kind == "moment":
            moments.append(Moment(name(f"M{ld.link}"), ld.link, frozen(np.full(N, float(ld.value or 0.0))), "moment"))
    return LoadSet(tuple(forces), tuple(moments))


def inertia_loads(linkage: Linkage, kin: KinematicsResult) -> LoadSet:
    """d'Alembert: Fи_k = −m_k·a_Sk at S_k, Mи_k = −J_Sk·ε_k (links with a mass or inertia)."""
    forces, moments = [], []
    for k in linkage.moving:
        b = linkage.bodies[k]
        if b.mass > 0:
            forces.append(Force(f"Fи{k}", k, f"S{k}", shared(kin.coms[k].pos), frozen(-b.mass * np.asarray(kin.coms[k].acc)),
                                "inertia"))
        if b.inertia > 0:
            moments.append(Moment(f"Mи{k}", k, frozen(-b.inertia * np.asarray(kin.links[k].epsilon)), "inertia"))
    return LoadSet(tuple(forces), tuple(moments))


def external_loads(mech: Mechanism, linkage: Linkage, model, kin: KinematicsResult, strokes: Strokes | None) -> LoadSet:
    """All loads but inertia: resistance, gravity, constant task loads."""
    return resistance_loads(mech, linkage, model, kin, strokes) + gravity_loads(linkage, kin) + \
        constant_loads(mech, kin)


def power(loads: LoadSet, kin: KinematicsResult) -> np.ndarray:
    """Σ(F·v_point + M·ω_link) at every position, W — the velocity of each force's own point."""
    q, qd = np.asarray(kin.q), np.asarray(kin.qd)
    P = np.zeros(kin.phi.size)
    for f in loads.forces:
        k = f.link
        r = np.asarray(f.point) - q[:, k, :2]
        v = qd[:, k, :2] + qd[:, k, 2][:, None] * np.stack((-r[:, 1], r[:, 0]), -1)
        P += _dot(np.asarray(f.vector), v)   # = (F·v).sum(1): two products and one sum, the same bits
    for m in loads.moments:
        P += np.asarray(m.value) * qd[:, m.link, 2]
    return P


@dataclass(frozen=True)
class ResistanceAt:
    """The production resistance of one load at the force position, from its law: the output's
    travel from the start of its stroke ``s`` and the whole stroke ``H`` (m or rad), the law's
    factor ``k`` = law(s/H), the load's value (N or N·m, as the solver applied it)."""
    link: int
    law: str
    is_force: bool
    maximum: float             # F_max (N) or M_max (N·m)
    working: bool              # the force position is on the working stroke
    on: bool                   # the load acts there
    value: float               # |F| or |M| applied by the solver
    unit: str                  # "м" (a slider) or "рад" (a rocker)
    s: float | None = None
    H: float | None = None
    k: float | None = None


def resistance_at(project) -> tuple[ResistanceAt, ...]:
    """The production resistance at the force position of ``project`` (section 2 prints it; the
    solver's load is the same number)."""
    ks = project.kinetostatics
    mech, lk, strokes = project.task.mechanism, project.linkage, project.strokes
    solver = {f.link: float(np.hypot(*np.asarray(f.vector)[0])) for f in ks.reactions.loads.forces
              if f.kind == "resistance"}
    solver.update({m.link: abs(float(np.asarray(m.value)[0])) for m in ks.reactions.loads.moments
                   if m.kind == "resistance"})
    out = []
    for ld in mech.loads:
        if ld.kind != "resistance" or strokes is None:
            continue
        q = np.asarray(ks.reactions.kin.q)
        x_arr, kind = link_coordinate(lk, ld.link, q)
        ends, _ = project.model.positions(np.array([strokes.phi_start, strokes.phi_end]))
        xe, _ = link_coordinate(lk, ld.link, ends)
        x = float(x_arr[0])
        if kind == "rocker":
            x = float(xe[0]) + (x - float(xe[0]) + math.pi) % (2 * math.pi) - math.pi
        win = StrokeWindow(strokes.phi_start, strokes.phi_end, 1.0 if lk.omega >= 0 else -1.0)
        working = bool(win.on_working(np.array([ks.phi]))[0])
        travel = float(xe[1] - xe[0])
        on = (working and ld.stroke in ("working", "both")) or (not working and ld.stroke in ("idle", "both"))
        is_force = ld.force is not None
        maximum = float(ld.force if is_force else ld.moment)
        unit = "м" if kind == "slider" else "рад"
        s_val = H = k = None
        if on and travel != 0:
            s_val = abs(x - float(xe[0])) if working else abs(float(xe[1]) - x)
            H = abs(travel)
            k = float(law_value(ld.law, np.array([s_val / H]))[0])
        out.append(ResistanceAt(ld.link, ld.law, is_force, maximum, working, on, solver.get(ld.link, 0.0), unit,
                                s_val, H, k))
    return tuple(out)
