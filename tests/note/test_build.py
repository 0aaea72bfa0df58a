"""Building the note with xelatex: text of the PDF, reproducibility, and the error paths."""
from __future__ import annotations

import shutil
import subprocess
import unicodedata

import pytest

from reportgen.calc import evaluate_displayed
from reportgen.errors import BuildError

from latex_templates import build_pdf

from .sample import NASTY_TITLE, sample_note

needs_tex = pytest.mark.skipif(
    not (shutil.which("latexmk") and shutil.which("xelatex") and shutil.which("pdftotext")),
    reason="TeX Live (latexmk, xelatex) and poppler-utils are not installed")
pytestmark = pytest.mark.slow


def pdf_text(pdf) -> str:
    """The PDF's text, NFKC-normalised: xdvipdfmx maps Liberation's ';' glyph to U+037E (Greek
    question mark, canonically equal to ';')."""
    out = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], check=True,
                         capture_output=True, text=True).stdout
    return unicodedata.normalize("NFKC", out)


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("note")
    note = sample_note(tmp)
    report = note.build(tmp / "out")
    return note, report


@needs_tex
def test_sample_note_builds_and_reads_as_a_note(built):
    note, report = built
    text = pdf_text(report.pdf)
    flat = " ".join(text.split())
    for heading in ("СОДЕРЖАНИЕ", "ВВЕДЕНИЕ", "1 Кинематический анализ", "1.1 Скорости",
                    "ЗАКЛЮЧЕНИЕ", "СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ", "ПОЯСНИТЕЛЬНАЯ ЗАПИСКА"):
        assert heading in flat, heading
    assert NASTY_TITLE in flat                 # the title prints literally
    assert "Рисунок 1.1 — Перемещение ползуна" in flat
    assert "Таблица 1.1 — Скорости точек" in flat
    assert "Продолжение таблицы 1.1" in flat    # the long table broke across pages
    assert "1,98 м/с" in flat and "0,4453 м" in flat and "(1.1)" in flat and "(1.3)" in flat
    assert "где ω1 — угловая скорость кривошипа, рад/с;" in flat
    assert "формуле (1.1)" in flat and "рисунке 1.1" in flat
    assert "??" not in text
    assert "ТММ.КП.01.00.000 ПЗ" in flat         # the title block of the frame
    assert report.warnings == ()
    assert report.seconds > 0


@needs_tex
def test_every_printed_record_reproduces_its_printed_result(built):
    note, _ = built
    assert len(note.records) == 3
    for rec in note.records:
        assert evaluate_displayed(rec).ok, rec


@needs_tex
def test_two_builds_give_identical_pdfs(built, tmp_path):
    note, report = built
    again = sample_note(tmp_path).build(tmp_path / "again")
    assert again.pdf.read_bytes() == report.pdf.read_bytes()


@needs_tex
def test_latex_error_names_the_line_and_keeps_the_source(tmp_path):
    note = sample_note(tmp_path, body_template="Текст \\undefinedmacro{x}\n")
    with pytest.raises(BuildError) as info:
        note.build(tmp_path / "out")
    msg = str(info.value)
    assert "! Undefined control sequence." in msg
    assert "l." in msg and "\\undefinedmacro" in msg
    assert str(tmp_path / "out" / "report.tex") in msg and "report.log" in msg
    assert (tmp_path / "out" / "report.tex").is_file()


@needs_tex
def test_unresolved_reference_is_an_error_or_a_warning(tmp_path):
    note = sample_note(tmp_path, body_template="См. формулу~\\eqref{eq:nowhere}.\n")
    with pytest.raises(BuildError, match="unresolved references"):
        note.build(tmp_path / "strict")
    report = note.build(tmp_path / "lax", strict_references=False)
    assert any("eq:nowhere" in w for w in report.warnings)


def test_without_tex_the_error_says_how_to_install_and_keeps_the_source(tmp_path):
    note = sample_note(tmp_path, body_template="Текст.\n")
    with pytest.raises(BuildError) as info:
        note.build(tmp_path / "out", latexmk=str(tmp_path / "no" / "latexmk"))
    msg = str(info.value)
    assert "apt-get install" in msg and "texlive-xetex" in msg
    assert info.value.stage == "note (LaTeX)"
    assert (tmp_path / "out" / "report.tex").is_file() and "report.tex" in msg


def test_build_pdf_of_a_missing_latexmk_does_not_touch_the_file(tmp_path):
    tex = tmp_path / "x.tex"
    tex.write_text("\\documentclass{article}\\begin{document}x\\end{document}\n")
    with pytest.raises(BuildError):
        build_pdf(tex, latexmk="definitely-not-latexmk")
    assert tex.read_text().startswith("\\documentclass")
