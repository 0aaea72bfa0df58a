"""Structural analysis: Chebyshev's mobility, the numerical mobility, and the decomposition of the
chain into the driver and Assur groups of any class (Artobolevsky's classification).

Chebyshev (planar): W = 3n − 2p1 − p2, with n moving links, p1 one-mobility pairs (revolute and
prismatic), p2 two-mobility pairs (none in a linkage of this task format). A point shared by k bodies
is k − 1 revolute pairs.

Assur groups are found as the smallest set S of the links not yet attached such that its pairs with
itself and with the links already attached satisfy 3·|S| = 2·p(S) (a group of zero mobility);
searching sets of 2, 4, 6, … links in that order gives the groups in order of attachment, each
minimal. Class (Artobolevsky): a dyad is class II; a larger group takes the number of pairs of its
most complex closed contour of internal pairs, or III when its internal pairs form no contour (a base
link with three legs). The order is the number of external pairs.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .errors import StructureError
from .linkage import Linkage, sketch_q
from .tolerances import RTOL_RANK

#: Largest Assur group searched (links). Class IV and two-contour groups have at most 6 links here.
MAX_GROUP_LINKS = 8


@dataclass(frozen=True)
class Pair:
    """A kinematic pair of a group: kind "R" at ``point`` or "P" of slide ``slide``; ``bodies`` the
    two links it joins; ``external`` if one of them was attached before the group."""
    kind: str
    bodies: tuple[int, int]
    point: str
    external: bool
    slide: int = -1


@dataclass(frozen=True)
class Group:
    """An Assur group (or the driver, class 1)."""
    links: tuple[int, ...]
    group_class: int
    order: int
    kind: str
    pairs: tuple[Pair, ...]

    @property
    def label(self) -> str:
        roman = {1: "I", 2: "II", 3: "III", 4: "IV", 5: "V", 6: "VI"}.get(self.group_class, str(self.group_class))
        return f"{roman}({','.join(map(str, self.links))})"

    @property
    def key(self) -> str:
        """Key of the group in results.json maps, e.g. "2-3"."""
        return "-".join(map(str, self.links))


@dataclass(frozen=True)
class Structure:
    n: int
    p1: int
    p2: int
    W: int
    groups: tuple[Group, ...]
    mechanism_class: int
    linkage: Linkage = field(repr=False, compare=False)

    @cached_property
    def _numerical(self) -> tuple[int, int]:
        return numerical_mobility(self.linkage)

    @property
    def W_numeric(self) -> int:
        """W from the rank of the constraint Jacobian at the sketch (computed when first read: the
        solve does not need it)."""
        return self._numerical[0]

    @property
    def redundant(self) -> int:
        """Redundant constraints: rows of the Jacobian less its rank (computed when first read)."""
        return self._numerical[1]

    @property
    def formula(self) -> str:
        parts = []
        for g in self.groups:
            if g.group_class == 1:
                parts.append(f"I(0,{','.join(map(str, g.links))})")
            else:
                parts.append(g.label)
        return " → ".join(parts)

    def to_dict(self) -> dict:
        groups = []
        for g in self.groups:
            if g.group_class == 1:
                groups.append({"links": list(g.links), "class": 1, "kind": "driver"})
            else:
                groups.append({"links": list(g.links), "class": g.group_class, "order": g.order, "kind": g.kind})
        return {"n": self.n, "p1": self.p1, "p2": self.p2, "W": self.W, "W_numeric": self.W_numeric,
                "redundant_constraints": self.redundant, "groups": groups,
                "mechanism_class": self.mechanism_class, "formula": self.formula}


def _pairs_of(linkage: Linkage, S: frozenset[int], known: frozenset[int]) -> list[Pair]:
    """The pairs that bind the links of S to each other and to the known links."""
    pairs: list[Pair] = []
    for j in linkage.joints:
        in_s = [b for b in j.bodies if b in S]
        if not in_s:
            continue
        in_k = [b for b in j.bodies if b in known]
        if in_k:
            ref = in_k[0]
            pairs.extend(Pair("R", (ref, b), j.name, True) for b in in_s)
        else:
            pairs.extend(Pair("R", (in_s[0], b), j.name, False) for b in in_s[1:])
    for s in linkage.slides:
        a, g = s.link, s.guide
        if (a in S and (g in S or g in known)) or (g in S and a in known):
            ext = (a in known) or (g in known)
            pairs.append(Pair("P", (g, a), s.point, ext, s.index))
    return pairs


def _is_connected(S: frozenset[int], pairs: list[Pair]) -> bool:
    if len(S) <= 1:
        return True
    adj: dict[int, set[int]] = {k: set() for k in S}
    for p in pairs:
        a, b = p.bodies
        if a in S and b in S:
            adj[a].add(b)
            adj[b].add(a)
    start = next(iter(S))
    seen = {start}
    stack = [start]
    while stack:
        for nb in adj[stack.pop()]:
            if nb not in seen:
                seen.add(nb)
                stack.append(nb)
    return seen == set(S)


def _longest_cycle(nodes: tuple[int, ...], edges: list[tuple[int, int]]) -> int:
    """Length of the longest simple cycle of a small multigraph (0 if none)."""
    adj: dict[int, list[int]] = {k: [] for k in nodes}
    for a, b in edges:
        adj[a].append(b)
        adj[b].append(a)
    best = 0
    # parallel edges make a contour of two links
    seen_pairs: dict[frozenset, int] = {}
    for a, b in edges:
        seen_pairs[frozenset((a, b))] = seen_pairs.get(frozenset((a, b)), 0) + 1
    if any(v >= 2 for v in seen_pairs.values()):
        best = 2

    def dfs(start: int, cur: int, visited: list[int]) -> None:
        nonlocal best
        for nb in adj[cur]:
            if nb == start and len(visited) >= 3:
                best = max(best, len(visited))
            elif nb not in visited and nb > start:
                visited.append(nb)
                dfs(start, nb, visited)
                visited.pop()

    for s in nodes:
        dfs(s, s, [s])
    return best


def _classify(S: tuple[int, ...], pairs: list[Pair]) -> tuple[int, int, str]:
    internal = [p for p in pairs if not p.external]
    order = sum(1 for p in pairs if p.external)
    if len(S) == 2:
        a, b = S
        ext_a = next(p for p in pairs if p.external and a in p.bodies)
        ext_b = next(p for p in pairs if p.external and b in p.bodies)
        code = ext_a.kind + internal[0].kind + ext_b.kind
        canon = {"PRR": "RRP", "PPR": "RPP"}.get(code, code)
        return 2, order, canon
    edges = [p.bodies for p in internal]
    cyc = _longest_cycle(S, edges)
    cls = max(3, cyc)
    prismatic = sum(1 for p in pairs if p.kind == "P")
    base = {"III": "triad", "IV": "quad"}.get({3: "III", 4: "IV"}.get(cls, ""), f"class-{cls}")
    kind = base if not prismatic else f"{base}-{prismatic}P"
    return cls, order, kind


def chebyshev(linkage: Linkage) -> tuple[int, int, int, int]:
    """(n, p1, p2, W) with W = 3n − 2p1 − p2."""
    n = len(linkage.moving)
    p1 = sum(j.pairs for j in linkage.joints) + len(linkage.slides)
    p2 = 0
    return n, p1, p2, 3 * n - 2 * p1 - p2


def numerical_mobility(linkage: Linkage) -> tuple[int, int]:
    """(W, redundant) from the rank of the constraint Jacobian at the sketch (a generic position).

    W = 3n − rank(J); redundant constraints = rows(J) − rank(J).
    """
    from .kinematics.constraints import all_pair_constraints, jacobian_full

    q = sketch_q(linkage)[None, :, :]
    cons = all_pair_constraints(linkage)
    J = jacobian_full(linkage, cons, q)[0]
    if J.size == 0:
        return 3 * len(linkage.moving), 0
    # Scale rotations by a characteristic length so that the rank test is unit-free.
    lengths = [abs(v) for b in linkage.bodies.values() for p in b.local.values() for v in p]
    L = max(lengths) if lengths else 1.0
    J = J.copy()
    J[:, 2::3] /= L
    s = np.linalg.svd(J, compute_uv=False)
    tol = s.max() * max(J.shape) * RTOL_RANK if s.size else 0.0
    rank = int((s > tol).sum())
    return 3 * len(linkage.moving) - rank, J.shape[0] - rank


def analyse_structure(linkage: Linkage) -> Structure:
    """Chebyshev's W, numerical W, and the decomposition into the driver and Assur groups."""
    n, p1, p2, W = chebyshev(linkage)
    d = linkage.drive_link
    known = frozenset({0, d})
    driver_pairs = _pairs_of(linkage, frozenset({d}), frozenset({0}))
    groups = [Group((d,), 1, 1, "driver", tuple(driver_pairs))]
    remaining = set(linkage.moving) - {d}
    while remaining:
        found = None
        for size in range(2, min(len(remaining), MAX_GROUP_LINKS) + 1, 2):
            for combo in itertools.combinations(sorted(remaining), size):
                S = frozenset(combo)
                pairs = _pairs_of(linkage, S, known)
                if 3 * size != 2 * len(pairs):
                    continue
                if not any(p.external for p in pairs) or not _is_connected(S, pairs):
                    continue
                # every link of S must take part in at least two pairs
                if any(sum(1 for p in pairs if k in p.bodies) < 2 for k in S):
                    continue
                found = (combo, pairs)
                break
            if found:
                break
        if not found:
            left = tuple(sorted(remaining))
            if W <= 0:
                cause = (f"W = {W}: the chain has too many pairs or a redundant link (the remaining links "
                         f"form a rigid or over-constrained structure)")
            elif W >= 2:
                cause = (f"W = {W}: the chain needs {W} drivers, or a pair is missing (a point listed by one "
                         f"link only, or a slide not given); reportgen analyses mechanisms with one driver (W = 1)")
                jointed = {j.name for j in linkage.joints} | {(s.link, s.point) for s in linkage.slides}
                lone = [f"{name} (link {k})" for k in left for name in linkage.bodies[k].points
                        if name not in jointed and (k, name) not in jointed]
                if lone:
                    cause += (f"; points listed by one link only: {', '.join(lone)} (a revolute pair needs its "
                              f"point in the points of both links it joins)")
            else:
                cause = "a pair is missing or the links are attached to nothing already known"
            W_num, redundant = numerical_mobility(linkage)
            if W_num != W:
                cause += (f"; the rank of the constraint equations gives W = {W_num} with {redundant} redundant "
                          f"constraint(s) (e.g. a parallel link of a parallelogram)")
            raise StructureError("the chain cannot be decomposed into Assur groups", left, cause)
        combo, pairs = found
        cls, order, kind = _classify(combo, pairs)
        groups.append(Group(tuple(combo), cls, order, kind, tuple(pairs)))
        known = known | frozenset(combo)
        remaining -= set(combo)
    if W != 1:
        raise StructureError(f"the mechanism has W = 3·{n} − 2·{p1} − {p2} = {W} by Chebyshev; "
                             f"reportgen analyses mechanisms with one driver (W = 1)", (), None)
    mclass = max(g.group_class for g in groups)
    return Structure(n, p1, p2, W, tuple(groups), mclass, linkage)
