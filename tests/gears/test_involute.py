"""The involute function and its inverse."""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from reportgen.errors import ReportgenInputError
from reportgen.gears.involute import inv, inv_inverse


def test_inv_20_deg_table_value():
    # table of the involute function (Кудрявцев «Зубчатые передачи», appendix; ГОСТ 16532-70):
    # inv 20° = 0.014904
    assert inv(math.radians(20.0)) == pytest.approx(0.0149043839, abs=1e-10)


def test_inverse_of_seed_value():
    # seed 000, 4.1.1: inv αw = 0.39169062e-1 → αw = 27.193°
    assert math.degrees(inv_inverse(0.039169062)) == pytest.approx(27.193, abs=5e-4)


def test_round_trip_dense_grid_1e12():
    alpha = np.linspace(math.radians(0.5), math.radians(80.0), 20001)
    back = inv_inverse(inv(alpha))
    assert np.max(np.abs(back - alpha)) < 1e-12


@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=1e-9, max_value=100.0))
def test_residual_small(value):
    a = inv_inverse(value)
    assert 0.0 < a < math.pi / 2
    # |Δα| ≈ |Δinv| / tan²α: the residual, converted to an angle, is below 1e-12 rad
    assert abs(inv(a) - value) / math.tan(a) ** 2 < 1e-12


def test_series_matches_direct_at_switch():
    a = 0.02
    assert inv(a * (1 - 1e-12)) == pytest.approx(math.tan(a) - a, rel=1e-9)


@pytest.mark.parametrize("bad", [0.0, -1e-3, 101.0, float("nan")])
def test_domain(bad):
    with pytest.raises(ReportgenInputError):
        inv_inverse(bad)
