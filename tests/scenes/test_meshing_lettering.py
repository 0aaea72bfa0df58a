"""The lettering of the meshing picture as a teacher reads it (issue 12: sheet 4 and the note's
fig. 4.1 were crowded with leaders round the pole — P, a, b, p, s1, αw each on a leader 30–55 mm
long on the sheet, αw's crossing b's). For every example with a gear pair (ru, uk, en), on the
scene's designations that the sheet and the note both draw (:func:`reportgen.scenes.meshing.meshing_marks`):

- no two leaders cross, and no leader crosses another designation's text;
- every leader is short: its slanted part at most LEADER_MAX_MM on the sheet (but two of the
  pole's names, whose texts a short leader leaves crossed by the circles meeting at P), and still
  visible in the note's reduced figure;
- nothing is piled round the pole: within POLE_MM of P only the names of what is there (P, αw, a, b);
- a circle's name without a leader stands beside its own circle: nearer to it than to any other
  drawn circle or line.

Each check fails on the placement before this commit (its leaders were sized on the note's page,
three times longer on the sheet, and αw's leader crossed b's on every example)."""
from __future__ import annotations

import math
import re

import pytest
from shapely.geometry import LineString, Point, box

from reportgen.project import Project
from reportgen.scenes.meshing import detail_reduction
from reportgen.scenes.meshing_marks import LEADER_MAX_MM, LONG_LEADERS
from reportgen.taskfile import load_task
from scene_readback import ROOT

GEAR_EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml")
                       if re.search(r"^\[gears\]", p.read_text(encoding="utf-8"), re.M))
#: Round the pole, sheet mm: only the names of what is there (P, αw, and a, b at the ends of the
#: working section, which lie within it on a short ab) stand within this distance of P.
POLE_MM = 25.0
POLE_NAMES = {"P", "alpha_w", "a", "b"}
#: The shortest leader the note's figure draws, page mm (shorter reads as a tick).
NOTE_LEADER_MIN_MM = 1.5


@pytest.fixture(scope="module", params=GEAR_EXAMPLES)
def meshing(request):
    project = Project(load_task(str(ROOT / "examples" / request.param / "task.toml")))
    return project.scenes.meshing


def test_examples_cover_three_languages():
    langs = {load_task(str(ROOT / "examples" / n / "task.toml")).document.language or "ru" for n in GEAR_EXAMPLES}
    assert langs >= {"ru", "uk", "en"}


def test_no_two_leaders_cross(meshing):
    marks = [m for m in meshing.marks.marks if m.leader]
    found = []
    for i, a in enumerate(marks):
        la = LineString(a.leader)
        for b in marks[i + 1:]:
            if la.intersects(LineString(b.leader)):
                found.append(f"{a.name}/{b.name}")
        for b in meshing.marks.marks:
            if b is not a and la.intersects(box(*b.box)):
                found.append(f"{a.name}'s leader over «{b.text}»")
    assert not found, found


#: The pole's names that may take one of the first two LONG_LEADERS where every short leader's text
#: is crossed by a circle (at P the pitch and working circles of both wheels meet: issue 12, an arc
#: through the press's and the shaper's «a» and «αw» for a short leader); at most this many.
POLE_NAMES, POLE_LONG = frozenset({"P", "a", "b", "alpha_w"}), 2


def test_leaders_short(meshing):
    k = meshing.scale.factor
    r = detail_reduction(meshing.pic, meshing.scale)
    long = []
    for m in meshing.marks.marks:
        if not m.leader:
            continue
        slant = math.dist(m.leader[0], m.leader[1]) * k          # sheet mm
        if slant > LEADER_MAX_MM + 1e-6 and m.name in POLE_NAMES:
            long.append(m.name)
            assert slant <= LONG_LEADERS[1] + 1e-6, f"{m.name}: a leader of {slant:.0f} mm on the sheet"
        else:
            assert slant <= LEADER_MAX_MM + 1e-6, f"{m.name}: a leader of {slant:.0f} mm on the sheet"
        if m.page_h > 0:
            assert slant * r >= NOTE_LEADER_MIN_MM, f"{m.name}: a leader of {slant * r:.1f} mm in the note"
    assert len(long) <= POLE_LONG, long


def test_nothing_piled_round_the_pole(meshing):
    k = meshing.scale.factor
    disc = Point(meshing.pic.points["P"]).buffer(POLE_MM / k)
    near = sorted(m.name for m in meshing.marks.marks
                  if box(*m.box).intersects(disc) or (m.leader and LineString(m.leader).intersects(disc)))
    assert set(near) <= POLE_NAMES, f"within {POLE_MM:g} mm of P: {near}"


def test_circle_names_beside_their_own_circle(meshing):
    """A name set beside its arc (no leader) is read as that circle's: the own circle is the
    nearest drawn line to its text (circles, the line of action, the tangent, the line of
    centres)."""
    pic = meshing.pic
    rings = {c.name: Point(c.centre).buffer(c.radius, 256).exterior for c in pic.circles}
    others = [LineString([pic.points["N1"], pic.points["N2"]]), LineString(pic.segments["tangent"])]
    beside = 0
    for m in meshing.marks.marks:
        if m.name not in rings or m.leader:
            continue
        beside += 1
        b = box(*m.box)
        own = b.distance(rings[m.name])
        nearest = min([b.distance(g) for n, g in rings.items() if n != m.name] + [b.distance(g) for g in others])
        assert own < nearest, f"«{m.text}» is nearer another line ({nearest:.2f}) than its circle ({own:.2f})"
    assert beside >= 1, "no circle named beside its arc"
