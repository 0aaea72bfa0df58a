"""Reading a build back as a teacher reads it: the numbers the note's PDF prints (pdftotext), the
texts of the sheets' DXF entities (with their table rows) and results.json (issue 12: one truth)."""
from __future__ import annotations

import json
import re
import subprocess
import tomllib
import unicodedata
from dataclasses import dataclass
from pathlib import Path

import ezdxf

ROOT = Path(__file__).resolve().parents[2]
#: Every example (course projects in ru, uk and en, the crane, the control work): the builds of
#: issue 12's checks come from ``built`` of tests/conftest.py (one per session).
EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml"))
#: a scale's symbol as note and sheets print it: μ and its index (μl, μv, μF, μφ, μM, μλ …)
SCALE = r"μ[A-Za-zА-Яа-яα-ωΑ-Ω]{1,2}(?![A-Za-zА-Яа-я])"


def language(example: str) -> str:
    data = tomllib.loads((ROOT / "examples" / example / "task.toml").read_text(encoding="utf-8"))
    return data.get("document", {}).get("language", "ru")


def number_re(mark: str) -> str:
    """A printed number: minus, digits grouped by spaces (thousands), the decimal mark."""
    return rf"[−-]?\d+(?:[ \u2009\u202f]\d{{3}})*(?:{re.escape(mark)}\d+)?(?![\d{re.escape(mark)}]\d)"


def to_float(text: str, mark: str) -> float:
    return float(re.sub(r"[ \u2009\u202f]", "", text).replace(mark, ".").replace("−", "-"))


@dataclass(frozen=True)
class Printed:
    """A number as printed: its value and its decimals (the precision it claims)."""
    text: str
    value: float
    decimals: int

    def agrees(self, exact: float) -> bool:
        """``exact`` rounds to this number at its printed precision (half a unit of the last digit)."""
        return abs(self.value - exact) <= 0.5 * 10.0 ** -self.decimals * (1 + 1e-9) + 1e-12 * abs(exact)


def printed(text: str, mark: str) -> Printed:
    frac = text.split(mark, 1)[1] if mark in text else ""
    return Printed(text, to_float(text, mark), len(frac))


def pdf_text(pdf: Path) -> str:
    txt = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True,
                         check=True).stdout
    return unicodedata.normalize("NFKC", txt)


def sheet_texts(folder: Path) -> dict[str, list[tuple[float, float, str]]]:
    """Every sheet's TEXT and MTEXT: (x, y of the anchor, text), per sheet file name."""
    out: dict[str, list[tuple[float, float, str]]] = {}
    for path in sorted(folder.glob("*.dxf")):
        rows = out.setdefault(path.name, [])
        for e in ezdxf.readfile(path).modelspace().query("TEXT MTEXT"):
            t = e.dxf.text if e.dxftype() == "TEXT" else e.plain_text()
            a = e.dxf.insert
            if e.dxftype() == "TEXT" and e.dxf.halign and e.dxf.hasattr("align_point"):
                a = e.dxf.align_point
            rows.append((float(a.x), float(a.y), unicodedata.normalize("NFKC", t)))
    return out


def table_rows(texts: list[tuple[float, float, str]], tol: float = 1.0) -> list[list[str]]:
    """Texts on one baseline (within ``tol`` mm), left to right: the rows of the sheets' tables."""
    rows: list[tuple[float, list[tuple[float, str]]]] = []
    for x, y, t in sorted(texts, key=lambda r: (-r[1], r[0])):
        if rows and abs(rows[-1][0] - y) <= tol:
            rows[-1][1].append((x, t))
        else:
            rows.append((y, [(x, t)]))
    return [[t for _, t in sorted(r)] for _, r in rows]


def scales_in_line(line: str, mark: str) -> list[tuple[str, Printed]]:
    """``μX = … = V`` (the value after the last «=» of the assignment) in one line of text."""
    num = number_re(mark)
    out = []
    # an assignment «μX = …», not a factor of a product («lR ⋅ μF = 10,6 ⋅ 25 = 265»)
    starts = [m for m in re.finditer(rf"({SCALE})\s*=", line)
              if not re.search(r"[⋅·×/+−=-]\s*$", line[:m.start()])]
    for k, m in enumerate(starts):
        end = starts[k + 1].start() if k + 1 < len(starts) else len(line)
        seg = line[m.start():end]
        values = list(re.finditer(rf"=\s*({num})(?!\s*[⋅·×]|\d)", seg))
        if values:
            out.append((m.group(1), printed(values[-1].group(1), mark)))
    return out


def note_scales(text: str, mark: str) -> list[tuple[str, Printed]]:
    return [sp for line in text.splitlines() for sp in scales_in_line(line, mark)]


def sheet_scales(texts: dict[str, list[tuple[float, float, str]]], mark: str) -> set[tuple[str, float]]:
    """Scales printed on the sheets: ``μX = V`` in a text, and a table row whose label cell is (or
    names) μX with a number in a later cell."""
    num = number_re(mark)
    out: set[tuple[str, float]] = set()
    for entries in texts.values():
        for _, _, t in entries:
            out |= {(s, p.value) for s, p in scales_in_line(t, mark)}
        for row in table_rows(entries):
            for i, cell in enumerate(row):
                m = re.fullmatch(rf"(?:.*\s)?({SCALE})(?:,.*)?", cell.strip())
                if not m:
                    continue
                for later in row[i + 1:]:
                    v = re.match(rf"\s*({num})(?:\s|$)", later)
                    if v:
                        out.add((m.group(1), printed(v.group(1), mark).value))
                        break
    return out


def results(out: Path) -> dict:
    return json.loads((out / "results.json").read_text(encoding="utf-8"))


POSITION = r"(?:положени[еяюи]|положення|position)"


def position_pairs(text: str, mark: str) -> list[tuple[int, Printed]]:
    """«положение N … (φ1 = X°)» (any language) with no other position named in between."""
    num = number_re(mark)
    flat = re.sub(r"-\n\s*", "", text)
    flat = re.sub(r"\s+", " ", flat)
    pat = rf"{POSITION} (\d+)\b((?:(?!{POSITION}|φ).){{0,40}})φ1? = ({num}) ?[°∘]"
    return [(int(m.group(1)), printed(m.group(3), mark)) for m in re.finditer(pat, flat, re.I)
            if "диаграм" not in m.group(2) and "diagram" not in m.group(2)]


def labelled_values(texts: dict[str, list[tuple[float, float, str]]], mark: str) -> list[tuple[str, list[Printed]]]:
    """Table rows of the sheets as (label cell, the numbers in the cells after it)."""
    num = number_re(mark)
    out = []
    for entries in texts.values():
        for row in table_rows(entries):
            label, values = None, []
            for cell in row:           # a label cell and the run of numbers right after it
                if re.fullmatch(num, cell.strip()):
                    if label is not None:
                        values.append(printed(cell.strip(), mark))
                elif cell.strip():
                    if label is not None and values:
                        out.append((label, values))
                    label, values = cell, []
            if label is not None and values:
                out.append((label, values))
    return out


def assigned(text: str, symbol: str, mark: str) -> list[Printed]:
    """The values a displayed formula of the note gives ``symbol`` (``symbol = … = V`` at a line's start)."""
    num = number_re(mark)
    out = []
    lines = text.splitlines()
    for n, line in enumerate(lines):
        m = re.match(rf"(\s*){re.escape(symbol)}\s*=(.*)", line)
        # a primed symbol (εα′: the value read on the drawing, not the exact one) has its prime on
        # the line above, over the symbol
        above = lines[n - 1] if n else ""
        if m and "′" in above[len(m.group(1)):len(m.group(1)) + len(symbol) + 3]:
            continue
        if m:
            # «aw = 119,122 мм, εα = 1,201», «εα = 1,152 ≥ [εα] = 1,05»: the symbol's own clause
            clause = re.split(r"[,;]\s+(?=\D)|[≥≤<>]", m.group(2))[0]
            values = re.findall(rf"=\s*({num})(?!\s*[⋅·×]|\d)", "=" + clause)
            if values:
                out.append(printed(values[-1], mark))
    return out
