"""Issue 16 item 1: a cold build's xelatex passes read their preambles early (docs/build.md).

Pass 1 starts before the solve on the preamble the note will have (``NoteBuilder.preamble``, made
from the document's settings only), pass 2 reads its preamble while pass 1 typesets; both only
save time, so what is checked is that the guess is right (else the early pass is thrown away) and
that the passes write the bytes latexmk writes."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from latex_templates import NoteBuilder
from latex_templates import passes
from latex_templates.note import Section
from latex_templates.render import Strings
from reportgen.commands import pipeline
from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
HAVE_TEX = all(shutil.which(p) for p in ("xelatex", "xdvipdfmx", "latexmk"))
needs_tex = pytest.mark.skipif(not HAVE_TEX, reason="TeX Live (xelatex, xdvipdfmx, latexmk) is not installed")
EXAMPLES = ["press", "press-en", "shaper-uk", "control-work", "class3"]


@pytest.mark.parametrize("example", EXAMPLES)
def test_the_preamble_made_before_the_sections_is_the_one_report_tex_gets(example, tmp_path):
    """The preamble is the document's settings, the language's words and the designation: the
    note rendered with sections (a formula, a table, a figure-free body) has that very text up to
    ``\\begin{document}`` — for each language and for the control work's catalogue overlay."""
    task = load_task(ROOT / "examples" / example / "task.toml")
    designation = Strings(task.document.language or "ru").designation(task.document)
    early = NoteBuilder(task.document, designation=designation).preamble()
    note = NoteBuilder(task.document, designation=designation, introduction=["Введение."],
                       conclusions=["Вывод."], references=["Источник."])
    note.add_section(Section(key="a", title="Раздел", body="Текст $x = 1$.\n\\begin{tabular}{l}a\\\\\\end{tabular}\n"))
    written = passes.split_note(note.render(tmp_path).read_text(encoding="utf-8"))
    assert early is not None and written is not None
    assert early == written[0]
    assert early.endswith("\\begin{document}\n")


def test_a_note_in_another_language_has_another_preamble():
    """The comparison the build makes is not vacuous: the language changes the preamble."""
    task = load_task(ROOT / "examples" / "press" / "task.toml")
    ru = NoteBuilder(task.document, designation="X").preamble()
    en = NoteBuilder(task.document, language="en", designation="X").preamble()
    assert ru != en


@pytest.mark.slow
@needs_tex
def test_a_cold_build_starts_its_first_pass_before_the_solve(tmp_path):
    """``pipeline._start_cold_latex``: a split first pass on the note's preamble (no auxiliary
    files restored); none for a task without the course project's note."""
    project = Project(load_task(ROOT / "examples" / "press" / "task.toml"))
    started = pipeline._start_cold_latex(project, tmp_path)
    try:
        assert started is not None and started.restored is False
        assert started.preamble == NoteBuilder(project.task.document, designation=Strings("ru").designation(
            project.task.document)).preamble()
        assert (tmp_path / "latex-build" / passes.PREAMBLE_FILE).is_file()
    finally:
        started.cancel()
    assert not (tmp_path / "latex-build" / passes.PREAMBLE_FILE).exists()
    crane = Project(load_task(ROOT / "examples" / "crane-hoist" / "task.toml"))
    assert pipeline._start_cold_latex(crane, tmp_path / "crane") is None


TOC_NOTE = ("\\documentclass{article}\n\\begin{document}\n\\tableofcontents\n\\section{One}\\label{a}\n"
            "See page \\pageref{b}.\\clearpage\n\\section{Two}\\label{b}\nSee page \\pageref{a}.\n\\end{document}\n")


@pytest.mark.slow
@needs_tex
def test_a_cold_drive_runs_its_second_pass_read_early_and_writes_latexmk_s_pdf(tmp_path):
    """No auxiliary files: pass 2 is begun ahead while pass 1 runs, in its own folder
    (:class:`passes._Standby`), and goes on after it; the PDF and the auxiliary files are latexmk's
    bytes, and the pass's folder is gone."""
    env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", FORCE_SOURCE_DATE="1")
    for name in ("drive", "latexmk"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "n.tex").write_text(TOC_NOTE, encoding="utf-8")
        (tmp_path / name / "b").mkdir()
    proc = subprocess.run([sys.executable, str(Path(passes.__file__)), "n.tex", "b"], cwd=tmp_path / "drive",
                          input=passes.SAME_BOXES, capture_output=True, env=env)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.decode().splitlines().count(passes.PASS_LINE) == 2
    subprocess.run(["latexmk", "-xelatex", "-interaction=nonstopmode", "-halt-on-error", "-outdir=b", "n.tex"],
                   cwd=tmp_path / "latexmk", env=env, capture_output=True, check=True)
    drive, mk = tmp_path / "drive" / "b", tmp_path / "latexmk" / "b"
    assert not (drive / passes.STANDBY_DIR).exists()
    for name in ("n.pdf", "n.aux", "n.toc"):
        assert (drive / name).read_bytes() == (mk / name).read_bytes(), name
