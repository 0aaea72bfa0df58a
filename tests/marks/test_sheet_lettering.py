"""Sheets lettered ГОСТ-like wherever they are shown, «Масштаб» filled (issue 12, sheets).

The text style keeps LibreCAD's OpenGostTypeB name (LibreCAD letters it with its own .lff) and
names osifont.ttf as its font file (ISO 3098, what ezdxf's previews and other CAD programs use);
every character of every sheet of every example has a real glyph in the font the previews letter
with (osifont completed with «ё», «Ё», «Э», «э»: drawings/sheet_font.py); the title block's
«Масштаб» holds the main view's scale, or «—» on the crane's sheets of schemes (ГОСТ 2.701)."""
from __future__ import annotations

import re
from pathlib import Path

import ezdxf
import pytest

from truth_read import EXAMPLES, ROOT
from drawings.sheet import Sheet
from drawings.sheet_font import drawable
from drawings.style import TEXT_STYLE, TEXT_STYLE_FONT, ensure_sheet_font

pytestmark = pytest.mark.slow

OSIFONT = Path("/usr/share/fonts/truetype/osifont/osifont.ttf")
SCALE_RE = re.compile(r"^\d+([,.]\d+)?:\d+([,.]\d+)?$")      # «1:2,5»; «1:2.5» in English


def test_the_font_is_a_debian_package_of_make_system():
    deb = re.search(r"^DEB_PACKAGES :=(.*?)\n\S", (ROOT / "Makefile").read_text(encoding="utf-8"), re.S | re.M)
    assert deb and "fonts-osifont" in deb.group(1).split()
    assert OSIFONT.is_file(), "fonts-osifont is not installed: run `make system`"
    assert TEXT_STYLE_FONT == "osifont.ttf" and ensure_sheet_font()


def _texts(doc):
    for e in doc.modelspace().query("TEXT MTEXT"):
        yield e, (e.dxf.text if e.dxftype() == "TEXT" else e.plain_text())


@pytest.mark.parametrize("example", EXAMPLES)
def test_every_sheet_letters_in_osifont_with_its_scale(example, built):
    sheets = sorted((built(example) / "sheets").glob("*.dxf"))
    assert sheets
    for path in sheets:
        doc = ezdxf.readfile(path)
        assert doc.styles.get(TEXT_STYLE).dxf.font == TEXT_STYLE_FONT
        assert doc.styles.get("Standard").dxf.font == TEXT_STYLE_FONT
        missing = {ch for _, t in _texts(doc) for ch in t if not drawable(ch)}
        assert not missing, (path.name, missing)
        # «Масштаб»: the cell 18 × 15 mm at the right of the title block (185 × 55 mm, lower right)
        xs = [e.dxf.insert.x for e, _ in _texts(doc)] or [0.0]
        right = max(x for x in xs)
        frame_right = max(le.dxf.end.x for le in doc.modelspace().query("LINE")) if right else 0.0
        cell = [t for e, t in _texts(doc) if (SCALE_RE.match(t.strip()) or t.strip() == Sheet.NO_SCALE)
                and frame_right - 18.5 <= _anchor(e)[0] <= frame_right + 0.5 and 5.0 + 20 <= _anchor(e)[1] <= 5.0 + 35]
        assert len(cell) == 1, (path.name, cell)
        assert (cell[0].strip() == Sheet.NO_SCALE) == example.startswith("crane"), (path.name, cell)


def _anchor(e):
    a = e.dxf.align_point if e.dxftype() == "TEXT" and e.dxf.hasattr("align_point") else e.dxf.insert
    return a.x, a.y
