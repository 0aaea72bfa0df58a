"""Checks (failures are findings), the blocking contour and the automatic shifts."""
import math

import numpy as np
import pytest

from reportgen.errors import TaskError
from reportgen.gears.checks import x_min
from reportgen.gears.geometry import pair_arrays
from reportgen.gears.meshing import meshing_picture
from reportgen.gears.pair import solve_gear_pair
from reportgen.gears.shifts import RULE_EQUAL_SLIDING, blocking_contour, choose_shifts

A20 = math.radians(20.0)


def failed(pair):
    return {c.name for c in pair.checks if not c.passed}


def test_x_min_classic():
    # x_min = (17 − z)/17 for α = 20°, ha* = 1 is the textbook approximation (Артоболевский);
    # the exact form 1 − z sin²20°/2 gives z_min = 2/sin²20° = 17.097
    assert float(x_min(17, A20, 1.0)) == pytest.approx((17 - 17) / 17, abs=0.006)
    assert float(x_min(13, A20, 1.0)) == pytest.approx(0.2396, abs=1e-4)


@pytest.mark.parametrize("z", [6, 7, 8, 9])
def test_small_pinion_needs_shift(z):
    assert "undercut1" in failed(solve_gear_pair(z, 2 * z, 2.0, 0.0, 0.0))
    p = solve_gear_pair(z, 2 * z, 2.0, float(x_min(z, A20, 1.0)) + 1e-6, 0.0)
    assert "undercut1" not in failed(p)


def test_shift_that_sharpens_the_tooth():
    p = solve_gear_pair(10, 30, 2.0, 1.2, 0.0)
    assert p.sa1 < 0 and "sharpening1" in failed(p)   # pointed before the tip circle


def test_contact_ratio_below_one_is_a_finding():
    p = solve_gear_pair(13, 26, 9.0, 1.0, 1.2)
    assert p.eps_alpha < 1 and "contact_ratio" in failed(p)
    pic = meshing_picture(p)
    assert any(z.pairs == 0 for z in pic.zones)


def test_seed_point_fails_only_contact_ratio():
    # seed 000 chose x = 0.63/0.67 with εα = 1.152, below the default limit 1.2
    assert failed(solve_gear_pair(13, 26, 9.0, 0.63, 0.67)) == {"contact_ratio"}


def test_auto_reproduces_seed_with_its_contact_ratio():
    # With the seed's own limit εα ≥ 1.152 the rule (equal maximal sliding, largest sum) lands on
    # the shifts the seed read off its blocking contour: x1 = 0.63, x2 = 0.67.
    ch = choose_shifts(13, 26, 9.0, eps_min=1.1524)
    assert (ch.x1, ch.x2) == pytest.approx((0.63, 0.67), abs=0.005)
    assert ch.rule == RULE_EQUAL_SLIDING


@pytest.mark.parametrize("z1, z2", [(9, 18), (9, 27), (10, 30), (13, 26), (17, 34), (25, 60)])
def test_auto_satisfies_every_check(z1, z2):
    p = solve_gear_pair(z1, z2, 5.0, "auto", "auto")
    assert p.all_passed, failed(p)
    ch = p.shift_choice
    assert abs(ch.x1 - ch.x1_exact) <= 0.011 and abs(ch.x2 - ch.x2_exact) <= 0.011
    if ch.rule == RULE_EQUAL_SLIDING:
        # the exact point is on the equal-sliding line and on the contour's boundary
        arr = pair_arrays(z1, z2, 5.0, ch.x1_exact, ch.x2_exact, A20, 1.0, 0.25)
        l1 = 1 - (arr["g"] - arr["n1a"]) / (arr["n1a"] * arr["u"])
        l2 = 1 - arr["n1b"] * arr["u"] / (arr["g"] - arr["n1b"])
        assert float(l1) == pytest.approx(float(l2), rel=1e-8)
        q = solve_gear_pair(z1, z2, 5.0, ch.x1_exact + 0.01, ch.x2_exact + 0.01, rounding=None)
        assert not q.all_passed


def test_auto_impossible_is_bad_input():
    with pytest.raises(TaskError) as info:
        solve_gear_pair(8, 16, 2.0, "auto", "auto")
    assert info.value.path == "gears.x1"


def test_contour_curves_lie_on_their_limits():
    c = blocking_contour(13, 26, 9.0, n=81)
    # the undercut line of gear 1 is the vertical x1 = x_min
    for line in c.curves["undercut1"]:
        assert np.allclose(line[:, 0], float(x_min(13, A20, 1.0)), atol=1e-9)
    # εα = 1.2 along its traced line (linear interpolation on a grid of step ~0.02)
    for line in c.curves["contact_ratio"]:
        arr = pair_arrays(13, 26, 9.0, line[:, 0], line[:, 1], A20, 1.0, 0.25)
        assert np.nanmax(np.abs(arr["eps_alpha"] - 1.2)) < 2e-3
    # the feasible region contains the automatic point (0.58, 0.52) and not the seed's point
    i = np.searchsorted(c.x1, 0.58)
    j = np.searchsorted(c.x2, 0.40)
    assert c.feasible[i, j]
    i, j = np.searchsorted(c.x1, 0.63), np.searchsorted(c.x2, 0.67)
    assert not c.feasible[i, j]
