"""Reactions in every kinematic pair, group by group, and the balancing moment on the crank.

The method of the course (Артоболевский И. И., «Теория механизмов и машин», гл. «Кинетостатика»;
seed 000, section 2): by d'Alembert's principle the loads together with the inertia loads are in
equilibrium; an Assur group is statically determinate, so the groups are solved one at a time from
the last attached back to the driver, each as its own square linear system, and the reactions of a
solved group act on the earlier links as known forces (``R21 = −R12``). Friction is neglected.

Unknowns of a group of n links (3n/2 pairs, 3n unknowns = 3n equations ΣFx = ΣFy = ΣM = 0 per link):
- revolute pair of bodies (i, j) at P: the force ``R_ij`` of i on j at P (two components);
- prismatic pair (guide g, slider a): the normal force N·n (n = the guide's normal) and the couple m
  that the guide applies to the slider about its sliding point W. Together they are one force N·n
  acting at ``W + (m/N)·u`` on the guide line (u = the guide's direction): that shifted point is
  reported as the point of action.

Then the crank: the balancing moment ``M_ур`` (what the drive applies, CCW positive) from its moment
equation about its axis O, the balancing force at the crank pin ``F_ур = M_ур/l_OA`` square to the
crank, and the frame reaction ``R01`` closing its force polygon (with ``F_ур`` at the pin, as the
course draws it; the reaction under a pure driving couple is kept as well).

Everything is in SI (N, m, N·m) in one matrix; the moment rows and the couple unknowns are scaled
by one length of the mechanism so that all entries have the same order (NOTES.md).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
import numpy as np

from ..errors import InternalError, NameLookupError, SingularPositionError
from ..kinematics import KinematicsResult
from ..kinematics.constraints import rot, world
from ..linkage import Linkage
from ..loads import Force, LoadSet, Moment
from ..structure import Group, Pair, Structure
from ..geometry import cross as _cross, perp, readonly as _ro

#: A prismatic pair whose point of action would lie farther than this many mechanism lengths from
#: its sliding point (normal force ≈ 0) reports its couple as a moment instead.
PRISMATIC_OFFSET_LIMIT = 100.0


def pair_name(i: int, j: int, prefix: str = "R") -> str:
    """``R12`` = force of link 1 on link 2; ids ≥ 10 are separated by a comma (``R3,12``)."""
    return f"{prefix}{i}{j}" if i < 10 and j < 10 else f"{prefix}{i},{j}"


@dataclass(frozen=True)
class PairReaction:
    """The reaction of one pair at every position.

    ``vector`` is the force of ``lo`` on ``hi`` (lo < hi, name ``R{lo}{hi}``) acting at ``point``;
    the force of hi on lo is its negative at the same point. For a prismatic pair ``sliding_point``
    is the pair's point W on the guide line, ``normal`` the unit normal of the guide, ``couple`` the
    moment about W of the pair's force on ``hi`` and ``residual_couple`` the part of it not carried by
    the shift of the point (non-zero only where the normal force vanishes; it is then listed as the
    moment ``M{lo}{hi}`` on hi and its negative on lo).
    """
    name: str
    kind: str                 # "R" | "P"
    lo: int
    hi: int
    joint: str                # the point name of the pair
    group: str                # key of the group whose system gave it ("1" for the driver's)
    external: bool
    point: np.ndarray         # (N, 2)
    vector: np.ndarray        # (N, 2)
    sliding_point: np.ndarray  # (N, 2)
    normal: np.ndarray        # (N, 2); zeros for a revolute pair
    couple: np.ndarray        # (N,)
    residual_couple: np.ndarray  # (N,)

    def on(self, k: int) -> np.ndarray:
        """The force of this pair on link k (k must be lo or hi)."""
        if k == self.hi:
            return self.vector
        if k == self.lo:
            return -self.vector
        raise NameLookupError(f"link of the pair {self.name}", k, (self.lo, self.hi))

    def other(self, k: int) -> int:
        return self.lo if k == self.hi else self.hi


@dataclass(frozen=True)
class Reactions:
    """Reactions of every pair and the balancing loads on the crank at the positions of ``kin``."""
    kin: KinematicsResult
    loads: LoadSet
    pairs: tuple[PairReaction, ...]            # in the order found: last group first, the crank last
    crank: int
    crank_axis: str
    crank_pin: str
    balancing_moment: np.ndarray               # (N,) N·m, CCW positive, applied by the drive
    balancing_force: np.ndarray                # (N, 2) at the crank pin, square to the crank
    balancing_point: np.ndarray                # (N, 2) the crank pin
    frame_reaction_with_moment: np.ndarray     # (N, 2) R01 if the drive applies a pure couple
    length_scale: float                        # the length used to scale the moment rows, m

    def pair(self, name: str) -> PairReaction:
        for p in self.pairs:
            if p.name == name:
                return p
        raise NameLookupError("pair", name, tuple(p.name for p in self.pairs))

    def pairs_of(self, k: int) -> tuple[PairReaction, ...]:
        return tuple(p for p in self.pairs if k in (p.lo, p.hi))

    def on_link(self, k: int) -> tuple[tuple[Force, ...], tuple[Moment, ...]]:
        """Every force and couple on link k: its loads, the reactions of its neighbours (named
        ``R{j}{k}``, the force of j on k) and, on the crank, the balancing force ``Fур``."""
        own_forces, own_moments = self.loads.on_link(k)
        forces, moments = list(own_forces), list(own_moments)
        for p in self.pairs_of(k):
            j = p.other(k)
            forces.append(Force(pair_name(j, k), k, p.joint, p.point, _ro(p.on(k)), "reaction"))
            if p.kind == "P" and np.any(p.residual_couple != 0.0):
                sgn = 1.0 if k == p.hi else -1.0
                moments.append(Moment(pair_name(j, k, "M"), k, _ro(sgn * p.residual_couple), "reaction"))
        if k == self.crank:
            forces.append(Force("Fур", k, self.crank_pin, self.balancing_point, self.balancing_force, "balancing"))
        return tuple(forces), tuple(moments)

    def residuals(self, k: int, about: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(ΣF (N, 2), ΣM about ``about`` (N,)) of link k — zero in equilibrium."""
        forces, moments = self.on_link(k)
        N = self.kin.phi.size
        o = np.zeros((N, 2)) if about is None else np.broadcast_to(about, (N, 2))
        F = np.zeros((N, 2))
        M = np.zeros(N)
        for f in forces:
            F += f.vector
            M += _cross(np.asarray(f.point) - o, np.asarray(f.vector))
        for m in moments:
            M += m.value
        return F, M


def length_scale(linkage: Linkage) -> float:
    """A length of the mechanism (the largest local coordinate), m."""
    vals = [abs(v) for b in linkage.bodies.values() for p in b.local.values() for v in p]
    vals += [abs(v) for p in linkage.sketch.values() for v in p]
    L = max(vals) if vals else 1.0
    return L if L > 0 else 1.0


@dataclass
class _Known:
    """Known forces and couples on the links, accumulated as the groups are solved."""
    forces: dict[int, list[tuple[np.ndarray, np.ndarray]]]
    couples: dict[int, np.ndarray]

    def add_force(self, k: int, point: np.ndarray, vector: np.ndarray) -> None:
        self.forces.setdefault(k, []).append((np.asarray(point, dtype=float), np.asarray(vector, dtype=float)))

    def add_couple(self, k: int, value: np.ndarray) -> None:
        self.couples[k] = self.couples.get(k, 0.0) + np.asarray(value, dtype=float)

    def resultant(self, k: int, o: np.ndarray, N: int) -> tuple[np.ndarray, np.ndarray]:
        F = np.zeros((N, 2))
        M = np.zeros(N)
        for p, v in self.forces.get(k, []):
            F += v
            M += _cross(p - o, v)
        M += self.couples.get(k, 0.0)
        return F, M


def known_from_loads(loads: LoadSet) -> _Known:
    kn = _Known({}, {})
    for f in loads.forces:
        kn.add_force(f.link, f.point, f.vector)
    for m in loads.moments:
        kn.add_couple(m.link, m.value)
    return kn


def _pair_geometry(linkage: Linkage, q: np.ndarray, p: Pair) -> tuple[np.ndarray, np.ndarray]:
    """(point W (N, 2), guide normal n (N, 2)) of a pair; n = 0 for a revolute pair."""
    if p.kind == "R":
        k = p.bodies[1]
        W = world(q, k, linkage.bodies[k].local[p.point])
        return W, np.zeros_like(W)
    s = linkage.slides[p.slide]
    W = world(q, s.link, s.point_local)
    u = rot(q[:, s.guide, 2], s.line_dir)
    return W, perp(u)


def solve_group(linkage: Linkage, group: Group, q: np.ndarray, known: _Known, L: float, phi: np.ndarray,
                ) -> list[tuple[Pair, np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    """Solve one Assur group: for each pair (pair, W, n, force of bodies[0] on bodies[1], couple).

    Equations, for each link k of the group: ΣF = 0 (two rows) and ΣM_O/L = 0 about the group's
    reference point O (the mean of its pair points); unknowns (Rx, Ry) of a revolute pair and (N, m/L)
    of a prismatic pair (force N·n on the slider plus the couple m about W).
    """
    N = q.shape[0]
    links = list(group.links)
    row = {k: 3 * i for i, k in enumerate(links)}
    n_unk = 2 * len(group.pairs)
    if n_unk != 3 * len(links):
        raise InternalError(f"group {group.label}", f"not statically determinate ({n_unk} unknowns, {3 * len(links)} equations)")
    geo = [_pair_geometry(linkage, q, p) for p in group.pairs]
    O = np.mean([g[0] for g in geo], axis=0)
    A = np.zeros((N, 3 * len(links), n_unk))
    b = np.zeros((N, 3 * len(links)))
    for c, (p, (W, n)) in enumerate(zip(group.pairs, geo)):
        r = W - O
        for body, sgn in ((p.bodies[1], 1.0), (p.bodies[0], -1.0)):
            if body not in row:
                continue
            i = row[body]
            if p.kind == "R":
                A[:, i, 2 * c] = sgn
                A[:, i + 1, 2 * c + 1] = sgn
                A[:, i + 2, 2 * c] = sgn * (-r[:, 1]) / L
                A[:, i + 2, 2 * c + 1] = sgn * r[:, 0] / L
            else:
                A[:, i, 2 * c] = sgn * n[:, 0]
                A[:, i + 1, 2 * c] = sgn * n[:, 1]
                A[:, i + 2, 2 * c] = sgn * _cross(r, n) / L
                A[:, i + 2, 2 * c + 1] = sgn
    for k in links:
        F, M = known.resultant(k, O, N)
        i = row[k]
        b[:, i] = -F[:, 0]
        b[:, i + 1] = -F[:, 1]
        b[:, i + 2] = -M / L
    try:
        x = np.linalg.solve(A, b[..., None])[..., 0]
    except np.linalg.LinAlgError:
        bad = next(i for i in range(N) if np.linalg.matrix_rank(A[i]) < A.shape[1])
        raise SingularPositionError(group.label, math.degrees(float(phi[bad])) % 360.0,
                                    "its equilibrium equations are singular (a dead centre)") from None
    out = []
    for c, (p, (W, n)) in enumerate(zip(group.pairs, geo)):
        if p.kind == "R":
            vec = x[:, 2 * c:2 * c + 2]
            couple: np.ndarray = np.zeros(N)
        else:
            vec = x[:, 2 * c, None] * n
            couple = x[:, 2 * c + 1] * L
        out.append((p, W, n, vec, couple))
    return out


def _record(p: Pair, W: np.ndarray, n: np.ndarray, vec: np.ndarray,
            couple: np.ndarray, group_key: str, L: float) -> PairReaction:
    """Canonical orientation (force of the lower id on the higher) and the point of action."""
    i, j = p.bodies
    if p.kind == "R":
        point = W
        residual = np.zeros(W.shape[0])
    else:
        Nn = (vec * n).sum(-1)                      # the normal force along n, on bodies[1]
        u = -perp(n)                                # the guide's direction (n = perp(u))
        with np.errstate(divide="ignore", invalid="ignore"):
            x = np.where(Nn != 0.0, couple / np.where(Nn != 0.0, Nn, 1.0), np.inf)
        ok = np.abs(x) <= PRISMATIC_OFFSET_LIMIT * L
        x = np.where(ok, x, 0.0)
        point = W + x[:, None] * u
        residual = np.where(ok, 0.0, couple)
    if i < j:
        lo, hi, v, c, rc = i, j, vec, couple, residual
    else:
        lo, hi, v, c, rc = j, i, -vec, -couple, -residual
    return PairReaction(pair_name(lo, hi), p.kind, lo, hi, p.point, group_key, p.external, _ro(point), _ro(v),
                        _ro(W), _ro(n), _ro(c), _ro(rc))


def solve_reactions(linkage: Linkage, structure: Structure, kin: KinematicsResult, loads: LoadSet) -> Reactions:
    """All reactions and the balancing moment at every position of ``kin`` (exact, vectorised)."""
    q = np.asarray(kin.q)
    N = q.shape[0]
    L = length_scale(linkage)
    known = known_from_loads(loads)
    pairs: list[PairReaction] = []
    for g in reversed(structure.groups[1:]):
        for p, W, n, vec, couple in solve_group(linkage, g, q, known, L, kin.phi):
            rec = _record(p, W, n, vec, couple, g.key, L)
            pairs.append(rec)
            for k in (rec.lo, rec.hi):
                if k not in g.links and k != 0:
                    known.add_force(k, rec.point, rec.on(k))
                    if np.any(rec.residual_couple != 0.0):
                        known.add_couple(k, rec.residual_couple if k == rec.hi else -rec.residual_couple)
    # the crank: M_ур + ΣM_O = 0, R01 + ΣF + F_ур = 0
    d = linkage.drive_link
    body = linkage.bodies[d]
    O = world(q, d, body.local[linkage.drive_axis])
    A = world(q, d, body.local[linkage.drive_tip])
    F, M = known.resultant(d, O, N)
    M_b = -M
    OA = A - O
    l_OA = np.hypot(OA[:, 0], OA[:, 1])
    F_b = (M_b / l_OA)[:, None] * perp(OA / l_OA[:, None])
    R0d_couple = -F
    R0d = -F - F_b
    drv = structure.groups[0]
    fp = next(p for p in drv.pairs if p.kind == "R" and 0 in p.bodies and p.point == linkage.drive_axis)
    vec = R0d if fp.bodies == (0, d) else -R0d
    pairs.append(_record(fp, O, np.zeros_like(O), vec, np.zeros(N), str(d), L))
    return Reactions(kin, loads, tuple(pairs), d, linkage.drive_axis, linkage.drive_tip, _ro(M_b), _ro(F_b), _ro(A),
                     _ro(R0d_couple), L)

