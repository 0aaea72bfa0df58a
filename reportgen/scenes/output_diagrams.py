"""The kinematic diagrams of the output (s–v–a, or ψ–ω–ε of a rocker) as one scene, from
:class:`reportgen.diagrams.Diagrams` (``project.output_diagrams``): the three diagrams one above
the other, the φ axis of each divided into the n intervals, the exact curves (thin), the measured
nodes of s and the polyline through them, the steps of the velocity and acceleration replicas and
the curves through their middles, the poles P1, P2 at H1, H2 with their rays. Paper mm at the
diagrams' own scales (μs, μv, μa over μφ); the origins of the three diagrams are the scene's points
``o_s``, ``o_v``, ``o_a``; the axes are entities ``axis:…`` (a sheet draws its own, with arrows)."""
from __future__ import annotations

import numpy as np

from ..diagrams import Diagrams
from .scene import Circle, Entity, Label, Polyline, Scale, Scene, Segment, frozen
from ..tolerances import MM_EPS, MM_ROUNDOFF

#: Space above a diagram's largest ordinate (title, dimensions) and between diagrams, mm.
TOP_MM = 32.0
GAP_MM = 8.0
#: Room right of the φ axis (its arrow and name), mm.
RIGHT_MM = 28.0
#: Radius of the measured nodes of s and of the poles, mm.
NODE_MM = 0.7
POLE_MM = 0.8


def x_nodes(d: Diagrams) -> np.ndarray:
    return np.asarray(d.nodes) / d.mu_phi


def v_steps(d: Diagrams) -> list[tuple[float, float, float]]:
    """(x0, x1, y) of the velocity steps: over each interval."""
    x = x_nodes(d)
    return [(float(x[i]), float(x[i + 1]), float(d.v_chord_mm[i])) for i in range(d.n)]


def a_steps(d: Diagrams) -> list[tuple[float, float, float]]:
    """(x0, x1, y) of the acceleration steps: between the middles of the velocity steps; the last
    one wraps round to the start of the axis (the motion is periodic)."""
    x = x_nodes(d)
    dx = d.axis_mm / d.n
    out = []
    for j in range(d.n):
        x0, x1 = float(x[j] + dx / 2), float(x[j] + 3 * dx / 2)
        if x1 <= d.axis_mm + MM_ROUNDOFF:
            out.append((x0, x1, float(d.a_chord_mm[j])))
        else:
            out.append((x0, d.axis_mm, float(d.a_chord_mm[j])))
            out.append((0.0, x1 - d.axis_mm, float(d.a_chord_mm[j])))
    return out


def ranges(d: Diagrams) -> list[tuple[float, float]]:
    """(up, down) ordinates in mm of the three diagrams (both ≥ 0)."""
    s = np.concatenate([np.asarray(d.s) / d.mu_s, d.s_nodes_mm])
    v = np.concatenate([np.asarray(d.v) / d.mu_v, d.v_chord_mm])
    a = np.concatenate([np.asarray(d.a) / d.mu_a, d.a_chord_mm])
    return [(max(float(arr.max()), 10.0) + 4.0, max(-float(arr.min()), 0.0) + 4.0) for arr in (s, v, a)]


def left_mm(d: Diagrams) -> float:
    """From the left edge to the ordinate axes (the longer pole and its letter), mm."""
    return max(d.H1, d.H2) + 22.0


def size(d: Diagrams) -> tuple[float, float]:
    """Width and height of the three diagrams with their titles' room, mm."""
    w = left_mm(d) + d.axis_mm + RIGHT_MM + 6.0
    h = sum(up + down + TOP_MM + GAP_MM for up, down in ranges(d)) + 6.0
    return w, h


def _steps(prefix: str, o, steps) -> list[Entity]:
    """The steps of a replica: horizontal segments and the verticals joining them."""
    out: list[Entity] = []
    prev = None
    for k, (a, b, y) in enumerate(sorted(steps)):
        if prev is not None and abs(prev[0] - a) < MM_EPS:
            out.append(Segment(f"{prefix}:riser:{k}", (o[0] + a, o[1] + prev[1]), (o[0] + a, o[1] + y), "thin"))
        out.append(Segment(f"{prefix}:step:{k}", (o[0] + a, o[1] + y), (o[0] + b, o[1] + y), "thin"))
        prev = (b, y)
    return out


def _pole(prefix: str, o, H: float, ordinates, index: str) -> tuple[list[Entity], Label, tuple[float, float]]:
    p = (o[0] - H, o[1])
    ents: list[Entity] = [Segment(f"{prefix}:ray:{k}", p, (o[0], o[1] + y), "construction")
                          for k, y in enumerate(sorted(set(float(v) for v in ordinates)))]
    ents.append(Circle(f"{prefix}:pole", p, POLE_MM))
    return ents, Label(f"P_{{{index}}}", f"{prefix}:pole", p), p


def output_diagrams_scene(d: Diagrams, positions: int) -> Scene:
    """The s–v–a diagrams of ``d``; ``positions``: the mechanism's positions numbered under the
    φ axis of s (the last is position 0 again)."""
    rng = ranges(d)
    _, height = size(d)
    x0 = left_mm(d)
    top = height - 2.0
    origins = []
    for up, down in rng:
        oy = top - TOP_MM - up
        origins.append((x0, oy))
        top = oy - down - GAP_MM
    xs = x_nodes(d)
    dense_x = np.asarray(d.dense_offset) / d.mu_phi
    ents: list[Entity] = []
    labels: list[Label] = []
    names = ("s", "v", "a")
    y_names = ("s", "v", "a") if d.unit == "м" else (r"\psi", r"\omega", r"\varepsilon")
    for (up, down), o, name, y_name in zip(rng, origins, names, y_names):
        x_end, y_end = (o[0] + d.axis_mm + RIGHT_MM - 6.0, o[1]), (o[0], o[1] + up + 10.0)
        ents.append(Segment(f"{name}:axis:phi", o, x_end, "thin"))
        ents.append(Segment(f"{name}:axis:y", (o[0], o[1] - down), y_end, "thin"))
        labels += [Label(r"\varphi", f"{name}:axis:phi", x_end), Label(y_name, f"{name}:axis:y", y_end)]
    # s(φ)
    o = origins[0]
    ents.append(Polyline("s:exact", tuple(zip(map(float, o[0] + dense_x), map(float, o[1] + np.asarray(d.s) / d.mu_s))),
                         "thin"))
    s_pts = tuple((float(o[0] + x), float(o[1] + y)) for x, y in zip(xs, d.s_nodes_mm))
    ents.append(Polyline("s:curve", s_pts, "contour"))
    ents += [Circle(f"s:node:{k}", p, NODE_MM) for k, p in enumerate(s_pts)]
    y_num = o[1] - max(rng[0][1] - 4.0, 0.0) - 2.5
    labels += [Label(str(j % positions), f"position:{j}", (o[0] + d.axis_mm * j / positions, y_num), "number")
               for j in range(positions + 1)]
    # v(φ)
    o = origins[1]
    pole, lb, p1 = _pole("v", o, d.H1, d.v_chord_mm, "1")
    ents += pole
    labels.append(lb)
    ents.append(Polyline("v:exact", tuple(zip(map(float, o[0] + dense_x), map(float, o[1] + np.asarray(d.v) / d.mu_v))),
                         "thin"))
    steps = v_steps(d)
    ents += _steps("v", o, steps)
    mids = [((a + b) / 2, y) for a, b, y in steps]
    ends = [(0.0, (mids[0][1] + mids[-1][1]) / 2)] + mids + [(d.axis_mm, (mids[0][1] + mids[-1][1]) / 2)]
    ents.append(Polyline("v:curve", tuple((float(o[0] + x), float(o[1] + y)) for x, y in ends), "contour"))
    # a(φ)
    o = origins[2]
    pole, lb, p2 = _pole("a", o, d.H2, d.a_chord_mm, "2")
    ents += pole
    labels.append(lb)
    ents.append(Polyline("a:exact", tuple(zip(map(float, o[0] + dense_x), map(float, o[1] + np.asarray(d.a) / d.mu_a))),
                         "thin"))
    st = a_steps(d)
    ents += _steps("a", o, st)
    half = d.axis_mm / d.n / 2
    pts = sorted(((a + b) / 2, y) for a, b, y in st if b - a > half)
    pts = [(0.0, float(d.a_chord_mm[-1]))] + pts + [(d.axis_mm, float(d.a_chord_mm[-1]))]
    ents.append(Polyline("a:curve", tuple((float(o[0] + x), float(o[1] + y)) for x, y in pts), "contour"))
    sym = ("μs", "μv", "μa") if d.unit == "м" else ("μψ", "μω", "με")
    units = ("м/мм", "(м/с)/мм", "(м/с²)/мм") if d.unit == "м" else ("рад/мм", "(рад/с)/мм", "(рад/с²)/мм")
    scales = tuple(Scale(s, mu, u) for s, mu, u in zip(sym, (d.mu_s, d.mu_v, d.mu_a), units)) + \
        (Scale("μφ", d.mu_phi, "рад/мм"), Scale("μt", d.mu_t, "с/мм"))
    points = {"o_s": origins[0], "o_v": origins[1], "o_a": origins[2], "P1": p1, "P2": p2}
    values = {"H1": float(d.H1), "H2": float(d.H2), "L": float(d.axis_mm), "width": size(d)[0], "height": height}
    return Scene("output_diagrams", scales, tuple(ents), tuple(labels), frozen(points), frozen(values))
