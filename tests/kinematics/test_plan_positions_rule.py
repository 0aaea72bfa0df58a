"""The default plan positions (reportgen.plan_positions): the analysed position first, then the
position of the other stroke nearest that stroke's middle — checked against a brute force over
random strokes and grids, and on the examples (press: seed 000's positions 2 and 6 of 8)."""
from __future__ import annotations

import math
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from reportgen.kinematics.extremes import Strokes
from reportgen.plan_positions import default_plan_positions, stroke_of
from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]


def _strokes(start_deg: float, working: float) -> Strokes:
    return Strokes(output=None, phi_start=math.radians(start_deg), phi_end=math.radians(start_deg + working),
                   working_deg=working, idle_deg=360.0 - working, stroke=0.1, direction=1.0,
                   time_ratio=working / (360.0 - working))


@settings(max_examples=300, deadline=None)
@given(start=st.floats(0, 360), working=st.floats(20, 340), n=st.integers(3, 36),
       sign=st.sampled_from([1.0, -1.0]), data=st.data())
def test_default_against_brute_force(start, working, n, sign, data):
    s = _strokes(start, working)
    # the grid of [analysis] positions: from the start of the working stroke in the sense of rotation
    phi = [(math.radians(start) + sign * k * 2 * math.pi / n) % (2 * math.pi) for k in range(n)]
    analysed = data.draw(st.integers(0, n - 1))
    got = default_plan_positions(phi, s, sign, analysed)
    assert got[0] == analysed
    own = stroke_of(phi[analysed], s, sign)
    other = "idle" if own in (None, "working") else "working"
    # brute force: degrees of rotation from the start of the working stroke
    t = [(k * 360.0 / n) for k in range(n)]
    inside = [k for k in range(n) if k != analysed and
              ((other == "working" and 1e-6 < t[k] < working - 1e-6) or
               (other == "idle" and working + 1e-6 < t[k] < 360.0 - 1e-6))]
    if not inside:
        assert got == (analysed,)
        return
    middle = working / 2 if other == "working" else working + (360.0 - working) / 2
    best = min(inside, key=lambda k: (round(abs(t[k] - middle), 6), k))
    assert len(got) == 2 and stroke_of(phi[got[1]], s, sign) == other
    assert abs(t[got[1]] - middle) <= abs(t[best] - middle) + 1e-6


def test_extreme_positions_belong_to_no_stroke():
    s = _strokes(30.0, 200.0)
    assert stroke_of(math.radians(30.0), s, 1.0) is None
    assert stroke_of(math.radians(230.0), s, 1.0) is None
    assert stroke_of(math.radians(31.0), s, 1.0) == "working"
    assert stroke_of(math.radians(29.0), s, 1.0) == "idle"
    assert stroke_of(math.radians(29.0), s, -1.0) == "working"
    assert stroke_of(1.0, None, 1.0) is None


def test_examples_one_plan_of_each_stroke():
    expected = {"press": (2, 6), "shaper": (3, 10), "conveyor": (4, 9), "crank-slider": (3, 9), "class3": (3, 9)}
    for name, positions in expected.items():
        project = Project(load_task(ROOT / "examples" / name / "task.toml"))
        assert project.plan_positions == positions, name
        sign = 1.0 if project.model.omega >= 0 else -1.0
        strokes = [stroke_of(float(project.phi[j]), project.strokes, sign) for j in positions]
        assert strokes == ["working", "idle"], name
        # the analysed position keeps the plans (and scales) it had: results.json numbers unchanged
        assert project.plans_by_position[positions[0]] is project.plans
