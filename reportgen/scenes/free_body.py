"""The free-body diagrams of section 2 and sheet 2 as scenes: an Assur group (or the crank) cut out
of the mechanism in the analysed position at μl, the pairs where it was cut (hinges, blocks on
their guides), and every force at its point of application — the loads (Fи′ at its shifted point
where Fи and Mи were replaced), the reactions known from the groups solved before, and the group's
own reactions (R^n and R^τ where the dyad splits them).

Arrow lengths are schematic (one rule, :func:`schematic_length`): a force's direction and point are
true, its length grows as the square root of its magnitude — the largest force ``ARROW_MM`` long,
none shorter than ``MIN_ARROW_MM`` — so that a weight of 10 N stays visible beside a resistance of
10 kN; the magnitudes are read from the force polygon, which is drawn at its scale μF. The note and
the sheet draw these scenes (docs/kinetostatics-presentation.md)."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..geometry import Vec2, vec2
from ..tolerances import MM_EPS
from .forces import force_tex
from .scene import Arrow, Circle, Entity, Label, Polyline, Scale, Scene, Segment, frozen

#: The largest force arrow (paper mm) and the shortest; the hinge circles' radius; a block's size.
ARROW_MM = 40.0
MIN_ARROW_MM = 15.0
HINGE_MM = 1.5
BLOCK_MM = (12.0, 6.0)
GUIDE_MM = 30.0
#: A couple (a moment not replaced by a shifted force): an arc of this radius (paper mm).
COUPLE_MM = 7.0


@dataclass(frozen=True)
class BodyForce:
    """A force on the cut-out body: its point (m), vector (N), solver name and role — "load" (a
    given load), "known" (a reaction found on an earlier step), "found" (found on this one)."""
    point: Vec2
    vector: Vec2
    name: str
    role: str

    @property
    def magnitude(self) -> float:
        return math.hypot(*self.vector)


@dataclass(frozen=True)
class Couple:
    """A moment on a link (N·m, counter-clockwise positive) drawn at ``point`` (m)."""
    point: Vec2
    value: float
    name: str


@dataclass(frozen=True)
class FreeBody:
    """One free-body diagram: the links drawn, its forces and couples, and its scene."""
    key: str                       # the group's key, or "crank"
    links: tuple[int, ...]
    forces: tuple[BodyForce, ...]
    couples: tuple[Couple, ...]
    scene: Scene


def schematic_length(magnitude: float, largest: float) -> float:
    """The arrow of a force of ``magnitude`` on a diagram whose largest force is ``largest``:
    ARROW_MM·√(|F|/F_max), at least MIN_ARROW_MM (paper mm)."""
    if largest <= 0.0:
        return MIN_ARROW_MM
    return max(MIN_ARROW_MM, ARROW_MM * math.sqrt(min(abs(magnitude) / largest, 1.0)))


def _vec(x) -> Vec2:
    return vec2(np.asarray(x, float).reshape(-1)[:2])


def loads_on(ks, links: tuple[int, ...]) -> tuple[list[BodyForce], list[Couple]]:
    """The loads and the couples on ``links`` as drawn: Fи′ at its shifted point where Fи and Mи
    were replaced (then Mи is not drawn)."""
    repl = {x.link: x for x in ks.graphical.inertia}
    forces: list[BodyForce] = []
    couples: list[Couple] = []
    for f in ks.reactions.loads.forces:
        if f.link not in links:
            continue
        v = _vec(np.asarray(f.vector)[0])
        if f.kind == "inertia" and f.link in repl:
            forces.append(BodyForce(_vec(repl[f.link].point), v, f.name + "′", "load"))
        else:
            forces.append(BodyForce(_vec(np.asarray(f.point)[0]), v, f.name, "load"))
    for m in ks.reactions.loads.moments:
        val = float(np.asarray(m.value)[0])
        if m.link not in links or val == 0.0 or (m.kind == "inertia" and m.link in repl):
            continue
        couples.append(Couple(_vec(np.asarray(ks.reactions.kin.coms[m.link].pos)[0]), val, m.name))
    return forces, couples


def group_forces(ks, links: tuple[int, ...], key: str, splits) -> tuple[list[BodyForce], list[Couple]]:
    """The forces on a group: loads, reactions known from earlier groups, the group's own outer
    reactions (R^n and R^τ where ``splits`` split them)."""
    from ..kinetostatics.reactions import pair_name
    r = ks.reactions
    forces, couples = loads_on(ks, links)
    own = {p.name for p in r.pairs if p.group == key}
    for k in links:
        for p in r.pairs_of(k):
            j = p.other(k)
            if p.name not in own and j not in links:
                forces.append(BodyForce(_vec(p.point[0]), _vec(p.on(k)[0]), pair_name(j, k), "known"))
    by_link = {sp.link: sp for sp in splits}
    for p in r.pairs:
        if p.group != key or not p.external:
            continue
        k = p.hi if p.hi in links else p.lo
        nm = pair_name(p.other(k), k)
        sp = by_link.get(k)
        if sp is not None and p.kind == "R":
            forces.append(BodyForce(_vec(p.point[0]), _vec(sp.normal * np.asarray(sp.along)), "Rn" + nm[1:], "found"))
            forces.append(BodyForce(_vec(p.point[0]), _vec(sp.tau * np.asarray(sp.tangent)), "Rτ" + nm[1:], "found"))
        else:
            forces.append(BodyForce(_vec(p.point[0]), _vec(p.on(k)[0]), nm, "found"))
    return [f for f in forces if f.magnitude > 0.0], couples


def crank_forces(ks) -> tuple[list[BodyForce], list[Couple]]:
    """The forces on the crank: its loads, the reaction of the next group at the pin (known), F_ур
    at the pin and the frame's reaction (found)."""
    from ..kinetostatics.reactions import pair_name
    r = ks.reactions
    d = r.crank
    fp = next(p for p in r.pairs if p.group == str(d))
    forces, couples = loads_on(ks, (d,))
    for p in r.pairs_of(d):
        if p.name != fp.name:
            forces.append(BodyForce(_vec(p.point[0]), _vec(p.on(d)[0]), pair_name(p.other(d), d), "known"))
    forces.append(BodyForce(_vec(r.balancing_point[0]), _vec(r.balancing_force[0]), "Fур", "found"))
    forces.append(BodyForce(_vec(fp.point[0]), _vec(fp.on(d)[0]), pair_name(0, d), "found"))
    return [f for f in forces if f.magnitude > 0.0], couples


def _pairs_drawn(ks, key: str | None) -> tuple[list[Vec2], list[tuple[Vec2, Vec2]]]:
    """Hinges (points, m) and blocks (point m, guide direction) of the pairs where the group (or,
    ``key`` None, the crank) was cut out and of its inner pairs."""
    from ..geometry import perp
    r = ks.reactions
    crank = {q.name for q in r.pairs_of(r.crank)}
    group = str(r.crank) if key is None else key
    hinges: list[Vec2] = []
    blocks: list[tuple[Vec2, Vec2]] = []
    for p in r.pairs:
        if p.group != group and not (key is None and p.name in crank):
            continue
        if p.kind == "R":
            hinges.append(_vec(p.point[0]))
        else:
            blocks.append((_vec(p.sliding_point[0]), _vec(-np.asarray(perp(np.asarray(p.normal[0], float))))))
    return hinges, blocks


def free_body_scene(ks, linkage, links: tuple[int, ...], key: str | None, forces: list[BodyForce],
                    couples: list[Couple], mu_l: float, name: str) -> Scene:
    """The scene of one free-body diagram at ``mu_l`` (m per paper mm): links (contour, cut at
    the hinge circles), hinges, blocks with their guides, the forces at :func:`schematic_length`,
    the couples as arcs with a head; labels: the points' letters, the links' numbers, each force's
    name beside its own arrow."""
    pos = {n: _vec(np.asarray(m.pos)[0]) for n, m in ks.reactions.kin.points.items()}

    def mm(p) -> Vec2:
        return (float(p[0]) / mu_l, float(p[1]) / mu_l)

    ents: list[Entity] = []
    labels: list[Label] = []
    points: dict[str, Vec2] = {}
    for k in links:
        names = linkage.bodies[k].points
        pts = [mm(pos[n]) for n in names]
        outline = [(0, 1)] if len(names) == 2 else [(i, (i + 1) % len(names)) for i in range(len(names))] \
            if len(names) > 2 else []
        for i, j in outline:
            ents.append(Segment(f"link{k}:{names[i]}{names[j]}", pts[i], pts[j], "contour", (HINGE_MM, HINGE_MM)))
        for n, p in zip(names, pts):
            points[n] = p
        if outline:           # the link's number beside the middle of its longest side
            i, j = max(outline, key=lambda e: math.dist(pts[e[0]], pts[e[1]]))
            a, b = np.asarray(pts[i]), np.asarray(pts[j])
            d = b - a
            nrm = np.array([-d[1], d[0]]) / (float(np.hypot(*d)) or 1.0)
            labels.append(Label(str(k), f"link:{k}", _vec((a + b) / 2 + nrm * 4.0), "link"))
        elif pts:             # a block: beside its point
            labels.append(Label(str(k), f"link:{k}", _vec(np.asarray(pts[0]) + np.array([0.0, 4.0])), "link"))
    hinges, blocks = _pairs_drawn(ks, key)
    drawn: list[Vec2] = []
    for p in hinges + [b for b, _ in blocks]:
        q = mm(p)
        if any(math.dist(q, o) < MM_EPS for o in drawn):
            continue
        drawn.append(q)
        ents.append(Circle(f"hinge:{len(drawn)}", q, HINGE_MM, "contour", hinge=True))
    for i, (p, g) in enumerate(blocks):
        c = np.asarray(mm(p))
        u = np.asarray(g) / (float(np.hypot(*g)) or 1.0)
        n = np.array([-u[1], u[0]])
        hl, hh = BLOCK_MM[0] / 2, BLOCK_MM[1] / 2
        box = tuple(_vec(c + sx * u * hl + sy * n * hh) for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1)))
        ents.append(Polyline(f"block:{i}", box, "contour", closed=True))
        ents.append(Segment(f"guide:{i}", _vec(c - u * GUIDE_MM / 2 - n * hh), _vec(c + u * GUIDE_MM / 2 - n * hh),
                            "axis"))
    for n, p in points.items():
        labels.append(Label(n, f"point:{n}", p, "point"))
    top = max([f.magnitude for f in forces] + [0.0])
    for f in forces:
        a = np.asarray(mm(f.point))
        u = np.asarray(f.vector) / f.magnitude
        b = a + u * schematic_length(f.magnitude, top)
        ident = f"force:{f.name}"
        ents.append(Arrow(ident, _vec(a), _vec(b), f.role))
        labels.append(Label(force_tex(f.name), ident, _vec((a + b) / 2), "vector", (_vec(a), _vec(b))))
    for cp in couples:
        o = np.asarray(mm(cp.point))
        a0, a1 = (math.radians(150.0), math.radians(390.0))
        if cp.value < 0:
            a0, a1 = a1, a0
        t = np.linspace(a0, a1, 25)
        arc = [_vec(o + COUPLE_MM * np.array([math.cos(x), math.sin(x)])) for x in t]
        ident = f"couple:{cp.name}"
        ents.append(Polyline(f"{ident}:arc", tuple(arc[:-3]), "vectors"))
        ents.append(Arrow(ident, arc[-4], arc[-1], "load"))
        labels.append(Label(force_tex(cp.name), ident, _vec(o + np.array([0.0, COUPLE_MM])), "point"))
    values = {f"force:{f.name}": f.magnitude for f in forces}
    return Scene(name, (Scale("μl", mu_l, "м/мм"),), tuple(ents), tuple(labels), frozen(points), frozen(values))


def group_free_body(ks, linkage, group, splits, mu_l: float) -> FreeBody:
    """The free-body diagram of an Assur group (:class:`reportgen.structure` group) at ``mu_l``."""
    forces, couples = group_forces(ks, group.links, group.key, splits)
    scene = free_body_scene(ks, linkage, group.links, group.key, forces, couples, mu_l, f"free-body-{group.key}")
    return FreeBody(group.key, tuple(group.links), tuple(forces), tuple(couples), scene)


def crank_free_body(ks, linkage, mu_l: float) -> FreeBody:
    """The free-body diagram of the crank at ``mu_l``."""
    d = ks.reactions.crank
    forces, couples = crank_forces(ks)
    scene = free_body_scene(ks, linkage, (d,), None, forces, couples, mu_l, "free-body-crank")
    return FreeBody("crank", (d,), tuple(forces), tuple(couples), scene)


def free_bodies(ks, linkage, structure, mu_l: float) -> tuple[FreeBody, ...]:
    """Every group's diagram (in the replica's order: the last attached first), then the crank's."""
    by_key = {gr.key: gr for gr in structure.groups}
    out = [group_free_body(ks, linkage, by_key[gg.key], gg.splits, mu_l) for gg in ks.graphical.groups]
    out.append(crank_free_body(ks, linkage, mu_l))
    return tuple(out)
