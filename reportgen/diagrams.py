"""Kinematic diagrams of the output link (s–v–a against the crank angle): the exact curves and the
replica of graphical differentiation by chords as the course draws it (seed 000, § 1.5; seed 004).

The crank angle axis of length ``L`` mm stands for one turn: μφ = 2π/L rad/mm, μt = μφ/|ω1| s/mm.
Displacements are drawn at μs; the curve is replaced on each of ``n`` equal intervals by its chord;
a ray from the pole at distance H parallel to a chord cuts the ordinate y = H·Δy_s/Δx, so
μv = μs/(μt·H); the same again on the velocity replica gives the acceleration, μa = μv/(μt·H2).
The chord's value belongs to the middle of its interval; its deviation from the exact value there is
the method's error (NOTES.md: 1.4–2.7 % on velocity and 3.5–6.5 % on acceleration at 12 positions).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .kinematics.extremes import Output, Strokes, output_coordinate
from .kinematics.solve import KinematicModel
from .plans import MEASURE_MM, round_scale
from .geometry import readonly as _ro
from .tolerances import TINY

#: Length of the crank-angle axis for one turn, mm (seed 000 uses 192–240 mm).
AXIS_MM = 240.0
#: Intervals of the chord replica over one turn (sheet 1 and section 1 draw the same).
INTERVALS = 24
#: Pole distances a student picks from, mm.
POLE_CHOICES = (10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0)
#: The largest ordinate of a diagram is about this, mm.
ORDINATE_MM = 50.0


@dataclass(frozen=True)
class Diagrams:
    output: Output
    unit: str                      # "м" for a slider, "рад" for a rocker
    phi0: float                    # crank angle of position 0, rad
    sign: float                    # +1 if φ grows with time
    # exact curves on a dense grid of crank-angle offsets from position 0 (rad, 0 … 2π)
    dense_offset: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    # the graphical construction
    n: int
    axis_mm: float
    mu_phi: float
    mu_t: float
    mu_s: float
    H1: float
    H2: float
    mu_v: float
    mu_a: float
    nodes: np.ndarray              # offsets of the n + 1 division points (rad)
    s_nodes_mm: np.ndarray         # ordinates of s at the division points, as measured (mm)
    v_chord_mm: np.ndarray         # step ordinates of the velocity replica (mm), at the interval middles
    a_chord_mm: np.ndarray         # step ordinates of the acceleration replica (mm), between middles
    v_mid_exact: np.ndarray        # exact v at the interval middles
    a_mid_exact: np.ndarray        # exact a at the acceleration steps' middles

    @property
    def v_graph(self) -> np.ndarray:
        return self.v_chord_mm * self.mu_v

    @property
    def a_graph(self) -> np.ndarray:
        return self.a_chord_mm * self.mu_a

    @property
    def v_deviation(self) -> float:
        """Largest deviation of the velocity replica, relative to the largest exact |v|."""
        return float(np.abs(self.v_graph - self.v_mid_exact).max() / max(np.abs(self.v).max(), TINY))

    @property
    def a_deviation(self) -> float:
        return float(np.abs(self.a_graph - self.a_mid_exact).max() / max(np.abs(self.a).max(), TINY))


def _pick_pole(peak_value: float, mu_prev: float, mu_t: float) -> float:
    """The pole distance H that draws ``peak_value`` closest to ``ORDINATE_MM``."""
    best = POLE_CHOICES[0]
    for H in POLE_CHOICES:
        y = peak_value / (mu_prev / (mu_t * H))
        if abs(y - ORDINATE_MM) < abs(peak_value / (mu_prev / (mu_t * best)) - ORDINATE_MM):
            best = H
    # A near-singular mechanism (e.g. a slotted link whose pivot nearly touches the crank circle) can
    # have a peak that even the shortest pole draws metres tall: go down the 5-2-1 series until the
    # exact curve fits in 2 ordinates (the replica is then coarse there, which is the method's truth).
    k = 0
    while peak_value / (mu_prev / (mu_t * best)) > 2 * ORDINATE_MM and k < 60:
        best = (5.0, 2.0, 1.0)[k % 3] * 10.0 ** (-(k // 3))
        k += 1
    return best


def _measure(mm: np.ndarray) -> np.ndarray:
    return np.round(np.asarray(mm) / MEASURE_MM) * MEASURE_MM


def build_diagrams(model: KinematicModel, strokes: Strokes, phi0: float, n: int = 24, dense: int = 361) -> Diagrams:
    """The s–v–a diagrams of the output from position 0 (crank angle ``phi0``) over one turn."""
    out = strokes.output
    sign = 1.0 if model.omega >= 0 else -1.0
    w = abs(model.omega)
    off = np.linspace(0.0, 2 * math.pi, dense)
    phis = phi0 + sign * off
    q, _ = model.positions(phis)
    qd = model.velocities(q)
    qdd = model.accelerations(q, qd)
    x, v = output_coordinate(model, out, q, qd)
    a = _output_acc(model, out, q, qd, qdd)
    s = (x - x[0]) * strokes.direction
    v = v * strokes.direction
    a = a * strokes.direction
    mu_phi = 2 * math.pi / AXIS_MM
    mu_t = mu_phi / w
    mu_s = round_scale(float(np.abs(s).max()), ORDINATE_MM * 1.6)
    nodes = np.linspace(0.0, 2 * math.pi, n + 1)
    qn, _ = model.positions(phi0 + sign * nodes)
    sn = (output_coordinate(model, out, qn) - x[0]) * strokes.direction
    s_mm = _measure(sn / mu_s)
    dx_mm = AXIS_MM / n
    H1 = _pick_pole(float(np.abs(v).max()), mu_s, mu_t)
    mu_v = mu_s / (mu_t * H1)
    v_mm = _measure(H1 * np.diff(s_mm) / dx_mm)
    # second differentiation: chords of the velocity steps' middles (cyclic)
    H2 = _pick_pole(float(np.abs(a).max()), mu_v, mu_t)
    mu_a = mu_v / (mu_t * H2)
    v_next = np.roll(v_mm, -1)
    a_mm = _measure(H2 * (v_next - v_mm) / dx_mm)
    mids = (nodes[:-1] + nodes[1:]) / 2
    qm, _ = model.positions(phi0 + sign * mids)
    qmd = model.velocities(qm)
    _, vm = output_coordinate(model, out, qm, qmd)
    amid = np.mod(mids + (2 * math.pi / n) / 2, 2 * math.pi)
    qa, _ = model.positions(phi0 + sign * amid)
    qad = model.velocities(qa)
    qadd = model.accelerations(qa, qad)
    am = _output_acc(model, out, qa, qad, qadd)
    return Diagrams(out, "м" if out.kind == "slider" else "рад", float(phi0), sign, _ro(off), _ro(s), _ro(v), _ro(a),
                    n, AXIS_MM, mu_phi, mu_t, mu_s, H1, H2, mu_v, mu_a, _ro(nodes), _ro(s_mm), _ro(v_mm), _ro(a_mm),
                    _ro(vm * strokes.direction), _ro(am * strokes.direction))


def _output_acc(model: KinematicModel, out: Output, q, qd, qdd) -> np.ndarray:
    """Acceleration of the output coordinate (m/s² along the guide, or ε of the rocker)."""
    if out.kind == "slider":
        s = model.linkage.slides[out.slide]
        from .kinematics.constraints import rot
        Rp = rot(q[:, out.link, 2], s.point_local)
        w = qd[:, out.link, 2][:, None]
        e = qdd[:, out.link, 2][:, None]
        acc = qdd[:, out.link, :2] + e * np.stack((-Rp[:, 1], Rp[:, 0]), -1) - w * w * Rp
        return acc @ np.asarray(s.line_dir)
    return qdd[:, out.link, 2]


