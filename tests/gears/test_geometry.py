"""Pair geometry: golden values from two published pairs, identities, property tests."""
import math

import pytest
from hypothesis import assume, given, settings, strategies as st

from reportgen.errors import ReportgenInputError, TaskError
from reportgen.gears.involute import inv
from reportgen.gears.pair import from_task, solve_gear_pair
from reportgen.task import Gears


def test_seed_000_pair():
    # seed 000 (press mechanism note), section 4.1.1 and 4.1.3: z 13/26, m 9, x 0.63/0.67
    p = solve_gear_pair(13, 26, 9.0, 0.63, 0.67)
    assert p.inv_alpha_w == pytest.approx(0.039169062, abs=5e-9)
    assert p.alpha_w_deg == pytest.approx(27.193, abs=5e-4)
    assert p.aw == pytest.approx(185.409, abs=5e-4)
    assert p.y == pytest.approx(1.10099, abs=5e-5)          # the seed rounds αw first: 1.10099
    assert p.dy == pytest.approx(0.19901, abs=5e-5)
    assert (p.d1, p.d2) == (117.0, 234.0)
    assert p.dw1 == pytest.approx(123.606, abs=5e-4)
    assert p.dw2 == pytest.approx(247.212, abs=5e-4)
    assert p.da1 == pytest.approx(142.758, abs=5e-4)
    assert p.da2 == pytest.approx(260.478, abs=5e-4)
    assert p.df1 == pytest.approx(105.84, abs=5e-4)
    assert p.df2 == pytest.approx(223.56, abs=5e-4)
    assert p.db1 == pytest.approx(109.944, abs=5e-4)
    assert p.db2 == pytest.approx(219.888, abs=5e-4)
    assert p.s1 == pytest.approx(18.265, abs=5e-4)
    assert p.s2 == pytest.approx(18.527, abs=5e-4)
    assert math.degrees(p.alpha_a1) == pytest.approx(39.633, abs=5e-4)
    assert math.degrees(p.alpha_a2) == pytest.approx(32.417, abs=5e-4)
    assert p.sa1 == pytest.approx(4.925, abs=2e-3)           # seed rounds αa1 to 0.001°
    assert p.sa2 == pytest.approx(6.467, abs=1e-3)
    assert p.pb == pytest.approx(26.569, abs=5e-4)
    assert p.ab == pytest.approx(30.618, abs=5e-3)
    assert p.eps_alpha == pytest.approx(1.152, abs=5e-4)
    # 4.1.3: N1N2 = 169.46 mm and N1P = 56.487 mm on the drawing at 2:1
    assert 2 * p.g == pytest.approx(169.46, abs=0.01)
    assert 2 * p.n1p == pytest.approx(56.487, abs=2e-3)


def test_seed_000_sliding_table():
    # seed 000, table 4.1 (X measured on the 2:1 drawing)
    p = solve_gear_pair(13, 26, 9.0, 0.63, 0.67)
    rows = [r for r in p.sliding.rows if r.label not in ("N1", "N2")]
    xs = [29.825, 38.712, 47.6, 56.487, 68.012, 79.536, 91.061]
    lam1 = [-1.341, -0.689, -0.280, 0.0, 0.254, 0.435, 0.570]
    lam21 = [0.573, 0.408, 0.219, 0.0, -0.341, -0.769, -1.323]
    assert [2 * r.rho for r in rows] == pytest.approx(xs, abs=3e-3)
    assert [r.lambda1 for r in rows] == pytest.approx(lam1, abs=1.5e-3)
    assert [r.lambda2 for r in rows] == pytest.approx(lam21, abs=1.5e-3)
    assert p.sliding.rows[0].lambda1 == -math.inf and p.sliding.rows[-1].lambda2 == -math.inf


def test_khk_published_pair():
    # KHK Gears, «Gear Technical Reference», calculation example of profile-shifted spur gears
    # (m 3, α 20°, z 12/24, x 0.6/0.36); reproduced at bolsover.com/utilitiesforalibre
    # ("Profile Shifted External Spur Gears"): inv αw 0.034316, αw 26.0886°, y 0.83329,
    # a 56.4999, db 33.8289/67.6579, dw 37.667/75.333, da 44.840/79.400, df 32.100/66.660, ε 1.202
    p = solve_gear_pair(12, 24, 3.0, 0.6, 0.36)
    assert p.inv_alpha_w == pytest.approx(0.034316, abs=1e-6)
    assert p.alpha_w_deg == pytest.approx(26.0886, abs=1e-4)
    assert p.y == pytest.approx(0.83329, abs=1e-5)
    assert p.aw == pytest.approx(56.4999, abs=1e-4)
    assert p.db1 == pytest.approx(33.8289, abs=1e-4)
    assert p.db2 == pytest.approx(67.6579, abs=1e-4)
    assert p.dw1 == pytest.approx(37.667, abs=1e-3)
    assert p.dw2 == pytest.approx(75.333, abs=1e-3)
    assert p.da1 == pytest.approx(44.840, abs=1e-3)
    assert p.da2 == pytest.approx(79.400, abs=1e-3)
    assert p.df1 == pytest.approx(32.100, abs=1e-3)
    assert p.df2 == pytest.approx(66.660, abs=1e-3)
    assert p.h1 == pytest.approx(6.370, abs=1e-3)
    assert p.eps_alpha == pytest.approx(1.202, abs=1e-3)


def test_zero_shift_is_standard_pair():
    p = solve_gear_pair(20, 40, 2.0, 0.0, 0.0)
    assert p.alpha_w == pytest.approx(p.alpha, abs=1e-14)
    assert p.aw == pytest.approx(60.0, abs=1e-12)
    assert p.da1 == pytest.approx(44.0) and p.df1 == pytest.approx(35.0)
    assert p.s1 == pytest.approx(math.pi)


def test_equal_and_opposite_shifts_keep_centre_distance():
    p = solve_gear_pair(15, 45, 4.0, 0.4, -0.4)
    assert p.aw == pytest.approx(120.0, abs=1e-12) and p.dy == pytest.approx(0.0, abs=1e-14)


pairs = st.tuples(st.integers(10, 80), st.integers(10, 150), st.sampled_from([1.0, 2.5, 9.0]),
                  st.floats(-0.5, 1.0), st.floats(-0.5, 1.0), st.sampled_from([14.5, 20.0, 25.0]))


@settings(max_examples=150, deadline=None)
@given(pairs)
def test_identities(args):
    z1, z2, m, x1, x2, alpha = args
    try:
        p = solve_gear_pair(z1, z2, m, x1, x2, alpha_deg=alpha)
    except TaskError:  # a shift sum with inv αw ≤ 0: no pair exists; tested elsewhere
        assume(False)
    rb1, rb2 = p.db1 / 2, p.db2 / 2
    # aw = (rb1 + rb2) / cos αw
    assert p.aw == pytest.approx((rb1 + rb2) / math.cos(p.alpha_w), rel=1e-12)
    # the working pitch circles roll: dw1 + dw2 = 2 aw, dw2/dw1 = u, dw = db / cos αw
    assert p.dw1 + p.dw2 == pytest.approx(2 * p.aw, rel=1e-12)
    assert p.dw1 == pytest.approx(p.db1 / math.cos(p.alpha_w), rel=1e-12)
    # on the working circles the thicknesses add up to the working pitch (zero backlash)
    pw = math.pi * p.dw1 / z1
    assert p.sw1 + p.sw2 == pytest.approx(pw, rel=1e-9)
    # sa from the involute function equals the thickness computed from angles on the tip circle
    psi = p.s1 / p.d1 + inv(p.alpha) - inv(math.acos(p.db1 / p.da1))
    assert p.sa1 == pytest.approx(p.da1 * psi, rel=1e-12)
    # εα: line-of-action form equals the angle form
    assert p.eps_alpha == pytest.approx(p.eps_alpha_angular, rel=1e-10, abs=1e-12)
    # radial clearance equals c* m at aw: aw − ra1 − rf2 = c m
    assert p.aw - p.da1 / 2 - p.df2 / 2 == pytest.approx(p.c * m, abs=1e-9)
    assert p.aw - p.da2 / 2 - p.df1 / 2 == pytest.approx(p.c * m, abs=1e-9)
    # P divides N1N2 in the ratio of the base radii
    assert p.n1p / (p.g - p.n1p) == pytest.approx(rb1 / rb2, rel=1e-10)
    # base pitch equals the base-circle arc of one tooth
    assert p.pb == pytest.approx(math.pi * p.db1 / z1, rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.floats(-0.3, 0.8), st.floats(-0.3, 0.8))
def test_base_tangent_length_matches_geometry(x1, x2):
    # W spans zw teeth: W = (zw − 1) pb + sb, sb = db (s/d + inv α) the base-circle thickness
    p = solve_gear_pair(30, 60, 5.0, x1, x2)
    sb = p.db1 * (p.s1 / p.d1 + inv(p.alpha))
    assert p.w1 == pytest.approx((p.zw1 - 1) * p.pb + sb, rel=1e-12)


def test_from_task():
    p = from_task(Gears(z1=13, z2=26, module=9.0, x1=0.63, x2=0.67))
    assert p.da1 == pytest.approx(142.758, abs=5e-4)


@pytest.mark.parametrize("kwargs, key", [
    (dict(z1=3, z2=20, module=2.0), "gears.z1"),
    (dict(z1=13, z2=26, module=0.0), "gears.module"),
    (dict(z1=13, z2=26, module=2.0, x1=-3.0, x2=-3.0), "gears.x1"),
    (dict(z1=13, z2=26, module=2.0, x1="auto", x2=0.5), "gears.x2"),
    (dict(z1=13, z2=26, module=2.0, alpha_deg=60.0), "gears.alpha_deg"),
    (dict(z1=13, z2=26, module=2.0, x1="bad", x2=0.0), "gears.x1"),
])
def test_bad_input_names_the_key(kwargs, key):
    with pytest.raises(TaskError) as info:
        solve_gear_pair(**kwargs)
    assert info.value.path == key
    assert isinstance(info.value, ReportgenInputError)
