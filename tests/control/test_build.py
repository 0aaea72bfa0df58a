"""`reportgen new` → `reportgen build`: the control-work note and its one sheet, for two kinds of
scheme (a bar on the rocker; a triangular rocker whose crank cannot turn fully, on A3)."""
from __future__ import annotations

import json
import re
import shutil
import subprocess

import pytest

from reportgen.cli import main
from reportgen.control.analysis import control_work_of
from reportgen.project import Project
from reportgen.taskfile import load_task


def _new(tmp_path, table: int, variant: int, a3: bool = False):
    task = tmp_path / f"t{table}.toml"
    assert main(["new", "--table", str(table), "--variant", str(variant), "-o", str(task)]) == 0
    if a3:
        task.write_text(task.read_text(encoding="utf-8").replace('sheet = "A1"', 'sheet = "A3"'), encoding="utf-8")
    return task


def test_new_build_without_latex(tmp_path):
    task = _new(tmp_path, 22, 3, a3=True)
    out = tmp_path / "out"
    assert main(["build", str(task), "-o", str(out), "--no-pdf", "--quiet"]) == 0
    assert sorted(p.name for p in (out / "sheets").iterdir()) == ["sheet1-control.dxf", "sheet1-control.png"]
    tex = (out / "report.tex").read_text(encoding="utf-8")
    assert "реконструирована" in tex and "Задание на контрольную работу" in tex
    assert "Реакции в~кинематических парах" not in tex        # a control work has no reactions
    # issue 12: the introduction and the plans speak of a control work, not of a course project
    # with force polygons, several sheets and strokes (nothing the control work has)
    intro = tex[tex.index("Объект"):tex.index("\\section", tex.index("Объект"))]
    assert "Объект контрольной работы" in intro and "на~листе графической" in intro
    for absent in ("проект", "планов сил", "на~листах"):
        assert absent not in intro, absent
    assert "рабочий ход)" not in tex and "холостой ход)" not in tex
    import ezdxf
    doc = ezdxf.readfile(out / "sheets" / "sheet1-control.dxf")
    xs = [x for e in doc.modelspace().query("LINE") for x in (e.dxf.start.x, e.dxf.end.x)]
    assert 390.0 < max(xs) - min(xs) <= 420.0                    # A3 (420 × 297), not A1 (841)
    r = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert r["kinetostatics"]["phi_deg"] == pytest.approx(100.0)


@pytest.mark.parametrize("a3", [False, True], ids=["A1", "A3"])
def test_the_sheet_names_the_given_position_not_a_number(tmp_path, a3):
    """A control work has one position: its sheet's plan titles and table «Масштабы» say «заданного
    положения» (on A1 they printed «План скоростей положения 0», «план … положения 0»)."""
    import ezdxf
    task = _new(tmp_path, 4, 1, a3=a3)
    out = tmp_path / "out"
    assert main(["build", str(task), "-o", str(out), "--no-pdf", "--quiet"]) == 0
    doc = ezdxf.readfile(out / "sheets" / "sheet1-control.dxf")
    texts = [e.dxf.text if e.dxftype() == "TEXT" else e.text for e in doc.modelspace().query("TEXT MTEXT")]
    assert not [t for t in texts if re.search(r"положени[яей]\s*\d", t)], texts
    assert "План скоростей" in texts and "План ускорений" in texts
    if not a3:                                                   # A1 has the table «Масштабы»
        assert "план скоростей заданного положения" in texts


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("latexmk") is None, reason="LaTeX is not installed")
def test_new_build_pdf_prints_the_answers(tmp_path):
    task = _new(tmp_path, 1, 1)
    out = tmp_path / "out"
    assert main(["build", str(task), "-o", str(out), "--quiet"]) == 0
    text = subprocess.run(["pdftotext", "-layout", str(out / "report.pdf"), "-"], capture_output=True,
                          text=True).stdout
    res = control_work_of(Project(load_task(str(task))))
    from latex_templates.numbers import num
    for needle in ("ЗАДАНИЕ НА КОНТРОЛЬНУЮ РАБОТУ", "к контрольной работе", "реконструирована",
                   "Угловые скорости и угловые ускорения звеньев", "Рычаг Жуковского",
                   "по балансу мощностей", num(res.P_y, 5).replace("{,}", ","), "против часовой стрелки"):
        assert needle in text, needle
    assert "курсовому проекту" not in text
