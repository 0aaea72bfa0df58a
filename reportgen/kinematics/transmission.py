"""Transmission angles μ of the groups (0° = the group is at a singular, dead-centre position).

Per dyad kind (the acute angle between two directions, 0…90°):
- RRR: between the two links at the inner joint (lines P*Q and S*Q);
- RRP: between the link P*Q and the normal of the slide (90° when the link runs along the guide);
- RPR: between the normal of the slot and the line joining the two pins;
- PRP, RPP: between the two lines of the slides.
Class III group of a base link on three legs (binary links, revolute pairs): the base in equilibrium
takes three forces along the legs and is singular when the three leg lines meet in one point. For each
leg i, let P be the meeting point of the other two leg lines (the instant centre of the base with
those legs locked); μ_i is the acute angle between leg i and the line from P to its pin on the base
(90° when the force is square to the pin's velocity, 0° at the singular position), and μ = min μ_i.
Other groups of class III and higher: μ = asin(σ_min/σ_max) of the group's Jacobian with rotations
scaled by the group's size — 0° exactly where the group is singular, an index rather than an angle. Positions with μ below
``NEAR_SINGULAR_DEG`` are flagged: there the reactions grow like 1/sin μ (NOTES.md).
"""
from __future__ import annotations


import numpy as np

from ..linkage import Linkage
from ..structure import Group
from .constraints import assemble, rot, world
from .positions import group_constraints
from ..tolerances import ABS_ROUNDOFF, TINY

#: A position whose transmission angle is below this is flagged as near a singular position.
NEAR_SINGULAR_DEG = 5.0


def _acute(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    cr = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
    dt = np.abs(u[:, 0] * v[:, 0] + u[:, 1] * v[:, 1])
    return np.degrees(np.arctan2(cr, dt))


def _point(q, linkage: Linkage, k: int, name: str) -> np.ndarray:
    return world(q, k, linkage.bodies[k].local[name])


def transmission_angle(linkage: Linkage, group: Group, q: np.ndarray) -> np.ndarray:
    """μ in degrees at every position, shape (N,)."""
    if group.group_class == 2:
        a, b = group.links
        inner = next(p for p in group.pairs if not p.external)
        ext = {k: next(p for p in group.pairs if p.external and k in p.bodies) for k in (a, b)}
        if group.kind == "RRR":
            Q = _point(q, linkage, a, inner.point)
            u = Q - _point(q, linkage, a, ext[a].point)
            v = Q - _point(q, linkage, b, ext[b].point)
            return _acute(u, v)
        if group.kind == "RRP":
            r = a if ext[a].kind == "R" else b
            Q = _point(q, linkage, r, inner.point)
            u = Q - _point(q, linkage, r, ext[r].point)
            s = linkage.slides[ext[b if r == a else a].slide]
            d = rot(q[:, s.guide, 2], s.line_dir)
            n = np.stack((-d[:, 1], d[:, 0]), axis=-1)
            return _acute(u, n)
        if group.kind == "RPR":
            s = linkage.slides[inner.slide]
            d = rot(q[:, s.guide, 2], s.line_dir)
            n = np.stack((-d[:, 1], d[:, 0]), axis=-1)
            G = _point(q, linkage, s.guide, ext[s.guide].point)
            H = _point(q, linkage, s.link, ext[s.link].point)
            return _acute(n, H - G)
        # PRP, RPP: the two slide lines
        dirs = []
        for p in group.pairs:
            if p.kind == "P":
                s = linkage.slides[p.slide]
                dirs.append(rot(q[:, s.guide, 2], s.line_dir))
        return _acute(dirs[0], dirs[1])
    legs = _base_and_legs(group)
    if legs is not None:
        return _class3_angle(linkage, q, legs[1])
    cons = group_constraints(linkage, group)
    J, _ = assemble(cons, q, list(group.links))
    L = max([abs(v) for k in group.links for p in linkage.bodies[k].local.values() for v in p] + [ABS_ROUNDOFF])
    J = J.copy()
    J[:, :, 2::3] /= L
    sv = np.linalg.svd(J, compute_uv=False)
    return np.degrees(np.arcsin(np.clip(sv[:, -1] / sv[:, 0], 0.0, 1.0)))


def _base_and_legs(group: Group):
    """(base, [(leg, pin on base, other pin of the leg)]) for a base link on three legs, else None."""
    if len(group.links) != 4 or any(p.kind != "R" for p in group.pairs):
        return None
    internal = [p for p in group.pairs if not p.external]
    count = {k: sum(1 for p in internal if k in p.bodies) for k in group.links}
    bases = [k for k, c in count.items() if c == 3]
    if len(bases) != 1 or any(c != 1 for k, c in count.items() if k != bases[0]):
        return None
    base = bases[0]
    legs = []
    for p in internal:
        leg = p.bodies[0] if p.bodies[1] == base else p.bodies[1]
        ext = next(e for e in group.pairs if e.external and leg in e.bodies)
        legs.append((leg, p.point, ext.point))
    return base, legs


def _line_meet(p1, d1, p2, d2):
    """Intersection of two lines (N, 2), NaN where parallel."""
    den = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    w = p2 - p1
    t = (w[:, 0] * d2[:, 1] - w[:, 1] * d2[:, 0]) / np.where(np.abs(den) > TINY, den, np.nan)
    return p1 + t[:, None] * d1


def _class3_angle(linkage: Linkage, q: np.ndarray, legs) -> np.ndarray:
    pins, dirs = [], []
    for leg, pin, other in legs:
        a = _point(q, linkage, leg, pin)
        b = _point(q, linkage, leg, other)
        pins.append(a)
        dirs.append(a - b)
    mus = []
    for i in range(3):
        j, k = [x for x in range(3) if x != i]
        P = _line_meet(pins[j], dirs[j], pins[k], dirs[k])
        r = pins[i] - P
        mu = _acute(dirs[i], r)
        # the other two legs parallel: the base translates square to them
        par = ~np.isfinite(P[:, 0])
        if par.any():
            mu[par] = 90.0 - _acute(dirs[i][par], dirs[j][par])
        mus.append(mu)
    return np.minimum.reduce(mus)
