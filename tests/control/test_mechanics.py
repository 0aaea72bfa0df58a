"""The control work's mechanics for every variant of the 22 tables: structure, the lever against the
power balance, and one reference variant per kind of scheme against an independent calculation
written here (closed-form positions of the scheme, velocities and accelerations by central
differences in φ, masses by the manual's rules (29)–(34), the balancing moment by virtual work)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from reportgen.control.analysis import control_work_of
from reportgen.control.sketch import sketch
from reportgen.control.tables import table, tables
from reportgen.commands.new import task_words
from reportgen.control.task_text import DEFAULT_G, DEFAULT_Q, DEFAULT_SLIDER_FACTOR, DEFAULT_TRIANGLE_FACTOR, task_text
from reportgen.project import Project
from reportgen.taskfile import loads_task

BUILDABLE = [(t.number, v.number) for t in tables() for v in t.variants if v.flag is None]


def _project(t: int, v: int) -> Project:
    tab = table(t)
    return Project(loads_task(task_text(tab, tab.variant(v), words=task_words("ru", t, v))))


def test_219_of_220_variants_assemble():
    assert len(BUILDABLE) == 219


@pytest.mark.parametrize("t,v", BUILDABLE)
def test_structure_and_lever_against_power_balance(t, v):
    p = _project(t, v)
    s = p.structure
    assert s.W == 1
    assert [(g.label, g.kind) for g in s.groups[1:]] == [("II(2,3)", "RRR"), ("II(4,5)", "RRP")]
    r = control_work_of(p)
    assert r.phi_deg == pytest.approx(table(t).variant(v).phi_deg, abs=1e-9)
    # P_у of the lever (moments of the turned plan) equals the power balance (ΣF·v + ΣM·ω)
    assert r.M_y == pytest.approx(r.M_y_power, rel=1e-9, abs=1e-9)
    assert r.P_y * r.l_AB == pytest.approx(r.M_y, rel=1e-12)


# one reference variant per kind of reconstructed scheme
REFERENCES = [
    (1, 1),    # E on the rocker's line beyond C (bar D–C–E)
    (8, 4),    # E on the coupler's line (bar B–E–C)
    (5, 3),    # triangular rocker CDE
    (6, 2),    # equilateral triangular coupler BCE
    (17, 6),   # link 4 from C to the slider E
    (22, 4),   # a crank that cannot turn fully, analysed at its φ
]


def _independent(t: int, v: int) -> dict:
    tab = table(t)
    var = tab.variant(v)
    sc = tab.scheme
    phi0 = var.phi_deg
    w1 = var.omega1
    h = 0.05                                 # deg; five-point differences: truncation ~h⁴, round-off ~1e-16/h²

    def pts(dphi: float) -> dict[str, np.ndarray]:
        return {k: np.asarray(x) for k, x in sketch(sc, var, phi0 + dphi).points.items()}

    P = {d: pts(d * h) for d in (-2, -1, 0, 1, 2)}
    dt = math.radians(h) / w1                # time of a crank step

    def vel(f):
        return (-f(P[2]) + 8 * f(P[1]) - 8 * f(P[-1]) + f(P[-2])) / (12 * dt)

    def acc(f):
        return (-f(P[2]) + 16 * f(P[1]) - 30 * f(P[0]) + 16 * f(P[-1]) - f(P[-2])) / (12 * dt * dt)

    def ang(a, b):
        def f(p):
            d = p[b] - p[a]
            return math.atan2(d[1], d[0])

        def g(p):                             # unwrapped about the angle at dphi = 0
            return f(P[0]) + math.remainder(f(p) - f(P[0]), 2 * math.pi)
        return g

    slider = sc.slider
    start = sc.f_from
    links = {2: ("B", "C"), 3: ("D", "C"), 4: (start, slider)}
    out = {f"omega{k}": vel(ang(*ab)) for k, ab in links.items()}
    out |= {f"eps{k}": acc(ang(*ab)) for k, ab in links.items()}
    out["vF"] = float(np.hypot(*vel(lambda p: p[slider])))
    out["aF"] = float(np.hypot(*acc(lambda p: p[slider])))
    # masses by (29)–(34); centres of mass: middle of a bar, centroid of a triangle (§5)
    q = DEFAULT_Q
    members = {1: ["A", "B"], 2: ["B", "C"], 3: ["D", "C"], 4: [start, slider]}
    if sc.e_kind != "none":
        members[sc.e_link].append("E")
    mass, J, com = {}, {}, {}
    for k, names in members.items():
        p0 = P[0]
        sides = sorted(float(np.hypot(*(p0[a] - p0[b]))) for i, a in enumerate(names) for b in names[i + 1:])
        if len(names) == 2 or abs(sides[0] + sides[1] - sides[2]) < 1e-9 * sides[2]:
            l = sides[-1]
            mass[k] = q * l
            J[k] = mass[k] * l * l / 12
            e1, e2 = max(((a, b) for i, a in enumerate(names) for b in names[i + 1:]),
                         key=lambda ab: float(np.hypot(*(p0[ab[0]] - p0[ab[1]]))))
            com[k] = (lambda u, w: lambda p: (p[u] + p[w]) / 2)(e1, e2)
        else:
            mass[k] = q * sum(sides)
            ml = mass[k] * sides[-1] / sum(sides)
            J[k] = DEFAULT_TRIANGLE_FACTOR * ml * sides[-1] ** 2 / 12
            com[k] = (lambda ns: lambda p: sum(p[n] for n in ns) / 3)(tuple(names))
    mass[5], J[5] = DEFAULT_SLIDER_FACTOR * mass[1], 0.0
    com[5] = lambda p: p[slider]
    omega = {1: w1, **{k: out[f"omega{k}"] for k in (2, 3, 4)}, 5: 0.0}
    eps = {1: 0.0, **{k: out[f"eps{k}"] for k in (2, 3, 4)}, 5: 0.0}
    power = 0.0
    for k in mass:
        vS, aS = vel(com[k]), acc(com[k])
        power += float(np.dot(-mass[k] * aS, vS)) - mass[k] * DEFAULT_G * float(vS[1]) - J[k] * eps[k] * omega[k]
    out["My"] = -power / w1
    return out


@pytest.mark.parametrize("t,v", REFERENCES)
def test_reference_variant_against_an_independent_calculation(t, v):
    r = control_work_of(_project(t, v))
    ref = _independent(t, v)
    row = r.answers()
    for k in ("omega2", "omega3", "omega4", "eps2", "eps3", "eps4"):
        assert row[k] == pytest.approx(ref[k], rel=1e-6, abs=1e-7 * r.omega1 ** 2), k
    slider = table(t).scheme.slider
    assert row[f"v{slider}"] == pytest.approx(ref["vF"], rel=1e-7)
    a_scale = r.omega1 ** 2 * r.l_AB                # |a_B|: differences err by ~1e-9 of it
    assert row[f"a{slider}"] == pytest.approx(ref["aF"], rel=1e-6, abs=1e-7 * a_scale)
    assert r.M_y == pytest.approx(ref["My"], rel=1e-6)
