"""Section 4 of the note (parts gear_pair, planetary) and sheet 4 (drawings/sheets/gears.py)."""
from __future__ import annotations

import math
import re
import shutil
import subprocess
import unicodedata
from pathlib import Path

import ezdxf
import pytest

from drawings.sheets import gears as gear_sheet
from latex_templates import NoteBuilder
from latex_templates.compose import compose
from latex_templates.parts import gear_pair as gear_part
from latex_templates.render import Strings
from reportgen.calc import evaluate_displayed
from reportgen.project import Project
from reportgen.results import build_results
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
def _russian(path) -> bool:
    """The examples written in Russian (these tests read Russian text; tests/lang covers uk and en)."""
    import tomllib
    return tomllib.loads(path.read_text(encoding="utf-8")).get("document", {}).get("language", "ru") == "ru"


EXAMPLES = [p.parent.name for p in sorted((ROOT / "examples").glob("*/task.toml"))
            if _russian(p) and re.search(r"^\[(gears|planetary)\]", p.read_text(encoding="utf-8"), re.M)]

GEAR_ONLY = """
[document]
title = "Синтез зубчатой передачи"
author = "А. А. Тестов"
group = "ТМ-00"

[gears]
z1 = 14
z2 = 35
module = 4.0
x1 = "auto"
x2 = "auto"

[planetary]
scheme = "two-row-ext-int"
ratio = 12.27
motor_rpm = 1500
module = 5.0
"""


def project_of(name: str) -> Project:
    return Project(load_task(str(ROOT / "examples" / name / "task.toml")))


def render_section(project: Project, out: Path) -> NoteBuilder:
    sections, _ = compose(project, Strings("ru"), only=("gears",))
    assert sections and sections[0].parts, "section 4 has no parts"
    note = NoteBuilder(project.task.document, conclusions=[c for s in sections for c in s.conclusions])
    for s in sections:
        note.add_section(s.section)
    note.render(out)
    return note


def test_examples_found():
    assert {"press", "crank-slider", "shaper"} <= set(EXAMPLES)


@pytest.mark.parametrize("name", EXAMPLES)
def test_section_renders_and_every_record_reevaluates(name, tmp_path):
    project = project_of(name)
    note = render_section(project, tmp_path)
    records = note.records
    assert len(records) > 40
    bad = [r.symbol for r in records if not evaluate_displayed(r).ok]
    assert not bad
    assert not note.symbols.unexplained, note.symbols.unexplained
    tex = (tmp_path / "report.tex").read_text(encoding="utf-8")
    assert "Проектирование эвольвентной зубчатой передачи" in tex
    assert "Синтез планетарного редуктора" in tex


@pytest.mark.parametrize("name", EXAMPLES)
def test_records_are_the_solver_numbers(name):
    pair = project_of(name).gears
    r = gear_part.gear_records(pair)
    g = pair.geometry
    for key in ("aw", "a", "y", "dy", "d1", "d2", "db1", "db2", "dw1", "dw2", "da1", "da2", "df1", "df2",
                "s1", "s2", "sa1", "sa2", "pb", "ab", "n1a", "n1b", "n1p"):
        assert math.isclose(r[key].value, getattr(g, key), rel_tol=1e-9, abs_tol=1e-9), key
    assert math.isclose(r["eps"].value, g.eps_alpha, rel_tol=1e-9)
    assert math.isclose(r["g"].value, g.g, rel_tol=1e-9)
    assert math.isclose(r["c_w"].value, g.c * g.m, rel_tol=1e-9)
    for line in gear_part.check_lines(pair, r):
        chk = pair.check(line.name)
        assert line.passed == chk.passed
        if line.name.startswith("undercut"):
            assert math.isclose(line.records[0].value, chk.limit, rel_tol=1e-9)
        if line.name.startswith("interference"):
            assert math.isclose(line.records[0].value, chk.limit, rel_tol=1e-9)
            assert math.isclose(line.records[-1].value, chk.value, rel_tol=1e-9)


def test_failed_check_is_stated_as_a_finding(tmp_path):
    from dataclasses import replace
    press = project_of("press")
    # the seed's pair against the default limit: εα = 1,152 < 1,2
    project = Project(replace(press.task, gears=replace(press.task.gears, eps_min=1.2)))
    assert not project.gears.check("contact_ratio").passed
    note = render_section(project, tmp_path)
    tex = (tmp_path / "report.tex").read_text(encoding="utf-8")
    assert r"\varepsilon_\alpha = 1{,}152 < [\varepsilon_\alpha] = 1{,}2" in tex
    assert "не~выполнено" in tex
    # … and the passing pair of the blocking contour with its numbers, in the text and the conclusions
    assert "Заданная пара смещений не~проходит проверку" in tex
    assert "$x_1 = 0{,}58$, $x_2 = 0{,}52$" in tex and r"\varepsilon_\alpha = 1{,}201 \ge 1{,}2" in tex
    assert any("0{,}58" in c and "0{,}52" in c for c in note.conclusions)


def _pdf_text(pdf: Path) -> str:
    text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True,
                          check=True).stdout
    return unicodedata.normalize("NFKC", text)


def _comma(value: float, decimals: int) -> str:
    return f"{value:.{decimals}f}".replace(".", ",").replace("-", "−")


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("latexmk") is None or shutil.which("pdftotext") is None,
                    reason="needs latexmk and pdftotext")
@pytest.mark.parametrize("name", ["press", "shaper"])
def test_pdf_has_the_key_numbers_of_results_json(name, tmp_path):
    project = project_of(name)
    note = render_section(project, tmp_path)
    report = note.build(tmp_path)
    text = _pdf_text(report.pdf)
    res = build_results(project)
    gears = res["gears"]
    for key in ("aw", "da1", "da2", "sa1"):
        assert _comma(gears[key], 3) in text, (key, gears[key])
    assert _comma(gears["eps_alpha"], 3) in text
    pl = res["planetary"]
    for zz in pl["z"]:
        assert re.search(rf"z\S* = {zz}\b", text), zz
    assert _comma(abs(pl["ratio"]), 4) in text


def _sheet(project: Project, tmp_path: Path):
    sheet = gear_sheet.draw(project, 4, 4)
    dxf = tmp_path / "sheet4.dxf"
    sheet.save(dxf)
    return sheet, dxf


@pytest.mark.parametrize("name", EXAMPLES)
def test_sheet_audit_and_no_overlaps(name, tmp_path):
    project = project_of(name)
    assert gear_sheet.available(project)
    sheet, dxf = _sheet(project, tmp_path)
    assert not sheet.overlaps(), sheet.overlaps()
    doc = ezdxf.readfile(dxf)
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]
    assert set(sheet.views) >= {"meshing", "sliding", "reducer_front", "reducer_side", "reducer_table"}
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    assert any("Картина зацепления  М " in t for t in texts)
    assert any(t.startswith("μv = ") for t in texts)
    assert "Синтез" in " ".join(sheet.title_block_texts())


@pytest.mark.slow
def test_librecad_draws_sheet4(tmp_path):
    from drawings.librecad import check_sheet, missing_tools
    if missing_tools():
        pytest.skip("needs " + ", ".join(missing_tools()))
    _, dxf = _sheet(project_of("press"), tmp_path)
    result = check_sheet(dxf, tmp_path / "lc")
    assert result.drawn


def test_gear_only_task_builds_section_and_sheet_without_the_linkage(tmp_path):
    task_file = tmp_path / "task.toml"
    task_file.write_text(GEAR_ONLY, encoding="utf-8")
    project = Project(load_task(str(task_file)))
    assert project.task.mechanism is None
    note = render_section(project, tmp_path / "note")
    assert len(note.records) > 40
    assert gear_sheet.available(project)
    sheet, dxf = _sheet(project, tmp_path)
    assert not sheet.overlaps(), sheet.overlaps()
    assert not ezdxf.readfile(dxf).audit().has_errors
    for stage in ("linkage", "structure", "model", "kinematics", "strokes"):
        assert stage not in project.__dict__, f"the linkage stage {stage} ran"


def test_sheet_halves_follow_the_task(tmp_path):
    only_gears = tmp_path / "g.toml"
    only_gears.write_text(GEAR_ONLY.split("[planetary]")[0], encoding="utf-8")
    project = Project(load_task(str(only_gears)))
    sheet = gear_sheet.draw(project, 1, 1)
    assert "meshing" in sheet.views and "reducer_front" not in sheet.views
    only_planetary = tmp_path / "p.toml"
    only_planetary.write_text(GEAR_ONLY.split("[gears]")[0] + "[planetary]" + GEAR_ONLY.split("[planetary]")[1],
                              encoding="utf-8")
    project = Project(load_task(str(only_planetary)))
    sheet = gear_sheet.draw(project, 1, 1)
    assert "reducer_side" in sheet.views and "meshing" not in sheet.views
    assert not sheet.overlaps(), sheet.overlaps()
    from reportgen.zoo import four_bar  # a linkage only: no gear sheet
    nothing = tmp_path / "n.toml"
    nothing.write_text(four_bar(0.1, 0.3, 0.25, 0.3, phi_deg=30, omega=10), encoding="utf-8")
    assert not gear_sheet.available(Project(load_task(str(nothing))))
