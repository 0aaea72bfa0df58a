"""reportgen.geometry and reportgen.tolerances (issue 13 item 3): the shared helpers, their
identities, and one home for each (no module keeps its own copy)."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from reportgen.geometry import cross, dot, perp, readonly, rot, rot_vec2, vec2

ROOT = Path(__file__).resolve().parents[1]
finite = st.floats(-1e6, 1e6, allow_nan=False)
angle = st.floats(-20.0, 20.0, allow_nan=False)


@settings(deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(angle, finite, finite)
def test_rotation_keeps_length_and_turns_by_the_angle(theta: float, x: float, y: float) -> None:
    p = np.array([x, y])
    r = rot(theta, (x, y))
    n = math.hypot(x, y)
    assert math.isclose(float(np.hypot(*r)), n, rel_tol=1e-12, abs_tol=1e-9)
    assert math.isclose(float(dot(r, p)), n * n * math.cos(theta), rel_tol=1e-9, abs_tol=1e-6 * max(n * n, 1))
    assert math.isclose(float(cross(p, r)), n * n * math.sin(theta), rel_tol=1e-9, abs_tol=1e-6 * max(n * n, 1))


@settings(deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(angle, angle, finite, finite)
def test_rotations_compose(a: float, b: float, x: float, y: float) -> None:
    assert np.allclose(rot(a, rot(b, (x, y))), rot(a + b, (x, y)), rtol=1e-9, atol=1e-6)


def test_rotation_broadcasts_over_angles() -> None:
    th = np.array([0.0, math.pi / 2, math.pi])
    assert np.allclose(rot(th, (1.0, 0.0)), [[1, 0], [0, 1], [-1, 0]], atol=1e-15)
    assert rot_vec2(math.pi / 2, (2.0, 0.0)) == pytest.approx((0.0, 2.0), abs=1e-15)


@settings(deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(finite, finite)
def test_perp_is_a_quarter_turn_counter_clockwise(x: float, y: float) -> None:
    v = np.array([x, y])
    assert np.array_equal(perp(v), [-y, x])
    assert dot(perp(v), v) == 0.0
    assert np.array_equal(perp(perp(v)), -v)
    assert np.allclose(perp(v), rot(math.pi / 2, (x, y)), atol=1e-9 * max(1.0, abs(x), abs(y)))


def test_readonly_copies_and_cannot_be_written() -> None:
    src = [1, 2, 3]
    a = readonly(src)
    assert a.dtype == float and list(a) == [1.0, 2.0, 3.0]
    with pytest.raises(ValueError):
        a[0] = 5.0
    b = np.zeros(2)
    c = readonly(b)
    b[0] = 1.0
    assert c[0] == 0.0  # a copy: later writes to the source do not reach the result


def test_vec2_gives_two_plain_floats() -> None:
    v = vec2(np.array([1, 2]))
    assert v == (1.0, 2.0) and all(type(x) is float for x in v)
    with pytest.raises(ValueError):
        vec2([1.0, 2.0, 3.0])


def _sources() -> list[Path]:
    return [p for pkg in ("reportgen", "drawings", "latex_templates") for p in (ROOT / pkg).rglob("*.py")]


@pytest.mark.parametrize("pattern, home", [
    (r"^\s*\w+\s*=\s*tuple\[float,\s*float\]\s*$", "reportgen/geometry.py"),   # a vector type alias
    (r"setflags\(write=False\)", "reportgen/geometry.py"),                     # a read-only helper
    (r"^def _?(perp|cross|rot)\(", "reportgen/geometry.py"),                    # vector helpers
])
def test_one_home_for_each_helper(pattern: str, home: str) -> None:
    rx = re.compile(pattern, re.M)
    found = [str(p.relative_to(ROOT)) for p in _sources() if rx.search(p.read_text(encoding="utf-8"))]
    assert found == [home], f"{pattern} defined outside {home}: {found}"


def test_the_core_keeps_no_bare_division_floor() -> None:
    """reportgen/ (the pure core) writes its division floor as tolerances.TINY, not 1e-300."""
    found = [str(p.relative_to(ROOT)) for p in (ROOT / "reportgen").rglob("*.py")
             if p.name != "tolerances.py" and re.search(r"(?<![\w.])1e-300", p.read_text(encoding="utf-8"))]
    assert not found, found


def test_frozen_makes_the_array_itself_read_only() -> None:
    from reportgen.geometry import frozen
    a = np.arange(3.0)
    b = frozen(a)
    assert b is a and not a.flags.writeable
    with pytest.raises(ValueError):
        a[0] = 1.0


def test_shared_keeps_a_read_only_array_and_copies_a_writable_one() -> None:
    from reportgen.geometry import shared
    ro = readonly([1.0, 2.0])
    assert shared(ro) is ro
    w = np.array([1.0, 2.0])
    c = shared(w)
    assert c is not w and not c.flags.writeable
    w[0] = 5.0
    assert c[0] == 1.0
