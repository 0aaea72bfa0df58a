"""Issue 12, «Scales»: the scale of the plan of positions is chosen once, in the core, from the
sheet's whole arrangement (reportgen/scenes/arrangement.py), and sheet 1 and the control work's
sheet draw at it — they never fall back to another scale on their own.

On main before this, sheet 1 tried the scales in turn and drew at the first whose views fitted,
while the note printed the first of all: a crank-slider with a 0.6 m coupler and three plan
positions drew 1:2,5 while the note printed 1:2. tests/control/test_control_scales.py has the control
work's cases (table 4 variant 1 on A3 drew 1:50 against the note's 1:40, tables 2 and 22 failed on A3);
the slow test below draws every table's variant 1 (and a sample of others) on A1 and A3.
"""
from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path

import ezdxf
import pytest

from drawings import style
from drawings.sheets import control as control_sheet
from drawings.sheets import kinematics as sheet1
from drawings.words import language, tr
from reportgen.errors import ReportgenInputError
from reportgen.project import Project
from reportgen.scenes import arrangement
from reportgen.scenes.boxes import (LEVER_TITLE_MM, PLAN_TITLE_A3_MM, PLAN_TITLE_DIGIT_MM, PLAN_TITLE_MM, SceneBoxes,
                                    free_field)
from reportgen.scenes.positions import bounds
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
LANGUAGES = ("ru", "en", "uk")
EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3", "control-work")


def long_crank_slider(tmp: Path, coupler: float = 0.6, plan_positions: str = "3, 8, 10") -> Path:
    """The crank-slider example with a longer coupler (the slider's point where it assembles) and
    three plan positions."""
    text = (ROOT / "examples" / "crank-slider" / "task.toml").read_text(encoding="utf-8")
    xb = 0.0866 + math.sqrt(coupler ** 2 - 0.03 ** 2)
    for old, new in (("B = [0.3765, 0.02]", f"B = [{xb:.6f}, 0.02]"), ("length = 0.30", f"length = {coupler}"),
                     ("force_position = 3", f"force_position = 3\nplan_positions = [{plan_positions}]"),
                     ("#:schema ../task.schema.json", "")):
        assert old in text
        text = text.replace(old, new)
    path = tmp / "long-crank-slider.toml"
    path.write_text(text, encoding="utf-8")
    return path


def control_variant(tmp: Path, table: int, variant: int, sheet: str) -> Path:
    path = tmp / f"t{table}v{variant}{sheet}.toml"
    subprocess.run([sys.executable, "-m", "reportgen", "new", "--table", str(table), "--variant", str(variant),
                    "-o", str(path)], check=True, capture_output=True)
    text = path.read_text(encoding="utf-8")
    assert '\nsheet = "A1"' in text
    path.write_text(text.replace('\nsheet = "A1"', f'\nsheet = "{sheet}"'), encoding="utf-8")
    return path


def scheme_scale_on_the_sheet(doc, rect) -> tuple[float, str]:
    """μl and «1:N» as the sheet prints them under the scheme (read back from the DXF)."""
    found = []
    for e in doc.modelspace().query("TEXT"):
        x, y = tuple(e.dxf.insert)[:2]
        if rect.x0 - 1e-6 <= x <= rect.x1 + 1e-6 and rect.y0 - 1e-6 <= y <= rect.y1 + 1e-6:
            m = re.match(r"μl = ([\d,]+) м/мм \(М (1:[\d,]+)\)", e.dxf.text)
            if m:
                found.append((float(m.group(1).replace(",", ".")), m.group(2)))
    assert len(found) == 1, found
    return found[0]


def assert_sheet_prints_the_notes_scale(project: Project, drawn, tmp: Path) -> None:
    drawn.save(tmp / "sheet.dxf")
    mu, ratio = scheme_scale_on_the_sheet(ezdxf.readfile(tmp / "sheet.dxf"), drawn.views["scheme"].rect)
    note = project.scenes.positions.scale("μl")           # what the note prints (μl and «М 1:N»)
    assert mu == pytest.approx(note.value, rel=1e-12)
    assert ratio == note.ratio
    assert drawn.fields.scale == note.ratio               # the title block's «Масштаб»
    assert drawn.views["scheme"].transform.scale == pytest.approx(1.0 / note.value, rel=1e-12)
    assert not [o for o in drawn.overlaps() if "outside the frame" in str(o)]


def test_course_sheet_with_three_plan_positions_draws_the_notes_scale(tmp_path):
    """The case that fell back on main (note 1:2, sheet 1:2,5): the core now prints the one the
    sheet draws, and the box's larger scale does not fit the sheet."""
    project = Project(load_task(long_crank_slider(tmp_path)))
    assert_sheet_prints_the_notes_scale(project, sheet1.draw(project, 1, 4), tmp_path)
    first, chosen = project.scenes.positions_scales[0], project.scenes.positions_scale
    assert chosen != first                                # the box alone would say 1:2
    b = bounds(project.scenes.scheme_data, project.linkage)
    assert arrangement.layout_at(project, b, *first) is None


def test_the_chosen_scale_is_the_largest_that_fits(tmp_path):
    """Every scale of the box's list larger than the chosen one leaves some view without room."""
    for path in (long_crank_slider(tmp_path), control_variant(tmp_path, 1, 1, "A3")):
        project = Project(load_task(path))
        b = bounds(project.scenes.scheme_data, project.linkage)
        scales = project.scenes.positions_scales
        chosen = scales.index(project.scenes.positions_scale)
        assert all(arrangement.layout_at(project, b, *s) is None for s in scales[:chosen])
        layout = project.scenes.sheet_layout
        field = free_field(*{"A1": (841.0, 594.0), "A3": (420.0, 297.0)}[layout.sheet]).buffer(1e-6)
        rects = list(layout.rects.items())
        for k, (n, r) in enumerate(rects):
            assert field.contains(r.polygon()), n
            assert not any(r.overlaps(q) for m, q in rects[k + 1:]), n


def test_a_variant_that_cannot_fit_a3_says_so_and_suggests_a1(tmp_path):
    """Plans drawn 300 mm from the pole cannot fit A3 at any scale: bad input (exit 2) naming
    [control_work] sheet and "A1", not a layout failure."""
    project = Project(load_task(control_variant(tmp_path, 1, 1, "A3")), boxes=SceneBoxes(plan_control_a3_mm=300.0))
    assert project.scenes.sheet_layout is None
    with pytest.raises(ReportgenInputError, match=r'control_work\.sheet.*A3.*"A1"'):
        control_sheet.draw(project, 1, 1)


def test_the_sheets_use_the_cores_free_field():
    from drawings.sheet import A1, A3, Sheet, TitleBlock
    for fmt in (A1, A3):
        sheet = Sheet(fmt, TitleBlock(title="t", code="c"))
        assert sheet.free_region.equals(free_field(fmt.width, fmt.height))


@pytest.mark.parametrize("lang", LANGUAGES)
def test_the_lettering_fits_the_cores_room(lang):
    """The core sizes the views with the lettering's room of reportgen/scenes/boxes.py: every
    language's titles (position numbers of two digits) fit it, so a view is never narrower than
    what the sheet writes in it."""
    from drawings.scenes.kinetostatics_views import lever_subtitle, lever_title
    with language(lang):
        for key, room in zip(("sheets.sk103", "sheets.sk104"), PLAN_TITLE_MM[lang]):
            for i in (2, 11, 123):
                assert style.text_width(tr(key, i=i), 5.0) + 10.0 <= room + PLAN_TITLE_DIGIT_MM * (len(str(i)) - 1), key
        assert max(style.text_width(lever_title(), 5.0), style.text_width(lever_subtitle(), 3.5)) + 4.0 \
            <= LEVER_TITLE_MM[lang]
    with language("ru"):                        # the control work's catalogue is Russian
        for key, room in zip(("control.sheet.vplan_a3", "control.sheet.aplan_a3"), PLAN_TITLE_A3_MM["ru"]):
            assert style.text_width(tr(key), 5.0) + 10.0 <= room, key


@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("example", EXAMPLES)
def test_the_table_of_scales_fits_the_cores_room(example, lang):
    project = Project(load_task(ROOT / "examples" / example / "task.toml"))
    control = project.task.document.kind == "control-work"
    if control and lang != "ru":
        pytest.skip("the control work's catalogue is Russian")
    k, ratio = project.scenes.positions_scale
    pairs = dict(project.plans_by_position)
    with language(lang):
        d = None if control else sheet1.diagrams_of(project)
        small = None if control else sheet1.small_plans(project, sheet1.SMALL_PLAN_MM[0])
        rows = sheet1.scale_rows(1.0 / k, ratio, pairs, d, small)
        reserved = arrangement.scales_table_width(project, k, ratio, project.output_diagrams, not control, lang)
        assert sum(sheet1._table_widths([rows])) <= reserved + 1e-9
    assert len(rows) <= project.scenes.sheet_layout.table_rows


@pytest.mark.slow
@pytest.mark.parametrize("sheet", ["A1", "A3"])
def test_every_table_fits_at_the_notes_scale(tmp_path, sheet):
    """Variant 1 of all 22 tables and a sample of other variants: the sheet is drawn (no «sheet layout
    failed»), at the note's scale, nothing over the frame."""
    cases = [(t, 1) for t in range(1, 23)] + [(t, v) for t in (1, 2, 7, 13, 22) for v in (4, 10)]
    for table, variant in cases:
        project = Project(load_task(control_variant(tmp_path, table, variant, sheet)))
        assert project.scenes.sheet_layout is not None, (table, variant)
        assert_sheet_prints_the_notes_scale(project, control_sheet.draw(project, 1, 1), tmp_path)
