"""Property-based tests over random four-bars and slider-cranks (hypothesis)."""
from __future__ import annotations

import math

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from reportgen.kinematics.constraints import all_pair_constraints, residual

from .zoo import four_bar, model_from_text, slider_crank

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _velocity_matches(m, phi, h=1e-5):
    r = m.solve([phi - h, phi, phi + h])
    for pm in r.points.values():
        fd = (pm.pos[2] - pm.pos[0]) / (2 * h) * m.omega
        assert np.allclose(fd, pm.vel[1], atol=1e-6 * max(1.0, np.abs(pm.vel[1]).max()))
        fa = (pm.vel[2] - pm.vel[0]) / (2 * h) * m.omega
        assert np.allclose(fa, pm.acc[1], atol=2e-5 * max(1.0, np.abs(pm.acc[1]).max()))


@SETTINGS
@given(s=st.floats(0.02, 0.1), p=st.floats(0.15, 0.5), q=st.floats(0.15, 0.5), l=st.floats(0.15, 0.5),
       phi=st.floats(0, 2 * math.pi), branch=st.sampled_from([1.0, -1.0]))
def test_random_crank_rockers(s, p, q, l, phi, branch):
    assume(s + max(p, q, l) < 0.9 * (s + p + q + l - s - max(p, q, l)))   # Grashof with margin
    assume(s + l < 0.97 * (p + q) and abs(p - q) < 0.97 * (l - s) if l > s else False)
    m = model_from_text(four_bar(s, p, q, l, phi_deg=45.0, branch=branch))
    r = m.solve(np.linspace(0, 2 * math.pi, 24, endpoint=False))
    assert np.abs(residual(all_pair_constraints(m.linkage), np.array(r.q))).max() < 1e-11
    assume(r.transmission_deg["2-3"].min() > 3.0)
    _velocity_matches(m, phi)


@SETTINGS
@given(r_=st.floats(0.02, 0.2), ratio=st.floats(0.1, 0.9), e_frac=st.floats(-0.5, 0.5), phi=st.floats(0, 2 * math.pi))
def test_random_slider_cranks(r_, ratio, e_frac, phi):
    l = r_ / ratio
    e = e_frac * (l - r_)
    m = model_from_text(slider_crank(r_, l, e))
    r = m.solve(np.linspace(0, 2 * math.pi, 36, endpoint=False))
    # slider stays on its line, rod length holds
    assert np.allclose(r.points["B"].pos[:, 1], e, atol=1e-12)
    d = np.hypot(*(r.points["B"].pos - r.points["A"].pos).T)
    assert np.allclose(d, l, atol=1e-12)
    _velocity_matches(m, phi)
