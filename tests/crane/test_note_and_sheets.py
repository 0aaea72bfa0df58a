"""The crane note and sheets: every printed formula re-evaluates, every symbol is explained, the
sections are in the course's order, the sheets show the note's numbers and overlap nothing."""
from __future__ import annotations

import json
import shutil
import subprocess

import pytest

from reportgen.calc import evaluate_displayed
from reportgen.crane.steps import shown
from reportgen.project import Project

from .helpers import EXAMPLE, example_task


@pytest.fixture(scope="module")
def project():
    return Project(example_task())


@pytest.fixture(scope="module")
def rendered(project, tmp_path_factory):
    from latex_templates.parts.crane_document import note_builder
    out = tmp_path_factory.mktemp("crane-note")
    note = note_builder(project)
    tex = note.render(out).read_text(encoding="utf-8")
    return note, tex


def test_sections_in_the_order_of_the_course(rendered):
    note, tex = rendered
    assert [s.key for s in note.sections] == ["hoist", "trolley"]
    order = ["Выбор каната и~полиспаста", "Блоки", "Барабан", "Выбор двигателя", "Выбор передачи",
             "Проверка двигателя", "Выбор муфт", "Выбор тормоза", "Колёса и~рельс",
             "Сопротивление передвижению", "Проверка запаса сцепления приводных колёс"]
    positions = [tex.index("\\subsection{" + title + "}") for title in order]
    assert positions == sorted(positions)


def test_every_printed_formula_reevaluates_and_every_symbol_is_explained(rendered, project):
    note, tex = rendered
    assert note.records, "the note prints records"
    assert all(evaluate_displayed(r).ok for r in note.records)
    assert note.symbols.unexplained == set()
    printed = {r.symbol for r in note.records}
    for _, mech in project.crane.mechanisms:
        for key in ("M_nom", "M_st", "v_act"):
            assert mech.records[key].symbol in printed


def test_title_page_and_references_are_the_cranes(rendered):
    _, tex = rendered
    assert "«Грузоподъёмные машины»" in tex
    assert "ПБ 10-382-00" in tex and "Казака" in tex
    assert "теории механизмов" not in tex


def test_check_sentences_print_the_checked_numbers(rendered, project):
    _, tex = rendered
    c = project.crane.hoist.check("rope")
    assert "Условие прочности каната" in tex
    assert r"782\,500 \ge F_{\text{тр}} = 667\,243" in tex
    assert c.passed and "не~выполняется" not in tex


def test_a_check_prints_the_quantity_as_its_formula_did(rendered):
    """Issue 12: one quantity, one rounding — (1.6) ends «D_бл = … = 1130,5 мм», so its check reads
    «D_бл = 1130,5 ≥ …», not «1130»; (1.13) «l_0max = … = 1187,6 мм», its check «≤ l_0max = 1187,6»."""
    _, tex = rendered
    assert r"D_{\text{бл}} = 1130{,}5 \ge" in tex
    assert r"l_{0\max} = 1187{,}6~\text{мм}$~---" in tex


def test_a_failed_check_prints_the_advice(project, tmp_path):
    import dataclasses as dc
    from latex_templates.parts.crane_document import note_builder
    task = example_task()
    rope = dc.replace(task.crane.hoist.rope, breaking_force_kn=600.0)
    crane = dc.replace(task.crane, hoist=dc.replace(task.crane.hoist, rope=rope))
    tex = note_builder(Project(dc.replace(task, crane=crane))).render(tmp_path).read_text(encoding="utf-8")
    assert "не~выполняется. Рекомендация: выбрать канат с~разрывным усилием не~менее 667{,}2~кН" in tex
    assert "Не~выполнены проверки: прочности каната." in tex


def test_sheets_show_the_notes_numbers_and_overlap_nothing(project):
    from drawings.sheets import available_sheets
    todo = available_sheets(project)
    assert [stem for stem, _ in todo] == ["sheet1-crane_hoist", "sheet2-crane_trolley"]
    texts = {}
    for i, (stem, mod) in enumerate(todo, start=1):
        sheet = mod.draw(project, i, len(todo))
        assert sheet.overlaps() == [], stem
        texts[stem] = " | ".join(e.dxf.text for e in sheet.msp.query("TEXT"))
    h, t = project.crane.hoist.records, project.crane.trolley.records
    for key in ("S_max", "F_req", "D_bl", "D_c", "L_dr", "eta_p"):
        assert shown(h[key]) in texts["sheet1-crane_hoist"], key
    assert f"vф = {shown(h['v_act'])} м/с" in texts["sheet1-crane_hoist"]
    for key in ("W_st", "k_sp", "k_sb", "T_br", "v_act"):
        assert shown(t[key]) in texts["sheet2-crane_trolley"], key


def test_results_json_has_the_crane_block(project):
    from reportgen.results import build_results
    res = build_results(project)
    assert set(res) == {"format", "crane"}
    assert res["crane"]["hoist"]["values"]["G"]["value"] == pytest.approx(2_061_921.75)
    assert {c["key"] for c in res["crane"]["trolley"]["checks"]} >= {"adhesion_start", "adhesion_brake"}


@pytest.mark.skipif(shutil.which("latexmk") is None, reason="no TeX")
def test_build_writes_note_sheets_and_results(tmp_path):
    from reportgen.cli import main
    out = tmp_path / "out"
    assert main(["build", str(EXAMPLE), "-o", str(out), "--quiet"]) == 0
    assert (out / "report.pdf").is_file()
    assert sorted(p.name for p in (out / "sheets").iterdir()) == [
        "sheet1-crane_hoist.dxf", "sheet1-crane_hoist.png", "sheet2-crane_trolley.dxf", "sheet2-crane_trolley.png"]
    res = json.loads((out / "results.json").read_text(encoding="utf-8"))
    text = subprocess.run(["pdftotext", "-layout", str(out / "report.pdf"), "-"], capture_output=True,
                          text=True, check=True).stdout
    s_max = res["crane"]["hoist"]["values"]["S_max"]["value"]
    assert f"{round(s_max):,}".replace(",", "\u2009") in text or f"{round(s_max):,}".replace(",", " ") in text
    assert "Грузоподъёмные машины" in text and "ГПМ.КП.00.00.000 ПЗ" in text
