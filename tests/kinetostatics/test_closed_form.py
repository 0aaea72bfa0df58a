"""Closed forms of the slider-crank (no masses, a force F on the slider along its guide):

- the moment on the crank (Артоболевский И. И., «Теория механизмов и машин», the slider-crank's
  reduced moment; the "crank effort" T = F·r·sin(θ + φ)/cos φ of Khurmi & Gupta, «Theory of
  Machines», chapter «Inertia forces in reciprocating parts»): M_ур = F·r·sin(φ + β)/cos β with
  sin β = (r·sin φ − e)/l;
- the rod is a two-force member: |R12| = |F|/cos β along AB; the guide's normal force N = F·tan β
  (its sign from the rod's slope); the crank's frame reaction under a pure couple R01 = R12 … i.e.
  −R21 = R12 (the crank is massless).

No trustworthy textbook example with printed reactions was found to cite digit by digit; these
closed forms are independent of the solver (no linear system, no kinematics module).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from reportgen.kinetostatics import solve_reactions
from reportgen.loads import Force, LoadSet

from .cases import slider_crank


def solve(r, l, e, F, phi_deg):
    p = slider_crank(r, l, e)
    phi = np.radians(np.atleast_1d(phi_deg))
    kin = p.kinematics_at(phi)
    B = np.asarray(kin.points["B"].pos)
    loads = LoadSet((Force("F", 3, "B", B, np.tile([F, 0.0], (phi.size, 1)), "force"),), ())
    return phi, kin, solve_reactions(p.linkage, p.structure, kin, loads)


def closed(r, l, e, F, phi):
    sb = (r * np.sin(phi) - e) / l
    beta = np.arcsin(sb)
    M = F * r * np.sin(phi + beta) / np.cos(beta)
    return beta, M


def test_printed_digits_central():
    """r = 0.1 m, l = 0.4 m, e = 0, F = 1000 N at φ = 30°: sin β = 0.125, β = 7.18076°,
    M = 1000·0.1·sin 37.18076°/cos 7.18076° = 60.9109 N·m, |R12| = 1007.905 N, N = 125.988 N."""
    phi, kin, r = solve(0.1, 0.4, 0.0, 1000.0, 30.0)
    assert r.balancing_moment[0] == pytest.approx(60.9109, abs=5e-5)
    assert np.hypot(*r.pair("R12").vector[0]) == pytest.approx(1007.905, abs=5e-4)
    assert abs(r.pair("R03").vector[0][1]) == pytest.approx(125.988, abs=5e-4)
    assert np.hypot(*r.pair("R12").vector[0]) == pytest.approx(1000.0 / math.cos(math.asin(0.125)), rel=1e-12)
    assert abs(r.pair("R03").vector[0][1]) == pytest.approx(1000.0 * math.tan(math.asin(0.125)), rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(r=st.floats(0.02, 0.3), lam=st.floats(1.3, 6.0), e_frac=st.floats(-0.3, 0.3),
       F=st.floats(-5000.0, 5000.0).filter(lambda x: abs(x) > 1.0), phi_deg=st.floats(0.0, 360.0))
def test_slider_crank_closed_form(r, lam, e_frac, F, phi_deg):
    l = lam * r
    e = e_frac * r
    phi, kin, res = solve(r, l, e, F, phi_deg)
    beta, M = closed(r, l, e, F, phi)
    scale = abs(F) * r
    assert res.balancing_moment[0] == pytest.approx(M[0], abs=1e-9 * scale)
    R12 = res.pair("R12").vector[0]
    assert np.hypot(*R12) == pytest.approx(abs(F) / math.cos(beta[0]), rel=1e-9)
    A, B = kin.points["A"].pos[0], kin.points["B"].pos[0]
    assert abs(R12[0] * (B - A)[1] - R12[1] * (B - A)[0]) <= 1e-9 * abs(F) * l      # along AB
    N = res.pair("R03").vector[0]
    assert N[0] == pytest.approx(0.0, abs=1e-9 * abs(F))
    assert abs(N[1]) == pytest.approx(abs(F) * abs(math.tan(beta[0])), abs=1e-9 * abs(F))
    assert np.allclose(res.frame_reaction_with_moment[0], R12, atol=1e-9 * abs(F))
