"""Zhukovsky's lever at one μv for the note and the sheet that draws it (issue 12).

- The μv sheet 2 (the control work's sheet) prints under the lever, read back from its DXF, is the
  μv the note prints and the scale of the note's figure; every arm drawn on the sheet (the thin
  construction lines from the pole, read back from the DXF) is an arm of the note's figure and has
  the length the note prints for it (h_i, mm, read to 0,01 mm), and every arm the note prints (longer
  than the 3 mm the lever leaves undrawn) is on the sheet.
- The lever fills the room sheet 2 gives it: at the next larger round drawing (the next finer μv of
  the plans' series) it no longer fits beside the groups and the polygons (on main class3's lever
  was drawn at 0,005 (м/с)/мм, 198 × 195 mm, where 0,004 fits); the control work's lever on A1 is
  at least half the width of the sheet's free field it could take.
"""
from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest

from drawings.sheets import control as control_sheet
from drawings.sheets import kinetostatics as sheet2
from latex_templates.parts import kinetostatics as part
from reportgen.scenes.scales import PLAN_SERIES
from reportgen.scenes.scene import Segment
from scene_readback import example_project, part_and_sheet

#: The examples with a sheet 2 (their own languages: the numbers do not depend on them).
SHEET2_EXAMPLES = ("press", "press-en", "crank-slider", "shaper", "shaper-uk", "conveyor", "class3")
EXAMPLES = SHEET2_EXAMPLES + ("control-work",)
#: The lever leaves an arm of this length or shorter undrawn (reportgen/scenes/lever.py).
UNDRAWN_ARM_MM = 3.0


@pytest.fixture(scope="module", params=EXAMPLES)
def built(request, tmp_path_factory):
    name = request.param
    sheet, number = (control_sheet, 1) if name == "control-work" else (sheet2, 2)
    project, content, doc = part_and_sheet(name, part, sheet, number, tmp_path_factory.mktemp(name))
    from scene_readback import drawn_sheet
    drawn = drawn_sheet(name, sheet, number, tmp_path_factory.mktemp(name))[0]
    return project, content, doc, drawn.views["lever"].rect


def _inside(rect, p) -> bool:
    return rect.x0 - 1e-6 <= p[0] <= rect.x1 + 1e-6 and rect.y0 - 1e-6 <= p[1] <= rect.y1 + 1e-6


def _sheet_mu_v(doc, rect) -> float:
    for e in doc.modelspace().query("TEXT"):
        m = re.match(r"μv = ([\d.,]+) ", e.dxf.text)
        if m and _inside(rect, tuple(e.dxf.insert)[:2]):
            return float(m.group(1).replace(",", "."))
    raise AssertionError("no «μv = …» under the lever on the sheet")


def _sheet_arms(doc, rect) -> list[float]:
    """Lengths (mm) of the construction lines of the lever's view: its arms."""
    out = []
    for e in doc.modelspace().query("LINE[layer=='construction']"):
        a, b = tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]
        if _inside(rect, a) and _inside(rect, b):
            out.append(math.dist(a, b))
    return out


def _printed_arms(content) -> dict[str, float]:
    """The arms the note prints in the lever's moment equation: symbol → mm."""
    terms = content.context["lever"]["balance"].balance.terms
    return {t.arm.latex: t.arm.value for t in terms if t.arm is not None}


def test_the_note_prints_the_sheets_mu_v(built):
    _, content, doc, rect = built
    fig = content.figures["kst_lever"]
    mu_sheet = _sheet_mu_v(doc, rect)
    assert content.context["lever"]["mu_v"].value == pytest.approx(mu_sheet, rel=1e-12)
    assert fig.scene.scale("μv").value == pytest.approx(mu_sheet, rel=1e-12)


def test_the_arms_on_the_sheet_are_the_notes(built):
    project, content, doc, rect = built
    on_sheet = sorted(_sheet_arms(doc, rect))
    scene = content.figures["kst_lever"].scene
    in_figure = sorted(e.length for e in scene.entities if isinstance(e, Segment) and e.id.startswith("arm:"))
    assert len(on_sheet) == len(in_figure) and on_sheet, (on_sheet, in_figure)
    assert np.allclose(on_sheet, in_figure, atol=1e-6), (on_sheet, in_figure)
    printed = _printed_arms(content)
    assert printed
    half = project.kinetostatics.graphical.reading_mm / 2      # the lever is read as a drawing: 0,1 mm
    for h, mm in printed.items():
        if mm > UNDRAWN_ARM_MM + 0.01:
            assert any(abs(x - mm) <= half + 1e-9 for x in on_sheet), (h, mm, on_sheet)
    for x in on_sheet:     # each drawn arm is a printed one, as the note read it (0,1 mm)
        assert any(abs(x - mm) <= half + 1e-9 for mm in printed.values()), (x, printed)


def test_the_note_says_the_lever_is_reduced_where_it_is(built):
    project, content, _, _ = built
    fig = content.figures["kst_lever"]
    note = str(content.context["fig_note"]["kst_lever"])
    sheet = "1" if project.task.document.kind == "control-work" else "2"
    assert note.rstrip().endswith(sheet), note
    assert (fig.reportgen_reduction < 1.0) == ("уменьш" in note or "зменш" in note or "reduced" in note), note


def _finer(mu: float) -> float:
    """The next finer round scale of the plans' series (a drawing one step larger)."""
    k = math.floor(math.log10(mu)) + 1
    cands = [m * 10.0 ** e for e in range(k - 2, k + 1) for m in PLAN_SERIES]
    return max(c for c in cands if c < mu * (1 - 1e-9))


def _lever_panel_at(project, mu_v: float):
    from drawings.scenes import kinetostatics_views as kv
    from reportgen.kinetostatics.graphical import lever_graphic
    from reportgen.scenes.lever import lever_scene
    ks = project.kinetostatics
    g = ks.graphical
    lev = lever_graphic(ks.lever, ks.reactions, 0, g.reading_mm, mu_v)
    return kv.lever_panel("lever", lever_scene(dataclasses.replace(ks, graphical=dataclasses.replace(g, lever=lev)),
                                               project.linkage))


def test_finer_golden():
    assert _finer(0.005) == pytest.approx(0.004)
    assert _finer(0.01) == pytest.approx(0.005)
    assert _finer(0.004) == pytest.approx(0.0025)
    assert _finer(0.1) == pytest.approx(0.05)


@pytest.mark.parametrize("example", SHEET2_EXAMPLES)
def test_the_lever_fills_the_room_sheet_2_gives_it(example):
    project = example_project(example)
    mu = project.kinetostatics.graphical.lever.scale
    assert sheet2.lever_fits(project, sheet2.lever_panel_of(project))
    assert not sheet2.lever_fits(project, _lever_panel_at(project, _finer(mu))), \
        f"{example}: the lever would fit at μv = {_finer(mu):g} (drawn at {mu:g})"


def test_the_control_works_lever_takes_its_room():
    """On the control work's A1 sheet the lever's plan spans at least half of the box the sheet gives it
    (``SceneBoxes.lever_control``) one way (on main: 0,1 (м/с)/мм, 137 × 99 mm of 300 × 250)."""
    from reportgen.scenes.boxes import DEFAULT
    from reportgen.kinetostatics.graphical import lever_scale
    project = example_project("control-work")
    ks = project.kinetostatics
    box = DEFAULT.lever_for(project.task)
    assert box == DEFAULT.lever_control
    mu = ks.graphical.lever.scale
    assert mu == lever_scale(ks.lever, ks.reactions, 0, box)
    scene = _lever_panel_at(project, mu)
    assert scene.width - 24.0 >= 0.5 * box[0] or scene.height >= 0.5 * box[1], (scene.width, scene.height)


def test_the_a3_control_sheet_draws_the_notes_lever(tmp_path):
    """The control work on A3: the sheet's lever is at the μv the note prints, with the note's arms (on
    main the A3 sheet redrew the lever at a μv of its own, 0,2 (м/с)/мм, while the note printed 0,1)."""
    import ezdxf

    from reportgen.project import Project
    from reportgen.taskfile import load_task
    from scene_readback import ROOT
    text = (ROOT / "examples" / "control-work" / "task.toml").read_text(encoding="utf-8")
    assert '\nsheet = "A1"' in text
    task = tmp_path / "task.toml"
    task.write_text(text.replace('\nsheet = "A1"', '\nsheet = "A3"').replace("#:schema ../task.schema.json", ""),
                    encoding="utf-8")
    project = Project(load_task(task))
    content = part.content(project)
    drawn = control_sheet.draw(project, 1, 1)
    drawn.save(tmp_path / "s.dxf")
    doc = ezdxf.readfile(tmp_path / "s.dxf")
    rect = drawn.views["lever"].rect
    assert content.context["lever"]["mu_v"].value == pytest.approx(_sheet_mu_v(doc, rect), rel=1e-12)
    on_sheet = sorted(_sheet_arms(doc, rect))
    printed = _printed_arms(content)
    half = project.kinetostatics.graphical.reading_mm / 2      # read as a drawing, to 0,1 mm
    assert on_sheet and all(any(abs(x - mm) <= half + 1e-9 for mm in printed.values()) for x in on_sheet), \
        (on_sheet, printed)


@pytest.mark.parametrize("example", EXAMPLES)
def test_equal_arms_are_drawn_and_named_once(example):
    """Forces on one line of action have one arm: it is drawn once and named once, «h_{1} = h_{9}»
    (on main the press's F_пс and F_и5, G3 and G4 had two arm segments on one spot and two names
    on them); every arm name of the equation is on the figure."""
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings
    project = example_project(example)
    with active_strings(Strings(project.task.document.language or "ru")):
        content = part.content(project)
    scene = content.figures["kst_lever"].scene
    feet = [np.asarray(e.b) for e in scene.entities if isinstance(e, Segment) and e.id.startswith("arm:")]
    same = [(i, j) for i in range(len(feet)) for j in range(i + 1, len(feet)) if np.hypot(*(feet[i] - feet[j])) < 0.01]
    assert not same, same
    names = [lb.text for lb in scene.labels if lb.anchor.startswith("arm:")]
    on_figure = {h.strip() for text in names for h in text.split("=")}
    printed = {h for h, mm in _printed_arms(content).items() if mm > UNDRAWN_ARM_MM + 0.01}
    assert printed <= on_figure, printed - on_figure
    if example in ("press", "shaper", "crank-slider"):          # F_пс and F_и at the slider's image
        assert any("=" in t for t in names), names
