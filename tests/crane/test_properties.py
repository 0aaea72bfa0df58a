"""Property tests over cranes of other sizes: every record reproduces its printed result, every
check's verdict agrees with its numbers, and the physics keeps its direction."""
from __future__ import annotations

import dataclasses as dc

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from reportgen.calc import evaluate_displayed
from reportgen.crane import crane_calc

from .helpers import example_crane, with_hoist, with_trolley

BASE = example_crane()


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(capacity=st.floats(1.0, 400.0), speed=st.floats(0.5, 30.0), height=st.floats(3.0, 40.0),
       trolley_speed=st.floats(5.0, 60.0), trolley_mass=st.floats(2.0, 120.0),
       power=st.floats(5.0, 300.0), ratio=st.integers(1, 10), branches=st.integers(1, 2))
def test_records_reevaluate_and_checks_agree(capacity, speed, height, trolley_speed, trolley_mass, power,
                                              ratio, branches):
    poly = dc.replace(BASE.hoist.polyspast, ratio=ratio, branches=branches)
    crane = with_hoist(BASE, capacity_t=capacity, lifting_speed_m_min=speed, lifting_height_m=height,
                       polyspast=poly, motor=dc.replace(BASE.hoist.motor, power_kw=power))
    crane = with_trolley(crane, speed_m_min=trolley_speed, mass_t=trolley_mass)
    calc = crane_calc(crane)
    for _, mech in calc.mechanisms:
        for key, rec in mech.records.items():
            assert evaluate_displayed(rec).ok, key
        for c in mech.checks:
            ok = c.value >= c.limit if c.relation == "≥" else c.value <= c.limit
            assert c.passed == ok or abs(c.value - c.limit) <= 1e-9 * max(abs(c.value), abs(c.limit)), c.key
            assert (c.advice == "") == c.passed


@settings(max_examples=20, deadline=None)
@given(st.floats(1.0, 400.0), st.floats(1.0, 400.0))
def test_more_load_needs_a_stronger_rope_and_brake(q1, q2):
    lo, hi = sorted((q1, q2))
    a = crane_calc(with_hoist(BASE, capacity_t=lo)).hoist
    b = crane_calc(with_hoist(BASE, capacity_t=hi)).hoist
    assert a.value("F_req") <= b.value("F_req")
    assert a.value("T_br") <= b.value("T_br")
    assert a.value("M_st") <= b.value("M_st")
