"""The solver's fast paths give the same bits as the plain ones (issue 16 item 3): the Jacobian
written straight into J against the stacked rows, cos/sin per solve against ``rot`` one by one,
positions and velocities without the accelerations, a batch against its angles one by one, and
the dead centres' Brent searches in lockstep against one by one."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reportgen.geometry import rot
from reportgen.kinematics.constraints import arm, assemble, jacobian_rows, trig_of
from reportgen.kinematics.extremes import find_strokes
from reportgen.roots import brent_root, brent_roots

from .zoo import EXAMPLE_NAMES, example_model, four_bar, model_from_text, slider_crank, slotted_lever

RNG = np.random.default_rng(20261124)
ANGLES = RNG.uniform(-2 * math.pi, 4 * math.pi, 41)


def _same_bits(a, b) -> bool:
    """Equal values and equal signs of zero (−0.0 and 0.0 print differently in results.json)."""
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=True) and np.array_equal(np.signbit(a), np.signbit(b))


def _stacked(cons, q, cols):
    """The Jacobian as it was assembled before: each row's coefficients stacked, then copied."""
    rows_all = [jacobian_rows(c, q) for c in cons]
    m = sum(len(r) for r in rows_all)
    J = np.zeros((q.shape[0], m, 3 * len(cols)))
    idx = {b: 3 * i for i, b in enumerate(cols)}
    r = 0
    for rows in rows_all:
        for row in rows:
            for b, coef in row.items():
                if b in idx:
                    J[:, r, idx[b]:idx[b] + 3] = coef
            r += 1
    return J, rows_all


MODELS = [*EXAMPLE_NAMES, "four-bar", "slider-crank-offset", "slotted-lever"]


def _model(name):
    if name == "four-bar":
        return model_from_text(four_bar(0.1, 0.35, 0.3, 0.4))
    if name == "slider-crank-offset":
        return model_from_text(slider_crank(0.1, 0.4, 0.03))
    if name == "slotted-lever":
        return model_from_text(slotted_lever(0.1, 0.3))
    return example_model(name)


@pytest.fixture(scope="module", params=MODELS)
def model(request):
    return _model(request.param)


def test_assemble_writes_the_stacked_rows_bit_for_bit(model):
    q, _ = model.positions(ANGLES)
    trig = trig_of(q)
    for g, cons in zip(model.structure.groups[1:], model.group_rows):
        cols = list(g.links)
        J0, rows0 = _stacked(cons, q, cols)
        for tr in (None, trig):
            J, rows = assemble(cons, q, cols, tr)
            assert _same_bits(J, J0)
            for new, old in zip(rows, rows0):
                for r_new, r_old in zip(new, old):
                    others = {b: v for b, v in r_old.items() if b not in cols and b != 0}
                    assert r_new.keys() == others.keys()
                    assert all(_same_bits(r_new[b], others[b]) for b in others)


def test_solve_without_accelerations_keeps_positions_and_velocities(model):
    full = model.solve(ANGLES)
    lean = model.solve(ANGLES, accelerations=False)
    assert _same_bits(lean.q, full.q) and _same_bits(lean.qd, full.qd)
    assert np.isnan(lean.qdd).all()
    for name in full.points:
        assert _same_bits(lean.points[name].pos, full.points[name].pos)
        assert _same_bits(lean.points[name].vel, full.points[name].vel)
        assert np.isnan(lean.points[name].acc).all() or not np.asarray(full.points[name].acc).any()
    for k in full.coms:
        assert _same_bits(lean.coms[k].vel, full.coms[k].vel)
        assert _same_bits(lean.links[k].omega, full.links[k].omega) and np.isnan(lean.links[k].epsilon).all()


def test_transmission_and_flags_read_lazily_match_the_groups(model):
    from reportgen.kinematics.transmission import NEAR_SINGULAR_DEG, transmission_angle
    r = model.solve(ANGLES)
    q = np.array(r.q)
    flags = []
    for g in model.structure.groups[1:]:
        mu = transmission_angle(model.linkage, g, q)
        assert _same_bits(r.transmission_deg[g.key], mu)
        flags += [(int(i), g.key, float(mu[i])) for i in np.flatnonzero(mu < NEAR_SINGULAR_DEG)]
    assert r.near_singular == tuple(flags)


def test_a_batch_equals_its_angles_one_by_one_where_positions_are_independent(model):
    """What the dynamics' memory and the lockstep Brent rely on: a closed-form model's value at an
    angle does not depend on the other angles of the call (class III Newton runs to the slowest)."""
    if not model.positions_independent:
        pytest.skip("class III: Newton iterates until the whole call converges")
    batch = model.solve(ANGLES)
    for i in range(0, ANGLES.size, 5):
        one = model.solve(ANGLES[i:i + 1])
        assert _same_bits(one.q[0], batch.q[i]) and _same_bits(one.qd[0], batch.qd[i])
        assert _same_bits(one.qdd[0], batch.qdd[i])


def test_class_iii_is_not_taken_as_independent():
    assert not example_model("class3").positions_independent
    assert example_model("press").positions_independent


@settings(max_examples=80, deadline=None)
@given(theta=st.lists(st.floats(-50.0, 50.0), min_size=1, max_size=9),
       p=st.tuples(st.floats(-3.0, 3.0), st.floats(-3.0, 3.0)))
def test_arm_from_the_solve_trig_equals_rot(theta, p):
    q = np.zeros((len(theta), 3, 3))
    q[:, 1, 2] = theta
    q[:, 2, 2] = np.array(theta) * 0.5
    trig = trig_of(q)
    for k in (1, 2):
        assert _same_bits(arm(q, k, p, trig), rot(q[:, k, 2], p))
        assert _same_bits(arm(q, k, p), rot(q[:, k, 2], p))


@settings(max_examples=40, deadline=None)
@given(roots=st.lists(st.floats(-3.0, 3.0), min_size=1, max_size=4), k=st.floats(0.1, 10.0))
def test_brent_roots_in_lockstep_equal_one_by_one(roots, k):
    def f(x):
        return k * (np.sin(np.asarray(x)) - 0.3 * np.asarray(x) ** 3) - 0.5

    def fs(x):
        return float(f(np.array([x]))[0])
    brackets = []
    for r in roots:
        lo, hi = r - 0.37, r + 0.41
        if fs(lo) * fs(hi) < 0:
            brackets.append((lo, hi))
    if not brackets:
        return
    one = [brent_root(fs, lo, hi, xtol=1e-13) for lo, hi in brackets]
    assert brent_roots(f, brackets, xtol=1e-13) == one
    known = [(fs(lo), fs(hi)) for lo, hi in brackets]
    assert brent_roots(f, brackets, xtol=1e-13, known=known) == one


@pytest.mark.parametrize("name", ["press", "shaper", "crank-slider", "conveyor", "slotted-lever"])
def test_strokes_in_lockstep_equal_the_sequential_search(name, monkeypatch):
    lockstep = find_strokes(_model(name))
    m = _model(name)
    monkeypatch.setattr(type(m), "positions_independent", property(lambda self: False))
    sequential = find_strokes(m)
    assert dataclasses.astuple(lockstep) == dataclasses.astuple(sequential)


def test_positions_with_the_cos_sin_cache_equal_the_plain_solvers(model):
    """The position solvers fill the solve's cos/sin cache as each group is solved; without the
    cache (``trig=None``) every rotation is computed by ``rot`` afresh: the same bits."""
    if not model.positions_independent:
        pytest.skip("class III goes by continuation (its cache is made after the positions)")
    q = np.zeros((ANGLES.size, model.nb, 3))
    model._driver(q, ANGLES)
    for solver in model.solvers:
        solver.solve(q, ANGLES, strict=True)
    assert _same_bits(model.positions(ANGLES)[0], q)
