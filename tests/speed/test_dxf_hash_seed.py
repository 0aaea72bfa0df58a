"""The DXF bytes of every sheet do not depend on PYTHONHASHSEED (ezdxf wrote its CLASSES section in
the order of a set of type names; drawings.style.fix_classes_order fixes it)."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

SCRIPT = r"""
import sys
from pathlib import Path
from drawings.sheets import available_sheets
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task
project = Project(load_task(sys.argv[1]))
todo = available_sheets(project)
for i, (stem, mod) in enumerate(todo, start=1):
    if stem in sys.argv[3:]:
        draw_sheet(project, mod, i, len(todo)).save(Path(sys.argv[2]) / f"{stem}.dxf")
"""


@pytest.mark.parametrize("stem", ["sheet4-gears", "sheet1-kinematics"])
def test_sheet_dxf_is_the_same_under_different_hash_seeds(tmp_path, stem):
    outs = []
    for seed in ("1", "4"):     # these two seeds order the set of type names differently (old ezdxf order)
        folder = tmp_path / seed
        folder.mkdir()
        subprocess.run([sys.executable, "-c", SCRIPT, str(ROOT / "examples" / "press" / "task.toml"), str(folder),
                        stem], check=True, cwd=ROOT, env=dict(os.environ, PYTHONHASHSEED=seed), timeout=600)
        outs.append((folder / f"{stem}.dxf").read_bytes())
    assert outs[0] == outs[1]
    classes = outs[0].split(b"CLASSES", 1)[1].split(b"ENDSEC", 1)[0]
    assert b"LAYOUT" in classes   # the section is there and holds the classes
