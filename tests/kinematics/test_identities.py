"""Identities that any correct position/velocity/acceleration solution satisfies, on every example."""
from __future__ import annotations

import math

import numpy as np
import pytest

from reportgen.kinematics.constraints import all_pair_constraints, residual

from .zoo import EXAMPLE_NAMES, example_model

RNG = np.random.default_rng(20261121)
ANGLES = RNG.uniform(0, 2 * math.pi, 7)


def _derivative(model, phi, h=1e-4):
    """Five-point central difference in φ of positions and velocities, times ω (d/dt)."""
    pts = np.array([phi - 2 * h, phi - h, phi + h, phi + 2 * h])
    r = model.solve(pts)
    w = model.omega
    d = lambda a: (a[0] - 8 * a[1] + 8 * a[2] - a[3]) / (12 * h) * w
    return r, d


@pytest.fixture(scope="module", params=EXAMPLE_NAMES)
def model(request):
    return example_model(request.param)


def test_pairs_and_lengths_hold(model):
    r = model.solve(ANGLES)
    cons = all_pair_constraints(model.linkage)
    res = np.abs(residual(cons, np.array(r.q)))
    assert res.max() < 1e-12
    for k, body in model.linkage.bodies.items():
        if k == 0:
            continue
        names = body.points
        for i in range(len(names)):
            for j in range(i + 1, len(names)):
                want = math.dist(body.local[names[i]], body.local[names[j]])
                got = np.hypot(*(r.points[names[i]].pos - r.points[names[j]].pos).T)
                assert np.allclose(got, want, rtol=0, atol=1e-12)


def test_velocity_is_derivative_of_position(model):
    for phi in ANGLES:
        r0 = model.solve([phi])
        r, d = _derivative(model, phi)
        for name, pm in r0.points.items():
            fd = d(r.points[name].pos)
            scale = max(1.0, np.abs(pm.vel).max())
            assert np.allclose(fd, pm.vel[0], atol=1e-7 * scale), name
        for k, lm in r0.links.items():
            fd = d(np.unwrap(r.links[k].angle))
            assert abs(fd - lm.omega[0]) < 1e-7 * max(1.0, abs(lm.omega[0])), k


def test_acceleration_is_derivative_of_velocity(model):
    for phi in ANGLES:
        r0 = model.solve([phi])
        r, d = _derivative(model, phi)
        for name, pm in r0.points.items():
            fd = d(r.points[name].vel)
            scale = max(1.0, np.abs(pm.acc).max())
            assert np.allclose(fd, pm.acc[0], atol=1e-6 * scale), name
        for k, lm in r0.links.items():
            fd = d(r.links[k].omega)
            assert abs(fd - lm.epsilon[0]) < 1e-6 * max(1.0, abs(lm.epsilon[0])), k


def test_periodic_over_a_turn(model):
    a = model.solve(ANGLES)
    b = model.solve(ANGLES + 2 * math.pi)
    for name in a.points:
        assert np.allclose(a.points[name].pos, b.points[name].pos, atol=1e-12)
        assert np.allclose(a.points[name].acc, b.points[name].acc, atol=1e-9)


def test_centres_of_mass_move_with_their_links(model):
    r = model.solve(ANGLES)
    for k, cm in r.coms.items():
        body = model.linkage.bodies[k]
        p0 = body.points[0]
        d_local = math.dist(body.com_local, body.local[p0])
        got = np.hypot(*(cm.pos - r.points[p0].pos).T)
        assert np.allclose(got, d_local, atol=1e-12)
