"""Issue 12: sheet 1's small velocity plans are a required part of its layout, and their scale does
not depend on the language of the sheet's words.

On main the core chose the scale of the plan of positions from the views without the small plans,
and the sheet added them only where they happened to fit: class3 with three plan positions lost
them once the table «Масштабы» got its real width. Their μv was the largest that fitted the room
the language's titles left: the press printed μv = 0,04 in Russian and 0,05 in English, class3
0,04 and 0,05, the short-crank shaper 0,04 in Russian and 0,05 in Ukrainian and English. Now the
core (reportgen/scenes/arrangement.py) chooses the scale with their block among the views (the
scheme drops a ГОСТ step where they need it) and their μv as the largest that fits sheet 1 in
every catalogue language, their block's lettering reserved for the widest language.
"""
from __future__ import annotations

import re
from pathlib import Path

import ezdxf
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from drawings.sheets import kinematics as sheet1
from drawings.words import language
from reportgen.project import Project
from reportgen.scenes import arrangement
from reportgen.scenes.boxes import free_field
from reportgen.scenes.positions import bounds
from reportgen.taskfile import load_task
from test_plan_pairs_layout import with_plan_positions  # noqa: E402 (tests/sheet1 is on the path)

ROOT = Path(__file__).resolve().parents[2]
#: Every linkage example of the course project and the test tasks that no example is.
TASKS = [f"examples/{e}/task.toml" for e in ("press", "press-en", "crank-slider", "shaper", "shaper-uk",
                                             "conveyor", "class3")] + sorted(
    str(p.relative_to(ROOT)) for p in (ROOT / "tests" / "data").glob("*.toml"))
EPS = 1e-6


def in_language(path: Path, lang: str, tmp: Path) -> Path:
    """The task at ``path`` with ``[document] language = lang``."""
    text = path.read_text(encoding="utf-8")
    if re.search(r"(?m)^language\s*=", text):
        text = re.sub(r"(?m)^language\s*=.*$", f'language = "{lang}"', text)
    else:
        text = text.replace("[document]", f'[document]\nlanguage = "{lang}"', 1)
    out = tmp / f"{path.parent.name}-{path.stem}-{lang}.toml"
    out.write_text(text.replace("#:schema ../task.schema.json", ""), encoding="utf-8")
    return out


def assert_small_plans_in_the_field(project: Project, rects) -> None:
    """The core's layout: the small plans' block with every position's plan, inside the free field,
    clear of every other view (``VIEW_GAP`` apart)."""
    layout = project.scenes.sheet_layout
    assert layout is not None
    assert layout.small is not None and "plans_all" in rects, "the small velocity plans were left out"
    assert [p.position for p in layout.small] == list(range(len(project.phi)))
    assert len({p.scale for p in layout.small}) == 1
    field = free_field(841.0, 594.0).buffer(EPS)
    holder = rects["plans_all"]
    assert field.contains(holder.polygon())
    for name, r in rects.items():
        if name != "plans_all":
            assert not holder.expanded(arrangement.VIEW_GAP - 1e-3).overlaps(r), name


def small_caption(doc, rect) -> str:
    """The small plans' caption «μv = …» read back from the DXF within their view."""
    found = []
    for e in doc.modelspace().query("TEXT"):
        x, y = tuple(e.dxf.insert)[:2]
        if rect.x0 - EPS <= x <= rect.x1 + EPS and rect.y0 - EPS <= y <= rect.y1 + EPS:
            m = re.match(r"μv = ([\d.,]+) ", e.dxf.text)
            if m:
                found.append(m.group(1).replace(",", "."))
    assert len(found) == 1, found
    return found[0]


@pytest.mark.parametrize("task", TASKS)
def test_every_task_draws_all_its_small_plans_in_the_field(task, tmp_path):
    """Drawn: the block and one cell per position, each cell inside the block, the block inside the
    field and over no other view, its caption the core's μv."""
    project = Project(load_task(ROOT / task))
    with language(project.task.document.language):
        sheet = sheet1.draw(project, 1, 4)
    assert "plans_all" in sheet.views
    assert_small_plans_in_the_field(project, {n: v.rect for n, v in sheet.views.items()})
    holder = sheet.views["plans_all"].rect
    cells = sorted((n for n in sheet.all_views if n.startswith("plans_all/")), key=lambda n: int(n.split("/")[1]))
    assert cells == [f"plans_all/{j}" for j in range(len(project.phi))]
    for n in cells:
        cell = sheet.all_views[n].rect
        assert holder.expanded(EPS).polygon().contains(cell.polygon()), n
    assert not sheet.overlaps()
    sheet.save(tmp_path / "sheet1.dxf")
    caption = small_caption(ezdxf.readfile(tmp_path / "sheet1.dxf"), holder)
    assert float(caption) == pytest.approx(project.scenes.sheet_layout.small[0].scale, rel=1e-12)


@pytest.mark.parametrize("count", [1, 2, 3])
@pytest.mark.parametrize("example", ["press", "crank-slider", "shaper", "conveyor", "class3"])
def test_the_core_reserves_the_small_plans_for_every_number_of_plan_positions(example, count, tmp_path):
    """1 to 3 plan positions (the task format's limit): the core's layout has the small plans."""
    project = with_plan_positions(example, count, tmp_path)
    assert_small_plans_in_the_field(project, project.scenes.sheet_layout.rects)


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(st.integers(0, 11).filter(lambda j: j != 3), max_size=2, unique=True).flatmap(
    lambda others: st.permutations([3, *others])))
def test_any_plan_positions_keep_the_small_plans(tmp_path, positions):
    """Any choice of plan positions of the crank-slider (12 positions; its force position 3 among
    them, as the task format requires)."""
    text = (ROOT / "examples" / "crank-slider" / "task.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^plan_positions\s*=.*\n", "", text)
    text = text.replace("#:schema ../task.schema.json", "")
    line = f"plan_positions = [{', '.join(map(str, positions))}]\n"
    text = re.sub(r"(?m)^(\[analysis\][^\n]*\n)", lambda m: m.group(1) + line, text, count=1)
    path = tmp_path / f"cs-{'-'.join(map(str, positions))}.toml"
    path.write_text(text, encoding="utf-8")
    project = Project(load_task(path))
    assert sorted(project.plan_positions) == sorted(positions)
    assert_small_plans_in_the_field(project, project.scenes.sheet_layout.rects)


#: The same mechanism in the catalogue's languages: the examples in another language, and the
#: examples with [document] language changed.
SAME_MECHANISM = {"press": ("examples/press/task.toml", "examples/press-en/task.toml", "uk"),
                  "shaper": ("examples/shaper/task.toml", "examples/shaper-uk/task.toml", "en"),
                  "class3": ("examples/class3/task.toml", "uk", "en"),
                  "shaper-short-crank": ("tests/data/shaper-short-crank.toml", "uk", "en")}


def _projects(name: str, tmp: Path) -> list[Project]:
    first, *others = SAME_MECHANISM[name]
    paths = [ROOT / first] + [ROOT / o if o.endswith(".toml") else in_language(ROOT / first, o, tmp) for o in others]
    projects = [Project(load_task(p)) for p in paths]
    assert sorted(p.task.document.language for p in projects) == ["en", "ru", "uk"]
    return projects


@pytest.mark.parametrize("name", list(SAME_MECHANISM))
def test_the_small_plans_scale_is_the_same_in_every_language(name, tmp_path):
    """The small plans' μv of one mechanism in ru, uk and en is one (the press: 0,04 in ru and 0,05
    in en on main), and it is the largest such: one size larger does not fit sheet 1 in some
    language (each at its scale of the plan of positions), so the common μv is not needlessly small."""
    projects = _projects(name, tmp_path)
    scales = {p.task.document.language: p.scenes.sheet_layout.small[0].scale for p in projects}
    assert len(set(scales.values())) == 1, scales
    project = projects[0]
    choice = project.scenes.sheet_choice
    b = bounds(project.scenes.scheme_data, project.linkage)
    at = {p.task.document.language: p.scenes.positions_scale for p in projects}
    for lang, scale in at.items():
        assert arrangement.fits_at(project, b, *scale, small=choice.small, language=lang)
    if choice.small > 0:
        assert not all(arrangement.fits_at(project, b, *scale, small=choice.small - 1, language=lang)
                       for lang, scale in at.items())


@pytest.mark.parametrize("pair", ["press", "shaper"])
def test_the_sheets_print_one_small_plans_scale_in_every_language(pair, tmp_path):
    """Read back from the drawn sheets: the caption under the small plans of press and press-en
    (shaper and shaper-uk) prints the same μv."""
    printed = {}
    for project in _projects(pair, tmp_path)[:2]:
        lang = project.task.document.language
        with language(lang):
            sheet = sheet1.draw(project, 1, 4)
        sheet.save(tmp_path / f"{lang}.dxf")
        printed[lang] = small_caption(ezdxf.readfile(tmp_path / f"{lang}.dxf"), sheet.views["plans_all"].rect)
    assert len({v.replace(",", ".") for v in printed.values()}) == 1, printed


def test_a_mechanism_near_a_toggle_keeps_its_small_plans():
    """A slotted lever whose pivot stands 1,01 crank radii from the crank's axis: the rocker's
    velocity is up to a thousand times the crank pin's, and at the crank's μv (a 20 mm crank vector)
    the plans were metres long, so main dropped them. The small plans' μv also keeps every point
    within ``SMALL_PLAN_FAR`` crank vectors of the pole (as the plans' PLAN_MAX_MM)."""
    import sys
    sys.path.insert(0, str(ROOT / "tests" / "hard_cases"))
    from test_hard_stages import slotted_lever

    from reportgen.scenes.boxes import SMALL_PLAN_MM
    from reportgen.scenes.small_plans import SMALL_PLAN_FAR, plan_extent
    from reportgen.taskfile import loads_task
    project = Project(loads_task(slotted_lever(0.1, 0.101)))
    assert_small_plans_in_the_field(project, project.scenes.sheet_layout.rects)
    plans = project.scenes.sheet_layout.small
    reach = max(max(abs(c) for c in plan_extent(p)) for p in plans)
    assert reach <= SMALL_PLAN_FAR * max(SMALL_PLAN_MM) + 1e-6
