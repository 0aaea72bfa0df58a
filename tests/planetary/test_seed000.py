"""Seed 000 (§4.2, a real student note): the reducer z = 17/64/40/121, K = 3, u = 12.388, the drive
1500 rpm with the open pair 13/26 and ω1 = 6.4 1/s, and its velocity triangle (v_A drawn as 100 mm,
v_B measured 38.457 mm, ω_H = 12.678 1/s, u = 12.39 by construction)."""

import pytest

from reportgen.planetary import evaluate
from reportgen.planetary.drive import drive_check, drive_ratio
from reportgen.planetary.velocity import velocity_triangle

SEED_Z = (17, 64, 40, 121)


@pytest.fixture(scope="module")
def seed():
    drv = drive_ratio(1500, 13, 26, 6.4)
    d = evaluate("two-row-ext-int", SEED_Z, "auto", target=drv.required, module=6.4)
    return drv, d


def test_drive_ratio_of_seed(seed):
    drv, _ = seed
    assert drv.omega_motor == pytest.approx(157.08, abs=5e-3)          # seed: 157.08 1/s
    assert drv.required == pytest.approx(12.272, abs=5e-4)             # seed: iред = 12,272


def test_every_condition_holds(seed):
    _, d = seed
    assert d.valid
    assert d.satellites == 3                                           # seed: K = 3
    assert d.coaxial.left == d.coaxial.right == 81                     # 17 + 64 = 121 − 40
    assert float(d.ratio_check.u1h) == pytest.approx(12.388, abs=5e-4) # seed: 12,388
    assert d.ratio_check.deviation * 100 == pytest.approx(0.95, abs=0.01)   # seed: 0,95 %
    assert d.adjacency.k_limit == pytest.approx(3.3, abs=0.05)         # seed: K = 3,3
    assert d.adjacency.k_max == 3
    assert d.assembly.holds and d.assembly.g == 8 and d.assembly.quotient == 351
    assert all(i.holds for i in d.undercut.items)
    assert {i.what: i.value for i in d.undercut.items}["3"] == 121     # seed: z6 > 85


def test_seed_is_rejected_with_four_planets():
    d = evaluate("two-row-ext-int", SEED_Z, 4)
    assert not d.adjacency.holds                                       # 81·sin45° = 57.3 < 66
    assert not d.valid


def test_velocity_triangle_matches_the_seed_drawing(seed):
    drv, d = seed
    t = velocity_triangle(d, drv.omega_planetary_in)
    assert t.v_a * 1000 == pytest.approx(8545.152, rel=2e-5)           # seed: 8545,152 mm/s
    assert t.v_b_mm_read == pytest.approx(38.457, abs=0.01)            # seed measured 38,457 mm
    assert t.omega_h == pytest.approx(12.678, abs=0.005)               # seed: 12,678 1/s
    assert t.ratio_graphical == pytest.approx(12.39, abs=0.005)        # seed: 12,39
    assert abs(t.difference_percent) < 0.01                            # seed: 0,008 %
    assert t.plan.ratio_read == pytest.approx(d.ratio, rel=2e-3)


def test_achieved_crank_speed(seed):
    drv, d = seed
    chk = drive_check(drv, d.ratio)
    assert chk.omega_crank_achieved == pytest.approx(157.0796 / (2 * 12.38824), rel=1e-5)
    assert chk.deviation == pytest.approx(12.272 / 12.388 - 1, abs=2e-4)
    # identity: motor speed = crank speed · open ratio · planetary ratio
    assert chk.omega_crank_achieved * drv.open_ratio * d.ratio == pytest.approx(drv.omega_motor, rel=1e-12)
