"""Whole builds in Ukrainian and English (issue 14): examples/shaper-uk against examples/shaper and
examples/press-en against examples/press — the same mechanism, so the same numbers and the same
count of figures, tables and equations; no Russian letters in the Ukrainian work, no Cyrillic in
the English one outside the names the user typed; the key Ukrainian terms of the course."""
from __future__ import annotations

import json
import re
import subprocess
import tomllib
import unicodedata
from pathlib import Path

import ezdxf
import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"

pytestmark = pytest.mark.slow

CYRILLIC = re.compile("[\u0400-\u04FF]")
NOT_UKRAINIAN = re.compile("[ыэъёЫЭЪЁ]")


def _pdftext(pdf: Path) -> str:
    txt = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True,
                         check=True).stdout
    return unicodedata.normalize("NFKC", txt)


def _flat(text: str) -> str:
    """One line of words: hyphenation at line ends undone, runs of white space as one space."""
    return re.sub(r"\s+", " ", re.sub(r"-\n\s*", "", text))


def _user_strings(task: Path) -> list[str]:
    """The names the user typed ([document] fields, the mechanism's name), which stay as typed."""
    data = tomllib.loads(task.read_text(encoding="utf-8"))
    out = [str(v) for k, v in data.get("document", {}).items() if isinstance(v, str)]
    name = data.get("mechanism", {}).get("name")
    if name:
        out += [name, name.lower()]
    return out


def _without(text: str, strings: list[str]) -> str:
    flat = _flat(text)
    for s in sorted(strings, key=len, reverse=True):
        for word in s.split():             # names may be broken over lines: drop their words
            flat = flat.replace(word, " ")
    return flat


def _dxf_texts(folder: Path) -> list[str]:
    texts = []
    for path in sorted(folder.glob("*.dxf")):
        for e in ezdxf.readfile(path).modelspace().query("TEXT MTEXT"):
            texts.append(e.dxf.text if e.dxftype() == "TEXT" else e.plain_text())
    return texts


def _counts(text: str, figure: str, table: str) -> tuple[int, int, int]:
    """Captions of figures and tables and equation numbers «(N.M)» at a line's end in the PDF text."""
    figures = len(set(re.findall(rf"{figure} (\d+\.\d+) —", text)))
    tables = len(set(re.findall(rf"{table} (\d+\.\d+) —", text)))
    equations = len(set(re.findall(r"\((\d+\.\d+)\)\s*$", text, re.M)))
    return figures, tables, equations


@pytest.fixture
def builds(built):
    """The four builds, shared with the other whole-build checks (``built`` of tests/conftest.py)."""
    return {name: built(name) for name in ("shaper-uk", "shaper", "press-en", "press")}


def test_examples_declare_their_language():
    assert tomllib.loads((EXAMPLES / "shaper-uk" / "task.toml").read_text("utf-8"))["document"]["language"] == "uk"
    assert tomllib.loads((EXAMPLES / "press-en" / "task.toml").read_text("utf-8"))["document"]["language"] == "en"
    press = tomllib.loads((EXAMPLES / "press" / "task.toml").read_text("utf-8"))
    assert press["document"].get("language", "ru") == "ru"          # `make demo` stays Russian
    assert tomllib.loads((EXAMPLES / "shaper-uk" / "task.toml").read_text("utf-8"))["analysis"]["positions"] == 12


def test_same_numbers_whatever_the_language(builds):
    for other, ru in (("shaper-uk", "shaper"), ("press-en", "press")):
        a = json.loads((builds[other] / "results.json").read_text(encoding="utf-8"))
        b = json.loads((builds[ru] / "results.json").read_text(encoding="utf-8"))
        assert a == b, other


def test_ukrainian_note_has_no_russian_letters_and_the_course_terms(builds):
    task = EXAMPLES / "shaper-uk" / "task.toml"
    text = _pdftext(builds["shaper-uk"] / "report.pdf")
    bad = NOT_UKRAINIAN.findall(_without(text, _user_strings(task)))
    assert not bad, re.findall(r".{30}[ыэъёЫЭЪЁ].{10}", _flat(text))[:5]
    flat = _flat(text).lower()
    for term in ("ланка", "кривошип", "шатун", "повзун", "куліса", "кулісний камінь", "план швидкостей",
                 "план прискорень", "прискорення коріоліса", "передавальні функції", "група ассура",
                 "важіль жуковського", "зрівноважувальний момент", "маховик",
                 "коефіцієнт нерівномірності руху", "евольвентн", "коефіцієнт перекриття", "водило",
                 "сателіт", "зміст", "вступ", "висновки"):
        assert term in flat, term
    assert "0,05" in flat and "«" in flat                     # decimal comma, Ukrainian quotes


def test_ukrainian_sheets(builds):
    texts = _dxf_texts(builds["shaper-uk"] / "sheets")
    joined = " ".join(texts)
    assert not NOT_UKRAINIAN.search(joined), [t for t in texts if NOT_UKRAINIAN.search(t)][:5]
    for word in ("Розроб.", "Перев.", "Арк.", "Масштаб", "План швидкостей", "Важіль Жуковського",
                 "Кінематичний аналіз важільного механізму"):
        assert word in joined, word


def test_english_note_has_no_cyrillic_outside_user_names(builds):
    task = EXAMPLES / "press-en" / "task.toml"
    assert not CYRILLIC.search(" ".join(_user_strings(task)))          # the example is English throughout
    text = _pdftext(builds["press-en"] / "report.pdf")
    assert not CYRILLIC.search(text), re.findall(r".{30}[\u0400-\u04FF].{10}", _flat(text))[:5]
    flat = _flat(text).lower()
    for term in ("crank", "coupler", "rocker", "slider", "velocity polygon", "acceleration polygon",
                 "assur group", "zhukovsky's lever", "flywheel", "coefficient of speed fluctuation",
                 "contact ratio", "carrier", "planet", "contents", "introduction", "conclusions"):
        assert term in flat, term
    assert re.search(r"\b18\.45\b|\b0\.05\b", flat) and not re.search(r"\d,\d{2}\b", flat)  # decimal point
    # no decimal comma anywhere, a scale's ratio included («2,5:1» was printed for the meshing's
    # scale): only the Assur groups' links «II(2,3)» and lists «1,2» inside parentheses remain
    rest = re.sub(r"\([\d,\s]+\)", "", flat)
    assert not re.findall(r".{20}\d,\d.{10}", rest), re.findall(r".{20}\d,\d.{10}", rest)[:5]


def test_english_sheets(builds):
    texts = _dxf_texts(builds["press-en"] / "sheets")
    assert not [t for t in texts if CYRILLIC.search(t)], [t for t in texts if CYRILLIC.search(t)][:5]
    joined = " ".join(texts)
    for word in ("Drawn", "Checked", "Scale", "Zhukovsky's lever", "Kinematic analysis of the linkage"):
        assert word in joined, word


def test_english_sheets_print_the_decimal_point(builds):
    """Every number on the English sheets has a decimal point, a scale's ratio included; only the
    Assur groups' links «II(2,3)» keep their comma."""
    texts = [re.sub(r"\([\d,\s]+\)", "", t) for t in _dxf_texts(builds["press-en"] / "sheets")]
    assert not [t for t in texts if re.search(r"\d,\d", t)], [t for t in texts if re.search(r"\d,\d", t)][:5]


def test_same_count_of_figures_tables_and_equations(builds):
    ru_shaper = _counts(_pdftext(builds["shaper"] / "report.pdf"), "Рисунок", "Таблица")
    uk_shaper = _counts(_pdftext(builds["shaper-uk"] / "report.pdf"), "Рисунок", "Таблиця")
    assert ru_shaper == uk_shaper and min(ru_shaper) > 5, (ru_shaper, uk_shaper)
    ru_press = _counts(_pdftext(builds["press"] / "report.pdf"), "Рисунок", "Таблица")
    en_press = _counts(_pdftext(builds["press-en"] / "report.pdf"), "Figure", "Table")
    assert ru_press == en_press and min(ru_press) > 5, (ru_press, en_press)
