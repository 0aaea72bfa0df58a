"""The diagrams of section 3 as scenes, from :class:`reportgen.dynamics.DynamicsResult` and its
graphical replica (:mod:`reportgen.dynamics.graphical`, whose lengths are already paper mm at the
scales it chose from ``project.boxes.diagrams``):

* ``moment``: M_red(φ) at μM over the φ axis at μφ, the mid-interval ordinates (steps) carried to
  the M axis and joined to the pole P at H;
* ``work``: the work of resistance A_с by chords and the straight line of A_дв (from the origin to
  −A_с(2π): the note's convention ΔE = A_дв + A_с) at μA = μM·μφ·H;
* ``energy``: ΔE(φ) at μE = μA / k;
* ``wittenbauer``: ΔE(J) through the positions, the tangents at ψmax, ψmin from K and L on the ΔE
  axis (μE, μJ); its values hold K, L, KL (mm) and the flywheel's J read back from KL;
* ``inertia``: J_red(φ) turned (J to the right, φ downwards) at μJ, sharing the Wittenbauer J axis;
* ``omega``: ω(φ) of the steady motion with the flywheel (the φ axis at ω_m) at a round μω, the
  band ω_m(1 ± δ/2).

Each scene has its origin where its axes cross; the axes are entities ``axis:…`` (a sheet may draw
its own, with arrows and ticks). ``wittenbauer_group`` puts ΔE(φ), the Wittenbauer diagram and
J_red(φ) together as the construction is made (ΔE levels shared, J axis shared) for the note."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .boxes import GraphLayout
from .numbering import diagram_labels
from .scales import PLAN_SERIES, round_scale
from .scene import Circle, Entity, Label, Polyline, Scale, Scene, Segment, frozen

#: Radius of the small circles at the positions' nodes, mm.
NODE_MM = 0.6
#: Radius of the points P, K, L, mm.
POINT_MM = 0.8
#: The tangents and the J axis go this far beyond the largest J_red, mm.
J_BEYOND_MM = 12.0
#: Room for the axes' arrows beyond the drawing, mm.
AXIS_BEYOND_MM = 8.0
#: The gap between ΔE(φ) and the Wittenbauer diagram, and above J_red(φ), in the note's group, mm.
GROUP_GAP_MM = 30.0

MU_PHI, MU_M, MU_A, MU_E, MU_J, MU_OMEGA = "μφ", "μM", "μA", "μE", "μJ", "μω"


@dataclass(frozen=True)
class DynamicsScenes:
    moment: Scene
    work: Scene
    energy: Scene
    wittenbauer: Scene
    inertia: Scene
    omega: Scene
    #: the names of the diagrams' positions (:func:`reportgen.scenes.numbering.diagram_labels`)
    positions: tuple[str, ...]

    def column_group(self) -> Scene:
        """M_red(φ), A(φ) and ΔE(φ) one under the other on one φ axis length (as sheet 3's column)."""
        parts, top = [], 0.0
        for sc in (self.moment, self.work, self.energy):
            y0, y1 = sc.bounds()[1], sc.bounds()[3]
            dy = top - y1
            parts.append((sc, 0.0, dy, sc.name))
            top = y0 + dy - GROUP_GAP_MM
        return merged("column_group", parts, self.moment.scales + self.work.scales[:1] + self.energy.scales[:1],
                      {**self.moment.values, **self.energy.values})

    def wittenbauer_group(self) -> Scene:
        """ΔE(φ) on the left, the Wittenbauer diagram right of it at the same ΔE level, J_red(φ)
        turned under the Wittenbauer diagram on the same J axis (the construction of φ's elimination)."""
        e, w, j = self.energy, self.wittenbauer, self.inertia
        ex1 = e.bounds()[2]
        dx = ex1 + GROUP_GAP_MM
        dy_j = w.bounds()[1] - GROUP_GAP_MM
        # the positions are numbered on ΔE(φ) and J_red(φ); on the small Wittenbauer curve between
        # them their numbers would crowd (the sheet, at 1:1, numbers its points)
        w_plain = replace(w, labels=tuple(lb for lb in w.labels if lb.role != "number"))
        return merged("wittenbauer_group", ((e, 0.0, 0.0, "energy"), (w_plain, dx, 0.0, ""), (j, dx, dy_j, "inertia")),
                      w.scales, w.values)


def merged(name: str, parts, scales, values) -> Scene:
    """One scene of several, each moved by (dx, dy); the entity ids of a part get ``prefix:``."""
    ents: list[Entity] = []
    labels: list[Label] = []
    for sc, dx, dy, prefix in parts:
        def mv(p, dx=dx, dy=dy):
            return (p[0] + dx, p[1] + dy)
        pre = f"{prefix}:" if prefix else ""
        for ent in sc.entities:
            if isinstance(ent, Segment):
                ents.append(Segment(pre + ent.id, mv(ent.a), mv(ent.b), ent.kind, ent.trim))
            elif isinstance(ent, Polyline):
                ents.append(Polyline(pre + ent.id, tuple(mv(p) for p in ent.points), ent.kind, ent.closed))
            elif isinstance(ent, Circle):
                ents.append(Circle(pre + ent.id, mv(ent.c), ent.r, ent.kind, ent.filled, ent.hinge))
        for lb in sc.labels:
            along = None if lb.along is None else (mv(lb.along[0]), mv(lb.along[1]))
            labels.append(Label(lb.text, pre + lb.anchor, mv(lb.at), lb.role, along, lb.leader))
    return Scene(name, tuple(scales), tuple(ents), tuple(labels), frozen({}), frozen(values))


def _nodes(xs, ys, prefix: str = "node") -> list[Entity]:
    return [Circle(f"{prefix}:{k}", (float(x), float(y)), NODE_MM) for k, (x, y) in enumerate(zip(xs, ys))]


def _phi_axis(x_end: float, y_lo: float, y_hi: float, y_name: str) -> tuple[list[Entity], list[Label]]:
    """The φ axis from the origin to ``x_end`` (plus the arrows' room) and the ordinate axis."""
    ents: list[Entity] = [Segment("axis:phi", (0.0, 0.0), (x_end + AXIS_BEYOND_MM, 0.0), "thin"),
                          Segment("axis:y", (0.0, y_lo), (0.0, y_hi + AXIS_BEYOND_MM), "thin")]
    labels = [Label(r"\varphi", "axis:phi", (x_end + AXIS_BEYOND_MM, 0.0)),
              Label(y_name, "axis:y", (0.0, y_hi + AXIS_BEYOND_MM))]
    return ents, labels


def _numbers(xs, y: float, names) -> list[Label]:
    """The positions' numbers under the φ axis (the break positions are named in the tables)."""
    return [Label(n, f"position:{n}", (float(x), y), "number") for x, n in zip(xs, names) if n.isdigit()]


def _lo_hi(*arrays) -> tuple[float, float]:
    v = np.concatenate([np.atleast_1d(np.asarray(a, dtype=float)) for a in arrays])
    return min(float(v.min()), 0.0), max(float(v.max()), 0.0)


def moment_scene(g, names) -> Scene:
    x, m = np.asarray(g.x), np.asarray(g.M_mm)
    lo, hi = _lo_hi(m, g.mid_mm)
    ents, labels = _phi_axis(float(x[-1]), lo, hi, "M")
    ents.append(Polyline("curve", tuple(zip(map(float, x), map(float, m))), "contour"))
    ents += _nodes(x, m)
    pole = (-float(g.H), 0.0)
    for k, (a, b, y) in enumerate(zip(x[:-1], x[1:], g.mid_mm)):
        ents.append(Segment(f"step:{k}", (float(a), float(y)), (float(b), float(y)), "thin"))
        ents.append(Segment(f"ray:{k}", (0.0, float(y)), pole, "construction"))
    ents.append(Circle("pole", pole, POINT_MM))
    # the break positions (switching of the resistance, corners of its law): thin verticals
    ents += [Segment(f"break:{n}", (float(xx), lo), (float(xx), hi), "thin")
             for xx, n in zip(x, names) if not n.isdigit()]
    labels.append(Label("P", "pole", pole))
    labels += _numbers(x, lo, names)
    return Scene("moment", (Scale(MU_M, g.mu_M, "Н·м/мм"), Scale(MU_PHI, g.mu_phi, "рад/мм")), tuple(ents),
                 tuple(labels), frozen({"P": pole}), frozen({"H": float(g.H), "L_phi": float(x[-1])}))


def work_scene(g, names) -> Scene:
    x, a = np.asarray(g.x), np.asarray(g.a_mm)
    end = (float(x[-1]), float(g.drive_mm[-1]))
    lo, hi = _lo_hi(a, [end[1]])
    ents, labels = _phi_axis(float(x[-1]), lo, hi, "A")
    ents.append(Polyline("curve", tuple(zip(map(float, x), map(float, a))), "contour"))
    ents += _nodes(x, a)
    ents.append(Segment("drive", (0.0, 0.0), end, "contour"))
    # the end ordinate of A_с carried over with its sign changed
    ents.append(Segment("carry", (float(x[-1]), float(a[-1])), end, "thin"))
    # the curve's name on a node of its middle half, the one farthest above the positions' numbers
    # (at the curve's lowest level ``lo``): beside the curve, never on a number (class3's «6»)
    n = len(x)
    mid = range(n // 4, max(n // 4 + 1, 3 * n // 4 + 1))
    i_mid = max(mid, key=lambda i: (abs(float(a[i]) - lo), -abs(i - n // 2)))
    labels.append(Label(r"A_{\text{с}}", "curve", (float(x[i_mid]), float(a[i_mid]))))
    labels.append(Label(r"A_{\text{дв}}", "drive", (end[0] / 2, end[1] / 2)))
    labels += _numbers(x, lo, names)
    return Scene("work", (Scale(MU_A, g.mu_A, "Дж/мм"), Scale(MU_PHI, g.mu_phi, "рад/мм")), tuple(ents),
                 tuple(labels), frozen({}), frozen({"A_end": float(a[-1]), "drive_end": end[1]}))


def energy_scene(g, names) -> Scene:
    x, e = np.asarray(g.x), np.asarray(g.e_mm)
    lo, hi = _lo_hi(e)
    ents, labels = _phi_axis(float(x[-1]), lo, hi, r"\Delta E")
    ents.append(Polyline("curve", tuple(zip(map(float, x), map(float, e))), "contour"))
    ents += _nodes(x, e)
    labels += _numbers(x, lo, names)
    return Scene("energy", (Scale(MU_E, g.mu_E, "Дж/мм"), Scale(MU_PHI, g.mu_phi, "рад/мм")), tuple(ents),
                 tuple(labels), frozen({}), frozen({"k": float(g.enlargement), "E_span": float(e.max() - e.min())}))


def j_length(g) -> float:
    """Length of the drawn tangents and of the J axis up to its arrow's room, mm."""
    return float(np.max(g.j_mm)) + J_BEYOND_MM


def wittenbauer_scene(g, names, omega_m: float, delta: float) -> Scene:
    """ΔE(J), the tangents at ψmax, ψmin, K, L and the segment KL on the ΔE axis; values: K_mm,
    L_mm, KL_mm (as constructed), KL_read_mm (as dimensioned and read: the replica's
    ``KL_read_mm``) and J_fly = KL_read·μE/(ω_m²·δ) read back from it."""
    j, e = np.asarray(g.j_mm), np.asarray(g.e_mm)
    x_len = j_length(g)
    t_max, t_min = math.tan(math.radians(g.psi_max_deg)), math.tan(math.radians(g.psi_min_deg))
    ends = (g.K_mm + x_len * t_max, g.L_mm + x_len * t_min)
    lo, hi = _lo_hi(e, [g.K_mm, g.L_mm], ends)
    ents: list[Entity] = [Segment("axis:J", (0.0, 0.0), (x_len + AXIS_BEYOND_MM, 0.0), "thin"),
                          Segment("axis:y", (0.0, lo), (0.0, hi + AXIS_BEYOND_MM), "thin")]
    labels = [Label("J", "axis:J", (x_len + AXIS_BEYOND_MM, 0.0)),
              Label(r"\Delta E", "axis:y", (0.0, hi + AXIS_BEYOND_MM))]
    ents.append(Polyline("curve", tuple(zip(map(float, j), map(float, e))), "contour"))
    ents += _nodes(j[:-1], e[:-1])
    K, L = (0.0, float(g.K_mm)), (0.0, float(g.L_mm))
    ents.append(Segment("tangent:K", K, (x_len, float(ends[0])), "contour"))
    ents.append(Segment("tangent:L", L, (x_len, float(ends[1])), "contour"))
    ents.append(Segment("KL", L, K, "contour"))
    ents.append(Circle("point:K", K, POINT_MM))
    ents.append(Circle("point:L", L, POINT_MM))
    labels += [Label("K", "point:K", K), Label("L", "point:L", L),
               Label(r"\psi_{\max}", "tangent:K", (x_len * 0.6, g.K_mm + x_len * 0.6 * t_max), "vector",
                     (K, (x_len, float(ends[0])))),
               Label(r"\psi_{\min}", "tangent:L", (x_len * 0.6, g.L_mm + x_len * 0.6 * t_min), "vector",
                     (L, (x_len, float(ends[1]))))]
    labels += [Label(n, f"position:{n}", (float(p), float(q)), "number")
               for p, q, n in zip(j[:-1], e[:-1], names[:-1]) if n.isdigit()]
    KL = float(g.K_mm - g.L_mm)
    KL_read = float(g.KL_read_mm)
    J_fly = KL_read * g.mu_E / (omega_m * omega_m * delta)
    values = {"K_mm": float(g.K_mm), "L_mm": float(g.L_mm), "KL_mm": KL, "KL_read_mm": KL_read, "J_fly": J_fly,
              "psi_max_deg": float(g.psi_max_deg), "psi_min_deg": float(g.psi_min_deg),
              "index_K": float(g.index_K), "index_L": float(g.index_L), "j_length": x_len}
    return Scene("wittenbauer", (Scale(MU_E, g.mu_E, "Дж/мм"), Scale(MU_J, g.mu_J, "кг·м²/мм")), tuple(ents),
                 tuple(labels), frozen({"K": K, "L": L}), frozen(values))


def inertia_scene(g, names) -> Scene:
    """J_red(φ) turned: J to the right (the Wittenbauer diagram's J axis), φ downwards."""
    j, x = np.asarray(g.j_mm), np.asarray(g.x)
    x_len, phi_len = j_length(g), float(x[-1])
    ents: list[Entity] = [Segment("axis:J", (0.0, 0.0), (x_len + AXIS_BEYOND_MM, 0.0), "thin"),
                          Segment("axis:phi", (0.0, 0.0), (0.0, -phi_len - AXIS_BEYOND_MM), "thin")]
    labels = [Label("J", "axis:J", (x_len + AXIS_BEYOND_MM, 0.0)),
              Label(r"\varphi", "axis:phi", (0.0, -phi_len - AXIS_BEYOND_MM))]
    for k, y in enumerate(-x):
        ents.append(Segment(f"tick:{k}", (-1.5, float(y)), (1.5, float(y)), "thin"))
    ents.append(Polyline("curve", tuple(zip(map(float, j), map(float, -x))), "contour"))
    ents += _nodes(j, -x)
    labels += [Label(n, f"position:{n}", (0.0, float(-xx)), "number") for xx, n in zip(x, names) if n.isdigit()]
    return Scene("inertia", (Scale(MU_J, g.mu_J, "кг·м²/мм"), Scale(MU_PHI, g.mu_phi, "рад/мм")), tuple(ents),
                 tuple(labels), frozen({}), frozen({"L_phi": phi_len}))


def omega_scale(res, layout: GraphLayout) -> float:
    """μω, rad/s per mm: the smallest round one that draws |ω − ω_m| and the band within
    ``layout.omega_height``."""
    w = np.asarray(res.motion.omega) - res.omega_m
    lo, hi = (b - res.omega_m for b in res.motion.band)
    return round_scale(max(float(np.abs(w).max()), hi, -lo), layout.omega_height, PLAN_SERIES)


def omega_scene(res, g, layout: GraphLayout) -> Scene:
    """ω(φ) with the flywheel: the φ axis at ω_m, the band lines ω_min, ω_max (hidden lines)."""
    mu = omega_scale(res, layout)
    x = np.append(np.asarray(res.theta), 2 * math.pi) / g.mu_phi
    w = (np.append(np.asarray(res.motion.omega), res.motion.omega[0]) - res.omega_m) / mu
    lo_w, hi_w = (b - res.omega_m for b in res.motion.band)
    band = (hi_w / mu, lo_w / mu)
    x_end = float(g.x[-1])
    lo, hi = _lo_hi(w, band)
    ents, labels = _phi_axis(x_end, lo, hi, r"\omega")
    ents.append(Polyline("curve", tuple(zip(map(float, x), map(float, w))), "contour"))
    ents.append(Segment("band:max", (0.0, float(band[0])), (x_end, float(band[0])), "hidden"))
    ents.append(Segment("band:min", (0.0, float(band[1])), (x_end, float(band[1])), "hidden"))
    labels += [Label(r"\omega_{\max}", "band:max", (x_end, float(band[0]))),
               Label(r"\omega_{\min}", "band:min", (x_end, float(band[1])))]
    return Scene("omega", (Scale(MU_OMEGA, mu, "рад/(с·мм)"), Scale(MU_PHI, g.mu_phi, "рад/мм")), tuple(ents),
                 tuple(labels), frozen({}),
                 frozen({"omega_m": float(res.omega_m), "omega_max": float(res.motion.band[1]),
                         "omega_min": float(res.motion.band[0])}))


def dynamics_scenes(res, layout: GraphLayout) -> DynamicsScenes:
    """The scenes of section 3 of ``res`` (a :class:`reportgen.dynamics.DynamicsResult`)."""
    g = res.graphical
    names = tuple(diagram_labels(res))
    return DynamicsScenes(moment_scene(g, names), work_scene(g, names), energy_scene(g, names),
                          wittenbauer_scene(g, names, res.omega_m, res.delta_target), inertia_scene(g, names),
                          omega_scene(res, g, layout), names)
