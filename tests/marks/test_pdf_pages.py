"""The typeset note of every example, read back from its PDF (issue 12: figures and residue).

* every figure's box (written by ``\\notefigure`` at shipout: page, position, size) lies inside the
  text block of the ГОСТ page (30/15/20/27 mm margins) and every figure but the assignment's scheme
  has a numbered caption «Рисунок N.M — …»;
* no glyph of any page (pdftotext -bbox) lies outside the text block, except in the title block;
* no LaTeX or Jinja residue («\\%», «??», a backslash, ``\\VAR``, ``{{``) in the PDF text, and no
  round-off residue printed as a number (·10⁻⁹ and below: below the precision of any quantity of
  the course).
"""
from __future__ import annotations

import re
import subprocess
import tomllib
import unicodedata

import pytest

from truth_read import EXAMPLES, ROOT
from latex_templates.render import Strings

pytestmark = pytest.mark.slow

MM_PER_PT = 25.4 / 72.0             # PDF points (bp)
MM_PER_SP = 25.4 / 72.27 / 65536.0  # TeX scaled points
PAGE_H = 297.0
TEXT = (30.0, 195.0, 20.0, 270.0)   # x from, x to, y from the top, y to (mm): preamble's geometry
DEPTH = 4.0                          # the last line's descenders, subscripts and a display's denominators below the block, mm
STAMP = (20.0, 205.0, 277.0, 292.0)  # the title block (form 2a) inside the frame
STAMP_FORM2 = (20.0, 205.0, 252.0, 292.0)  # form 2 on the first sheet of the text (the contents)
SLACK = 0.5


def _figboxes(out):
    log = (out / "latex-build" / "report.log").read_text(encoding="utf-8", errors="replace")
    boxes = []
    for m in re.finditer(r"^FIGBOX(\*?) (\d+)\s+(-?\d+)\s+(-?\d+)\s+([\d.]+)pt\s+([\d.]+)pt", log, re.M):
        star, page, x, y, w, h = m.groups()
        x_mm, y_mm = int(x) * MM_PER_SP, PAGE_H - int(y) * MM_PER_SP   # y: baseline, from the top
        w_mm, h_mm = float(w) * 25.4 / 72.27, float(h) * 25.4 / 72.27
        boxes.append((bool(star), int(page), x_mm, y_mm - h_mm, x_mm + w_mm, y_mm))
    return boxes


def _words(example: str) -> Strings:
    """The example's catalogue (its language; the control work's overlay): the words the checks
    look for (captions, the stamp) are the note's own."""
    data = tomllib.loads((ROOT / "examples" / example / "task.toml").read_text(encoding="utf-8"))
    doc = data.get("document", {})
    return Strings(doc.get("language", "ru"),
                   overlay="control.overrides" if doc.get("kind") == "control-work" else None)


def _word(example: str, key: str) -> str:
    """A catalogue word as the PDF shows it (TeX's ties and thin spaces undone)."""
    text = str(_words(example).raw(key))
    return text.replace("~", " ").replace("\\,", " ").replace("\\", "")


def _pdftext(pdf) -> str:
    txt = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True,
                         check=True).stdout
    return unicodedata.normalize("NFKC", txt)


@pytest.mark.parametrize("example", EXAMPLES)
def test_every_figure_inside_the_text_block_with_a_caption(example, built):
    out = built(example)
    boxes = _figboxes(out)
    includes = len(re.findall(r"\\includegraphics", (out / "report.tex").read_text(encoding="utf-8")))
    assert len(boxes) == includes                # every figure went through \notefigure
    if _words(example).language and "crane" not in example:
        assert boxes                              # a course project or control work has figures
    x0, x1, y0, y1 = TEXT
    bad = [b for b in boxes if b[2] < x0 - SLACK or b[4] > x1 + SLACK or b[3] < y0 - SLACK or b[5] > y1 + SLACK]
    assert not bad, bad
    text = _pdftext(out / "report.pdf")
    captions = re.findall(re.escape(_word(example, "captions.figure")) + r" \d+\.\d+ — \S", text)
    assert len(set(captions)) >= sum(1 for b in boxes if not b[0])
    assert sum(1 for b in boxes if b[0]) <= 1


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_glyph_outside_the_text_block(example, built):
    out = built(example)
    html = subprocess.run(["pdftotext", "-bbox", str(out / "report.pdf"), "-"], capture_output=True,
                          text=True, check=True).stdout
    x0, x1, y0, y1 = TEXT
    author = f">{_word(example, 'marks.stamp.author')}<"
    bad = []
    for n, page in enumerate(html.split("<page ")[1:], 1):
        if n == 1:
            continue                  # the title page has its own layout (ГОСТ 7.32: no frame)
        box = STAMP_FORM2 if author in page else STAMP
        for m in re.finditer(r'xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">([^<]*)<', page):
            a, b, c, d = (float(v) * MM_PER_PT for v in m.groups()[:4])
            inside = a >= x0 - 1 and c <= x1 + 1 and b >= y0 - 1 and d <= y1 + DEPTH
            stamp = a >= box[0] and c <= box[1] and b >= box[2] and d <= box[3]
            if not inside and not stamp:
                bad.append((n, m.group(5), round(a), round(b)))
    assert not bad, bad[:20]


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_page_runs_into_the_stamp(example, built):
    """LaTeX's own word for a page whose text runs past the text block (into the stamp): an overfull
    \\vbox of the output routine (seen with longtable after a top float, shaper p. 28)."""
    log = (built(example) / "latex-build" / "report.log").read_text(encoding="utf-8", errors="replace")
    assert "Overfull \\vbox" not in log, [ln for ln in log.splitlines() if "Overfull \\vbox" in ln]


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_residue_in_the_pdf_text(example, built):
    text = _pdftext(built(example) / "report.pdf")
    for residue in ("\\%", "??", "\\", "VAR{", "BLOCK{", "{{", "}}", "{%", "%}"):
        assert residue not in text, residue
    tiny = [m.group(0) for m in re.finditer(r"\d\s*[·⋅]\s*10\s*[−-]\s*(\d+)", text) if int(m.group(1)) >= 9]
    assert not tiny, tiny


@pytest.mark.parametrize("example", ["press", "conveyor"])
def test_front_matter(example, built):
    """Title page with the university; form 2 (ГОСТ 2.104) on the first sheet of the text, the contents;
    an introduction that says what the machine does and cites the references."""
    out = built(example)
    pages = _pdftext(out / "report.pdf").split("\f")
    if example == "press":
        assert "Технический университет" in pages[0]
    first = next(i for i, p in enumerate(pages) if "СОДЕРЖАНИЕ" in p)
    assert "Разраб." in pages[first] and "Листов" in pages[first] and "Утв." in pages[first]
    assert all("Разраб." not in p for p in pages[first + 1:])
    intro = next(p for p in pages if "ВВЕДЕНИЕ" in p and "СОДЕРЖАНИЕ" not in p)
    intro = " ".join(re.sub(r"-\s*\n\s*", "", intro).split())      # hyphenation and line breaks undone
    assert "Механизм преобразует" in intro and "[1, 2]" in intro and "[3]" in intro
    if example == "conveyor":
        assert "проектирование эвольвентной" not in intro      # no [gears]: the work designs no gears
        # the left-out section named in quotes, not as a capitalised word mid-sentence
        assert "не приводятся: «Проектирование зубчатых передач»." in intro


_AFTER_DISPLAY = re.compile(r"^\s*(\\end\{(equation|wherelist|align|gather|multline)\*?\}|\\\])\s*$")
#: the words that may continue a sentence after its display (the where-list and its kin)
_CONTINUES = ("где", "де", "where")


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_sentence_starts_in_lower_case_after_a_display(example, built):
    """The note's source as typeset: after a displayed formula or its where-list (which ends with a
    full stop) the text starts a new sentence with a capital letter — never «что на схеме
    составляет», «на плане — отрезок 0,9 мм», «что не превышает допустимых 5 %» (issue 12: a
    sentence without a subject, starting in lower case)."""
    lines = (built(example) / "report.tex").read_text(encoding="utf-8").splitlines()
    bad = []
    for i, line in enumerate(lines):
        if not _AFTER_DISPLAY.match(line):
            continue
        nxt = next((ln.strip() for ln in lines[i + 1:] if ln.strip()), "")
        word = re.match(r"[~\s]*([^\W\d_]+)", nxt)
        if word and word.group(1)[0].islower() and word.group(1) not in _CONTINUES:
            bad.append((i + 2, nxt[:70]))
    assert not bad, bad


def _table_parts(text: str, caption: str, continued: str):
    """(table, rows) of every part of a table on one page: the rows that follow its caption or its
    «continued» head, up to the first blank line (pdftotext -layout leaves one after a table)."""
    parts = []
    for page in text.split("\f"):
        lines = page.splitlines()
        for i, ln in enumerate(lines):
            m = re.match(rf"\s*(?:{re.escape(caption)} (\d+\.\d+) —|{re.escape(continued)} (\d+\.\d+))", ln)
            if not m:
                continue
            j = i + 1
            while j < len(lines) and lines[j].strip():
                j += 1                                  # the caption's other lines, the column header
            while j < len(lines) and not lines[j].strip():
                j += 1
            rows = 0
            while j < len(lines) and lines[j].strip():
                rows += 1
                j += 1
            parts.append((m.group(1) or m.group(2), rows))
    return parts


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_table_part_is_a_single_row(example, built):
    """A table broken over pages leaves at least two rows on each page (issue 12: orphaned table
    rows, pp. 8, 11, 56 of the press note), and its next page starts with «Продолжение таблицы N»
    (ГОСТ 7.32)."""
    text = _pdftext(built(example) / "report.pdf")
    caption = _word(example, "captions.table")
    continued = _word(example, "captions.table_continued")
    parts = _table_parts(text, caption, continued)
    numbers = [n for n, _ in parts]
    broken = {n for n in numbers if numbers.count(n) > 1}
    bad = [(n, rows) for n, rows in parts if n in broken and rows < 2]
    assert not bad, bad
    assert all(re.search(rf"{re.escape(continued)} {re.escape(n)}\b", text) for n in broken), broken


#: Words a teacher marks in red, found by reading every example's note (the review of issue 12):
#: (languages, pattern, what is wrong). The patterns are read on the flattened PDF text (hyphenation
#: and line breaks undone).
_MARKED = (
    (("ru", "uk", "en"), r"\d\s*шт\.", "«(3 шт.)» is the language of a parts list, not of a sentence"),
    (("ru", "uk", "en"), r"(?i)\b(\w{4,})\s+[«“\"]\1\b",
     "a word repeated inside the quotes after it («механизм «Механизм пресса»»)"),
    (("uk",), r"зневажлив", "«зневажливо мала» means «contemptuously small»: «нехтовно мала»"),
    (("uk",), r"передаточн", "a russism: the note says «передавальне відношення», so «передавальне число»"),
    (("en",), r"Merzalov", "Мерцалов is Mertsalov in English"),
    (("en",), r"[«»]", "Russian guillemets in an English note"),
    (("ru", "uk", "en"), r"--", "TeX's dash escaped and printed as hyphens («---» in the control work's ω/ε table)"),
    (("uk",), r"виробничого опору",
     "two terms for one load: the assignment and the symbol F_ко/M_ко say «корисного опору», the text said «виробничого»"),
    (("en",), r"(?i)\bworks\b", "«work» is uncountable: «the works», «balance of works» are calques of «работ»"),
    (("en",), r"\bMbZ\s*=", "the conclusions printed M_b^Z (italic b, Z) for the body's M_b^Zh"),
    (("en",), r"\bkind (?:[RP]{3}|triad)", "an Assur group's «type RRR», not «kind RRR»"),
    (("en",), r"(?i)flywheel masses", "«маховые массы» calqued: the moments of inertia of the couplings"),
)
#: in a control work only (one position: «the given position», not «position 0»)
_MARKED_CONTROL = (r"(?:положени[еяю]|положенн[яі]|position) 0\b|положения силового расчёта"
                   r"|положення силового розрахунку|the analysed position")
_MARKED_CONTROL_GROUPS = r"со схем групп|зі схем груп|from the schemes of the groups"
#: a control work draws the mechanism in its given position only: it has no plan of positions
_MARKED_CONTROL_POSITIONS = r"плана положений|плану положень|position diagram"


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_word_a_teacher_marks(example, built):
    flat = " ".join(re.sub(r"-\s*\n\s*", "", _pdftext(built(example) / "report.pdf")).split())
    language = _words(example).language
    bad = []
    marked = [(p, why) for languages, p, why in _MARKED if language in languages]
    kind = tomllib.loads((ROOT / "examples" / example / "task.toml").read_text(encoding="utf-8")
                         ).get("document", {}).get("kind")
    if kind == "control-work":
        marked.append((_MARKED_CONTROL, "a control work has one position: «the given position»"))
        marked.append((_MARKED_CONTROL_GROUPS, "a control work draws no schemes of the groups: the forces "
                       "come to the lever from the scheme of the mechanism"))
        marked.append((_MARKED_CONTROL_POSITIONS, "a control work has no plan of positions: μl is the scheme's"))
    for pattern, why in marked:
        for m in re.finditer(pattern, flat):
            bad.append((why, flat[max(0, m.start() - 40):m.end() + 20]))
    assert not bad, bad[:5]


@pytest.mark.parametrize("example", EXAMPLES)
def test_a_resistance_moment_is_not_called_a_force(example, built):
    """A resistance given as a moment (a rocker's, class3) is a moment in every sentence: section 3
    said «Учитываем силу производственного сопротивления», «сила сопротивления включается»."""
    task = tomllib.loads((ROOT / "examples" / example / "task.toml").read_text(encoding="utf-8"))
    loads = [ld for ld in task.get("mechanism", {}).get("load", []) if ld.get("kind") == "resistance"]
    if not loads or any("force" in ld for ld in loads):
        pytest.skip("no resistance moment")
    flat = " ".join(re.sub(r"-\s*\n\s*", "", _pdftext(built(example) / "report.pdf")).split())
    bad = [flat[max(0, m.start() - 40):m.end() + 20] for m in re.finditer(
        r"(?i)\bсил[аыуіи] (?:производственного |полезного |корисного |виробничого )?(?:сопротивлени|опор)"
        r"|\b(?:useful )?resistance force", flat)]
    assert not bad, bad[:5]


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_sentence_ends_on_a_colon_with_nothing_after_it(example, built):
    """A sentence that announces what follows with a colon is followed by it (a display, a list, the
    rest of the sentence in lower case), never by the next sentence: class3's plans said «…решая
    графически векторные уравнения: Построенный план показан…» (a class III group has no vector
    equations of two points), «Угловые ускорения звеньев: Скорости и ускорения центров масс…»."""
    lines = (built(example) / "report.tex").read_text(encoding="utf-8").splitlines()
    bad = []
    for i, line in enumerate(lines):
        text = line.rstrip()
        if not text.endswith(":") or text.lstrip().startswith("%"):
            continue
        nxt = next((ln.strip() for ln in lines[i + 1:] if ln.strip()), "")
        if re.match(r"[^\W\d_]", nxt) and nxt[0].isupper():
            bad.append((i + 1, text[-50:], nxt[:50]))
    assert not bad, bad


@pytest.mark.parametrize("example", EXAMPLES)
def test_a_single_row_reducer_has_no_second_row(example, built):
    """A single-row planetary reducer (crank-slider) has one row and a satellite with one crown: its
    coaxiality condition said «модуль обоих рядов одинаков», its adjacency condition «число зубьев
    большего венца сателлита»."""
    task = tomllib.loads((ROOT / "examples" / example / "task.toml").read_text(encoding="utf-8"))
    if task.get("planetary", {}).get("scheme") != "single-row":
        pytest.skip("not a single-row reducer")
    flat = " ".join(re.sub(r"-\s*\n\s*", "", _pdftext(built(example) / "report.pdf")).split())
    bad = [flat[max(0, m.start() - 40):m.end() + 20] for m in re.finditer(
        r"обоих рядов|обох рядів|both rows|большего венца|більшого вінця|larger planet row", flat)]
    assert not bad, bad
