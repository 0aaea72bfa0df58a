"""Velocity and acceleration plans (планы скоростей и ускорений) as the course draws them, built from
the exact kinematics: a round scale factor, the image of every point, every component of the vector
equations of each group (relative, normal, tangential, Coriolis and relative-sliding components) as
a segment between named plan points, its length in mm as drawn and as a student measures it
(to ``MEASURE_MM``), and the value read back with its deviation from the exact one.

Vector equations per group (Артоболевский, §§ 3–4; seed 000, § 1.3–1.4):
- RRR (outer pins P, S, inner joint Q): V_Q = V_P + V_QP (⊥ PQ), V_Q = V_S + V_QS (⊥ SQ);
  a_Q = a_P + aⁿ_QP + aᵗ_QP, aⁿ_QP = ω²·l_PQ (from Q to P), aᵗ_QP = ε·l_PQ (⊥ PQ); likewise from S.
- RRP (pin P, inner joint Q on a slider): V_Q = V_P + V_QP (⊥ PQ), V_Q = V_Q0 + V_QQ0 (∥ guide).
- RPR (block pinned at H slides in the slot of a link pivoted at G; H_g the point of the slotted
  link under H): V_Hg = V_H + V_HgH (∥ slot), V_Hg = V_G + V_HgG (⊥ GH); a_Hg = a_H + aᵏ + aʳ,
  aᵏ = 2·ω_g × V_HgH (Coriolis), aʳ ∥ slot; a_Hg = a_G + aⁿ_HgG + aᵗ_HgG.
Groups of other kinds (PRP, RPP, class III and higher) are shown by the images of their points.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from .geometry import perp as _perp
from .kinematics import KinematicsResult
from .linkage import Linkage
from .scenes.scales import PLAN_SERIES
from .scenes.scales import round_scale as _round_scale
from .structure import Group, Structure
from .errors import NameLookupError
from .tolerances import MM_ROUNDOFF

#: The crank's vector is drawn 50–100 mm long (the one round-scale rule of
#: :mod:`reportgen.scenes.scales`, series 1, 2, 2.5, 4, 5), unless another point's vector would then
#: stand beyond ``PLAN_MAX_MM``.
ROUND_STEPS = PLAN_SERIES
#: The drawn length of the crank's vector is at most this, mm.
CRANK_VECTOR_MAX_MM = 100.0
#: No point of a plan stands farther than this from the pole, mm (a link that turns much faster
#: than the crank — near a toggle — would otherwise draw a plan of metres).
PLAN_MAX_MM = 200.0
#: Resolution of a student's measurement on the plan, mm.
MEASURE_MM = 0.1
#: The shortest segment a plan is read by, mm: a segment read to ``MEASURE_MM`` errs by at most
#: MEASURE_MM/2, i.e. ``READ_DEVIATION_BOUND`` = 2,5 % at this length (a 0,1-mm segment read to
#: 0,1 mm errs by up to 100 %). Shorter read segments are named in the note and left out of the
#: comparison with the exact values (docs/kinematics.md «Reading the plans»).
LEGIBLE_MM = 2.0
#: The largest deviation of a value read from a legible segment: MEASURE_MM / 2 / LEGIBLE_MM.
READ_DEVIATION_BOUND = MEASURE_MM / 2.0 / LEGIBLE_MM
#: Components the course computes by formula and lays off on the plan (aⁿ = ω²·l, aᵏ = 2·ω·V_r),
#: never reads back: their value is the formula's; one shorter than ``LEGIBLE_MM`` is not laid off
#: (its end point coincides with its start on the plan).
COMPUTED_KINDS = ("normal", "coriolis")


def round_scale(value: float, max_mm: float = CRANK_VECTOR_MAX_MM) -> float:
    """The plans' round μ: :func:`reportgen.scenes.scales.round_scale` (series 1, 2, 2.5, 4, 5)."""
    return _round_scale(value, max_mm, PLAN_SERIES)


def letter(name: str) -> str:
    """Plan point of a mechanism point: A → a, S2 → s2."""
    return name.lower()


@dataclass(frozen=True)
class PlanComponent:
    """One vector of a plan: from plan point ``start`` to ``end``; ``vector`` exact (SI)."""
    name: str            # LaTeX, e.g. V_{BA}, a^{n}_{BA}
    kind: str            # absolute | relative | normal | tangential | coriolis | sliding
    start: str
    end: str
    vector: tuple[float, float]
    direction: str       # LaTeX, e.g. \perp AB
    group: str           # the group's key ("1" for the driver)

    @property
    def value(self) -> float:
        return math.hypot(*self.vector)


@dataclass(frozen=True)
class Plan:
    """A velocity (``kind`` = "velocity", pole p) or acceleration plan (pole π) at one position."""
    kind: str
    position: int
    phi: float
    scale: float                                   # μ, (m/s)/mm or (m/s²)/mm
    points: Mapping[str, tuple[float, float]]      # plan points in mm (the pole at (0, 0))
    components: tuple[PlanComponent, ...]
    equations: tuple[tuple[str, str], ...]         # (group key, LaTeX of the vector equations)

    def length_mm(self, c: PlanComponent) -> float:
        return c.value / self.scale

    def measured_mm(self, c: PlanComponent) -> float:
        return round(self.length_mm(c) / MEASURE_MM) * MEASURE_MM

    def computed(self, c: PlanComponent) -> bool:
        """Is ``c`` computed by formula and laid off (a normal or Coriolis component), not read?"""
        return c.kind in COMPUTED_KINDS

    def legible(self, c: PlanComponent) -> bool:
        """Is the segment of ``c`` at least ``LEGIBLE_MM`` long (a reading to 0,1 mm within 2,5 %)?"""
        return self.length_mm(c) >= LEGIBLE_MM - MM_ROUNDOFF

    def drawn(self, c: PlanComponent) -> bool:
        """Is ``c`` drawn on the plan? Every read component; a computed one when it is legible."""
        return not self.computed(c) or self.legible(c)

    def compared(self, c: PlanComponent) -> bool:
        """Does ``c`` count in the comparison of the plan's readings with the exact values? Read
        (not computed) and legible."""
        return not self.computed(c) and self.legible(c)

    def read_value(self, c: PlanComponent) -> float:
        """The plan's value of ``c``: its segment measured × μ; a computed component's formula value."""
        if self.computed(c):
            return c.value
        return self.measured_mm(c) * self.scale

    def deviation(self, c: PlanComponent) -> float:
        """Relative deviation of the value read from the plan from the exact value."""
        return (self.read_value(c) - c.value) / c.value if c.value > 0 else 0.0

    def component(self, name: str) -> PlanComponent:
        for c in self.components:
            if c.name == name:
                return c
        raise NameLookupError("plan component", name, tuple(c.name for c in self.components))


class _Builder:
    def __init__(self, linkage: Linkage, structure: Structure, kin: KinematicsResult, i: int):
        self.lk, self.st, self.kin, self.i = linkage, structure, kin, i
        self.q = np.asarray(kin.q)[i]
        self.qd = np.asarray(kin.qd)[i]
        self.qdd = np.asarray(kin.qdd)[i]

    def pos(self, name: str) -> np.ndarray:
        return np.asarray(self.kin.points[name].pos[self.i])

    def vel(self, name: str) -> np.ndarray:
        return np.asarray(self.kin.points[name].vel[self.i])

    def acc(self, name: str) -> np.ndarray:
        return np.asarray(self.kin.points[name].acc[self.i])

    def body_point_vel(self, k: int, p: np.ndarray) -> np.ndarray:
        """Velocity of the material point of body k now at p."""
        r = p - self.q[k, :2]
        return self.qd[k, :2] + self.qd[k, 2] * _perp(r)

    def body_point_acc(self, k: int, p: np.ndarray) -> np.ndarray:
        r = p - self.q[k, :2]
        return self.qdd[k, :2] + self.qdd[k, 2] * _perp(r) - self.qd[k, 2] ** 2 * r


def _ext(group: Group, k: int):
    return next(p for p in group.pairs if p.external and k in p.bodies)


def _inner(group: Group):
    return next(p for p in group.pairs if not p.external)


def build_plans(linkage: Linkage, structure: Structure, kin: KinematicsResult, i: int,
                mu_v: float | None = None, mu_a: float | None = None) -> tuple[Plan, Plan]:
    """The velocity and acceleration plans at position ``i`` of ``kin``."""
    b = _Builder(linkage, structure, kin, i)
    tip, axis = linkage.drive_tip, linkage.drive_axis
    if mu_v is None:
        far = max(float(np.hypot(*np.asarray(m.vel[i]))) for m in kin.points.values())
        mu_v = max(round_scale(float(np.hypot(*b.vel(tip)))), round_scale(far, PLAN_MAX_MM))
    if mu_a is None:
        far = max(float(np.hypot(*np.asarray(m.acc[i]))) for m in kin.points.values())
        mu_a = max(round_scale(float(np.hypot(*b.acc(tip)))), round_scale(far, PLAN_MAX_MM))
    vpts: dict[str, tuple[float, float]] = {"p": (0.0, 0.0)}
    apts: dict[str, tuple[float, float]] = {"π": (0.0, 0.0)}
    for name in kin.points:
        vpts[letter(name)] = tuple(b.vel(name) / mu_v)
        apts[letter(name)] = tuple(b.acc(name) / mu_a)
    for k in kin.coms:
        vpts[f"s{k}"] = tuple(np.asarray(kin.coms[k].vel[i]) / mu_v)
        apts[f"s{k}"] = tuple(np.asarray(kin.coms[k].acc[i]) / mu_a)
    for name in linkage.ground:
        vpts[letter(name)] = (0.0, 0.0)
        apts[letter(name)] = (0.0, 0.0)
    vc: list[PlanComponent] = []
    ac: list[PlanComponent] = []
    veq: list[tuple[str, str]] = []
    aeq: list[tuple[str, str]] = []
    # the driver
    d = str(linkage.drive_link)
    vc.append(PlanComponent(f"V_{{{tip}}}", "absolute", "p", letter(tip), tuple(b.vel(tip)), rf"\perp {axis}{tip}", d))
    an = b.acc(tip)
    ac.append(PlanComponent(f"a^{{n}}_{{{tip}{axis}}}", "normal", "π", letter(tip), tuple(an),
                            rf"\parallel {tip}{axis}", d))
    veq.append((d, rf"\bar V_{{{tip}}} = \bar\omega_{{{d}}} \times \bar l_{{{axis}{tip}}}"))
    aeq.append((d, rf"\bar a_{{{tip}}} = \bar a^{{n}}_{{{tip}{axis}}} + \bar a^{{\tau}}_{{{tip}{axis}}}"))
    for g in structure.groups[1:]:
        key = g.key
        if g.group_class == 2 and g.kind == "RRR":
            _rrr(b, g, mu_a, vc, ac, veq, aeq, apts)
        elif g.group_class == 2 and g.kind == "RRP":
            _rrp(b, g, mu_a, vc, ac, veq, aeq, apts)
        elif g.group_class == 2 and g.kind == "RPR":
            _rpr(b, g, mu_v, mu_a, vc, ac, veq, aeq, vpts, apts)
        else:
            outer = {p.point for p in g.pairs if p.external}
            seen: set[str] = set()
            for k in g.links:
                for name in linkage.bodies[k].points:
                    if name in linkage.ground or name in outer or name in seen:
                        continue
                    seen.add(name)
                    vc.append(PlanComponent(f"V_{{{name}}}", "absolute", "p", letter(name), tuple(b.vel(name)), "", key))
                    ac.append(PlanComponent(f"a_{{{name}}}", "absolute", "π", letter(name), tuple(b.acc(name)), "", key))
    phi = float(kin.phi[i])
    vplan = Plan("velocity", i, phi, mu_v, MappingProxyType(vpts), tuple(vc), tuple(veq))
    aplan = Plan("acceleration", i, phi, mu_a, MappingProxyType(apts), tuple(ac), tuple(aeq))
    return vplan, aplan


def _relative(b: _Builder, k: int, Q: str, P: str, mu_a: float, group: str, apts: dict,
              ac: list, helper: str) -> None:
    """Normal and tangential components of a_QP of body k, with the helper point n_QP."""
    rQP = b.pos(Q) - b.pos(P)
    w, e = b.qd[k, 2], b.qdd[k, 2]
    an = -w * w * rQP
    at = e * _perp(rQP)
    start = np.asarray(apts[letter(P)])
    apts[helper] = tuple(start + an / mu_a)
    ac.append(PlanComponent(f"a^{{n}}_{{{Q}{P}}}", "normal", letter(P), helper, tuple(an), rf"\parallel {Q}{P}", group))
    ac.append(PlanComponent(f"a^{{\\tau}}_{{{Q}{P}}}", "tangential", helper, letter(Q), tuple(at), rf"\perp {Q}{P}", group))


def _rrr(b, g, mu_a, vc, ac, veq, aeq, apts):
    a, c = g.links
    Q = _inner(g).point
    P, S = _ext(g, a).point, _ext(g, c).point
    for k, O in ((a, P), (c, S)):
        vc.append(PlanComponent(f"V_{{{Q}{O}}}", "relative", letter(O), letter(Q), tuple(b.vel(Q) - b.vel(O)),
                                rf"\perp {Q}{O}", g.key))
        _relative(b, k, Q, O, mu_a, g.key, apts, ac, f"n{letter(Q)}{letter(O)}")
    veq.append((g.key, rf"\bar V_{{{Q}}} = \bar V_{{{P}}} + \bar V_{{{Q}{P}}},\quad "
                       rf"\bar V_{{{Q}}} = \bar V_{{{S}}} + \bar V_{{{Q}{S}}}"))
    aeq.append((g.key, rf"\bar a_{{{Q}}} = \bar a_{{{P}}} + \bar a^{{n}}_{{{Q}{P}}} + \bar a^{{\tau}}_{{{Q}{P}}},\quad "
                       rf"\bar a_{{{Q}}} = \bar a_{{{S}}} + \bar a^{{n}}_{{{Q}{S}}} + \bar a^{{\tau}}_{{{Q}{S}}}"))


def _rrp(b, g, mu_a, vc, ac, veq, aeq, apts):
    a, c = g.links
    r, pl = (a, c) if _ext(g, a).kind == "R" else (c, a)
    Q = _inner(g).point
    P = _ext(g, r).point
    s = b.lk.slides[_ext(g, pl).slide]
    vc.append(PlanComponent(f"V_{{{Q}{P}}}", "relative", letter(P), letter(Q), tuple(b.vel(Q) - b.vel(P)),
                            rf"\perp {Q}{P}", g.key))
    _relative(b, r, Q, P, mu_a, g.key, apts, ac, f"n{letter(Q)}{letter(P)}")
    if s.guide == 0 and s.point == Q:
        vc.append(PlanComponent(f"V_{{{Q}}}", "sliding", "p", letter(Q), tuple(b.vel(Q)), r"\parallel x\text{-}x", g.key))
        ac.append(PlanComponent(f"a_{{{Q}}}", "sliding", "π", letter(Q), tuple(b.acc(Q)), r"\parallel x\text{-}x", g.key))
        veq.append((g.key, rf"\bar V_{{{Q}}} = \bar V_{{{P}}} + \bar V_{{{Q}{P}}},\quad \bar V_{{{Q}}} \parallel x\text{{-}}x"))
        aeq.append((g.key, rf"\bar a_{{{Q}}} = \bar a_{{{P}}} + \bar a^{{n}}_{{{Q}{P}}} + \bar a^{{\tau}}_{{{Q}{P}}},\quad "
                           rf"\bar a_{{{Q}}} \parallel x\text{{-}}x"))
    else:
        veq.append((g.key, rf"\bar V_{{{Q}}} = \bar V_{{{P}}} + \bar V_{{{Q}{P}}}"))
        aeq.append((g.key, rf"\bar a_{{{Q}}} = \bar a_{{{P}}} + \bar a^{{n}}_{{{Q}{P}}} + \bar a^{{\tau}}_{{{Q}{P}}}"))


def _rpr(b, g, mu_v, mu_a, vc, ac, veq, aeq, vpts, apts):
    s = b.lk.slides[_inner(g).slide]
    gl, sl = s.guide, s.link
    H = _ext(g, sl).point          # the block's pin (on a known link)
    G = _ext(g, gl).point          # the slotted link's pivot
    if s.point != H:
        veq.append((g.key, ""))
        aeq.append((g.key, ""))
        return
    Hg = f"{H}_{{{gl}}}"
    hg = f"{letter(H)}{gl}"
    pH = b.pos(H)
    v_hg = b.body_point_vel(gl, pH)
    a_hg = b.body_point_acc(gl, pH)
    vpts[hg] = tuple(v_hg / mu_v)
    apts[hg] = tuple(a_hg / mu_a)
    v_rel = v_hg - b.vel(H)
    vc.append(PlanComponent(f"V_{{{Hg}{H}}}", "sliding", letter(H), hg, tuple(v_rel), rf"\parallel {G}{H}", g.key))
    vc.append(PlanComponent(f"V_{{{Hg}{G}}}", "relative", letter(G), hg, tuple(v_hg - b.vel(G)), rf"\perp {G}{H}", g.key))
    w = b.qd[gl, 2]
    ak = 2 * w * _perp(v_rel)
    ar = a_hg - b.acc(H) - ak
    k_pt = f"k{letter(H)}{gl}"
    apts[k_pt] = tuple(np.asarray(apts[letter(H)]) + ak / mu_a)
    ac.append(PlanComponent(f"a^{{k}}_{{{Hg}{H}}}", "coriolis", letter(H), k_pt, tuple(ak), rf"\perp {G}{H}", g.key))
    ac.append(PlanComponent(f"a^{{r}}_{{{Hg}{H}}}", "sliding", k_pt, hg, tuple(ar), rf"\parallel {G}{H}", g.key))
    rr = pH - b.pos(G)
    an = -w * w * rr
    at = b.qdd[gl, 2] * _perp(rr)
    n_pt = f"n{hg}{letter(G)}"
    apts[n_pt] = tuple(np.asarray(apts[letter(G)]) + an / mu_a)
    ac.append(PlanComponent(f"a^{{n}}_{{{Hg}{G}}}", "normal", letter(G), n_pt, tuple(an), rf"\parallel {H}{G}", g.key))
    ac.append(PlanComponent(f"a^{{\\tau}}_{{{Hg}{G}}}", "tangential", n_pt, hg, tuple(at), rf"\perp {H}{G}", g.key))
    veq.append((g.key, rf"\bar V_{{{Hg}}} = \bar V_{{{H}}} + \bar V_{{{Hg}{H}}},\quad \bar V_{{{Hg}}} = \bar V_{{{G}}} + \bar V_{{{Hg}{G}}}"))
    aeq.append((g.key, rf"\bar a_{{{Hg}}} = \bar a_{{{H}}} + \bar a^{{k}}_{{{Hg}{H}}} + \bar a^{{r}}_{{{Hg}{H}}},\quad "
                       rf"\bar a_{{{Hg}}} = \bar a_{{{G}}} + \bar a^{{n}}_{{{Hg}{G}}} + \bar a^{{\tau}}_{{{Hg}{G}}}"))


def closure_error(plan: Plan) -> float:
    """Largest mismatch (mm) between each component's drawn vector and the segment between its
    plan points — zero for a consistent plan (a test)."""
    err = 0.0
    for c in plan.components:
        a = np.asarray(plan.points[c.start])
        e = np.asarray(plan.points[c.end])
        err = max(err, float(np.hypot(*((e - a) - np.asarray(c.vector) / plan.scale))))
    return err
