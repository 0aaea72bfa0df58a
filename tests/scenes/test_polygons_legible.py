"""Force polygons and Zhukovsky's lever that a teacher can read (issue 12): a vector shorter than
LEGIBLE_MM is shown again in an enlarged detail (ГОСТ 2.305) where it is at least that long, named
there and not on the polygon; the details lie clear of the polygon and of each other at a ГОСТ 2.302
enlargement with a round μF/k; the polygon fits its box turned along its longer side; the lever
draws F_ур at the pin's image, and its arrows do not lie over each other. Every example with a
mechanism, in every language (the scenes are the same; the sheets' and note's names are checked by
tests/labels)."""
from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from reportgen import gost_scales
from reportgen.project import Project
from reportgen.scenes.forces import (DETAIL_MAX_MM, LEADER_MM, LEGIBLE_MM, detail_ratio, polygon_details,
                                     polygon_scene)
from reportgen.scenes.lever import lever_scene
from reportgen.scenes.scales import FORCE_SERIES, round_up
from reportgen.scenes.scene import Arrow, Circle, Segment
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "press-en", "shaper", "shaper-uk", "conveyor", "crank-slider", "class3", "control-work")
_PROJECTS: dict[str, Project] = {}


def _project(name: str) -> Project:
    if name not in _PROJECTS:
        _PROJECTS[name] = Project(load_task(ROOT / "examples" / name / "task.toml"))
    return _PROJECTS[name]


def _polygons(project: Project):
    g = project.kinetostatics.graphical
    return [gg.polygon for gg in g.groups] + [g.crank.polygon]


def _box(project: Project) -> tuple[float, float]:
    return project.boxes.polygon if len(project.structure.groups) <= 2 else project.boxes.polygon_many


def _is_round(mu: float) -> bool:
    return math.isclose(round_up(mu, FORCE_SERIES), mu, rel_tol=1e-9)


def _check_details(poly, box=None) -> None:
    """Every drawn vector shorter than LEGIBLE_MM is in one detail, legible there (or the detail at
    the largest ratio that stays within DETAIL_MAX_MM), named there and nowhere else; every other
    vector is named on the polygon, on a leader when shorter than LEADER_MM."""
    details = polygon_details(poly) if box is None else polygon_details(poly, box)
    sc = polygon_scene(poly)
    named = {lb.anchor: lb for lb in sc.labels}
    shown = {n: d for d in details for n in d.names}
    assert sum(len(d.names) for d in details) == len(shown), "a vector in two details"
    sides = {e.id: e for e in sc.entities if isinstance(e, Arrow) and not e.id.startswith("detail")}
    for eid, e in sides.items():
        name = eid.split(":", 1)[1]
        if e.length < LEGIBLE_MM:
            assert name in shown, f"{poly.key}: {name} is {e.length:.2f} mm, in no detail"
            d = shown[name]
            assert eid not in named, f"{poly.key}: {name} named on the polygon and in detail"
            larger = [k for k in (gost_scales.factor(s) for s in gost_scales.ENLARGEMENTS) if k > d.ratio
                      and _is_round(poly.scale / k) and 2 * d.radius * k <= DETAIL_MAX_MM]
            assert e.length * d.ratio >= LEGIBLE_MM * (1 - 1e-9) or not larger, \
                f"{poly.key}: {name} {e.length * d.ratio:.2f} mm in detail at {d.ratio}:1"
            # drawn in the detail k times as long (or cut by its circle), and named there
            copy = next(x for x in sc.entities if x.id == f"detail{d.index}:{eid}")
            assert copy.length <= e.length * d.ratio * (1 + 1e-9)
            assert math.dist(copy.a, copy.b) > 0
            assert any(lb.anchor == copy.id and lb.along == (copy.a, copy.b) for lb in sc.labels)
            mark = next(x for x in sc.entities if x.id == f"detail{d.index}:mark")
            assert isinstance(mark, Circle) and mark.r == pytest.approx(d.radius)
            for p in (e.a, e.b):
                assert math.dist(p, d.centre) <= d.radius
        else:
            assert name not in shown
            lb = named[eid]
            assert lb.leader == (e.length < LEADER_MM)
    for d in details:
        k = d.ratio
        assert (k, 1) in [tuple(s) for s in gost_scales.ENLARGEMENTS]
        assert _is_round(d.scale) and math.isclose(d.scale * k, poly.scale, rel_tol=1e-9)
        assert 2 * d.radius * k <= DETAIL_MAX_MM + 1e-9 or k == min(
            kk for kk in (gost_scales.factor(s) for s in gost_scales.ENLARGEMENTS) if _is_round(poly.scale / kk))
        assert any(lb.role == "detail-title" and lb.text == f"{d.index} {d.ratio_text}" for lb in sc.labels)
        assert sc.scale(f"μF:{d.index}").value == d.scale


@pytest.mark.parametrize("example", EXAMPLES)
def test_short_vectors_are_shown_in_an_enlarged_detail(example):
    project = _project(example)
    for poly in _polygons(project):
        _check_details(poly, _box(project))


@pytest.mark.parametrize("example", EXAMPLES)
def test_polygon_fits_its_box_and_its_details_lie_clear(example):
    """The polygon (its vectors) fits the room the sheet gives it turned along its longer side; each
    detail (its disc and heading) lies outside the polygon's bounding box and clear of the others."""
    from reportgen.scenes.forces import DETAIL_TITLE_MM
    project = _project(example)
    for poly in _polygons(project):
        pts = np.array([v.start_mm for v in poly.vectors] + [poly.vectors[-1].end_mm])
        lo, hi = pts.min(0), pts.max(0)
        ext = sorted(hi - lo)
        assert ext[1] <= max(_box(project)) + 1e-6 and ext[0] <= min(_box(project)) + 1e-6, (poly.key, ext)
        boxes = []
        for d in polygon_details(poly, _box(project)):
            R = d.radius * d.ratio
            b = (d.at[0] - R, d.at[1] - R, d.at[0] + R, d.at[1] + R + DETAIL_TITLE_MM)
            assert b[2] <= lo[0] or b[0] >= hi[0] or b[3] <= lo[1] or b[1] >= hi[1], (poly.key, d)
            for o in boxes:
                assert b[2] <= o[0] or b[0] >= o[2] or b[3] <= o[1] or b[1] >= o[3]
            boxes.append(b)


@settings(suppress_health_check=[HealthCheck.too_slow], deadline=None, max_examples=40)
@given(st.lists(st.tuples(st.floats(0.05, 400.0), st.floats(0.0, 2 * math.pi)), min_size=2, max_size=7),
       st.sampled_from([1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0]))
def test_details_of_any_polygon(sides, mu):
    """Loads spanning up to 8000:1 laid head to tail, closed by the last side: every rule above."""
    vecs = [np.array([mm * math.cos(a), mm * math.sin(a)]) for mm, a in sides]
    vecs.append(-sum(vecs))
    start = np.zeros(2)
    vs = []
    for i, v in enumerate(vecs):
        vs.append(SimpleNamespace(name=f"G{i + 1}", start_mm=start.copy(), end_mm=start + v, known=True,
                                  measured_mm=float(np.hypot(*v)), read_value=0.0))
        start = start + v
    poly = SimpleNamespace(key="x", scale=mu, vectors=tuple(vs), extra=())
    _check_details(poly)


def test_detail_ratio_golden():
    """μF = 10 N/mm, 1.07 mm shortest in a 8 mm circle: 5:1 (5.35 mm; 4:1 gives μF/k = 2.5, round,
    but 4.28 mm); μF = 25: 2.5:1 and 5:1 qualify (10 and 5 N/mm), 4:1 does not (6.25)."""
    assert detail_ratio(10.0, 1.07, 8.0) == 5.0
    assert detail_ratio(10.0, 1.3, 8.0) == 4.0
    assert detail_ratio(25.0, 2.2, 8.0) == 2.5
    assert detail_ratio(25.0, 1.5, 8.0) == 5.0
    # a detail never beyond DETAIL_MAX_MM: 0.05 mm in a 7 mm circle at 10:1 (70 mm), not 100:1
    assert detail_ratio(10.0, 0.05, 7.0) == 10.0


@pytest.mark.parametrize("example", EXAMPLES)
def test_lever_draws_the_balancing_force_at_the_pin(example):
    project = _project(example)
    ks = project.kinetostatics
    sc = lever_scene(ks, project.linkage)
    fb = sc.entity("force:Fур")
    pin = tuple(np.asarray(ks.lever.crank_pin_image)[0] / ks.graphical.lever.scale)
    assert min(math.dist(fb.a, pin), math.dist(fb.b, pin)) < 1e-9
    assert any(lb.anchor == "force:Fур" and lb.along == (fb.a, fb.b) for lb in sc.labels)


def _over(e, f, within: float = 1.0, n: int = 50) -> float:
    """Length (mm) of arrow ``e`` lying within ``within`` mm of arrow ``f``."""
    a, b = np.asarray(e.a), np.asarray(e.b)
    c, d = np.asarray(f.a), np.asarray(f.b)
    m = float((d - c) @ (d - c))

    def dist(x):
        t = min(1.0, max(0.0, float((x - c) @ (d - c)) / m)) if m else 0.0
        return float(np.hypot(*(x - c - t * (d - c))))
    return sum(float(np.hypot(*(b - a))) / n for k in range(n + 1) if dist(a + (b - a) * k / n) < within)


@pytest.mark.parametrize("example", EXAMPLES)
def test_lever_arrows_do_not_lie_over_each_other(example):
    """No force arrow of the lever lies along another for more than 3 mm, an arrowhead (on today's main the
    press's F_пс and F_ур, the shaper's F_пс and F_и5 lay over each other at the top of the lever; class3's
    couples of links 4 and 5 at d and f lay over each other both ways until an arrow could follow the
    one already drawn along its own line of action)."""
    project = _project(example)
    sc = lever_scene(project.kinetostatics, project.linkage)
    arrows = [e for e in sc.entities if isinstance(e, Arrow)]
    found = [(e.id, f.id, round(_over(e, f), 1)) for i, e in enumerate(arrows) for f in arrows[i + 1:]
             if _over(e, f) > 3.0]
    assert not found, found


@pytest.mark.parametrize("example", EXAMPLES)
def test_lever_arm_names_stand_on_their_own_arms(example):
    """Each arm's name h_i stands on its own arm (the perpendicular from p to the force's line), and the
    names of two arms that differ (feet more than 1 mm apart) stand at least 2 mm apart (on main the
    names stood at each arm's middle: the press's h2/h10, h3/h7, h4/h6, class3's h2/h13, h4/h5 and the
    control work's h4/h5/h9 bunched within 0,7–1,6 mm round the pole)."""
    import itertools
    project = _project(example)
    sc = lever_scene(project.kinetostatics, project.linkage)
    feet = {e.id: np.asarray(e.b) for e in sc.entities if isinstance(e, Segment) and e.id.startswith("arm:")}
    names = [lb for lb in sc.labels if lb.anchor.startswith("arm:")]
    assert len(names) == len(feet)
    for lb in names:
        foot, at = feet[lb.anchor], np.asarray(lb.at)
        t = float(at @ foot) / float(foot @ foot)
        assert 0.0 < t < 1.0 and abs(float(foot[0] * at[1] - foot[1] * at[0])) / float(np.hypot(*foot)) < 1e-6, lb
    bunched = [(a.text, b.text, round(math.dist(a.at, b.at), 2)) for a, b in itertools.combinations(names, 2)
               if math.dist(feet[a.anchor], feet[b.anchor]) > 1.0 and math.dist(a.at, b.at) < 2.0]
    assert not bunched, bunched


@pytest.mark.slow
@pytest.mark.parametrize("example", EXAMPLES)
def test_sheet_names_the_balancing_force_on_the_lever(example):
    """Sheet 2 (the control work's sheet) draws F_ур on the lever and names it: a label of the view
    «lever» names a line with one end at the point the sheet letters as the crank pin's image."""
    from drawings.sheets import available_sheets
    from drawings.words import language, symbol, use_catalogue
    from latex_templates.render import Strings
    from reportgen.commands.pipeline import draw_sheet
    project = _project(example)
    todo = available_sheets(project)
    number, mod = next((i, m) for i, (s, m) in enumerate(todo, 1) if "kinetostatics" in s or "control" in s)
    sheet = draw_sheet(project, mod, number, len(todo))
    use_catalogue(Strings)
    with language(project.task.document.language):
        fb = symbol("Fур")
    records = [r for r in sheet.annotations.labels if r.view == "lever"]
    pin = project.kinetostatics.reactions.crank_pin.lower()
    at = [r.anchor for r in records if r.text == pin and r.anchor.geom_type == "Point"]
    # a record's text marks its indices (``F^B_Mи4``, drawings.lettering): the letters read F, у, р
    named = [r.anchor for r in records if r.text.replace("^", "").replace("_", "") == fb
             and r.anchor.geom_type in ("LineString", "MultiLineString")]
    assert len(at) == 1 and len(named) == 1, ([r.text for r in records], fb)
    lines = named[0].geoms if named[0].geom_type == "MultiLineString" else [named[0]]
    ends = [c for ln in lines for c in (ln.coords[0], ln.coords[-1])]
    assert min(math.dist(c, at[0].coords[0]) for c in ends) < 1e-6


@pytest.mark.slow
@pytest.mark.parametrize("example", ("press", "shaper-uk", "conveyor", "class3"))
def test_detail_letters_are_not_repeated_on_sheet_2(example, tmp_path):
    """A detail's letter names one detail of the sheet (ГОСТ 2.305 §6: А, Б, … through the sheet),
    so the polygons' details are lettered through the work, not from А in every polygon: the
    headings «А (5:1)» read back from sheet 2's DXF are all different, and the note's figures carry
    the same letters (the same first index, :func:`first_detail_indices`)."""
    import re

    import ezdxf

    from drawings.sheets import kinetostatics as sheet2
    project = _project(example)
    polygons = _polygons(project)
    count = sum(len(polygon_details(p)) for p in polygons)
    sheet2.draw(project, 2, 4).save(tmp_path / "s2.dxf")
    texts = [e.dxf.text for e in ezdxf.readfile(tmp_path / "s2.dxf").modelspace().query("TEXT MTEXT")
             if e.dxftype() == "TEXT"]
    headings = [t.split(" ", 1)[0] for t in texts if re.fullmatch(r"\w \(\d+(,\d+)?:1\)", t)]
    assert len(headings) == count
    assert len(set(headings)) == len(headings), headings
    from reportgen.scenes.forces import first_detail_indices
    firsts = first_detail_indices(polygons)
    indices = [d.index for p, f in zip(polygons, firsts) for d in polygon_details(p, first=f)]
    assert indices == list(range(count))


#: The slider's inertia force on the lever: it acts along the slider's guide, at the image of the
#: slider's point, where the coupler's image (a link of the lever) runs nearly along it. Not the
#: crank-slider's F_и3: F_пс pulls b away along the same line and F_и3 points against it, so every
#: way along that line lies over F_пс, sets two heads together, or lies along a–b (3,8 mm: left).
SLIDER_INERTIA = {"press": "Fи5", "press-en": "Fи5", "shaper": "Fи5", "shaper-uk": "Fи5", "conveyor": "Fи5"}


@pytest.mark.parametrize("example", sorted(SLIDER_INERTIA))
def test_lever_slider_inertia_is_not_hidden_in_a_link(example):
    """The slider's inertia force is not drawn along the coupler's image (on main the press's and the
    shaper's F_и5 and the conveyor's F_и5 lay 5–7 mm inside the thick line d–b, f–e…: only a head
    showed, and the name went on a leader): where both its ways lie over a drawn line, it slides along
    its line of action past F_пс, which acts on that line at its point (never head against head)."""
    project = _project(example)
    sc = lever_scene(project.kinetostatics, project.linkage)
    arrow = sc.entity(f"force:{SLIDER_INERTIA[example]}")
    links = [e for e in sc.entities if isinstance(e, Segment) and e.kind == "contour"]
    hidden = [(e.id, round(_over(arrow, e), 1)) for e in links if _over(arrow, e) > 3.0]
    assert not hidden, hidden


def test_a_slid_lever_force_never_meets_another_head_on():
    """Sliding along its line of action, a force follows the arrow at its point tail to head or tail
    to tail, never head against head (the crank-slider's F_и3 and F_пс, the crank–rocker's F^B_Mи3
    and M_пс's force at b would meet head-on at the far end of F_пс)."""
    names = {"crank-slider": None, "crank-rocker": None}
    for name in names:
        path = (Path(__file__).resolve().parents[2] / ("tests/data/crank-rocker.toml" if name == "crank-rocker"
                                                        else f"examples/{name}/task.toml"))
        project = Project(load_task(path))
        sc = lever_scene(project.kinetostatics, project.linkage)
        heads = [np.asarray(e.b) for e in sc.entities if isinstance(e, Arrow)]
        met = [(i, j) for i in range(len(heads)) for j in range(i + 1, len(heads))
               if float(np.hypot(*(heads[i] - heads[j]))) < 0.5]
        assert not met, (name, met)
