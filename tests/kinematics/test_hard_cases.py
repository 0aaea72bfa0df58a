"""Hard cases: near toggles, a mechanism that cannot be assembled, extreme ratios, scaling."""
from __future__ import annotations

import math

import numpy as np
import pytest

from reportgen.errors import AssemblyError
from reportgen.kinematics.constraints import all_pair_constraints, residual

from .zoo import four_bar, model_from_text, slider_crank


def _check_identities(m, phi):
    r = m.solve(phi)
    assert np.isfinite(np.asarray(r.q)).all() and np.isfinite(np.asarray(r.qdd)).all()
    assert np.abs(residual(all_pair_constraints(m.linkage), np.array(r.q))).max() < 1e-11
    return r


def test_four_bar_near_change_point():
    """s + l = 0.999·(p + q): the Grashof crank–rocker close to its change point."""
    s, l = 0.1, 0.35
    p = 0.25
    q = (s + l) / 0.999 - p
    m = model_from_text(four_bar(s, p, q, l, phi_deg=90.0))
    phi = np.radians(np.arange(0.0, 360.0, 0.5))
    r = _check_identities(m, phi)
    mu = r.transmission_deg["2-3"]
    assert mu.min() < 6.0            # it passes close to the toggle (μ ≈ 5.2°)
    assert all(mu[i] < 5.0 for i, _, _ in r.near_singular)
    # closer still (0.99995): those positions are flagged
    q2 = (s + l) / 0.99995 - p
    r2 = _check_identities(model_from_text(four_bar(s, p, q2, l, phi_deg=90.0)), phi)
    assert r2.near_singular and r2.transmission_deg["2-3"].min() < 2.0


def test_slider_crank_r_over_l_099():
    m = model_from_text(slider_crank(0.099, 0.1, 0.0, phi_deg=30.0))
    r = _check_identities(m, np.radians(np.arange(0.0, 360.0, 1.0)))
    assert r.transmission_deg["2-3"].min() == pytest.approx(math.degrees(math.acos(0.99)), rel=1e-3)


def test_cannot_assemble_names_group_angle_inequality_and_range():
    """A crank too long for its coupler and rocker: a non-Grashof chain whose crank cannot turn."""
    m = model_from_text(four_bar(0.2, 0.15, 0.15, 0.3, phi_deg=20.0))
    with pytest.raises(AssemblyError) as ei:
        m.solve(np.radians(np.arange(0.0, 360.0, 10.0)))
    err = ei.value
    assert err.group.startswith("II(2,3)")
    assert "≤" in err.inequality and "0.3" in err.inequality
    assert err.feasible and all(0 <= a <= 360 and 0 <= b <= 360 for a, b in err.feasible)
    # the feasible range really assembles and just outside it does not
    lo, hi = err.feasible[0]
    mid = math.radians((lo + (hi if hi > lo else hi + 360)) / 2)
    m.solve([mid])
    with pytest.raises(AssemblyError):
        m.solve([math.radians(err.phi_deg)])


@pytest.mark.parametrize("k", [1e-3, 1e3])
def test_scaling_is_exact(k):
    base = model_from_text(slider_crank(0.1, 0.32, 0.02))
    big = model_from_text(slider_crank(0.1 * k, 0.32 * k, 0.02 * k))
    phi = np.radians(np.arange(0.0, 360.0, 13.0))
    a, b = base.solve(phi), big.solve(phi)
    for name in a.points:
        assert np.allclose(b.points[name].pos, k * a.points[name].pos, rtol=1e-12, atol=1e-15 * k)
        assert np.allclose(b.points[name].acc, k * a.points[name].acc, rtol=1e-10, atol=1e-12 * k)
    assert np.allclose(b.links[2].epsilon, a.links[2].epsilon, rtol=1e-10, atol=1e-10)


def test_dead_centre_on_a_grid_point():
    """A central slider-crank turning clockwise with its sketch where a grid point of the extreme
    search falls on a dead centre (reported by the kinetostatics tests)."""
    from reportgen.kinematics.extremes import find_strokes
    m = model_from_text(slider_crank(0.125, 0.25, 0.0, phi_deg=30.0, omega=-2.0))
    st = find_strokes(m)
    assert st.working_deg == pytest.approx(180.0, abs=1e-6) and st.idle_deg == pytest.approx(180.0, abs=1e-6)
    assert st.stroke == pytest.approx(0.25, rel=1e-12)
