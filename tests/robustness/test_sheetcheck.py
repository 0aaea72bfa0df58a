"""The frame check of tests/robustness/sheetcheck.py finds what it looks for."""
from __future__ import annotations

from drawings.sheet import Sheet
from reportgen.taskfile import load_task

from .scaling import EXAMPLES
from .sheetcheck import outside_frame


def test_a_line_beyond_the_frame_is_found_the_trim_outline_is_not():
    sheet = Sheet.a1(load_task(EXAMPLES / "press" / "task.toml").document, title="t", code="c")
    assert outside_frame(sheet) == []
    fr = sheet.frame
    sheet.msp.add_line((fr.x0 + 10, fr.y0 + 10), (fr.x1 + 3, fr.y0 + 10))
    sheet.msp.add_circle((fr.x0 + 50, fr.y1), 2.0)
    found = outside_frame(sheet)
    assert len(found) == 2 and found[0].startswith("LINE") and found[1].startswith("CIRCLE")
