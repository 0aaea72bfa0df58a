"""Sheet 1 read back as a ТММ teacher reads it (issue 12): the small velocity plans' letters, the
scheme's labels against its links. Each check reads the texts and lines back from the DXF
(:mod:`tests.labels.readback`: a text's box from the entity alone) and takes from the drawn sheet
only what it cannot read there: which label names what (``Annotations.labels``), the views' and
the small plans' cells' names, and the scheme's scene (which of its lines are links)."""
from __future__ import annotations

import math
import re
from pathlib import Path

import ezdxf
import shapely
from shapely.geometry import LineString, Point, Polygon

from drawings.sheets import available_sheets
from drawings.scenes.kinematics_scheme import scene_links
from drawings.sheets import kinematics as sheet1
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task

from labels.readback import TOUCH_MM, sheet_texts

ROOT = Path(__file__).resolve().parents[2]
#: Every course example with a linkage (sheet 1), and a crank–rocker no example has.
CASES = ("press", "shaper", "conveyor", "crank-slider", "class3", "press-en", "shaper-uk", "rocker")
#: The smallest letter a teacher reads on an A1 sheet (ГОСТ 2.304 size 3,5).
MIN_LETTER_MM = 3.5

_DRAWN: dict[str, tuple[Project, object, object]] = {}


def rocker_task(folder: Path) -> Path:
    """A crank–rocker O–A–B–C with a resistance moment on the rocker: no slider, no triangular
    link, no gears (the mechanism of tests/lang's «a mechanism no example has»)."""
    from reportgen.zoo import four_bar
    text = four_bar(0.08, 0.30, 0.22, 0.28, phi_deg=30.0, omega=15.0, name="Rocker",
                    loads=[{"kind": "resistance", "link": 3, "moment": 120.0, "law": [[0.0, 1.0], [1.0, 1.0]],
                            "stroke": "working"}],
                    analysis={"positions": 12, "start": "extreme", "force_position": 3},
                    extra="[dynamics]\ndelta = 0.05\ncrank_inertia = 0.4\n")
    path = folder / "task.toml"
    path.write_text('[document]\ntitle = "Rocker"\n\n' + text, encoding="utf-8")
    return path


def project_of(case: str, folder: Path) -> Project:
    task = rocker_task(folder) if case == "rocker" else ROOT / "examples" / case / "task.toml"
    return Project(load_task(task))


def drawn_sheet1(case: str, folder: Path):
    """(project, sheet 1 as drawn, its DXF read back), once per test process."""
    if case not in _DRAWN:
        project = project_of(case, folder)
        todo = available_sheets(project)
        number, mod = next((k, m) for k, (_, m) in enumerate(todo, 1) if m is sheet1)
        sheet = draw_sheet(project, mod, number, len(todo))
        sheet.save(folder / "sheet1.dxf")
        _DRAWN[case] = (project, sheet, ezdxf.readfile(folder / "sheet1.dxf"))
    return _DRAWN[case]


def dxf_lines(doc) -> list:
    """Every drawn line of the sheet read back (LINE, LWPOLYLINE, ARC, CIRCLE as lines; a SOLID,
    an arrowhead, as its outline), in sheet mm."""
    out = []
    msp = doc.modelspace()
    for e in msp.query("LINE"):
        out.append(LineString([tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]]))
    for e in msp.query("LWPOLYLINE"):
        pts = [tuple(p)[:2] for p in e.get_points("xy")]
        if e.closed:
            pts.append(pts[0])
        if len(pts) > 1:
            out.append(LineString(pts))
    for e in msp.query("CIRCLE"):
        out.append(Point(tuple(e.dxf.center)[:2]).buffer(float(e.dxf.radius), 64).exterior)
    for e in msp.query("ARC"):
        c, r = tuple(e.dxf.center)[:2], float(e.dxf.radius)
        a0, a1 = float(e.dxf.start_angle), float(e.dxf.end_angle)
        sweep = (a1 - a0) % 360.0 or 360.0
        n = max(int(sweep / 3.0), 2)
        out.append(LineString([(c[0] + r * math.cos(math.radians(a0 + sweep * t / n)),
                                c[1] + r * math.sin(math.radians(a0 + sweep * t / n))) for t in range(n + 1)]))
    for e in msp.query("SOLID"):
        pts = [tuple(e.dxf.get(f"vtx{k}"))[:2] for k in range(3)]
        out.append(LineString(pts + [pts[0]]))
    return out


def letters_of(text: str) -> set[str]:
    """The plan letters of a label as its record names them: «a_3, e» → {a3, e}."""
    return {re.sub(r"[_^]", "", part.strip()) for part in text.split(",") if part.strip()}


def course_letters(project) -> set[str]:
    """The letters a teacher reads on a small velocity plan, from the mechanism itself: the pole
    p and the images of the points that move (a, b, c, …; a3 on a slotted link) — not the fixed
    points (they are the pole) nor the centres of mass s_k."""
    plan = project.plans[0]
    fixed = {g.lower() for g in project.linkage.ground}
    centres = {f"s{k}" for k in project.kinematics.coms}
    return {"p"} | {k for k in plan.points if k != "p" and k not in fixed | centres}


def small_plan_findings(project, sheet, doc) -> list[str]:
    """What a teacher would mark on the small velocity plans: a text crossed by a line, a letter of
    the course's (:func:`course_letters`) missing from a plan, a letter lower
    than ГОСТ 2.304's 3,5 mm, a letter crossed by a line, a letter farther from its point than
    ``SMALL_NEAR_MM`` without a leader drawn to it, a label of a point in another plan's cell."""
    from drawings.scenes import kinematics_plans as kp
    if "plans_all" not in sheet.views:
        return ["the small velocity plans are left out"]
    texts = {t.handle: t for t in sheet_texts(doc)}
    heights = {str(e.dxf.handle): float(e.dxf.height) for e in doc.modelspace().query("TEXT")}
    lines = dxf_lines(doc)
    tree = shapely.STRtree(lines)
    want = course_letters(project)
    found: list[str] = []
    holder = sheet.views["plans_all"].rect.polygon()
    for t in texts.values():              # any text of the small plans (records or not) on a line
        if holder.contains(t.box.centroid):
            core = t.box.buffer(-TOUCH_MM, join_style=2)
            if len(tree.query(core, predicate="intersects")):
                found.append(f"small plans: «{t.text}» crossed by a line")
    for j, plan in enumerate(sheet1.small_plans(project, 20.0)):
        view = f"plans_all/{j}"
        records = [r for r in sheet.annotations.labels if r.view == view]
        shown = set().union(*(letters_of(r.text) for r in records)) if records else set()
        expected = {k for k in plan.points if k in want}
        for k in sorted(expected - shown):
            found.append(f"plan {j}: letter «{k}» not drawn")
        region = sheet.all_views[view].rect.polygon()
        for r in records:
            boxes = [texts[h].box for h in r.handles if h in texts]
            if not boxes:
                found.append(f"plan {j}: «{r.text}» not in the DXF")
                continue
            base = max(heights[h] for h in r.handles if h in heights)
            if base < MIN_LETTER_MM - 1e-9:
                found.append(f"plan {j}: «{r.text}» {base} mm high")
            shape = shapely.union_all(boxes)
            core = shape.buffer(-TOUCH_MM, join_style=2)
            crossed = [k for k in tree.query(core, predicate="intersects")]
            if crossed:
                found.append(f"plan {j}: «{r.text}» crossed by {len(crossed)} line(s)")
            if not region.buffer(TOUCH_MM).contains(shape):
                found.append(f"plan {j}: «{r.text}» outside its cell")
            if isinstance(r.anchor, Point):
                d = shape.distance(r.anchor)
                if d > kp.SMALL_NEAR_MM + 1e-6:
                    found.append(f"plan {j}: «{r.text}» {d:.1f} mm from its point, no leader")
            else:
                start, end = r.anchor.coords[0], r.anchor.coords[-1]
                if shape.distance(Point(start)) > 0.5 or not any(
                        l.distance(Point(start)) < 1e-3 and l.distance(Point(end)) < 1e-3 for l in lines):
                    found.append(f"plan {j}: «{r.text}»'s leader not drawn")
    return found


def scheme_links(project, sheet) -> list:
    """The scheme's links (the bars and the sliders' blocks of every position) as drawn, sheet mm:
    from the plan of positions' scene at the scheme view's scale."""
    view = sheet.views["scheme"]
    k = view.transform.scale
    scene = project.scenes.positions
    if abs(scene.scale().value * k - 1.0) > 1e-9:
        scene = project.scenes.positions_at(k, "")

    return list(scene_links(view, scene, k).geoms)   # the lines the placer avoids; the texts are read from the DXF


def scheme_label_findings(project, sheet, doc) -> list[str]:
    """Texts of the scheme's view (letters, position and link numbers, the crank angles, the
    stroke) whose letters a link of any position crosses."""
    rect: Polygon = sheet.views["scheme"].rect.polygon()
    links = scheme_links(project, sheet)
    tree = shapely.STRtree(links)
    found = []
    for t in sheet_texts(doc):
        if not rect.contains(t.box.centroid):
            continue
        core = t.box.buffer(-TOUCH_MM, join_style=2)
        hits = tree.query(core, predicate="intersects")
        if len(hits):
            found.append(f"«{t.text}» crossed by {len(hits)} link line(s)")
    return found
