"""Positions of the groups: closed forms for the five dyads, Newton for class III and higher.

Every function takes the poses ``q`` (N, bodies, 3) with the bodies of earlier groups filled in,
and writes the poses of its group's bodies. Each dyad keeps the assembly branch ``sigma`` fixed
once from the sketch, so that every position is solved independently and reproducibly.

Closed forms (with P*, S* the known pins, Q the inner pair):
- RRR: Q on two circles: x = (l_a² + D² − l_b²)/(2D), h² = (l_a − x)(l_a + x) (no cancellation
  near toggles), Q = P* + x·e + σ·h·perp(e).
- RRP: Q on a circle and a line: foot F, δ = distance of P* from the line, t² = (l − δ)(l + δ),
  Q = F + σ·t·u.
- RPR: the slot angle ψ from n(ψ)·(H* − G*) = e: ψ = ∠(H* − G*) − ∠n₀ − σ·acos(e/ρ).
- PRP, RPP: both angles follow from the slides; the remaining equations are linear in the
  positions and are solved exactly by one linear step.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import AssemblyError
from ..geometry import cross as _cross, dot as _dot
from ..linkage import Linkage
from ..structure import Group, Pair
from ..tolerances import ABS_ROUNDOFF, NEWTON_REL_TOL, RTOL_EQUAL
from .constraints import Constraint, RevoluteC, SlideC, Trig, arm, assemble, perp, residual, revolute, world

#: Newton on class III+ groups: iteration cap (its step tolerance: tolerances.NEWTON_REL_TOL).
NEWTON_MAX_ITER = 50


def group_constraints(linkage: Linkage, group: Group) -> list[Constraint]:
    cons: list[Constraint] = []
    for p in group.pairs:
        if p.kind == "R":
            cons.append(revolute(linkage, p.point, p.bodies[0], p.bodies[1]))
        else:
            cons.append(SlideC(linkage.slides[p.slide]))
    return cons


def set_pose_two_points(q: np.ndarray, k: int, pl: tuple, ql: tuple, wp: np.ndarray, wq: np.ndarray,
                        trig: Trig | None = None) -> None:
    """Pose of body k from the world positions of two of its points."""
    ang_local = math.atan2(ql[1] - pl[1], ql[0] - pl[0])
    th = np.arctan2(wq[:, 1] - wp[:, 1], wq[:, 0] - wp[:, 0]) - ang_local
    q[:, k, 2] = th
    q[:, k, :2] = wp - arm(q, k, pl, trig)      # R(θ_k)·pl from the angle just stored


class DyadSolver:
    """Closed-form position solver of a dyad; ``sigma`` is the assembly branch (+1 or −1)."""

    def __init__(self, linkage: Linkage, group: Group, _known: set[int]):
        self.linkage = linkage
        self.group = group
        self.kind = group.kind
        self.sigma: float | np.ndarray = 1.0   # an array: one branch per position (both tried at once)
        self.cons = group_constraints(linkage, group)
        a, b = group.links
        self.a, self.b = a, b
        ext = [p for p in group.pairs if p.external]
        self.internal = next(p for p in group.pairs if not p.external)
        self.ext_of = {k: next(p for p in ext if k in p.bodies) for k in (a, b)}

    # -- helpers -------------------------------------------------------------------------------
    def _local(self, k: int, point: str) -> tuple[float, float]:
        return self.linkage.bodies[k].local[point]

    def _known_body(self, pair: Pair, k: int) -> int:
        return pair.bodies[0] if pair.bodies[1] == k else pair.bodies[1]

    def _angle_from_slide(self, q: np.ndarray, pair: Pair, k: int) -> np.ndarray:
        """θ_k from a slide whose other body is known."""
        s = self.linkage.slides[pair.slide]
        if s.link == k:
            return q[:, s.guide, 2] + s.rel_angle
        return q[:, s.link, 2] - s.rel_angle

    def _line_of_point(self, q: np.ndarray, pair: Pair, k: int, point: str, trig: Trig | None = None
                       ) -> tuple[np.ndarray, np.ndarray]:
        """The world line (origin, unit direction) on which ``point`` of body k must lie, given θ_k,
        from the slide ``pair`` between k and a body of known pose."""
        s = self.linkage.slides[pair.slide]
        pk = self._local(k, point)
        if s.link == k:   # k slides on the known guide's line
            L0 = world(q, s.guide, s.line_point, trig)
            u = arm(q, s.guide, s.line_dir, trig)
            off = arm(q, k, (pk[0] - s.point_local[0], pk[1] - s.point_local[1]), trig)
            return L0 + off, u
        # the known body's point slides on k's line
        D = world(q, s.link, s.point_local, trig)
        u = arm(q, k, s.line_dir, trig)
        off = arm(q, k, (pk[0] - s.line_point[0], pk[1] - s.line_point[1]), trig)
        return D + off, u

    # -- solving ---------------------------------------------------------------------------------
    def solve(self, q: np.ndarray, phi: np.ndarray, strict: bool = True, trig: Trig | None = None) -> np.ndarray:
        """Fill the group's poses; return the assembly margin (≥ 0 where it assembles). ``trig``:
        the cos/sin cache of ``q`` (:class:`~reportgen.kinematics.constraints.Trig`), when the
        caller keeps one for the whole solve."""
        kind = self.kind
        if kind == "RRR":
            return self._rrr(q, phi, strict, trig)
        if kind == "RRP":
            return self._rrp(q, phi, strict, trig)
        if kind == "RPR":
            return self._rpr(q, phi, strict, trig)
        return self._linear(q, phi, strict)

    def _fail(self, phi: np.ndarray, margin: np.ndarray, text) -> None:
        bad = np.flatnonzero(margin < 0)
        if bad.size:
            i = int(bad[0])
            raise AssemblyError(f"{self.group.label} {self.kind}", math.degrees(phi[i]) % 360.0, text(i))

    def _rrr(self, q, phi, strict, trig=None):
        a, b = self.a, self.b
        pa, pb, pi = self.ext_of[a], self.ext_of[b], self.internal
        P = world(q, self._known_body(pa, a), self._local(self._known_body(pa, a), pa.point), trig)
        S = world(q, self._known_body(pb, b), self._local(self._known_body(pb, b), pb.point), trig)
        la = math.dist(self._local(a, pa.point), self._local(a, pi.point))
        lb = math.dist(self._local(b, pb.point), self._local(b, pi.point))
        d = S - P
        D = np.hypot(d[:, 0], d[:, 1])
        margin = np.minimum(la + lb - D, D - abs(la - lb)) / (la + lb)
        if strict:
            self._fail(phi, margin, lambda i: (
                f"|l{a} − l{b}| ≤ {pa.point}{pb.point} ≤ l{a} + l{b} fails: |{la:.4g} − {lb:.4g}| ≤ {D[i]:.4g} ≤ "
                f"{la + lb:.4g} m (l{a} = {pa.point}{pi.point}, l{b} = {pb.point}{pi.point})"))
        Ds = np.where(D > 0, D, np.nan)
        e = d / Ds[:, None]
        x = (la * la - lb * lb + D * D) / (2 * Ds)
        h = np.sqrt(np.clip((la - x) * (la + x), 0.0, None))
        Q = P + x[:, None] * e + (self.sigma * h)[:, None] * perp(e)
        set_pose_two_points(q, a, self._local(a, pa.point), self._local(a, pi.point), P, Q, trig)
        set_pose_two_points(q, b, self._local(b, pb.point), self._local(b, pi.point), S, Q, trig)
        return margin

    def _rrp(self, q, phi, strict, trig=None):
        a, b = self.a, self.b
        # r: the link with the external revolute; p: the link with the external slide
        r, p = (a, b) if self.ext_of[a].kind == "R" else (b, a)
        pr, pp, pi = self.ext_of[r], self.ext_of[p], self.internal
        kr = self._known_body(pr, r)
        P = world(q, kr, self._local(kr, pr.point), trig)
        th_p = self._angle_from_slide(q, pp, p)
        q[:, p, 2] = th_p           # (the link's angle first: the line of its point turns with it)
        L0, u = self._line_of_point(q, pp, p, pi.point, trig)
        l = math.dist(self._local(r, pr.point), self._local(r, pi.point))
        w = P - L0
        along = _dot(w, u)
        F = L0 + along[:, None] * u
        delta = np.abs(_cross(u, w))
        margin = (l - delta) / l
        if strict:
            self._fail(phi, margin, lambda i: (
                f"the distance from {pr.point} to the line of {pi.point}, {delta[i]:.4g} m, exceeds "
                f"{pr.point}{pi.point} = {l:.4g} m"))
        t = np.sqrt(np.clip((l - delta) * (l + delta), 0.0, None))
        Q = F + (self.sigma * t)[:, None] * u
        set_pose_two_points(q, r, self._local(r, pr.point), self._local(r, pi.point), P, Q, trig)
        q[:, p, :2] = Q - arm(q, p, self._local(p, pi.point), trig)
        return margin

    def _rpr(self, q, phi, strict, trig=None):
        s = self.linkage.slides[self.internal.slide]
        g, sl = s.guide, s.link
        pg, ps = self.ext_of[g], self.ext_of[sl]
        kg, ks = self._known_body(pg, g), self._known_body(ps, sl)
        G = world(q, kg, self._local(kg, pg.point), trig)
        H = world(q, ks, self._local(ks, ps.point), trig)
        gp, hp = self._local(g, pg.point), self._local(sl, ps.point)
        c = s.rel_angle
        cc, sc = math.cos(c), math.sin(c)
        dv = (s.point_local[0] - hp[0], s.point_local[1] - hp[1])
        rd = (cc * dv[0] - sc * dv[1], sc * dv[0] + cc * dv[1])
        n0 = (-s.line_dir[1], s.line_dir[0])
        e = -(n0[0] * (rd[0] - (s.line_point[0] - gp[0])) + n0[1] * (rd[1] - (s.line_point[1] - gp[1])))
        Dv = H - G
        rho = np.hypot(Dv[:, 0], Dv[:, 1])
        margin = (rho - abs(e)) / np.maximum(rho, abs(e) if e else 1.0)
        if strict:
            self._fail(phi, margin, lambda i: (
                f"the offset of the line {abs(e):.4g} m exceeds the distance {pg.point}{ps.point} = {rho[i]:.4g} m"))
        ratio = np.clip(e / np.where(rho > 0, rho, np.nan), -1.0, 1.0)
        psi = np.arctan2(Dv[:, 1], Dv[:, 0]) - math.atan2(n0[1], n0[0]) - self.sigma * np.arccos(ratio)
        q[:, g, 2] = psi
        q[:, g, :2] = G - arm(q, g, gp, trig)
        q[:, sl, 2] = psi + c
        q[:, sl, :2] = H - arm(q, sl, hp, trig)
        return margin

    def _linear(self, q, phi, strict):
        """PRP and RPP: angles from the slides, then positions from the linear equations."""
        a, b = self.a, self.b
        known_theta: dict[int, np.ndarray] = {}
        for _ in range(2):
            for p in self.group.pairs:
                if p.kind != "P":
                    continue
                s = self.linkage.slides[p.slide]
                if s.link in (a, b) and s.link not in known_theta and (s.guide not in (a, b) or s.guide in known_theta):
                    known_theta[s.link] = (known_theta.get(s.guide) if s.guide in (a, b) else q[:, s.guide, 2]) + s.rel_angle
                if s.guide in (a, b) and s.guide not in known_theta and (s.link not in (a, b) or s.link in known_theta):
                    known_theta[s.guide] = (known_theta.get(s.link) if s.link in (a, b) else q[:, s.link, 2]) - s.rel_angle
        for k in (a, b):
            q[:, k, 2] = known_theta[k]
            q[:, k, :2] = 0.0
        J, _ = assemble(self.cons, q, [a, b])
        F = residual(self.cons, q)
        pos_rows = [i for i, c in enumerate(_row_kinds(self.cons)) if c != "angle"]
        pos_cols = [0, 1, 3, 4]
        A = J[:, pos_rows][:, :, pos_cols]
        rhs = -F[:, pos_rows]
        det = np.linalg.det(A)
        scale = np.prod(np.linalg.norm(A, axis=2), axis=1)
        margin = np.abs(det) / np.where(scale > 0, scale, 1.0) - RTOL_EQUAL
        if strict:
            self._fail(phi, margin, lambda _i: "the two lines of the group are parallel: no intersection")
        ok = margin >= 0
        x = np.zeros((q.shape[0], 4))
        if ok.any():
            x[ok] = np.linalg.solve(A[ok], rhs[ok][..., None])[..., 0]
        x[~ok] = np.nan
        q[:, a, :2] = x[:, 0:2]
        q[:, b, :2] = x[:, 2:4]
        return margin


def _row_kinds(cons: list[Constraint]) -> list[str]:
    kinds = []
    for c in cons:
        if isinstance(c, RevoluteC):
            kinds += ["pos", "pos"]
        else:
            kinds += ["pos", "angle"]
    return kinds


class NewtonSolver:
    """Class III and higher: Newton–Raphson on the group's constraints, one position at a time,
    started from a prediction (the previous position advanced with the exact velocity and
    acceleration) or, at the sketch, from the sketch itself."""

    def __init__(self, linkage: Linkage, group: Group, _known: set[int]):
        self.linkage = linkage
        self.group = group
        self.cons = group_constraints(linkage, group)
        self.cols = list(group.links)
        lengths = [abs(v) for k in self.cols for p in linkage.bodies[k].local.values() for v in p]
        self.L = max(lengths + [ABS_ROUNDOFF])

    def newton(self, q: np.ndarray, phi: np.ndarray, strict: bool = True) -> np.ndarray:
        """Refine the group's poses in q (N positions, each from its own start); return a margin."""
        N = q.shape[0]
        converged = np.zeros(N, dtype=bool)
        for _ in range(NEWTON_MAX_ITER):
            F = residual(self.cons, q)
            J, _ = assemble(self.cons, q, self.cols)
            try:
                dx = np.linalg.solve(J, -F[..., None])[..., 0]
            except np.linalg.LinAlgError:
                dx = np.stack([np.linalg.lstsq(J[i], -F[i], rcond=None)[0] for i in range(N)])
            step = dx.reshape(N, len(self.cols), 3)
            # limit rotations per step (damping far from the solution)
            big = np.abs(step[..., 2]).max(axis=1) > 0.5
            if big.any():
                step[big] *= (0.5 / np.abs(step[big][..., 2]).max(axis=1))[:, None, None]
            for i, k in enumerate(self.cols):
                q[:, k, :] += step[:, i, :]
            size = np.abs(step[..., :2]).max(axis=(1, 2)) / self.L + np.abs(step[..., 2]).max(axis=1)
            converged = size < NEWTON_REL_TOL * 10
            if converged.all():
                break
        F = np.abs(residual(self.cons, q)).max(axis=1) / self.L
        margin = np.where(F < RTOL_EQUAL, 1.0, -1.0)
        if strict and (margin < 0).any():
            i = int(np.flatnonzero(margin < 0)[0])
            raise AssemblyError(f"{self.group.label} {self.group.kind}", math.degrees(phi[i]) % 360.0,
                                f"Newton's method found no closed position (residual {F[i]:.3g} of the "
                                f"group's size)")
        return margin
