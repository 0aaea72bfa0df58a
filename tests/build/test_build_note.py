"""`reportgen build` end to end on the press example: the PDF, its text against results.json,
records that re-evaluate, no unresolved references, atomic output, failures that keep the right things."""
from __future__ import annotations

import json
import re
import shutil
import subprocess
import unicodedata
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"

pytestmark = pytest.mark.slow


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "reportgen", *args], capture_output=True, text=True,
                          cwd=ROOT, timeout=600)


def pdftext(pdf: Path) -> str:
    txt = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    # NFKC: math italic letters (unicode-math) to plain ones, U+037E to ';'
    return unicodedata.normalize("NFKC", txt).replace("\u2212", "-")


@pytest.fixture(scope="module")
def press_build(tmp_path_factory):
    if shutil.which("latexmk") is None:
        pytest.fail("latexmk is not installed: run `make test` (it installs TeX Live)")
    out = tmp_path_factory.mktemp("press") / "out"
    r = run("build", str(PRESS), "-o", str(out))
    assert r.returncode == 0, r.stderr + r.stdout
    return out, r


def test_outputs_exist(press_build):
    out, r = press_build
    for name in ("report.pdf", "report.tex", "results.json"):
        assert (out / name).is_file(), name
    assert (out / "figures").is_dir()
    # progress with the time of each stage
    assert re.search(r"solve … \d+\.\d\d s", r.stdout) and "LaTeX" in r.stdout
    # nothing left beside OUT
    assert sorted(p.name for p in out.parent.iterdir()) == ["out"]


def test_headings_and_numbers_match_results(press_build):
    out, _ = press_build
    text = pdftext(out / "report.pdf")
    res = json.loads((out / "results.json").read_text(encoding="utf-8"))
    for heading in ("СОДЕРЖАНИЕ", "ВВЕДЕНИЕ", "Структурный анализ механизма", "План положений механизма",
                    "План скоростей", "План ускорений", "Кинематические диаграммы выходного звена",
                    "ЗАКЛЮЧЕНИЕ", "СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ"):
        assert heading.lower() in text.lower(), heading
    s = res["structure"]
    assert f"= {s['W']}" in text and "I(0,1) → II(2,3) → II(4,5)" in text
    k = res["kinematics"]
    work = k["extremes"]["working_stroke_deg"]
    assert f"{work:.1f}".replace(".", ",") in text
    # the speed of the crank pin: ω1·l_OA = 18·0,11 = 1,98 m/s
    assert re.search(r"18 [·⋅] 0,11 = 1,98", text)
    # every position's crank angle appears in the positions table
    for phi in k["phi_deg"]:
        assert f"{phi:.2f}".replace(".", ",") in text, phi
    # angular velocities of the analysed position (table of all positions, 3 decimals)
    w3 = k["links"]["3"]["omega"][2]
    assert f"{w3:.3f}".replace(".", ",").replace("-", "-") in text


def test_no_unresolved_references(press_build):
    out, _ = press_build
    text = pdftext(out / "report.pdf")
    assert "??" not in text
    log = next((out / "latex-build").glob("*.log")).read_text(encoding="utf-8", errors="replace") \
        if (out / "latex-build").exists() else ""
    assert "undefined references" not in log and "Rerun to get" not in log


def test_every_displayed_substitution_re_evaluates():
    from latex_templates import NoteBuilder
    from latex_templates.compose import compose
    from latex_templates.render import Strings
    from reportgen.calc import evaluate_displayed
    from reportgen.project import Project
    from reportgen.taskfile import load_task
    import tempfile
    project = Project(load_task(PRESS))
    sections, _ = compose(project, Strings("ru"), only=("linkage",))
    note = NoteBuilder(project.task.document)
    for s in sections:
        note.add_section(s.section)
    with tempfile.TemporaryDirectory() as d:
        note.render(d)
    assert len(note.records) >= 20
    bad = [r.symbol for r in note.records if not evaluate_displayed(r).ok]
    assert not bad


def test_failed_latex_keeps_tex_and_log(tmp_path):
    out = tmp_path / "out"
    r = run("build", str(PRESS), "-o", str(out), "--no-sheets", "--latexmk", str(tmp_path / "no-such-latexmk"))
    assert r.returncode == 1, r.stderr
    assert not out.exists()
    failed = tmp_path / "out.failed"
    assert (failed / "report.tex").is_file()
    assert str(failed) in r.stderr and "Traceback" not in r.stderr


def test_bad_input_leaves_nothing(tmp_path):
    bad = tmp_path / "task.toml"
    bad.write_text(PRESS.read_text(encoding="utf-8").replace("omega = 18.0", "omega = \"fast\""), encoding="utf-8")
    out = tmp_path / "out"
    r = run("build", str(bad), "-o", str(out))
    assert r.returncode == 2 and "mechanism.drive.omega" in r.stderr and "Traceback" not in r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["task.toml"]


def test_old_output_is_replaced_only_when_new_is_complete(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "old.txt").write_text("old", encoding="utf-8")
    from reportgen.commands.outdir import write_manifest
    write_manifest(out)  # an earlier output of reportgen's (a foreign folder is refused: test_output_folders)
    r = run("build", str(PRESS), "-o", str(out), "--no-pdf", "--no-sheets", "--quiet")
    assert r.returncode == 0, r.stderr
    assert not (out / "old.txt").exists() and (out / "report.tex").is_file()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
