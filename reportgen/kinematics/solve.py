"""Exact kinematics of the whole mechanism over any set of crank angles.

Positions group by group (closed forms for dyads, Newton for class III+); velocities and
accelerations group by group from the linear systems of the differentiated constraints
(J·q̇ = −J_known·q̇_known, J·q̈ = γ − J_known·q̈_known) — no finite differences. The crank turns at
constant ω: θ₁ = φ − α, θ̇₁ = ω, θ̈₁ = 0.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Callable, Mapping

import numpy as np

from ..errors import AssemblyError, SingularPositionError
from ..linkage import Linkage, compile_linkage, sketch_q
from ..numbers import clean_array
from ..structure import Group, Structure, analyse_structure
from ..task import Mechanism
from .constraints import Trig, arm, assemble, gamma, known_terms, perp, trig_of, world
from .positions import DyadSolver, NewtonSolver, group_constraints
from .transmission import NEAR_SINGULAR_DEG, transmission_angle
from ..geometry import frozen, readonly as _ro
from ..tolerances import ABS_ROUNDOFF

#: Largest crank step when following a class III+ group by continuation, rad.
CONTINUATION_STEP = math.radians(5.0)


@dataclass(frozen=True)
class PointMotion:
    """Position, velocity and acceleration of a point at every analysed position, (N, 2) each."""
    pos: np.ndarray
    vel: np.ndarray
    acc: np.ndarray


@dataclass(frozen=True)
class LinkMotion:
    """Angle (rad), angular velocity and angular acceleration of a link, (N,) each."""
    angle: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray


class DerivedMotions(Mapping):
    """A read-only mapping of motions derived from the poses, velocities and accelerations (q, q̇,
    q̈), each computed when first read and kept: a solve that reads one point pays for one."""

    def __init__(self, makers: dict) -> None:
        self._makers = dict(makers)
        self._done: dict = {}

    def __getitem__(self, key):
        try:
            return self._done[key]
        except KeyError:
            value = self._done[key] = self._makers[key]()
            return value

    def __iter__(self):
        return iter(self._makers)

    def __len__(self) -> int:
        return len(self._makers)

    def __repr__(self) -> str:
        return f"DerivedMotions({list(self._makers)})"


def _deferred(fn: Callable, *args) -> Callable[[], PointMotion]:
    return lambda: fn(*args)


def _cleaned(make: Callable[[], PointMotion], v_scale: float, a_scale: float) -> PointMotion:
    """A point's motion with its round-off residue made exact zeros (see ``_without_residue``); an
    acceleration not solved (NaN) is kept as it is."""
    m = make()
    acc = m.acc if m.acc is _NO_ACC.get(m.acc.shape[0]) else frozen(clean_array(m.acc, a_scale))
    return PointMotion(m.pos, frozen(clean_array(m.vel, v_scale)), acc)


#: The accelerations of a solve without them: one NaN array per number of positions, shared.
_NO_ACC: dict[int, np.ndarray] = {}


def _no_acc(n: int) -> np.ndarray:
    a = _NO_ACC.get(n)
    if a is None:
        if len(_NO_ACC) > 64:
            _NO_ACC.clear()
        a = _NO_ACC[n] = frozen(np.full((n, 2), np.nan))
    return a


def _fixed_point(xy, n: int) -> PointMotion:
    z = np.zeros((n, 2))
    p = np.broadcast_to(np.asarray(xy, dtype=float), (n, 2))
    return PointMotion(_ro(p), _ro(z), _ro(z.copy()))


@dataclass(frozen=True)
class KinematicsResult:
    phi: np.ndarray                       # crank angles φ1, rad
    omega1: float
    q: np.ndarray                         # (N, bodies, 3) poses
    qd: np.ndarray
    qdd: np.ndarray
    points: Mapping[str, PointMotion]
    coms: Mapping[int, PointMotion]
    links: Mapping[int, LinkMotion]
    transmission_deg: Mapping[str, np.ndarray]      # computed when first read

    @cached_property
    def near_singular(self) -> tuple[tuple[int, str, float], ...]:
        """(index, group key, μ) of every position where a group's transmission angle μ is below
        ``NEAR_SINGULAR_DEG`` (group by group, in the order of the structure)."""
        return tuple((int(i), key, float(mu[i])) for key, mu in self.transmission_deg.items()
                     for i in np.flatnonzero(mu < NEAR_SINGULAR_DEG))

    @property
    def phi_deg(self) -> np.ndarray:
        return np.degrees(self.phi)


class KinematicModel:
    """The mechanism ready to be solved at any crank angles (branches fixed from the sketch)."""

    _coarse: tuple[np.ndarray, np.ndarray, np.ndarray]  # set by _coarse_march

    def __init__(self, linkage: Linkage, structure: Structure):
        self.linkage = linkage
        self.structure = structure
        self.nb = max(linkage.bodies) + 1
        self.alpha = linkage.crank_offset()
        self.omega = linkage.omega
        known = {0, linkage.drive_link}
        self.solvers: list[DyadSolver | NewtonSolver] = []
        for g in structure.groups[1:]:
            self.solvers.append(DyadSolver(linkage, g, known) if g.group_class == 2 else NewtonSolver(linkage, g, known))
            known |= set(g.links)
        self.group_rows = [group_constraints(linkage, g) for g in structure.groups[1:]]
        self._sketch_q = sketch_q(linkage)
        try:
            self._choose_branches()
        except AssemblyError as exc:
            raise AssemblyError(exc.group, exc.phi_deg, exc.inequality + " (at the sketch's crank angle)",
                                self._feasible_dyads_only()) from None

    @property
    def positions_independent(self) -> bool:
        """Whether every position is solved on its own, so that its values do not depend on the
        other angles of the same call (closed-form dyads; a class III group's Newton iterations
        run until the whole call converges)."""
        return all(isinstance(s, DyadSolver) for s in self.solvers)

    # -- driver --------------------------------------------------------------------------------
    def _driver(self, q: np.ndarray, phi: np.ndarray, trig: Trig | None = None) -> None:
        d = self.linkage.drive_link
        b = self.linkage.bodies[d]
        th = phi - self.alpha
        q[:, d, 2] = th
        O = np.asarray(self.linkage.sketch[self.linkage.drive_axis])
        q[:, d, :2] = O - arm(q, d, b.local[self.linkage.drive_axis], trig)

    def _driver_vel(self, q: np.ndarray, qd: np.ndarray, trig: Trig | None = None) -> None:
        d = self.linkage.drive_link
        p = self.linkage.bodies[d].local[self.linkage.drive_axis]
        qd[:, d, 2] = self.omega
        qd[:, d, :2] = -self.omega * perp(arm(q, d, p, trig))

    def _driver_acc(self, q: np.ndarray, qdd: np.ndarray, trig: Trig | None = None) -> None:
        d = self.linkage.drive_link
        p = self.linkage.bodies[d].local[self.linkage.drive_axis]
        qdd[:, d, 2] = 0.0
        qdd[:, d, :2] = self.omega ** 2 * arm(q, d, p, trig)

    # -- branches --------------------------------------------------------------------------------
    def _choose_branches(self) -> None:
        """For each dyad, the branch whose inner point is nearest to the sketch."""
        phi0 = np.array([self.linkage.sketch_phi()])
        q = np.zeros((1, self.nb, 3))
        self._driver(q, phi0)
        for solver, g in zip(self.solvers, self.structure.groups[1:]):
            if isinstance(solver, DyadSolver):
                # both branches in one solve (rows σ = +1, −1; each position is solved on its own)
                sigmas = (1.0, -1.0)
                qq = np.repeat(q, 2, axis=0)
                solver.sigma = np.array(sigmas)
                try:
                    solver.solve(qq, np.repeat(phi0, 2), strict=True)
                finally:
                    solver.sigma = 1.0
                dist = [np.hypot(*(world(qq, k, self.linkage.bodies[k].local[name])
                                   - np.asarray(self.linkage.sketch[name])).T)
                        for k in g.links for name in self.linkage.bodies[k].points]
                best: tuple[float, int] | None = None
                for row in range(2):
                    err = 0.0
                    for h in dist:
                        err += float(h[row])
                    if best is None or err < best[0] - ABS_ROUNDOFF:
                        best = (err, row)
                assert best is not None
                solver.sigma = sigmas[best[1]]
                q = qq[best[1]:best[1] + 1].copy()
            else:
                for k in g.links:
                    q[:, k, :] = self._sketch_q[k]
                solver.newton(q, phi0, strict=True)
        self._q0 = q
        self._phi0 = float(phi0[0])

    # -- positions, velocities, accelerations ---------------------------------------------------
    def positions(self, phi: np.ndarray, strict: bool = True) -> tuple[np.ndarray, np.ndarray]:
        """Poses at the crank angles ``phi``; also a mask of the positions where all groups assemble."""
        q, ok, _ = self._positions(phi, strict)
        return q, ok

    def _positions(self, phi: np.ndarray, strict: bool = True) -> tuple[np.ndarray, np.ndarray, Trig]:
        """:meth:`positions` and the cos/sin cache of the poses (filled as the groups are solved: each
        body's rotation computed once for the positions, the velocities and the accelerations)."""
        phi = np.asarray(phi, dtype=float)
        if not self.positions_independent:
            q, ok = self._positions_by_continuation(phi, strict)
            return q, ok, trig_of(q)
        N = phi.size
        q = np.zeros((N, self.nb, 3))
        trig = trig_of(q)
        self._driver(q, phi, trig)
        ok = np.ones(N, dtype=bool)
        for solver in self.solvers:
            assert isinstance(solver, DyadSolver)  # a NewtonSolver went by continuation above
            margin = solver.solve(q, phi, strict=strict, trig=trig)
            ok &= margin >= 0
        return q, ok, trig

    def positions_kept(self, phi: tuple[float, ...]) -> np.ndarray:
        """Poses at a few fixed crank angles asked again and again (the stroke's ends, read by the
        resistance at every solve), computed once per model (read-only)."""
        kept = self.__dict__.setdefault("_kept", {})
        if phi not in kept:
            kept[phi] = _ro(self.positions(np.array(phi, dtype=float))[0])
        return kept[phi]

    def _step(self, ph: np.ndarray, prev_q: np.ndarray | None, dt: float, strict: bool) -> tuple[np.ndarray, bool]:
        """One position: dyads in closed form, class III+ groups by Newton from a prediction."""
        qq = np.zeros((1, self.nb, 3))
        self._driver(qq, ph)
        if prev_q is not None:
            qd = self.velocities(prev_q)
            qdd = self.accelerations(prev_q, qd)
        ok = True
        for solver, g in zip(self.solvers, self.structure.groups[1:]):
            if isinstance(solver, DyadSolver):
                ok &= bool((solver.solve(qq, ph, strict=strict) >= 0).all())
            else:
                cols = list(g.links)
                if prev_q is None:
                    qq[:, cols, :] = self._q0[:, cols, :]
                else:
                    qq[:, cols, :] = prev_q[:, cols, :] + qd[:, cols, :] * dt + 0.5 * qdd[:, cols, :] * dt * dt
                ok &= bool((solver.newton(qq, ph, strict=strict) >= 0).all())
        return qq, ok

    def _coarse_march(self, strict: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The whole turn from the sketch in steps of ``CONTINUATION_STEP`` (computed once): poses,
        velocities and accelerations at offsets j·step in the direction of rotation."""
        if getattr(self, "_coarse", None) is not None:
            return self._coarse
        n = int(math.ceil(2 * math.pi / CONTINUATION_STEP))
        step = 2 * math.pi / n
        sgn = 1.0 if self.omega >= 0 else -1.0
        w = abs(self.omega) if self.omega else 1.0
        qs = [self._q0.copy()]
        for j in range(1, n + 1):
            qq, _ = self._step(np.array([self._phi0 + sgn * j * step]), qs[-1], step / w, strict)
            qs.append(qq)
        q = np.concatenate(qs[:-1], axis=0)
        qd = self.velocities(q)
        qdd = self.accelerations(q, qd)
        self._coarse = (q, qd, qdd)
        return self._coarse

    def _positions_by_continuation(self, phi: np.ndarray, strict: bool) -> tuple[np.ndarray, np.ndarray]:
        """Class III+ groups: follow the mechanism once around the turn from the sketch in steps of at
        most ``CONTINUATION_STEP`` (so that they stay on the sketch's branch), then start Newton at every
        requested angle from the nearest preceding step, advanced with its exact velocity and
        acceleration (all positions at once)."""
        cq, cqd, cqdd = self._coarse_march(strict)
        n = cq.shape[0]
        step = 2 * math.pi / n
        sgn = 1.0 if self.omega >= 0 else -1.0
        w = abs(self.omega) if self.omega else 1.0
        offs = np.mod(sgn * (phi - self._phi0), 2 * math.pi)
        j = np.minimum((offs // step).astype(int), n - 1)
        dt = ((offs - j * step) / w)[:, None]
        N = phi.size
        q = np.zeros((N, self.nb, 3))
        self._driver(q, phi)
        ok = np.ones(N, dtype=bool)
        for solver, g in zip(self.solvers, self.structure.groups[1:]):
            if isinstance(solver, DyadSolver):
                ok &= solver.solve(q, phi, strict=strict) >= 0
            else:
                cols = list(g.links)
                q[:, cols, :] = cq[j][:, cols, :] + cqd[j][:, cols, :] * dt[:, :, None] \
                    + 0.5 * cqdd[j][:, cols, :] * (dt * dt)[:, :, None]
                ok &= solver.newton(q, phi, strict=strict) >= 0
        return q, ok

    def velocities(self, q: np.ndarray, upto: int | None = None, jacobians: dict | None = None,
                   trig: Trig | None = None) -> np.ndarray:
        """q̇ at the poses ``q``; ``jacobians`` (a dict) keeps each group's J for the accelerations;
        ``trig``: cos and sin of the poses' angles when the caller has them (:func:`trig_of`)."""
        qd = np.zeros_like(q)
        self._driver_vel(q, qd, trig)
        return self._by_groups(q, qd, lambda _cons, rows, cols: -known_terms(rows, qd, set(cols)), upto, jacobians,
                               trig)

    def accelerations(self, q: np.ndarray, qd: np.ndarray, upto: int | None = None,
                      jacobians: dict | None = None, trig: Trig | None = None) -> np.ndarray:
        """q̈ at the poses ``q`` with velocities ``qd`` (``jacobians``: those the velocities kept)."""
        qdd = np.zeros_like(q)
        self._driver_acc(q, qdd, trig)

        def rhs(cons, rows, cols):
            gm = np.stack([r for c in cons for r in gamma(c, q, qd, trig)], axis=-1)
            return gm - known_terms(rows, qdd, set(cols))
        return self._by_groups(q, qdd, rhs, upto, jacobians, trig)

    def _by_groups(self, q: np.ndarray, out: np.ndarray,
                   rhs: Callable[[list, list, list[int]], np.ndarray], upto: int | None,
                   jacobians: dict | None = None, trig: Trig | None = None) -> np.ndarray:
        """Solve the groups in order (the first ``upto`` of them): J·x = rhs(constraints, rows, columns)
        for each group's unknowns, written into ``out`` (the derivative the later groups read). The
        velocity and acceleration systems share J: a ``jacobians`` dict carries it from one to the other."""
        groups = self.structure.groups[1:]
        for n_g, (g, cons) in enumerate(zip(groups, self.group_rows)):
            if upto is not None and n_g >= upto:
                break
            cols = list(g.links)
            if jacobians is not None and n_g in jacobians:
                J, rows = jacobians[n_g]
            else:
                J, rows = assemble(cons, q, cols, trig)
                if jacobians is not None:
                    jacobians[n_g] = (J, rows)
            x = self._solve(J, rhs(cons, rows, cols), g, q)
            out[:, cols, :] = x.reshape(-1, len(cols), 3)
        return out

    def _solve(self, J: np.ndarray, rhs: np.ndarray, g: Group, q: np.ndarray) -> np.ndarray:
        try:
            return np.linalg.solve(J, rhs[..., None])[..., 0]
        except np.linalg.LinAlgError:
            for i in range(J.shape[0]):
                if np.linalg.matrix_rank(J[i]) < J.shape[1]:
                    raise SingularPositionError(g.label, math.degrees(float(np.arctan2(
                        np.sin(q[i, self.linkage.drive_link, 2] + self.alpha),
                        np.cos(q[i, self.linkage.drive_link, 2] + self.alpha)))) % 360.0,
                        "its velocity equations are singular") from None
            raise

    def feasible_ranges(self, grid: int = 1440) -> tuple[tuple[float, float], ...]:
        """Crank-angle intervals (deg, in 0…360, merged across 360°) where every group assembles."""
        phi = np.linspace(0.0, 2 * math.pi, grid, endpoint=False)
        _, ok = self.positions(phi, strict=False)
        return _intervals(np.degrees(phi), ok)

    def _feasible_dyads_only(self, grid: int = 1440) -> tuple[tuple[float, float], ...] | None:
        if not all(isinstance(s, DyadSolver) for s in self.solvers):
            return None
        phi = np.linspace(0.0, 2 * math.pi, grid, endpoint=False)
        q = np.zeros((grid, self.nb, 3))
        self._driver(q, phi)
        ok = np.ones(grid, dtype=bool)
        with np.errstate(invalid="ignore", divide="ignore"):
            for solver in self.solvers:
                assert isinstance(solver, DyadSolver)  # checked above
                ok &= solver.solve(q, phi, strict=False) >= 0
        return _intervals(np.degrees(phi), ok)

    def solve(self, phi, accelerations: bool = True) -> KinematicsResult:
        """Positions, velocities and accelerations at the crank angles ``phi`` (rad); without
        ``accelerations`` they are not solved (q̈, ε and every point's acceleration are NaN): for
        the callers that read positions and velocities only (the dynamics' M_red and J_red)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        try:
            q, _, trig = self._positions(phi, strict=True)
        except AssemblyError as exc:
            with np.errstate(invalid="ignore", divide="ignore"):
                feasible = self.feasible_ranges()
            raise AssemblyError(exc.group, exc.phi_deg, exc.inequality, feasible) from None
        jacobians: dict = {}
        qd = self.velocities(q, jacobians=jacobians, trig=trig)
        qdd = self.accelerations(q, qd, jacobians=jacobians, trig=trig) if accelerations else np.full_like(q, np.nan)
        return self._result(phi, q, qd, qdd, trig, accelerations)

    def _result(self, phi, q, qd, qdd, trig: Trig | None = None, accelerations: bool = True) -> KinematicsResult:
        """The result over the solve's own arrays q, q̇, q̈ (made read-only in place, not copied:
        the links' motions are views of them)."""
        lk = self.linkage
        q, qd, qdd = frozen(q), frozen(qd), frozen(qdd)
        points: dict[str, Callable[[], PointMotion]] = {}
        for k in sorted(lk.bodies):
            for name in lk.bodies[k].points:
                if name in points or (k == 0):
                    continue
                points[name] = _deferred(self._point_motion, q, qd, qdd, k, lk.bodies[k].local[name], trig,
                                         accelerations)
        for name in lk.ground:
            if name not in points:
                points[name] = _deferred(_fixed_point, lk.sketch[name], phi.size)
        coms = {k: _deferred(self._point_motion, q, qd, qdd, k, tuple(lk.bodies[k].com_local), trig, accelerations)
                for k in lk.moving}
        links = {k: LinkMotion(q[:, k, 2], qd[:, k, 2], qdd[:, k, 2]) for k in lk.moving}
        trans = {g.key: _deferred(_transmission, lk, g, q) for g in self.structure.groups[1:]}
        points, coms, links = self._without_residue(points, coms, links)
        return KinematicsResult(_ro(phi), self.omega, q, qd, qdd, DerivedMotions(points),
                                DerivedMotions(coms), DerivedMotions(links), DerivedMotions(trans))

    def _without_residue(self, points, coms, links):
        """Velocities and accelerations that are round-off residue (a centre of mass on a fixed axis
        comes out at ~1e-16 m/s²) become exact zeros: residue against |ω1|·L, ω1²·L (L the size of
        the mechanism), |ω1|, ω1² (:func:`reportgen.numbers.clean_array`)."""
        size = self._size
        w = abs(self.omega) or 1.0
        v_scale, a_scale = w * size, w * w * size

        def lm(m: LinkMotion) -> LinkMotion:
            return LinkMotion(m.angle, frozen(clean_array(m.omega, w)), frozen(clean_array(m.epsilon, w * w)))

        return ({n: _deferred(_cleaned, f, v_scale, a_scale) for n, f in points.items()},
                {k: _deferred(_cleaned, f, v_scale, a_scale) for k, f in coms.items()},
                {k: _deferred(lm, m) for k, m in links.items()})

    @cached_property
    def _size(self) -> float:
        """The size L of the mechanism: the larger side of its sketch's bounding box (m)."""
        sketch = np.array(list(self.linkage.sketch.values()), dtype=float).reshape(-1, 2)
        return float(np.ptp(sketch, axis=0).max()) if len(sketch) > 1 else 1.0

    @staticmethod
    def _point_motion(q, qd, qdd, k: int, p: tuple, trig: Trig | None = None,
                      accelerations: bool = True) -> PointMotion:
        Rp = arm(q, k, p, trig)
        w = qd[:, k, 2][:, None]
        pR = perp(Rp)
        pos = q[:, k, :2] + Rp
        vel = qd[:, k, :2] + w * pR
        if not accelerations:
            return PointMotion(frozen(pos), frozen(vel), _no_acc(q.shape[0]))
        e = qdd[:, k, 2][:, None]
        acc = qdd[:, k, :2] + e * pR - w * w * Rp
        return PointMotion(frozen(pos), frozen(vel), frozen(acc))


def _transmission(linkage: Linkage, g: Group, q: np.ndarray) -> np.ndarray:
    return _ro(transmission_angle(linkage, g, q))


def _intervals(deg: np.ndarray, ok: np.ndarray) -> tuple[tuple[float, float], ...]:
    """Runs of True in a periodic grid as (start, end) degree intervals."""
    if ok.all():
        return ((0.0, 360.0),)
    if not ok.any():
        return ()
    n = ok.size
    start = int(np.flatnonzero(~ok)[0])          # begin scanning at an infeasible sample
    runs, cur = [], None
    for j in range(1, n + 1):
        i = (start + j) % n
        if ok[i] and cur is None:
            cur = i
        elif not ok[i] and cur is not None:
            runs.append((float(deg[cur]), float(deg[(i - 1) % n])))
            cur = None
    if cur is not None:
        runs.append((float(deg[cur]), float(deg[(start - 1) % n])))
    return tuple(runs)


def build_model(mech: Mechanism) -> KinematicModel:
    linkage = compile_linkage(mech)
    structure = analyse_structure(linkage)
    return KinematicModel(linkage, structure)
