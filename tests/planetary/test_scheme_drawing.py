"""The reducer's kinematic scheme (ГОСТ 2.770) as sheet 4 and the note draw it: both satellites at
their carrier radius above and below the axis, the ring gear whole (above and below) and fixed to
the hatched housing, bearings on the shafts and on the satellites' axles; the front view's
satellites spaced round the centre. Every scheme of the course, K = 2 … 4."""
from __future__ import annotations

import itertools
import math
from pathlib import Path

import pytest

from reportgen.planetary.schemes import SCHEMES
from reportgen.project import Project
from reportgen.scenes.planetary import front_view, side_scheme
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
TASKS = {  # scheme → (z of its wheels, K) that satisfy coaxiality and assembly
    "single-row": ((20, 31, 82), 3),
    "two-row-ext-int": ((21, 29, 35, 85), 2),
    "two-row-ext-ext": ((20, 40, 30, 30), 2),
    "two-row-int-int": ((80, 20, 30, 90), 2),
}


class _Design:
    """The few fields of a design the scheme's drawing reads."""

    def __init__(self, scheme: str, z, K: int, m: float = 4.0) -> None:
        from reportgen.planetary.schemes import expand
        self.scheme = SCHEMES[scheme]
        self.z = z
        self.module = m
        self.satellites = K
        z1, z2, z2p, z3 = expand(self.scheme, z)
        left = z1 + z2 if self.scheme.row1 == "external" else z1 - z2

        class _C:
            pass
        self.coaxial = _C()
        self.coaxial.left = left


def _designs():
    out = []
    for name, (z, K) in TASKS.items():
        out.append((name, _Design(name, z, K)))
    for name in ("press", "crank-slider"):
        out.append((name, Project(load_task(str(ROOT / "examples" / name / "task.toml"))).planetary.design))
    return out


@pytest.mark.parametrize("name,design", _designs(), ids=lambda v: v if isinstance(v, str) else "")
def test_side_scheme_parts(name, design):
    k = 0.4
    s = side_scheme(design, k)
    a = k * design.module * design.coaxial.left / 2
    sats = s.parts("satellite")
    ys = {round(y, 6) for ln in sats for _, y in ln.points}
    # the satellite blocks above and below the axis, each about its own axle at ±a
    assert any(y > 0 for y in ys) and any(y < 0 for y in ys)
    for sg in (1, -1):
        assert any(all(abs(y - sg * a) < 1e-9 for _, y in ln.points) for ln in sats), "no axle line"
    # the fixed wheel 3 drawn on both sides of the axis (a whole wheel, not a stub)
    ring = s.parts("ring")
    assert any(max(y for _, y in ln.points) > 0 for ln in ring)
    assert any(min(y for _, y in ln.points) < 0 for ln in ring)
    # bearings: the input and output shafts' (on the axis) and one on each satellite axle
    bearing_ys = sorted({round(c.centre[1], 6) for c in s.circles if c.part == "bearing"})
    assert len([c for c in s.circles if c.part == "bearing"]) >= 8
    assert any(abs(abs(y) - a) < 5.0 for y in bearing_ys if y > 0)
    assert any(abs(y) < 5.0 for y in bearing_ys)
    # the housing is hatched, the shafts run out of it on both sides
    assert s.hatches and s.parts("housing")
    shafts = s.parts("shaft")
    xs = [x for ln in shafts for x, _ in ln.points]
    walls = [x for ln in s.parts("housing") for x, _ in ln.points]
    assert min(xs) < min(walls) and max(xs) > max(walls)


@pytest.mark.parametrize("name,design", _designs(), ids=lambda v: v if isinstance(v, str) else "")
def test_front_view_satellites_spaced(name, design):
    k = 0.4
    f = front_view(design, k)
    a = k * design.module * design.coaxial.left / 2
    K = design.satellites
    r2 = k * design.module * design.z[1] / 2
    centres = [c.centre for c in f.circles if c.part == "satellite" and abs(c.radius - r2) < 1e-9]
    assert len(centres) == K
    for c in centres:
        assert math.hypot(*c) == pytest.approx(a)
    for p, q in itertools.combinations(centres, 2):
        assert math.dist(p, q) == pytest.approx(2 * a * math.sin(math.pi / K), rel=1e-6) or \
            math.dist(p, q) >= 2 * a * math.sin(math.pi / K) - 1e-9
    # not on the vertical axis through wheel 1 (where they hid the carrier's arms and wheel 1)
    assert not all(abs(c[0]) < 1e-6 for c in centres)
