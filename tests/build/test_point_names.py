"""Issue 11: any point name a student types works. The press with Cyrillic names ("О", "А", "В",
"С", "Д", and "О₁" for the crank axis) gives the same numbers as with Latin ones, a note whose
velocity table has one distinct row per vector (was: every row "V̄", formulas "V̄ = V̄ + V̄" — the math
font has no Cyrillic), figures without missing glyphs (was: a box for "₁").
"""
from __future__ import annotations

import io
import json
import re
import shutil
import subprocess
import sys
import unicodedata
import warnings
from pathlib import Path

import pytest

from reportgen.project import Project
from reportgen.results import build_results, dumps
from reportgen.taskfile import loads_task

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"
CYRILLIC = {"O": "О₁", "A": "А", "B": "В", "C": "С", "D": "Д"}


def renamed_press(names: dict[str, str]) -> str:
    text = PRESS.read_text(encoding="utf-8")
    text = re.sub(r'"([OABCD])"', lambda m: json.dumps(names[m.group(1)], ensure_ascii=False), text)
    return re.sub(r"^([OABCD]) = \[", lambda m: json.dumps(names[m.group(1)], ensure_ascii=False) + " = [",
                  text, flags=re.M)


def test_same_numbers_with_cyrillic_names():
    latin = build_results(Project(loads_task(PRESS.read_text(encoding="utf-8"), source="task.toml")))
    cyr = build_results(Project(loads_task(renamed_press(CYRILLIC), source="task.toml")))
    back = dumps(cyr)
    for lat, cy in sorted(CYRILLIC.items(), key=lambda kv: -len(kv[1])):
        back = back.replace(f'"{cy}"', f'"{lat}"')
    assert json.loads(back) == json.loads(dumps(latin))


def test_figures_have_every_glyph():
    from latex_templates.compose import compose
    from latex_templates.render import Strings

    project = Project(loads_task(renamed_press(CYRILLIC)))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sections, _ = compose(project, Strings("ru"))
        n = 0
        for s in sections:
            for fig in s.section.figures.values():
                if hasattr(fig, "savefig"):
                    fig.savefig(io.BytesIO(), format="pdf")
                    n += 1
    assert n >= 10
    missing = sorted({str(w.message) for w in caught if "missing from font" in str(w.message)
                      or "does not have a glyph" in str(w.message)})
    assert not missing


@pytest.mark.slow
def test_note_keeps_cyrillic_subscripts(tmp_path):
    if shutil.which("latexmk") is None:
        pytest.fail("latexmk is not installed: run `make test` (it installs TeX Live)")
    task = tmp_path / "task.toml"
    task.write_text(renamed_press(CYRILLIC), encoding="utf-8")
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "reportgen", "build", str(task), "-o", str(out), "--quiet",
                        "--no-sheets"], capture_output=True, text=True, cwd=ROOT, timeout=900)
    assert r.returncode == 0, r.stderr
    log = next((out / "latex-build").glob("*.log")).read_text(encoding="utf-8", errors="replace")
    assert "Missing character" not in log
    raw = subprocess.run(["pdftotext", "-layout", str(out / "report.pdf"), "-"], capture_output=True,
                         text=True, check=True).stdout
    text = unicodedata.normalize("NFKC", raw)
    start = text.index("Отрезки плана скоростей")
    rows = [ln.split()[0] for ln in text[start:].splitlines()[1:40] if re.match(r"\s*V̄\S", ln)]
    assert rows[:5] == ["V̄А", "V̄ВА", "V̄ВС", "V̄ДВ", "V̄Д"], rows
    # the crank axis О₁ keeps its subscript in the formulas (l_О₁А), and nowhere a bare "V̄ ="
    assert "О1А" in text and not re.search(r"V̄ = V̄ \+ V̄", text)
