"""Pair constraints in pose coordinates, vectorised over positions.

Poses ``q[..., k, :] = (x_k, y_k, θ_k)``; a point with local coordinates p stands at
``w = r + R(θ)·p``, with ``dw/dθ = perp(R·p)`` and ``perp(x, y) = (−y, x)``.

Revolute pair of bodies i, j at a point: ``Φ = w_i − w_j = 0`` (two rows); its acceleration
right-hand side ``γ = θ̇_i²·R_i p_i − θ̇_j²·R_j p_j``.

Prismatic pair (point p_a of body a on the line of body g through l with direction u):
``f = n·d = 0`` with ``n = R_g·perp(u)``, ``d = w_a − (r_g + R_g l)``, and ``θ_a − θ_g − c = 0``.
Differentiating twice, ``f̈ = J·q̈ − γ`` with
``γ = θ̇_g²·n·d − 2θ̇_g·perp(n)·ḋ + n·(θ̇_a²·R_a p_a − θ̇_g²·R_g l)``; the term ``2θ̇_g·perp(n)·ḋ``
holds the Coriolis acceleration of the slotted link.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..geometry import dot as _dot, frozen, perp, rot
from ..linkage import Linkage, SlidePair


@dataclass(frozen=True)
class RevoluteC:
    point: str
    i: int
    j: int
    pi: tuple[float, float]
    pj: tuple[float, float]
    rows: int = 2


@dataclass(frozen=True)
class SlideC:
    s: SlidePair
    rows: int = 2


Constraint = RevoluteC | SlideC


def revolute(linkage: Linkage, point: str, i: int, j: int) -> RevoluteC:
    return RevoluteC(point, i, j, linkage.bodies[i].local[point], linkage.bodies[j].local[point])


def all_pair_constraints(linkage: Linkage) -> list[Constraint]:
    """Every pair of the mechanism (a joint of k bodies gives k − 1 revolute constraints)."""
    cons: list[Constraint] = []
    for jt in linkage.joints:
        b0 = jt.bodies[0]
        cons.extend(revolute(linkage, jt.name, b0, b) for b in jt.bodies[1:])
    cons.extend(SlideC(s) for s in linkage.slides)
    return cons


class Trig:
    """cos θ_k and sin θ_k of the bodies of one set of poses ``q`` (N positions), each computed when
    first asked (a body's angle must be final by then: the position solvers ask only for bodies
    already solved), and the arms R(θ_k)·p computed from them — each once per set of poses, kept
    read-only (every reader makes new arrays of them). The same bits as ``rot`` one by one."""

    __slots__ = ("q", "_cs", "arms")

    def __init__(self, q: np.ndarray) -> None:
        self.q = q
        self._cs: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        self.arms: dict[tuple[int, tuple[float, float]], np.ndarray] = {}

    def cs(self, k: int) -> tuple[np.ndarray, np.ndarray]:
        v = self._cs.get(k)
        if v is None:
            th = self.q[:, k, 2]
            v = self._cs[k] = (np.cos(th), np.sin(th))
        return v


def trig_of(q: np.ndarray) -> Trig:
    """The cos/sin (and arms) of the poses ``q``, computed as they are read (:class:`Trig`)."""
    return Trig(q)


def arm(q: np.ndarray, k: int, p, trig: Trig | None = None) -> np.ndarray:
    """R(θ_k)·p at every position, (N, 2): :func:`reportgen.geometry.rot`, from ``trig`` when given
    (each body and point once per set of poses; ``trig`` must be that of ``q``)."""
    if trig is None:
        return rot(q[:, k, 2], p)
    key = (k, (float(p[0]), float(p[1])))
    out = trig.arms.get(key)
    if out is None:
        c, s = trig.cs(k)
        out = np.empty((q.shape[0], 2))
        out[:, 0] = c * p[0] - s * p[1]
        out[:, 1] = s * p[0] + c * p[1]
        trig.arms[key] = frozen(out)
    return out


def world(q: np.ndarray, k: int, p: tuple[float, float], trig: Trig | None = None) -> np.ndarray:
    """Position of local point p of body k: shape (N, 2)."""
    return q[:, k, :2] + arm(q, k, p, trig)


def residual(cons: list[Constraint], q: np.ndarray) -> np.ndarray:
    out: list[np.ndarray] = []
    for c in cons:
        if isinstance(c, RevoluteC):
            d = world(q, c.i, c.pi) - world(q, c.j, c.pj)
            out.extend((d[:, 0], d[:, 1]))
        else:
            s = c.s
            n = rot(q[:, s.guide, 2], (-s.line_dir[1], s.line_dir[0]))
            d = world(q, s.link, s.point_local) - world(q, s.guide, s.line_point)
            out.append(_dot(n, d))
            out.append(q[:, s.link, 2] - q[:, s.guide, 2] - s.rel_angle)
    return np.stack(out, axis=-1) if out else np.zeros((q.shape[0], 0))


def _slide_frame(s: SlidePair, q: np.ndarray, trig: Trig | None = None
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Of a prismatic pair, all (N, 2): the guide line's normal n, the arms Rpa (the sliding point
    on its link) and Rl (the line's point on the guide), and d from the line's point to the sliding point."""
    a, g = s.link, s.guide
    n = arm(q, g, (-s.line_dir[1], s.line_dir[0]), trig)
    Rpa = arm(q, a, s.point_local, trig)
    Rl = arm(q, g, s.line_point, trig)
    d = q[:, a, :2] + Rpa - q[:, g, :2] - Rl
    return n, Rpa, Rl, d


def jacobian_rows(c: Constraint, q: np.ndarray, trig: Trig | None = None) -> list[dict[int, np.ndarray]]:
    """Rows of ∂Φ/∂q of one constraint: each row maps a body to its (N, 3) coefficients."""
    N = q.shape[0]
    one, zero = np.ones(N), np.zeros(N)
    if isinstance(c, RevoluteC):
        Rpi = arm(q, c.i, c.pi, trig)
        Rpj = arm(q, c.j, c.pj, trig)
        rx = {c.i: np.stack((one, zero, -Rpi[:, 1]), -1)}
        ry = {c.i: np.stack((zero, one, Rpi[:, 0]), -1)}
        rx[c.j] = rx.get(c.j, 0) + np.stack((-one, zero, Rpj[:, 1]), -1)
        ry[c.j] = ry.get(c.j, 0) + np.stack((zero, -one, -Rpj[:, 0]), -1)
        return [rx, ry]
    s = c.s
    a, g = s.link, s.guide
    n, Rpa, Rl, d = _slide_frame(s, q, trig)
    r1 = {a: np.stack((n[:, 0], n[:, 1], _dot(n, perp(Rpa))), -1)}
    r1[g] = r1.get(g, 0) + np.stack((-n[:, 0], -n[:, 1], _dot(perp(n), d) - _dot(n, perp(Rl))), -1)
    r2 = {a: np.stack((zero, zero, one), -1)}
    r2[g] = r2.get(g, 0) + np.stack((zero, zero, -one), -1)
    return [r1, r2]


def gamma(c: Constraint, q: np.ndarray, qd: np.ndarray, trig: Trig | None = None) -> list[np.ndarray]:
    """Acceleration right-hand side γ of each row: J·q̈ = γ."""
    if isinstance(c, RevoluteC):
        Rpi = arm(q, c.i, c.pi, trig)
        Rpj = arm(q, c.j, c.pj, trig)
        wi2 = qd[:, c.i, 2] ** 2
        wj2 = qd[:, c.j, 2] ** 2
        gm = wi2[:, None] * Rpi - wj2[:, None] * Rpj
        return [gm[:, 0], gm[:, 1]]
    s = c.s
    a, g = s.link, s.guide
    n, Rpa, Rl, d = _slide_frame(s, q, trig)
    wa, wg = qd[:, a, 2], qd[:, g, 2]
    dd = qd[:, a, :2] + wa[:, None] * perp(Rpa) - qd[:, g, :2] - wg[:, None] * perp(Rl)
    g1 = (wg ** 2) * _dot(n, d) - 2 * wg * _dot(perp(n), dd) + _dot(n, (wa ** 2)[:, None] * Rpa - (wg ** 2)[:, None] * Rl)
    return [g1, np.zeros_like(g1)]


def assemble(cons: list[Constraint], q: np.ndarray, cols: list[int], trig: Trig | None = None
             ) -> tuple[np.ndarray, list[list[dict[int, np.ndarray]]]]:
    """Jacobian restricted to the bodies ``cols`` (N, m, 3·len(cols)), plus the rows' coefficients
    of the other moving bodies (for the right-hand side, :func:`known_terms`).

    The entries are those of :func:`jacobian_rows`, bit for bit (a second body's coefficients are
    ``0 + x`` there, which turns −0.0 into 0.0: kept), written straight into J instead of being
    stacked per row and copied (the solve's most frequent step)."""
    N = q.shape[0]
    m = sum(c.rows for c in cons)
    J = np.zeros((N, m, 3 * len(cols)))
    if trig is None:
        trig = trig_of(q)
    idx = {b: 3 * i for i, b in enumerate(cols)}
    rows_all: list[list[dict[int, np.ndarray]]] = []
    Row = tuple[float | np.ndarray, float | np.ndarray, float | np.ndarray]   # noqa: N806 (a local type)
    first: tuple[Row, Row]
    second: tuple[Row, Row]
    r = 0
    for c in cons:
        if isinstance(c, RevoluteC):
            Rpi = arm(q, c.i, c.pi, trig)
            Rpj = arm(q, c.j, c.pj, trig)
            first = ((1.0, 0.0, -Rpi[:, 1]), (0.0, 1.0, Rpi[:, 0]))
            second = ((-1.0, 0.0, 0 + Rpj[:, 1]), (0.0, -1.0, 0 + -Rpj[:, 0]))
            bodies = (c.i, c.j)
        else:
            sp = c.s
            n, Rpa, Rl, d = _slide_frame(sp, q, trig)
            first = ((n[:, 0], n[:, 1], _dot(n, perp(Rpa))), (0.0, 0.0, 1.0))
            second = ((0 + -n[:, 0], 0 + -n[:, 1], 0 + (_dot(perp(n), d) - _dot(n, perp(Rl)))), (0.0, 0.0, -1.0))
            bodies = (sp.link, sp.guide)
        rows: list[dict[int, np.ndarray]] = [{}, {}]
        per_body: list[tuple[int, tuple[Row, Row]]] = [(bodies[0], first), (bodies[1], second)]
        for b, coefs in per_body:
            for k, coef in enumerate(coefs):
                if b in idx:
                    for t, v in enumerate(coef):
                        J[:, r + k, idx[b] + t] = v
                elif b != 0:
                    out = np.empty((N, 3))
                    for t, v in enumerate(coef):
                        out[:, t] = v
                    rows[k][b] = out
        rows_all.append(rows)
        r += c.rows
    return J, rows_all


def known_terms(rows_all: list[list[dict[int, np.ndarray]]], known_vals: np.ndarray, cols: set[int]) -> np.ndarray:
    """Σ over bodies not in ``cols`` of the row coefficients times their known q̇ (or q̈): (N, m)."""
    out = []
    for rows in rows_all:
        for row in rows:
            acc = np.zeros(known_vals.shape[0])
            for b, coef in row.items():
                if b not in cols and b != 0:
                    acc = acc + np.einsum("nk,nk->n", coef, known_vals[:, b, :])
            out.append(acc)
    return np.stack(out, axis=-1)


def jacobian_full(linkage: Linkage, cons: list[Constraint], q: np.ndarray) -> np.ndarray:
    """∂Φ/∂q over every moving body, (N, m, 3n)."""
    J, _ = assemble(cons, q, list(linkage.moving))
    return J
