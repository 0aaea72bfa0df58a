"""Item 1 of the issue: the loads of reportgen.loads as kinetostatics uses them — production
resistance by its law against the motion on the working stroke only, gravity, d'Alembert inertia
(course manual, seed 001, formulas (31), (32), (34): G = m·g, Fи = −m·a_S, Mи = −J_S·ε)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from reportgen.loads import gravity_loads, inertia_loads, resistance_loads

from .cases import EXAMPLE_NAMES, example


@pytest.mark.parametrize("name", ["press", "crank-slider", "shaper", "conveyor"])
def test_resistance_against_motion_on_working_stroke_only(name):
    p = example(name)
    phi = np.linspace(0.0, 2 * math.pi, 720, endpoint=False)
    kin = p.kinematics_at(phi)
    ls = resistance_loads(p.task.mechanism, p.linkage, p.model, kin, p.strokes)
    (f,) = ls.forces
    v = np.asarray(kin.points[f.where].vel)
    pw = (np.asarray(f.vector) * v).sum(1)
    assert (pw <= 1e-9 * np.abs(pw).max()).all()            # never drives the slider
    st = p.strokes
    sgn = 1.0 if p.model.omega >= 0 else -1.0
    span = (sgn * (st.phi_end - st.phi_start)) % (2 * math.pi)
    off = (sgn * (phi - st.phi_start)) % (2 * math.pi)
    idle = off > span + 1e-9
    assert idle.any() and np.all(np.asarray(f.vector)[idle] == 0.0)
    F = np.hypot(*np.asarray(f.vector).T)
    load = next(ld for ld in p.task.mechanism.loads if ld.kind == "resistance")
    assert F.max() <= load.force * (1 + 1e-12)


def test_press_law_is_linear_in_the_stroke():
    """The press: law [[0, 0], [1, 1]]: F = F_max·(fraction of the working stroke travelled)."""
    p = example("press")
    st = p.strokes
    span = (st.phi_end - st.phi_start) % (2 * math.pi)       # ω1 > 0
    phi = st.phi_start + np.linspace(0.05, 0.95, 7) * span
    kin = p.kinematics_at(phi)
    (f,) = resistance_loads(p.task.mechanism, p.linkage, p.model, kin, p.strokes).forces
    ends = p.kinematics_at(np.array([st.phi_start, st.phi_end]))
    x0, x1 = ends.points["D"].pos[:, 0]
    frac = (np.asarray(kin.points["D"].pos)[:, 0] - x0) / (x1 - x0)
    assert np.hypot(*np.asarray(f.vector).T) == pytest.approx(15800.0 * frac, rel=1e-9)


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_gravity_and_inertia(name):
    p = example(name)
    kin = p.kinematics
    g = gravity_loads(p.linkage, kin)
    ine = inertia_loads(p.linkage, kin)
    for k in p.linkage.moving:
        b = p.linkage.bodies[k]
        G = next(f for f in g.forces if f.link == k)
        assert np.allclose(G.vector, [0.0, -b.mass * p.linkage.g])
        assert np.allclose(G.point, kin.coms[k].pos)
        F = next(f for f in ine.forces if f.link == k)
        assert np.allclose(F.vector, -b.mass * np.asarray(kin.coms[k].acc))
        if b.inertia > 0:
            M = next(m for m in ine.moments if m.link == k)
            assert np.allclose(M.value, -b.inertia * np.asarray(kin.links[k].epsilon))


def test_seed_001_mass_rules_reach_the_loads():
    """The conveyor gives no masses: m = q·l (q = 12 kg/m), slider = 8·m1, J = m·l²/12."""
    p = example("conveyor")
    b = p.linkage.bodies
    assert b[1].mass == pytest.approx(12.0 * 0.15)
    assert b[5].mass == pytest.approx(8.0 * 12.0 * 0.15)
    assert b[2].inertia == pytest.approx(12.0 * 0.40 * 0.40 ** 2 / 12)
