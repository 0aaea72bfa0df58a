"""The graphical replicas of section 2 (seed 000, section 2; course manual, seed 001, sections 5–6):
what a student draws and measures, computed from the exact solution, with the deviation of each read
value from the exact one.

- Scales: a round scale μ = m·10^k with m ∈ {1, 2, 2.5, 5} (:data:`ROUND_MANTISSAS`; the one rule of
  :mod:`reportgen.scenes.scales`), the smallest
  one that draws the largest vector within ``max_mm`` — so the largest vector lies in
  (max_mm/2, max_mm] mm. Forces μF (N/mm): the largest vector within 200 mm, or — where that draws
  the polygon larger — the whole polygon within 400 × 180 mm (a flat polygon of two large, nearly
  opposite vectors is drawn long enough for its short sides to be read; 350 × 180 mm when the
  mechanism has two or more groups); the scheme μL (m/mm), the
  mechanism's extent (diagonal) within 450 mm, the scale of sheet 2's group views; the velocity plan
  of the lever μv ((m/s)/mm): the whole turned plan with the feet of the arms within the box of the
  sheet that draws it (:func:`lever_scale`, the plans' series). These are the scales of sheet 2 (of
  the control work's sheet for the lever), so the note and the sheet read the same mm.
- Measurements: every length a student reads off a drawing — a side of a polygon, an arm or a
  length on the scheme (R^τ's and the crank's moment equations, the shift h of Fи′), the lever's arms
  and pa — is rounded to ``reading_mm`` (:data:`READING_MM`, 0.1 mm): what a drawing is read to
  (issue 12: the note printed «h₉ = 37,46 мм» and «h₁ = 85,69 мм» off drawings read to 0,1 mm).
- Inertia: Fи and Mи of a link replaced by one force Fи′ = Fи shifted by h = Mи/Fи (seed 000, 2.2).
- A dyad (RRR, RRP): each reaction at an outer revolute pair is split into R^τ (square to the line
  from the pair to the inner joint Q) from the moment equation of its link about Q, with arms
  measured on the scheme, and R^n along that line; the group's force polygon (R^n_a, R^τ_a, the
  forces on a, the forces on b, R^τ_b, R^n_b) closes at the intersection of the two unknown
  directions; the reaction in the inner joint closes the polygon of one link. Other groups: the
  exact solution fed with the read values, each reaction read off its polygon.
- The crank: F_ур from its moment equation about O with measured arms; R01 closes its polygon.
- The lever: arms of the forces about the pole of the turned plan measured at μv; F_ур = ΣF·h/pa.
Reactions read from a polygon are passed on to the next group as the student does, so the errors
accumulate along the chain, as on paper.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..linkage import Linkage
from ..scenes.boxes import DEFAULT as DEFAULT_BOXES
from ..scenes.boxes import SceneBoxes
from ..scenes.scales import FORCE_SERIES, PLAN_SERIES
from ..scenes.scales import round_scale as _round_scale
from ..structure import Group, Structure
from .reactions import Reactions, _cross, _Known, _ro, pair_name, perp, solve_group
from .zhukovsky import Lever, turn_cw
from ..tolerances import RTOL_ROUNDOFF

#: Mantissas of a round scale (:data:`reportgen.scenes.scales.FORCE_SERIES`).
ROUND_MANTISSAS = FORCE_SERIES
#: Rounding of every length read off a drawing (a polygon's side, an arm or a length on the scheme,
#: the lever's arms and pa), mm: the one precision of «read off the drawing».
READING_MM = 0.1
#: Fи and Mи are not replaced by one force when h = M/F exceeds this many mechanism lengths.
REPLACEMENT_LIMIT = 100.0


def round_scale(largest: float, max_mm: float) -> float:
    """The smallest μ = m·10^k (m in :data:`ROUND_MANTISSAS`) with ``largest/μ ≤ max_mm``
    (:func:`reportgen.scenes.scales.round_scale`)."""
    return _round_scale(largest, max_mm, FORCE_SERIES)


def box_scale(points: np.ndarray, box: tuple[float, float]) -> float:
    """The smallest round μ that draws ``points`` (n × 2) within ``box`` (width, height, mm); inf for
    a single point."""
    ext = np.ptp(np.asarray(points, float).reshape(-1, 2), axis=0)
    mus = [round_scale(float(x), m) for x, m in zip(ext, box) if x > 0]
    return max(mus) if mus else math.inf


def polygon_scale(vectors, largest: float = 0.0, box: tuple[float, float] = DEFAULT_BOXES.polygon,
                  max_mm: float = DEFAULT_BOXES.polygon_mm) -> float:
    """μF of a force polygon (``vectors`` head to tail, N): the smallest round scale that draws its
    largest vector (or ``largest``, e.g. a diagonal) within ``max_mm``, or the larger drawing that
    puts the whole polygon within ``box``."""
    vs = [np.asarray(v, float) for v in vectors]
    big = max([float(np.hypot(*v)) for v in vs] + [largest])
    verts = np.cumsum([np.zeros(2)] + vs, axis=0)
    return min(round_scale(big, max_mm), box_scale(verts, box))


def measure(x: float, step: float) -> float:
    """A length as read to ``step`` (no rounding when step is 0)."""
    return round(x / step) * step if step > 0 else x


def _deviation(read: float, exact: float) -> float:
    """100·(read − exact)/exact, %; 0 when both vanish."""
    if exact == 0.0:
        return 0.0 if read == 0.0 else math.inf
    return 100.0 * (read - exact) / exact


def _unit(v: np.ndarray) -> np.ndarray:
    n = float(np.hypot(*v))
    return v / n if n > 0 else np.zeros(2)


def _read_vector(v: np.ndarray, mu: float, step: float) -> np.ndarray:
    """A vector as read off a plan: its direction, its length rounded to ``step`` mm."""
    return _unit(v) * measure(float(np.hypot(*v)) / mu, step) * mu


@dataclass(frozen=True)
class InertiaReplacement:
    """Fи and Mи of a link as one force Fи′ (seed 000, 2.2): shifted by h = |Mи|/|Fи| so that its
    moment about S has the sense of Mи; ``swing_point`` (k) where its line meets the link's axis."""
    link: int
    force_name: str
    moment_name: str
    force: np.ndarray          # (2,)
    moment: float
    com: np.ndarray            # S, (2,)
    h: float                   # m
    h_mm: float                # at μL
    h_mm_measured: float
    point: np.ndarray          # S + shift, exact, (2,)
    point_measured: np.ndarray  # with the measured h
    swing_point: np.ndarray | None
    moment_measured: float     # ±|Fи|·h_measured·μL
    deviation_percent: float


@dataclass(frozen=True)
class MomentTerm:
    """One term of a moment equation about a centre: ``moment = magnitude·arm`` (arm signed, m)."""
    name: str
    magnitude: float           # N (a couple: its value, N·m, with arm 1)
    arm: float                 # m, signed (CCW positive); 1.0 for a couple
    arm_mm: float              # at μL (couples: 0)
    arm_mm_measured: float
    moment: float              # N·m


@dataclass(frozen=True)
class TangentialSplit:
    """A reaction at an outer revolute pair of a dyad, on ``link`` (name ``R{j}{k}``): the normal
    part along ``along`` (pair → inner joint Q) and the tangential part along ``tangent`` = along
    turned +90°, from ΣM_Q(link) = 0: R^τ = ΣM_Q(other forces)/l."""
    name: str
    link: int
    centre: str
    centre_point: np.ndarray
    pair_point: np.ndarray
    along: np.ndarray
    tangent: np.ndarray
    length: float              # l = |PQ|, m
    length_mm_measured: float
    tau: float                 # N, along ``tangent``
    normal: float              # N, along ``along``
    terms: tuple[MomentTerm, ...]
    tau_measured: float        # from the measured arms
    deviation_percent: float


@dataclass(frozen=True)
class PolygonVector:
    """One side of a force polygon, drawn head to tail from the origin (mm on the polygon)."""
    name: str
    vector: np.ndarray         # N, exact, (2,)
    known: bool                # False: found by closing the polygon
    length_mm: float           # exact length at μF
    measured_mm: float         # as read (rounded to the reading)
    start_mm: np.ndarray
    end_mm: np.ndarray
    read_value: float          # N: the replica's value (measured_mm·μF for the unknowns)
    exact_value: float         # N
    deviation_percent: float


@dataclass(frozen=True)
class ForcePolygon:
    """Force polygon of a group (key "4-5") or of the crank (key "1") at scale μF (N/mm); ``extra``
    are reactions read off it as diagonals (the inner joint, or a full reaction R = R^n + R^τ)."""
    key: str
    scale: float
    vectors: tuple[PolygonVector, ...]
    extra: tuple[PolygonVector, ...]
    equation: str              # "Rn34 + Rτ34 + Fи4′ + G4 + … + R05 = 0"


@dataclass(frozen=True)
class GroupGraphic:
    key: str
    label: str
    kind: str
    splits: tuple[TangentialSplit, ...]
    polygon: ForcePolygon
    method: str                # "dyad" (R^τ from moments, then the polygon) | "exact-read" (other groups)


@dataclass(frozen=True)
class CrankGraphic:
    terms: tuple[MomentTerm, ...]           # moments about O of the forces on the crank (F_ур excluded)
    length_mm_measured: float               # OA on the scheme
    balancing_force: float                  # exact, N (signed: + gives a CCW moment)
    balancing_force_measured: float
    balancing_moment_measured: float        # F_ур,measured·l_OA
    polygon: ForcePolygon


@dataclass(frozen=True)
class LeverTerm:
    name: str
    source: str
    magnitude: float
    arm_mm: float              # signed, on the plan at μv
    arm_mm_measured: float
    moment: float              # W (= F·v), measured


@dataclass(frozen=True)
class LeverGraphic:
    scale: float               # μv, (m/s)/mm
    terms: tuple[LeverTerm, ...]
    direct: tuple[tuple[str, float], ...]   # couples of one-point links as M·ω, W
    pa_mm_measured: float
    balancing_force_measured: float         # N
    balancing_moment_measured: float        # N·m


@dataclass(frozen=True)
class GraphicalReplica:
    length_scale: float        # μL, m/mm
    reading_mm: float          # every length read off a drawing is rounded to this, mm
    inertia: tuple[InertiaReplacement, ...]
    groups: tuple[GroupGraphic, ...]        # in the order solved (last attached first)
    crank: CrankGraphic
    lever: LeverGraphic
    discrepancy_percent: float              # 100·(F_ур,groups − F_ур,lever)/F_ур,lever, measured


# -- helpers ---------------------------------------------------------------------------------------

@dataclass
class _Item:
    """A force on a link as the student draws it: exact and read (replica) versions."""
    name: str
    point: np.ndarray
    vector: np.ndarray
    point_r: np.ndarray
    vector_r: np.ndarray


def _moment_term(name: str, point: np.ndarray, vec: np.ndarray, centre: np.ndarray, mu_l: float, step: float,
                 point_r: np.ndarray | None = None, vec_r: np.ndarray | None = None) -> tuple[MomentTerm, float]:
    """Exact term and the measured moment (with the read vector and point, arm rounded)."""
    mag = float(np.hypot(*vec))
    mom = float(_cross(point - centre, vec))
    arm = mom / mag if mag > 0 else 0.0
    pr = point if point_r is None else point_r
    vr = vec if vec_r is None else vec_r
    mag_r = float(np.hypot(*vr))
    mom_r = float(_cross(pr - centre, vr))
    arm_r_mm = (mom_r / mag_r) / mu_l if mag_r > 0 else 0.0
    arm_meas = math.copysign(measure(abs(arm_r_mm), step), arm_r_mm)
    return MomentTerm(name, mag, arm, arm / mu_l, arm_meas, mom), mag_r * arm_meas * mu_l


def _polygon(key: str, entries: list[tuple[str, np.ndarray, bool, float]], mu: float, step: float,
             extra: Sequence[tuple[str, np.ndarray, float]] = ()) -> ForcePolygon:
    """entries: (name, exact vector, known, read value N); drawn head to tail from the origin."""
    vecs, cur = [], np.zeros(2)
    for name, v, known, read in entries:
        ln = float(np.hypot(*v)) / mu
        end = cur + v / mu
        exact = float(np.hypot(*v))
        vecs.append(PolygonVector(name, _ro(v), known, ln, measure(ln, step), _ro(cur), _ro(end), read, exact,
                                  _deviation(read, exact)))
        cur = end
    ex = []
    for name, v, read in extra:
        ln = float(np.hypot(*v)) / mu
        exact = float(np.hypot(*v))
        ex.append(PolygonVector(name, _ro(v), False, ln, measure(ln, step), _ro(np.zeros(2)), _ro(v / mu), read,
                                exact, _deviation(read, exact)))
    eq = " + ".join(e[0] for e in entries) + " = 0"
    return ForcePolygon(key, mu, tuple(vecs), tuple(ex), eq)


def _canon(name_on_k: tuple[int, int], vec_on_k: np.ndarray) -> tuple[str, np.ndarray]:
    """(j, k), force of j on k → canonical name and orientation (lower id on higher)."""
    j, k = name_on_k
    return (pair_name(j, k), vec_on_k) if j < k else (pair_name(k, j), -vec_on_k)


# -- the replica -----------------------------------------------------------------------------------

def inertia_replacements(linkage: Linkage, reactions: Reactions, mu_l: float, arm_step: float,
                         i: int = 0) -> dict[int, InertiaReplacement]:
    """Fи′ for every link with both an inertia force and a non-zero inertia moment."""
    out: dict[int, InertiaReplacement] = {}
    fs = {f.link: f for f in reactions.loads.forces if f.kind == "inertia"}
    ms = {m.link: m for m in reactions.loads.moments if m.kind == "inertia"}
    q = np.asarray(reactions.kin.q)[i:i + 1]
    for k in sorted(set(fs) & set(ms)):
        F = np.asarray(fs[k].vector)[i]
        M = float(np.asarray(ms[k].value)[i])
        mag = float(np.hypot(*F))
        if mag == 0.0 or M == 0.0:
            continue
        S = np.asarray(fs[k].point)[i]
        h = abs(M) / mag
        if h > REPLACEMENT_LIMIT * reactions.length_scale:   # Fи ≈ 0 (S on the axis): keep Mи as a couple
            continue
        shift_dir = -math.copysign(1.0, M) * perp(F) / mag          # s × F = M for s = −M·perp(F)/|F|²
        h_mm = h / mu_l
        h_meas = measure(h_mm, arm_step)
        point = S + h * shift_dir
        point_m = S + h_meas * mu_l * shift_dir
        swing = None
        pts = linkage.bodies[k].points
        if len(pts) >= 2:
            from ..kinematics.constraints import world
            P1 = world(q, k, linkage.bodies[k].local[pts[0]])[0]
            P2 = world(q, k, linkage.bodies[k].local[pts[1]])[0]
            d = P2 - P1
            den = float(_cross(F, d))
            if abs(den) > RTOL_ROUNDOFF * mag * float(np.hypot(*d)):
                t = float(_cross(P1 - point, d)) / den
                swing = _ro(point + t * F)
        m_meas = math.copysign(mag * h_meas * mu_l, M)
        out[k] = InertiaReplacement(k, fs[k].name, ms[k].name, _ro(F), M, _ro(S), h, h_mm, h_meas, _ro(point),
                                    _ro(point_m), swing, m_meas, _deviation(m_meas, M))
    return out


def graphical_replica(linkage: Linkage, structure: Structure, reactions: Reactions, lever: Lever, i: int = 0, *,
                      reading_mm: float = READING_MM,
                      length_scale: float | None = None, boxes: SceneBoxes = DEFAULT_BOXES,
                      lever_box: tuple[float, float] | None = None) -> GraphicalReplica:
    """The whole graphical chain at position ``i`` of ``reactions`` (see the module's docstring);
    ``boxes`` the room of the drawings (the stage passes ``project.boxes``), ``lever_box`` the
    lever's (default ``boxes.lever``, sheet 2's; the stage passes the box of the sheet that draws it)."""
    q = np.asarray(reactions.kin.q)[i:i + 1]
    pts = np.array([m.pos[i] for m in reactions.kin.points.values()])
    extent = float(np.hypot(*(pts.max(0) - pts.min(0)))) if len(pts) else 1.0
    mu_l = length_scale or round_scale(extent, boxes.scheme_diagonal_mm)
    repl = inertia_replacements(linkage, reactions, mu_l, reading_mm, i)
    box = boxes.polygon if len(structure.groups) <= 2 else boxes.polygon_many
    read: dict[str, np.ndarray] = {}          # canonical reaction name → read vector (lo on hi)
    read_pt: dict[str, np.ndarray] = {}

    def items_on(k: int, exclude: set[str]) -> tuple[list[_Item], float]:
        """The forces on link k that the student knows (loads, Fи′, reactions of solved pairs), and
        the sum of its couples other than Mи (which goes into Fи′)."""
        its: list[_Item] = []
        couples = 0.0
        for f in reactions.loads.forces:
            if f.link != k:
                continue
            P, V = np.asarray(f.point)[i], np.asarray(f.vector)[i]
            if f.kind == "inertia" and k in repl:
                r = repl[k]
                its.append(_Item(f.name + "′", r.point, V, r.point_measured, V))
            else:
                its.append(_Item(f.name, P, V, P, V))
        for m in reactions.loads.moments:
            if m.link == k and not (m.kind == "inertia" and k in repl):
                couples += float(np.asarray(m.value)[i])
        for p in reactions.pairs_of(k):
            if p.name in exclude or p.name not in read:
                continue
            j = p.other(k)
            its.append(_Item(pair_name(j, k), p.point[i], p.on(k)[i], read_pt[p.name],
                             read[p.name] if k == p.hi else -read[p.name]))
        return its, couples

    groups_out: list[GroupGraphic] = []
    for g in reversed(structure.groups[1:]):
        own = {p.name for p in reactions.pairs if p.group == g.key}
        if g.group_class == 2 and g.kind in ("RRR", "RRP"):
            groups_out.append(_dyad(g, reactions, i, items_on, own, read, read_pt, mu_l,
                                    reading_mm, box))
        else:
            groups_out.append(_generic(linkage, g, reactions, i, q, items_on, own, read, read_pt, reading_mm, box))
    crank = _crank(reactions, i, items_on, read, read_pt, mu_l, reading_mm, box)
    lev = _lever(lever, reactions, i, reading_mm, boxes.lever if lever_box is None else lever_box)
    disc = _deviation(crank.balancing_force_measured, lev.balancing_force_measured)
    return GraphicalReplica(mu_l, reading_mm, tuple(repl[k] for k in sorted(repl)), tuple(groups_out),
                            crank, lev, disc)


def _dyad(g: Group, reactions: Reactions, i: int, items_on, own: set[str], read, read_pt, mu_l: float,
          step: float, box: tuple[float, float] = DEFAULT_BOXES.polygon) -> GroupGraphic:
    a, b = g.links
    inner = next(p for p in g.pairs if not p.external)
    Q = next(r for r in reactions.pairs if r.group == g.key and r.joint == inner.point and r.kind == "R"
             and {r.lo, r.hi} == set(inner.bodies))
    Qp = Q.point[i]
    splits: list[TangentialSplit] = []
    head: list[tuple] = []        # per link: (link, ext PairReaction, items, couples, split or None)
    for k in (a, b):
        ext = next(r for r in reactions.pairs if r.group == g.key and r.external and k in (r.lo, r.hi))
        its, couples = items_on(k, own)
        split = None
        if ext.kind == "R":
            P = ext.point[i]
            d = Qp - P
            l = float(np.hypot(*d))
            e = d / l
            t = perp(e)
            R = ext.on(k)[i]
            terms, meas_sum = _moment_terms(its, couples, Qp, mu_l, step)
            l_meas = measure(l / mu_l, step)
            tau = float(R @ t)
            tau_m = meas_sum / (l_meas * mu_l)
            split = TangentialSplit(pair_name(ext.other(k), k), k, inner.point, _ro(Qp), _ro(P), _ro(e), _ro(t), l,
                                    l_meas, tau, float(R @ e), tuple(terms), tau_m, _deviation(tau_m, tau))
            splits.append(split)
        head.append((k, ext, its, split))
    seq = []                                    # the exact sides in the order drawn
    for n_k, (k, ext, its, split) in enumerate(head):
        side = [ext.on(k)[i]] if split is None else [split.normal * split.along, split.tau * split.tangent]
        body = [it.vector for it in its]
        seq += side + body if n_k == 0 else body + side[::-1]
    mu_f = polygon_scale(seq, max([float(np.hypot(*x.on(k)[i])) for k, x, _, _ in head] +
                                  [float(np.hypot(*Q.vector[i]))]), box)
    # the polygon with the read vectors: knowns rounded, the two unknown directions closing it
    known_sum = np.zeros(2)
    dirs = []
    for _k, ext, its, split in head:
        if split is not None:
            known_sum += _read_vector(split.tau_measured * split.tangent, mu_f, step) / mu_f
            dirs.append(split.along)
        else:
            dirs.append(ext.normal[i])
        for it in its:
            known_sum += _read_vector(it.vector_r, mu_f, step) / mu_f
    D = np.column_stack(dirs)
    s = np.linalg.solve(D, -known_sum)          # mm along each unknown direction
    s_read = [math.copysign(measure(abs(x), step), x) for x in s]
    entries: list[tuple] = []
    extra: list[tuple] = []
    link_sum_a = np.zeros(2)                    # read forces on link a (for the inner joint)
    for n_k, (k, ext, its, split) in enumerate(head):
        j = ext.other(k)
        unk_read = s_read[n_k] * mu_f * dirs[n_k]
        R_exact = ext.on(k)[i]
        if split is not None:
            tau_v = _read_vector(split.tau_measured * split.tangent, mu_f, step)
            n_vec = split.normal * split.along
            full_read = _read_vector(unk_read + tau_v, mu_f, step)
            pn = ("Rn" + pair_name(j, k)[1:], n_vec, False, abs(s_read[n_k]) * mu_f)
            pt = ("Rτ" + pair_name(j, k)[1:], split.tau * split.tangent, True, float(np.hypot(*tau_v)))
            side = [pn, pt] if n_k == 0 else [pt, pn]
            extra.append((pair_name(j, k), R_exact, float(np.hypot(*full_read))))
            R_read = full_read
        else:
            side = [(pair_name(j, k), R_exact, False, abs(s_read[n_k]) * mu_f)]
            R_read = unk_read
        body = [(it.name, it.vector, True, float(np.hypot(*_read_vector(it.vector_r, mu_f, step)))) for it in its]
        entries.extend(side + body if n_k == 0 else body + side)
        name, v = _canon((j, k), R_read)
        read[name] = v
        read_pt[name] = ext.point[i]
        if k == a:
            link_sum_a = R_read + sum((_read_vector(it.vector_r, mu_f, step) for it in its), np.zeros(2))
    # the inner joint: the force of b on a closes the polygon of link a
    R_ba_read = _read_vector(-link_sum_a, mu_f, step)
    R_ba = Q.on(a)[i]
    extra.append((pair_name(b, a), R_ba, float(np.hypot(*R_ba_read))))
    name, v = _canon((b, a), R_ba_read)
    read[name] = v
    read_pt[name] = Qp
    return GroupGraphic(g.key, g.label, g.kind, tuple(splits), _polygon(g.key, entries, mu_f, step, extra), "dyad")


def _generic(linkage, g: Group, reactions: Reactions, i: int, q, items_on, own: set[str], read, read_pt,
             step: float, box: tuple[float, float] = DEFAULT_BOXES.polygon) -> GroupGraphic:
    """Other groups: their exact equations fed with the read forces, each reaction read off."""
    kn = _Known({}, {})
    entries = []
    all_items = []
    for k in g.links:
        its, couples = items_on(k, own)
        for it in its:
            kn.add_force(k, it.point_r[None, :], it.vector_r[None, :])
            all_items.append(it)
        for m in reactions.loads.moments:
            if m.link == k:
                kn.add_couple(k, np.asarray(m.value)[i:i + 1])
        # Fи′ carries Mи: take the couple back out (the read point already holds it)
        for it in its:
            if it.name.endswith("′"):
                r_m = next(m for m in reactions.loads.moments if m.link == k and m.kind == "inertia")
                kn.add_couple(k, -np.asarray(r_m.value)[i:i + 1])
    sol = solve_group(linkage, g, q, kn, reactions.length_scale, reactions.kin.phi[i:i + 1])
    exacts = [next(r for r in reactions.pairs if r.group == g.key and r.joint == p.point and r.kind == p.kind
                   and {r.lo, r.hi} == set(p.bodies)) for p, *_ in sol]
    seq = [it.vector for it in all_items] + [ex.on(p.bodies[1])[i] for (p, *_), ex in zip(sol, exacts) if p.external]
    mu_f = polygon_scale(seq, max(float(np.hypot(*r.vector[i])) for r in reactions.pairs if r.group == g.key), box)
    for it in all_items:
        entries.append((it.name, it.vector, True, float(np.hypot(*_read_vector(it.vector_r, mu_f, step)))))
    extra = []
    for p, _W, _n, vec, _couple in sol:
        i0, j0 = p.bodies
        exact = next(r for r in reactions.pairs if r.group == g.key and r.joint == p.point and r.kind == p.kind
                     and {r.lo, r.hi} == {i0, j0})
        v_read = _read_vector(vec[0], mu_f, step)                       # force of i0 on j0
        name, v = _canon((i0, j0), v_read)
        read[name] = v
        read_pt[name] = exact.point[i]
        R_ex = exact.on(j0)[i]
        if p.external:
            entries.append((pair_name(i0, j0), R_ex, False, float(np.hypot(*v_read))))
        else:
            extra.append((pair_name(i0, j0), R_ex, float(np.hypot(*v_read))))
    return GroupGraphic(g.key, g.label, g.kind, (), _polygon(g.key, entries, mu_f, step, extra), "exact-read")


def _moment_terms(its, couples: float, centre: np.ndarray, mu_l: float,
                  arm_step: float) -> tuple[list[MomentTerm], float]:
    """The moments about ``centre`` of the forces ``its`` (arms measured on the drawing) and of the
    couples: the terms as the note lists them, and their sum from the measured arms."""
    terms, total = [], 0.0
    for it in its:
        term, m_r = _moment_term(it.name, it.point, it.vector, centre, mu_l, arm_step, it.point_r, it.vector_r)
        terms.append(term)
        total += m_r
    if couples:
        terms.append(MomentTerm("M", couples, 1.0, 0.0, 0.0, couples))
        total += couples
    return terms, total


def _crank(reactions: Reactions, i: int, items_on, read, read_pt, mu_l: float, step: float,
           box: tuple[float, float] = DEFAULT_BOXES.polygon) -> CrankGraphic:
    d = reactions.crank
    fp = next(r for r in reactions.pairs if r.group == str(d))
    its, couples = items_on(d, {fp.name})
    O = fp.point[i]
    A = reactions.balancing_point[i]
    l = float(np.hypot(*(A - O)))
    terms, meas = _moment_terms(its, couples, O, mu_l, step)
    l_meas = measure(l / mu_l, step)
    M_exact = float(reactions.balancing_moment[i])
    F_exact = M_exact / l
    F_meas = -meas / (l_meas * mu_l)
    t = perp((A - O) / l)
    Fb = reactions.balancing_force[i]
    R0 = fp.on(d)[i]
    mu_f = polygon_scale([Fb] + [it.vector for it in its] + [R0], box=box)
    Fb_read = _read_vector(F_meas * t, mu_f, step)
    close = -(Fb_read + sum((_read_vector(it.vector_r, mu_f, step) for it in its), np.zeros(2)))
    R0_read = _read_vector(close, mu_f, step)
    entries = [("Fур", Fb, True, float(np.hypot(*Fb_read)))]
    entries += [(it.name, it.vector, True, float(np.hypot(*_read_vector(it.vector_r, mu_f, step)))) for it in its]
    entries.append((pair_name(0, d), R0, False, float(np.hypot(*R0_read))))
    read[fp.name] = R0_read if d == fp.hi else -R0_read
    read_pt[fp.name] = O
    return CrankGraphic(tuple(terms), l_meas, F_exact, F_meas, F_meas * l,
                        _polygon(str(d), entries, mu_f, step))


def _arm_foot(image: np.ndarray, vector: np.ndarray) -> np.ndarray:
    """The foot of the perpendicular from the lever's pole to a force's line (the end of its arm)."""
    u = _unit(np.asarray(vector, float))
    return image - float(image @ u) * u


def lever_scale(lever: Lever, reactions: Reactions, i: int, box: tuple[float, float]) -> float:
    """μv of Zhukovsky's lever ((m/s)/mm): the smallest round scale of the plans' series (1, 2, 2.5,
    4, 5 — the lever is the velocity plan turned) that draws the turned plan — the pole, the images
    of every point and the feet of the forces' arms — within ``box`` (width, height, mm). One scale
    for the sheet that draws the lever, the note (reduced where it must be) and the arms read here."""
    plan = np.array([np.zeros(2), lever.crank_pin_image[i]] + [f.image[i] for f in lever.forces] +
                    [turn_cw(np.asarray(m.vel[i])) for m in reactions.kin.points.values()] +
                    [_arm_foot(f.image[i], f.vector[i]) for f in lever.forces])
    ext = np.ptp(plan, axis=0)
    mus = [_round_scale(float(x), m, PLAN_SERIES) for x, m in zip(ext, box) if x > 0]
    return max(mus) if mus else 1.0


def _lever(lever: Lever, reactions: Reactions, i: int, arm_step: float,
           box: tuple[float, float] = DEFAULT_BOXES.lever) -> LeverGraphic:
    return lever_graphic(lever, reactions, i, arm_step, lever_scale(lever, reactions, i, box))


def lever_graphic(lever: Lever, reactions: Reactions, i: int, arm_step: float, mu_v: float) -> LeverGraphic:
    """The lever drawn at ``mu_v``: each arm measured on it (to ``arm_step`` mm), pa, F_ур = ∓ΣF·h/pa."""
    terms, total = [], 0.0
    for f in lever.forces:
        mag = float(np.hypot(*f.vector[i]))
        arm_mm = float(f.arm[i]) / mu_v
        meas = math.copysign(measure(abs(arm_mm), arm_step), arm_mm)
        mom = mag * meas * mu_v
        terms.append(LeverTerm(f.name, f.source, mag, arm_mm, meas, mom))
        total += mom
    direct = tuple((name, float(p[i])) for name, _, p in lever.direct)
    total += sum(p for _, p in direct)
    pa = measure(float(np.hypot(*lever.crank_pin_image[i])) / mu_v, arm_step)
    sgn = 1.0 if lever.omega1 >= 0 else -1.0
    F = -sgn * total / (pa * mu_v)
    l = float(np.hypot(*(reactions.balancing_point[i] - next(r for r in reactions.pairs
                                                              if r.group == str(reactions.crank)).point[i])))
    return LeverGraphic(mu_v, tuple(terms), direct, pa, F, F * l)
