"""The linkage compiled for solving: every link as a rigid body with local point coordinates.

Each moving link k has a pose ``(x_k, y_k, θ_k)``: its frame's origin in the frame of the machine
and its angle. A point P of link k stands at ``r_k + R(θ_k)·p_k`` with ``p_k`` its local coordinates.
The local frame of a link with two or more points has its origin at ``points[0]`` and its x axis
towards ``points[1]``; the local coordinates come from the lengths the task gives, the other
distances from the sketch. The frame (link 0) has pose (0, 0, 0) and carries the ground points.

Pairs (Chebyshev: a point shared by k bodies is k − 1 pairs):
- a *joint* is a point carried by two or more bodies (the frame counts when the point is ground);
- a *slide* is a prismatic pair: a point of ``link`` stays on a line carried by ``guide``, and the
  two bodies keep their relative angle.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from .errors import TaskError
from .task import Mechanism
from .tolerances import RTOL_EQUAL

from .geometry import Vec2 as Vec, rot_vec2

#: Relative tolerance for a degenerate (straight) triangle: a bar with a point between its ends.
COLLINEAR_REL_TOL = RTOL_EQUAL


@dataclass(frozen=True)
class Body:
    """A rigid body: link ``id`` (0 = frame) with local coordinates of its points."""
    id: int
    kind: str
    points: tuple[str, ...]
    local: Mapping[str, Vec]
    sketch_pose: tuple[float, float, float]
    com_local: Vec
    mass: float
    inertia: float


@dataclass(frozen=True)
class Joint:
    """A revolute joint: point ``name`` carried by ``bodies`` (sorted; 0 = frame)."""
    name: str
    bodies: tuple[int, ...]

    @property
    def pairs(self) -> int:
        return len(self.bodies) - 1


@dataclass(frozen=True)
class SlidePair:
    """Prismatic pair: point ``point`` of body ``link`` on the line of body ``guide``.

    The line in the guide's frame passes through ``line_point`` with unit direction ``line_dir``;
    ``point_local`` is the sliding point in the slider's frame; ``rel_angle`` = θ_link − θ_guide,
    constant (from the sketch).
    """
    index: int
    link: int
    guide: int
    point: str
    point_local: Vec
    line_point: Vec
    line_dir: Vec
    rel_angle: float


@dataclass(frozen=True)
class Linkage:
    """The compiled mechanism: bodies, joints, slides and the drive."""
    bodies: Mapping[int, Body]
    joints: tuple[Joint, ...]
    slides: tuple[SlidePair, ...]
    ground: tuple[str, ...]
    sketch: Mapping[str, Vec]
    drive_link: int
    drive_axis: str
    drive_tip: str
    omega: float
    g: float
    name: str

    @property
    def moving(self) -> tuple[int, ...]:
        return tuple(sorted(k for k in self.bodies if k != 0))

    def sketch_phi(self) -> float:
        """Crank angle φ1 of the sketch, rad (axis → moving point, from +x, CCW)."""
        o = self.sketch[self.drive_axis]
        a = self.sketch[self.drive_tip]
        return math.atan2(a[1] - o[1], a[0] - o[0])

    def crank_offset(self) -> float:
        """Angle α with θ_drive = φ1 − α (the crank vector's angle in the crank's frame)."""
        b = self.bodies[self.drive_link]
        o = b.local[self.drive_axis]
        a = b.local[self.drive_tip]
        return math.atan2(a[1] - o[1], a[0] - o[0])


def _dist(p: Vec, q: Vec) -> float:
    return math.hypot(q[0] - p[0], q[1] - p[1])


def _local_coordinates(mech: Mechanism, link_index: int) -> dict[str, Vec]:
    """Local coordinates from the given lengths (others from the sketch); side from the sketch."""
    ln = mech.links[link_index]
    path = f"mechanism.link[{link_index}]"
    pts = ln.points
    sk = mech.points
    given: dict[frozenset, float] = {frozenset((p, q)): float(v) for p, q, v in ln.lengths}

    def d(p: str, q: str) -> float:
        return given.get(frozenset((p, q)), _dist(sk[p], sk[q]))

    if len(pts) == 1:
        return {pts[0]: (0.0, 0.0)}
    p0, p1 = pts[0], pts[1]
    d01 = d(p0, p1)
    if d01 <= 0.0:
        raise TaskError(f"{path}.points", f"points {p0} and {p1} coincide", "distinct positions or a length > 0")
    local: dict[str, Vec] = {p0: (0.0, 0.0), p1: (d01, 0.0)}
    s0, s1 = sk[p0], sk[p1]
    ex = ((s1[0] - s0[0]), (s1[1] - s0[1]))
    for pk in pts[2:]:
        a, b = d(p0, pk), d(p1, pk)
        x = (a * a - b * b + d01 * d01) / (2.0 * d01)
        h2 = (a - x) * (a + x)
        scale = max(a, b, d01)
        if h2 < -COLLINEAR_REL_TOL * scale * scale * 1e3:
            raise TaskError(f"{path}.lengths",
                            f"the sides {p0}{p1} = {d01:g}, {p0}{pk} = {a:g}, {p1}{pk} = {b:g} m do not form a triangle",
                            "each side no longer than the sum of the other two")
        h = math.sqrt(max(h2, 0.0))
        sk_k = sk[pk]
        cross = ex[0] * (sk_k[1] - s0[1]) - ex[1] * (sk_k[0] - s0[0])
        local[pk] = (x, h if cross >= 0 else -h)
    return local


def _com_local(ln, local: Mapping[str, Vec]) -> Vec:
    pts = ln.points
    if isinstance(ln.com, str):
        return local[ln.com]
    if isinstance(ln.com, (int, float)) and not isinstance(ln.com, bool) and len(pts) >= 2:
        f = float(ln.com)
        a, b = local[pts[0]], local[pts[1]]
        return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))
    if len(pts) == 1:
        return local[pts[0]]
    if len(pts) == 2:
        a, b = local[pts[0]], local[pts[1]]
        return ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    xs = [local[p][0] for p in pts]
    ys = [local[p][1] for p in pts]
    return (sum(xs) / len(xs), sum(ys) / len(ys))


def compile_linkage(mech: Mechanism) -> Linkage:
    """Build bodies, joints and slides from a validated :class:`Mechanism`."""
    sk = {k: (float(v[0]), float(v[1])) for k, v in mech.points.items()}
    bodies: dict[int, Body] = {}
    ground = tuple(mech.ground)
    bodies[0] = Body(0, "frame", ground, MappingProxyType({p: sk[p] for p in ground}), (0.0, 0.0, 0.0),
                     (0.0, 0.0), 0.0, 0.0)
    guide_angle_of_slider: dict[int, float] = {}
    # Sketch angles of bodies with two or more points.
    locals_: dict[int, dict[str, Vec]] = {}
    sketch_pose: dict[int, tuple[float, float, float]] = {}
    for i, ln in enumerate(mech.links):
        loc = _local_coordinates(mech, i)
        locals_[ln.id] = loc
        if len(ln.points) >= 2:
            p0, p1 = sk[ln.points[0]], sk[ln.points[1]]
            sketch_pose[ln.id] = (p0[0], p0[1], math.atan2(p1[1] - p0[1], p1[0] - p0[0]))
    # One-point links take the angle of the line they slide on (so their relative angle is 0).
    for s in mech.slides:
        ln = mech.link(s.link)
        if len(ln.points) == 1:
            if s.guide == 0:
                ang = math.radians(float(s.angle_deg or 0.0))
            else:
                pa, pb = s.along  # type: ignore[misc]
                ang = math.atan2(sk[pb][1] - sk[pa][1], sk[pb][0] - sk[pa][0])
            guide_angle_of_slider[s.link] = ang
    for ln in mech.links:
        if len(ln.points) == 1:
            p = sk[ln.points[0]]
            sketch_pose[ln.id] = (p[0], p[1], guide_angle_of_slider.get(ln.id, 0.0))
        loc = locals_[ln.id]
        bodies[ln.id] = Body(ln.id, ln.kind, tuple(ln.points), MappingProxyType(loc), sketch_pose[ln.id],
                             _com_local(ln, loc), float(ln.mass), float(ln.inertia))

    carriers: dict[str, list[int]] = {}
    for name in ground:
        carriers.setdefault(name, []).append(0)
    for ln in mech.links:
        for name in ln.points:
            carriers.setdefault(name, []).append(ln.id)
    joints = tuple(Joint(p, tuple(sorted(set(b)))) for p, b in sorted(carriers.items()) if len(set(b)) >= 2)

    slides = []
    for idx, s in enumerate(mech.slides):
        link_pose = sketch_pose[s.link]
        pl = locals_[s.link][s.point]
        if s.guide == 0:
            ang = math.radians(float(s.angle_deg or 0.0))
            lp = (float(s.through[0]), float(s.through[1]))  # type: ignore[index]
            ld = (math.cos(ang), math.sin(ang))
            guide_theta = 0.0
        else:
            gl = locals_[s.guide]
            pa, pb = s.along  # type: ignore[misc]
            a, b = gl[pa], gl[pb]
            n = _dist(a, b)
            if n <= 0:
                raise TaskError(f"mechanism.slide[{idx}].along", f"points {pa} and {pb} coincide",
                                "two distinct points of the guide link")
            lp, ld = a, ((b[0] - a[0]) / n, (b[1] - a[1]) / n)
            guide_theta = sketch_pose[s.guide][2]
        slides.append(SlidePair(idx, s.link, s.guide, s.point, pl, lp, ld, link_pose[2] - guide_theta))

    drive = mech.drive
    dl = mech.link(drive.link)
    axis = next((p for p in dl.points if p in ground), None)
    if axis is None:
        raise TaskError("mechanism.drive.link", f"the driving link {drive.link} has no ground point",
                        "a crank that lists one of mechanism.ground as its axis")
    tip = next((p for p in dl.points if p != axis), None)
    if tip is None:
        raise TaskError("mechanism.drive.link", f"the driving link {drive.link} has only its axis",
                        "a crank with its axis and a moving point")
    return Linkage(MappingProxyType(bodies), joints, tuple(slides), ground, MappingProxyType(sk),
                   drive.link, axis, tip, float(drive.omega), float(mech.g), mech.name)


def sketch_q(linkage: Linkage) -> np.ndarray:
    """Poses of all bodies in the sketch, shape (n+1, 3) (approximate: the sketch need not close)."""
    n = max(linkage.bodies)
    q = np.zeros((n + 1, 3))
    for k, b in linkage.bodies.items():
        if k == 0:
            continue
        x, y, th = b.sketch_pose
        p0 = b.local[b.points[0]]
        off = rot_vec2(th, p0)
        q[k] = (x - off[0], y - off[1], th)
    return q
