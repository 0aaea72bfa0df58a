"""Brent's root finder and the vectorised extreme search that replaced scipy in the solve path."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from reportgen.roots import RootNotBracketedError, brent_root, extremes


@pytest.mark.parametrize("f, a, b, root", [
    # Wallis' cubic x³ − 2x − 5 (the classic test of Newton's and Brent's methods); root by Cardano
    (lambda x: x ** 3 - 2 * x - 5, 2.0, 3.0,
     (5 / 2 + math.sqrt(25 / 4 - 8 / 27)) ** (1 / 3) + (5 / 2 - math.sqrt(25 / 4 - 8 / 27)) ** (1 / 3)),
    (math.cos, 1.0, 2.0, math.pi / 2),
    (lambda x: math.exp(x) - 2.0, 0.0, 1.0, math.log(2.0)),
    # Kepler's equation E − e·sin E = M, e = 0.9, M = 0.3: no closed form, scipy's brentq as reference
    (lambda E: E - 0.9 * math.sin(E) - 0.3, 0.0, math.pi, None),
    # a root at the bracket's end
    (lambda x: x - 1.0, 1.0, 2.0, 1.0),
])
def test_brent_root_against_closed_forms_and_scipy(f, a, b, root):
    x = brent_root(f, a, b, xtol=1e-14)
    ref = brentq(f, a, b, xtol=1e-14) if root is None else root
    assert abs(x - ref) <= 4e-14 * max(1.0, abs(ref))


def test_brent_root_refuses_an_unbracketed_interval():
    with pytest.raises(RootNotBracketedError) as exc:
        brent_root(lambda x: x * x + 1.0, -1.0, 1.0)
    assert exc.value.fa == 2.0 and exc.value.fb == 2.0


@settings(max_examples=60, deadline=None)
@given(r=st.floats(-5, 5), k=st.floats(0.01, 100), p=st.integers(1, 7), lo=st.floats(0.01, 3), hi=st.floats(0.01, 3))
def test_brent_root_finds_the_root_of_monotone_functions(r, k, p, lo, hi):
    f = lambda x: k * math.copysign(abs(x - r) ** p, x - r)  # noqa: E731 - odd power: one root at r
    x = brent_root(f, r - lo, r + hi, xtol=1e-12)
    # a p-fold root is flat: f reaches rounding level within |x − r| ≈ (ε/k)^(1/p)
    assert abs(x - r) <= max(2e-12, 4 * (1e-15 * max(1.0, abs(f(r + hi))) / k) ** (1.0 / p))


def test_extremes_finds_extremes_between_nodes():
    # g(t) = sin t + 0.3 sin(3t + 1) on a coarse periodic grid; reference: the root of the exact
    # derivative g′ = cos t + 0.9 cos(3t + 1) by scipy's brentq
    g = lambda t: np.sin(t) + 0.3 * np.sin(3 * t + 1.0)  # noqa: E731
    dg = lambda t: math.cos(t) + 0.9 * math.cos(3 * t + 1.0)  # noqa: E731
    nodes = np.linspace(0.0, 2 * math.pi, 37)
    vals = g(nodes)
    found = extremes(lambda t: (g(t),), nodes, [(lambda s: s[0], vals, "max"), (lambda s: s[0], vals, "min")])
    for (t_x, v_x), kind in zip(found, ("max", "min")):
        j = int(np.argmin(abs(nodes - t_x)))
        lo, hi = nodes[max(j - 1, 0)], nodes[min(j + 1, nodes.size - 1)]
        t_ref = brentq(dg, lo, hi, xtol=1e-15)
        v_ref = float(g(np.array([t_ref]))[0])
        # the value is flat at an extreme: it pins θ only to ~√ε, but the value to rounding
        assert abs(t_x - t_ref) <= 1e-7
        assert abs(v_x - v_ref) <= 4e-16
        assert (v_x >= vals.max()) if kind == "max" else (v_x <= vals.min())


def test_extremes_at_the_seam_of_a_periodic_grid():
    # the largest value just before 2π: the first and the last interval are the neighbours of node 0
    g = lambda t: np.cos(t + 0.01)  # noqa: E731 - maximum at t = 2π − 0.01
    nodes = np.linspace(0.0, 2 * math.pi, 25)
    (t, v), = extremes(lambda t: (g(t),), nodes, [(lambda s: s[0], g(nodes), "max")])
    assert abs(t - (2 * math.pi - 0.01)) <= 1e-7 and v == pytest.approx(1.0, abs=1e-15)


def test_extremes_one_evaluation_per_round_for_all_searches():
    calls = []

    def evaluate(t):
        calls.append(t.size)
        return (np.sin(t), np.cos(t))

    nodes = np.linspace(0.0, 2 * math.pi, 13)
    res = extremes(evaluate, nodes, [(lambda s: s[0], np.sin(nodes), "max"), (lambda s: s[1], np.cos(nodes), "min")])
    assert res[0][0] == pytest.approx(math.pi / 2, abs=1e-7) and res[1][0] == pytest.approx(math.pi, abs=1e-7)
    assert res[0][1] == pytest.approx(1.0, abs=1e-15) and res[1][1] == pytest.approx(-1.0, abs=1e-15)
    # the bracket shrinks by (SAMPLES − 1)/2 per round: from 2π/12 to 2e-9 in well under 15 rounds
    assert len(calls) <= 12
