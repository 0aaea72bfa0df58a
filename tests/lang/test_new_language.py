"""`reportgen new --language L` (issue 12): a new task file — a control-work variant, a course project
or the crane copied from an example — carries its [document] in L, so that the note's title page and
the sheets' title blocks have no word of another language: no Cyrillic in English, no Russian-only
letter (ы, э, ъ, ё) in Ukrainian, no Ukrainian-only letter (і, ї, є, ґ) in Russian. Before, `new`
wrote «Кафедра теории механизмов и машин» and a Cyrillic designation whatever the language (and had
no --language); and a task that left [document] title or code out printed the Russian default title
on an English title page and the Cyrillic default code on the English control sheet."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from reportgen.cli import main
from reportgen.commands.new import example_names
from reportgen.task import Document
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
FOREIGN = {"en": re.compile("[\u0400-\u04FF]"), "uk": re.compile("[ыэъёЫЭЪЁ]"), "ru": re.compile("[іїєґІЇЄҐ]")}
SOURCES = [("control", ("--table", "1", "--variant", "1")), ("control-t14", ("--table", "14", "--variant", "2"))] + \
    [(name, ("--example", name)) for name in example_names()]


def _foreign(text: str, language: str) -> list[str]:
    return FOREIGN[language].findall(text)


def _new(tmp_path: Path, args: tuple[str, ...], language: str) -> Path:
    path = tmp_path / f"new-{language}.toml"
    assert main(["new", *args, "--language", language, "-o", str(path)]) == 0
    return path


@pytest.mark.parametrize("language", ["ru", "uk", "en"])
@pytest.mark.parametrize("source, args", SOURCES, ids=[s for s, _ in SOURCES])
def test_new_writes_the_document_in_its_language(tmp_path, source, args, language):
    from latex_templates.render import Strings
    from reportgen.crane import crane_code

    task = load_task(_new(tmp_path, args, language))
    doc = task.document
    assert doc.language == language
    strings = Strings(language)
    crane = task.kind == "crane"
    key = ("document_defaults.crane_title" if crane else
           "control.sheet.title" if doc.kind == "control-work" else "document_defaults.title")
    printed = [strings.titled(doc, key).title, doc.university, doc.organization, doc.author, doc.group,
               doc.supervisor, doc.city]
    if crane:
        code = crane_code(doc, str(strings.raw("crane.sheet.default_code")))
        printed += [code + str(strings.raw("designation.note_suffix")), f"{code}.001"]
    else:
        printed += [strings.designation(doc), strings.designation(doc, 1)]
    if task.mechanism is not None and task.mechanism.name:
        printed.append(task.mechanism.name)
    bad = {s: _foreign(s, language) for s in printed if _foreign(s, language)}
    assert not bad, bad
    if doc.kind == "control-work":
        assert doc.code != Document().code            # a control work's own designation (КР / CW)
        assert doc.code.startswith("TMM.CW." if language == "en" else "ТММ.КР.")


def test_an_example_in_its_own_language_is_copied_byte_for_byte(tmp_path):
    for name, lang in (("press", "ru"), ("press-en", "en"), ("shaper-uk", "uk")):
        path = _new(tmp_path, ("--example", name), lang)
        assert path.read_bytes() == (ROOT / "examples" / name / "task.toml").read_bytes()
        path.unlink()


def test_the_title_left_out_is_the_languages(tmp_path):
    """A task without [document] title: the title page says the language's default title."""
    from latex_templates.note import NoteBuilder

    for language in ("uk", "en"):
        for kind, word in (("", {"uk": "Проєктування", "en": "Design"}), ("control-work", {"uk": "Кінематичний",
                                                                                        "en": "Kinematic"})):
            note = NoteBuilder(Document(language=language, kind=kind))
            tex = note.render(tmp_path / f"{language}{kind}").read_text(encoding="utf-8")
            page = tex[tex.index("\\thispagestyle{empty}"):]
            page = page[:page.index("\\clearpage")]
            assert word[language] in page
            assert not _foreign(page, language), page


def _title_block_texts(dxf: Path) -> list[str]:
    """The texts of the title block (bottom right, 185 × 55 mm) and of graph 26 (top left, turned)."""
    import ezdxf
    msp = ezdxf.readfile(dxf).modelspace()
    xs = [x for e in msp.query("LINE") for x in (e.dxf.start.x, e.dxf.end.x)]
    ys = [y for e in msp.query("LINE") for y in (e.dxf.start.y, e.dxf.end.y)]
    right, bottom = max(xs) - 5.0, min(ys) + 5.0
    out = []
    for e in msp.query("TEXT MTEXT"):
        x, y = e.dxf.insert.x, e.dxf.insert.y
        text = e.dxf.text if e.dxftype() == "TEXT" else e.plain_text()
        if (x >= right - 186.0 and y <= bottom + 56.0) or abs(float(e.dxf.get("rotation", 0.0)) - 180.0) < 1.0:
            out.append(text)
    return out


@pytest.mark.slow
@pytest.mark.parametrize("language", ["ru", "uk", "en"])
@pytest.mark.parametrize("source, args", [("control", ("--table", "1", "--variant", "1")),
                                          ("project", ("--example", "crank-slider")),
                                          ("crane", ("--example", "crane-hoist")),
                                          ("control-left-out", ("--table", "1", "--variant", "1"))])
def test_a_new_task_builds_without_a_word_of_another_language(tmp_path, source, args, language):
    """`new` → `build`: the title page and the frame's designation of the note, and every sheet's
    title block, are in the task's language; also with [document] title and code left out (the
    control sheet printed the core's Cyrillic default code)."""
    task = _new(tmp_path, args, language)
    if source.endswith("left-out"):
        text = re.sub(r'(?m)^(title|code) = .*\n', "", task.read_text(encoding="utf-8"), count=0)
        task.write_text(text, encoding="utf-8")
        assert load_task(task).document.code == Document().code
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "reportgen", "build", str(task), "-o", str(out), "--no-pdf",
                        "--quiet"], capture_output=True, text=True, cwd=ROOT, timeout=900)
    assert r.returncode == 0, r.stdout + r.stderr
    tex = (out / "report.tex").read_text(encoding="utf-8")
    page = tex[tex.index("\\thispagestyle{empty}"):]
    page = page[:page.index("\\clearpage")]
    frames = re.findall(r"\\makebox\(\d+,\d+\)\{\\large ([^}]*)\}", tex)
    assert frames, "no designation in the note's frame"
    bad = _foreign(page, language) + [f for f in frames if _foreign(f, language)]
    assert not bad, (bad, page)
    sheets = sorted((out / "sheets").glob("*.dxf"))
    assert sheets
    for dxf in sheets:
        texts = _title_block_texts(dxf)
        assert texts, dxf.name
        bad = [t for t in texts if _foreign(t, language)]
        assert not bad, (dxf.name, bad)
        if source.endswith("left-out"):          # a control work's letters (КР / CW), not a project's
            code = ("TMM.CW" if language == "en" else "ТММ.КР") + ".00.00.001"
            assert code in texts, (code, texts)
