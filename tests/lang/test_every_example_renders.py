"""Every example renders in every language (issue 14: "a test runs every template path of every
example in every language"): the note's LaTeX is made (no TeX run) for ru, uk and en, so a key
missing on a branch only some example reaches fails here, and the rendered source holds no Russian
word in English outside the user's strings."""
from __future__ import annotations

import dataclasses
import re
import tomllib
from pathlib import Path

import pytest

from latex_templates import NoteBuilder
from latex_templates.assignment import assignment_section, introduction_paragraphs
from latex_templates.compose import compose
from latex_templates.render import Strings
from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
BASE = ("press", "shaper", "conveyor", "crank-slider", "class3")

pytestmark = pytest.mark.slow


def _render(name: str, language: str, out: Path) -> str:
    task = load_task(ROOT / "examples" / name / "task.toml")
    task = dataclasses.replace(task, document=dataclasses.replace(task.document, language=language))
    project = Project(task)
    sections, left_out = compose(project, Strings(language))
    note = NoteBuilder(task.document, designation="X", introduction=introduction_paragraphs(project, left_out),
                       conclusions=[c for s in sections for c in s.conclusions],
                       assignment=assignment_section(project))
    for s in sections:
        note.add_section(s.section)
    return note.render(out).read_text(encoding="utf-8")


def _environments(tex: str) -> tuple[int, int, int]:
    return (tex.count(r"\begin{figure}"), tex.count(r"\begin{longtable}"), tex.count(r"\begin{equation}"))


@pytest.mark.parametrize("name", BASE)
def test_renders_in_every_language(name, tmp_path):
    data = tomllib.loads((ROOT / "examples" / name / "task.toml").read_text(encoding="utf-8"))
    user = [v for v in data.get("document", {}).values() if isinstance(v, str)]
    user += [data.get("mechanism", {}).get("name", "")] * 2
    counts = {}
    for lang in ("ru", "uk", "en"):
        tex = _render(name, lang, tmp_path / lang)
        counts[lang] = _environments(tex)
        body = tex[tex.index(r"\begin{document}"):]
        for word in sorted({w for u in user for w in u.split()}, key=len, reverse=True):
            body = re.sub(re.escape(word), "", body, flags=re.I)    # the user's words, any case
        body = re.sub(r"\\text\{[^{}]*\}", "", body)          # none left: checked below for en
        if lang == "uk":
            assert not re.search("[ыэъёЫЭЪЁ]", body.replace("Артоболевский", "")), \
                re.findall(r".{30}[ыэъё].{10}", body)[:3]
        if lang == "en":
            assert not re.search("[\u0400-\u04FF]", body), re.findall(r".{40}[\u0400-\u04FF]+.{10}", body)[:3]
    assert counts["ru"] == counts["uk"] == counts["en"], counts


def _four_bar_task(path: Path, language: str) -> Path:
    """A crank–rocker with a resistance moment on the rocker: a mechanism no example has (no slider,
    no triangular link, no gears)."""
    from reportgen.zoo import four_bar
    text = four_bar(0.08, 0.30, 0.22, 0.28, phi_deg=30.0, omega=15.0, name="Rocker",
                    loads=[{"kind": "resistance", "link": 3, "moment": 120.0, "law": [[0.0, 1.0], [1.0, 1.0]],
                            "stroke": "working"}],
                    analysis={"positions": 12, "start": "extreme", "force_position": 3},
                    extra="[dynamics]\ndelta = 0.05\ncrank_inertia = 0.4\n")
    path.write_text(f'[document]\nlanguage = "{language}"\ntitle = "Rocker"\n\n' + text, encoding="utf-8")
    return path


@pytest.mark.parametrize("language,moment", [("ru", "Момент полезного сопротивления"),
                                             ("uk", "Момент корисного опору"),
                                             ("en", "The useful resistance moment")])
def test_the_note_speaks_only_of_what_the_mechanism_has(language, moment, tmp_path):
    """Issue 12: «a statement about something the task does not have». A rocker driven against a
    resistance moment: the assignment calls it a moment (not «Сила … M_пс»), the mass rules name no
    slider and no triangular link, and the table of positions gives the rocker's angle in degrees as
    the text does (ψ = 47,73°), not in radians."""
    task = load_task(_four_bar_task(tmp_path / "task.toml", language))
    project = Project(task)
    strings = Strings(language)
    sections, left_out = compose(project, strings)
    note = NoteBuilder(task.document, designation="X", introduction=introduction_paragraphs(project, left_out),
                       conclusions=[c for s in sections for c in s.conclusions], assignment=assignment_section(project))
    for s in sections:
        note.add_section(s.section)
    tex = note.render(tmp_path / "out").read_text(encoding="utf-8")
    assert moment in tex
    rules = tex[tex.index("${}^{*}$"):]
    rules = rules[:rules.index("\n\n")]
    for absent in ("ползун", "повзун", "slider", "треугольн", "трикутн", "triangular"):
        assert absent not in rules, absent
    assert r"$\psi$, \textdegree" in tex and r"$\psi$, рад" not in tex and r"$\psi$, rad" not in tex


def test_a_prismatic_pair_is_named_in_the_group_description(tmp_path):
    """Issue 12 (a teacher's mark): «внутренних D и внешних B, D» named D twice; the outer D is the
    slider's prismatic pair with the frame, and the note says so."""
    tex = _render("press", "ru", tmp_path)
    assert "внутреннюю $D$ и~внешние $B$, $D$~(поступательную)" in tex
    assert "внутреннюю $B$ и~внешние $A$, $C$;" in tex
    # the count agrees with its noun (the review: «из звеньев 2, 3 и 3 кинематических пар» read
    # as «links 2, 3 and 3»)
    assert "состоит из~звеньев 2, 3\nи~имеет 3~кинематические пары:" in tex
