"""Sheet 3's positions' numbers (issue 12): on the Wittenbauer curve, and under ΔE(φ), M_red(φ) and
beside J_red(φ), no two texts touch — read back from the DXF, a gap of at least 1 mm — and each
number is beside its own node (tests/labels' rules), for every example with [dynamics] at its own
grid and at 24 positions, where the curve crowds its nodes (class3: «23» on «0», «12» on «13»).

Why the label check of every sheet (tests/labels/test_sheet_labels.py) let them pass: it shrinks
each box by TOUCH_MM before testing overlap (two texts set edge to edge in a table only touch), so
two numbers touching or overlapping by up to half a millimetre are not reported; and the examples'
12-position curves happened to leave room. Here the gap is measured, not the overlap."""
from __future__ import annotations

import re
from dataclasses import replace

import ezdxf
import pytest

from drawings.sheets import dynamics as sheet3
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task
from reportgen.tolerances import LABEL_NEAR_MM
from scene_readback import ROOT

DYNAMIC_EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml")
                          if re.search(r"^\[dynamics\]", p.read_text(encoding="utf-8"), re.M)
                          and not p.parent.name.endswith(("-en", "-uk")))
#: Two texts closer than this (sheet mm) touch for a reader.
GAP_MM = 1.0
VIEWS = ("wittenbauer", "inertia", "energy", "moment")


def _sheet3(name: str, positions: int | None, tmp_path):
    task = load_task(str(ROOT / "examples" / name / "task.toml"))
    if positions is not None:
        task = replace(task, analysis=replace(task.analysis, positions=positions))
    sheet = draw_sheet(Project(task), sheet3, 3, 4)
    sheet.save(tmp_path / "s3.dxf")
    return sheet, ezdxf.readfile(tmp_path / "s3.dxf")


@pytest.mark.parametrize("positions", [None, 24])
@pytest.mark.parametrize("name", DYNAMIC_EXAMPLES)
def test_sheet3_numbers_apart_and_beside_their_nodes(name, positions, tmp_path):
    from labels.readback import check_sheet, sheet_texts

    sheet, doc = _sheet3(name, positions, tmp_path)
    texts = sheet_texts(doc)
    found = []
    for view in VIEWS:
        rect = sheet.views[view].rect.polygon()
        inside = [t for t in texts if t.box.intersects(rect)]
        for i, a in enumerate(inside):
            for b in inside[i + 1:]:
                d = a.box.distance(b.box)
                if d < GAP_MM:
                    found.append(f"{view}: «{a.text}» / «{b.text}» {d:.2f} mm apart")
    found += [str(f) for f in check_sheet(doc, sheet.annotations.labels, LABEL_NEAR_MM)]
    assert not found, "\n".join(found)
