"""Sheet 3 for a machine whose reduced inertia dwarfs its work: the press with every length × 100 and
its masses kept (J_red × 10⁴, ΔE × 100). The Wittenbauer tangents stood at ψ ≈ 86°, K and L were
0.3 and 1.3 m below the ΔE axis at μE = μA, and sheet 3's layout refused the task (exit 1, «a limit
of reportgen's sheet layout»). Cause: μE was chosen to fit the ΔE(φ) curve only, as if K, L and the
tangents stood within the curve's magnitude; now μE is also large enough (a reduction k = 1/n) that
the whole Wittenbauer construction fits ``GraphLayout.w_height``, which sheet 3 has room for.

Every ordinate of the construction is ∝ 1/μE at a fixed μJ, so the rule holds for any mechanism:
the property test scales lengths and masses over four decades each."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, strategies as st

from drawings.primitives import format_number
from drawings.sheet import Sheet
from drawings.scenes import dynamics_diagrams as dd
from drawings.sheets import dynamics
from latex_templates.parts import dynamics as part
from reportgen.dynamics.graphical import ENLARGE, tangent_slopes, wittenbauer_height
from reportgen.project import Project
from reportgen.scenes.boxes import DEFAULT
from reportgen.taskfile import loads_task

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from robustness.scaling import Factors, robustness_settings, scaled  # noqa: E402
from robustness.sheetcheck import outside_frame, overlaps  # noqa: E402

LAY = DEFAULT.diagrams


def _project(k: float, m: float = 1.0) -> Project:
    return Project(loads_task(scaled("press", Factors(k=k, m=m), drop=("gears", "planetary"))))


def _height(g) -> float:
    tmax, tmin = (math.tan(math.radians(a)) for a in (g.psi_max_deg, g.psi_min_deg))
    return wittenbauer_height(np.asarray(g.e_mm), np.asarray(g.j_mm), tmax, tmin)


def test_press_lengths_x100_masses_kept_draws_sheet_3():
    project = _project(100.0)
    g = project.dynamics.graphical
    assert g.enlargement < 1 and 1.0 / g.enlargement == 20.0           # μE = 20·μA
    assert g.mu_E == pytest.approx(20.0 * g.mu_A, rel=1e-12)
    assert g.psi_max_deg < 45.0                                          # was 85.9°
    assert _height(g) <= LAY.w_height
    sheet = dynamics.draw(project, 3, 4)
    assert sheet.overlaps() == []
    assert outside_frame(sheet) == []
    texts = {e.dxf.text for e in sheet.msp if e.dxftype() == "TEXT"}
    assert any("(уменьшено в 20 раз)" in t for t in texts), "the ΔE(φ) scale says it is reduced"
    # KL on the sheet is the replica's, and J_fly read from it is the replica's
    kl = [d for d in sheet.msp if d.dxftype() == "DIMENSION" and d.dxf.text == format_number(g.KL_mm, 1)]
    assert kl
    p, q = kl[0].dxf.defpoint2, kl[0].dxf.defpoint3
    assert math.hypot(p[0] - q[0], p[1] - q[1]) == pytest.approx(g.KL_mm, abs=1e-6)
    # the note writes the reduction as μE = μA·n and its record holds
    c = part.scale_records(project.scenes.dynamics)
    assert c["mu_E"].value == pytest.approx(g.mu_E, rel=1e-12) and c["n"].value == 20.0


def test_the_examples_keep_their_enlargement():
    """The rule adds a reduction only where the construction would not fit: the press keeps μE = μA."""
    g = _project(1.0).dynamics.graphical
    assert g.enlargement == 1 and isinstance(g.enlargement, int)
    assert g.enlargement in ENLARGE


def test_sheet_3_has_room_for_w_height():
    """GraphLayout.w_height (+ the spans' 4 mm margins) fits sheet 3 above J_red(φ): the layout
    never refuses a construction the replica has fitted to w_height."""
    sheet = Sheet.a1(_project(1.0).task.document, title="", code="", number=3, count=4)
    fr = sheet.frame
    room = (sheet.extra_rect.y0 - dynamics.CLEAR_MM) - (fr.y0 + dynamics.CLEAR_MM)
    j_height = dd.J_TOP_MM + LAY.phi_axis + dd.J_BOTTOM_MM
    assert LAY.w_height + 8.0 + dd.TOP_MM + dd.BOTTOM_MM + dd.GAP_MM + j_height <= room


def test_sheet_3_column_has_room_for_column_height():
    """GraphLayout.column_height (M, A, ΔE) + ω(φ) at its largest (2·omega_height) + four titles,
    margins and gaps + the names of the break positions (≤ 6 letters: «к.р.х.», «e.w.s.») fit sheet 3's
    left column."""
    sheet = Sheet.a1(_project(1.0).task.document, title="", code="", number=3, count=4)
    fr = sheet.frame
    room = (sheet.extra_rect.y0 - dynamics.CLEAR_MM) - (fr.y0 + dynamics.CLEAR_MM)
    names = 6 * 2.6 + 6.0                                       # dynamics_diagrams.spans()
    fixed = 4 * (dd.TOP_MM + dd.BOTTOM_MM + 8.0) + names + 3 * dd.GAP_MM
    assert LAY.column_height + 2 * LAY.omega_height + fixed <= room


def test_conveyor_force_x8_column_fits():
    """Conveyor with lengths × 0.365 and its force × 8.5: M, A and ΔE each filled their box and the
    column ran 18 mm under the frame (ω(φ) outside it). Now μM is one round step coarser."""
    project = Project(loads_task(scaled("conveyor", Factors(k=0.3654892944104133, f=8.527420119552934),
                                        drop=("gears", "planetary"))))
    g = project.dynamics.graphical
    sheet = dynamics.draw(project, 3, 4)
    assert sheet.overlaps() == [] and outside_frame(sheet) == []
    assert g.mu_M == 20.0           # 10 fills the box of M alone


@robustness_settings(6)
@given(k=st.floats(0.01, 100.0), m=st.floats(0.01, 100.0))
def test_the_construction_fits_for_any_lengths_and_masses(k, m):
    project = _project(k, m)
    g = project.dynamics.graphical
    assert _height(g) <= LAY.w_height * (1 + 1e-9)
    # the tangents as the course draws them, at the chosen μE
    tmax, tmin = tangent_slopes(g.mu_J, g.mu_E, 18.0, 0.05)
    assert math.degrees(math.atan(tmax)) == pytest.approx(g.psi_max_deg, rel=1e-12)
    sheet = dynamics.draw(project, 3, 4)                  # the layout raised BuildError here
    assert overlaps(sheet) == [] and outside_frame(sheet) == []


@pytest.mark.parametrize("lang, words", [("ru", "с~уменьшением в~20~раз"), ("uk", "зі~зменшенням у~20~разів"),
                                         ("en", "drawn reduced 20~times")])
def test_the_note_says_the_energy_graph_is_reduced(tmp_path, lang, words):
    """Section 3 of the press × 100 (masses kept) in each language: the sentence of the reduction,
    μE = μA·n as a record, and every record re-evaluates from its printed numbers."""
    from latex_templates import NoteBuilder
    from latex_templates.compose import compose
    from latex_templates.render import Strings
    from reportgen.calc import evaluate_displayed

    text = scaled("press", Factors(k=100.0), drop=("gears", "planetary"))
    assert 'language = "ru"' in text
    project = Project(loads_task(text.replace('language = "ru"', f'language = "{lang}"')))
    sections, _ = compose(project, Strings(lang), only=("linkage", "dynamics"))
    note = NoteBuilder(project.task.document)
    for s in sections:
        note.add_section(s.section)
    tex = note.render(tmp_path).read_text(encoding="utf-8")
    assert words in tex
    assert all(evaluate_displayed(rec).ok for rec in note.records)
