"""Transmission angles μ of the groups (0° = the group is at a singular, dead-centre position).

Per dyad kind (the acute angle between two directions, 0…90°):
- RRR: between the two links at the inner joint (lines P*Q and S*Q);
- RRP: between the link P*Q and the normal of the slide (90° when the link runs along the guide);
- RPR: between the normal of the slot and the line joining the two pins;
- PRP, RPP: between the two lines of the slides.
For class III and higher there is no single angle; we report μ = asin(σ_min/σ_max) of the group's
Jacobian with rotations scaled by the group's size — it is 0° exactly where the group is singular and
equals the acute angle for a dyad of two equal bars at 90°. Positions with μ below
``NEAR_SINGULAR_DEG`` are flagged: there the reactions grow like 1/sin μ (NOTES.md).
"""
from __future__ import annotations

import math

import numpy as np

from ..linkage import Linkage
from ..structure import Group
from .constraints import assemble, rot, world
from .positions import group_constraints

#: A position whose transmission angle is below this is flagged as near a singular position.
NEAR_SINGULAR_DEG = 5.0
#: The course's usual design limit for the transmission angle (reported, not enforced).
RECOMMENDED_MIN_DEG = 40.0


def _acute(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    cr = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
    dt = np.abs(u[:, 0] * v[:, 0] + u[:, 1] * v[:, 1])
    return np.degrees(np.arctan2(cr, dt))


def _point(q, linkage: Linkage, k: int, name: str) -> np.ndarray:
    return world(q, k, tuple(linkage.bodies[k].local[name]))


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
    cons = group_constraints(linkage, group)
    J, _ = assemble(cons, q, list(group.links))
    L = max([abs(v) for k in group.links for p in linkage.bodies[k].local.values() for v in p] + [1e-12])
    J = J.copy()
    J[:, :, 2::3] /= L
    s = np.linalg.svd(J, compute_uv=False)
    return np.degrees(np.arcsin(np.clip(s[:, -1] / s[:, 0], 0.0, 1.0)))
