"""`reportgen new`, `batch`, `check` and single positions of a crank that cannot turn fully."""
from __future__ import annotations

import csv
import json
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest

from reportgen import zoo
from reportgen.cli import main


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


# ------------------------------------------------------------------------------------------- new
def test_new_writes_a_task_that_solves(tmp_path):
    out = tmp_path / "t.toml"
    assert main(["new", "--table", "1", "--variant", "1", "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert 'kind = "control-work"' in text and "RECONSTRUCTION" in text
    assert main(["solve", str(out), "--json", str(tmp_path / "r.json")]) == 0
    r = json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))
    assert r["structure"]["W"] == 1


def test_new_never_overwrites_without_force(tmp_path, capsys):
    out = tmp_path / "mine.toml"
    out.write_text("my thesis\n", encoding="utf-8")
    before = _snapshot(tmp_path)
    assert main(["new", "--table", "2", "--variant", "3", "-o", str(out)]) == 2
    assert _snapshot(tmp_path) == before
    assert "exists" in capsys.readouterr().err
    assert main(["new", "--table", "2", "--variant", "3", "-o", str(out), "--force"]) == 0
    assert "variant = 3" in out.read_text(encoding="utf-8")


def test_new_list_example_and_bad_input(tmp_path, capsys):
    assert main(["new", "--list"]) == 0
    listing = capsys.readouterr().out
    assert "table 22" in listing and "press" in listing
    assert main(["new", "--example", "press", "-o", str(tmp_path / "p.toml")]) == 0
    assert "[mechanism]" in (tmp_path / "p.toml").read_text(encoding="utf-8")
    assert main(["new", "--example", "nosuch"]) == 2
    assert main(["new", "--table", "23", "--variant", "1"]) == 2
    assert main(["new", "--table", "1", "--variant", "11"]) == 2
    capsys.readouterr()
    assert main(["new", "--table", "5", "--variant", "7"]) == 2          # flagged: no triangle
    assert "do not form a triangle" in capsys.readouterr().err


# ----------------------------------------------------------------------------------------- batch
def test_batch_three_variants_one_broken(tmp_path, capsys, monkeypatch):
    src = tmp_path / "v.csv"
    src.write_text("table,variant\n1,1\n5,7\n22,3\n", encoding="utf-8")
    out = tmp_path / "keys"
    assert main(["batch", "--csv", str(src), "--answers", "-o", str(out), "-j", "2", "--quiet"]) == 1
    text = capsys.readouterr().out
    assert "2 of 3" in text and "t05-v07" in text
    rows = list(csv.DictReader((out / "answers.csv").open(encoding="utf-8")))
    assert [(r["table"], r["variant"]) for r in rows] == [("1", "1"), ("22", "3")]
    assert float(rows[0]["Py"]) * 0.32 == pytest.approx(float(rows[0]["My"]), rel=1e-5)
    for t in (1, 5, 22):
        assert (out / f"answer-key-table-{t}.pdf").read_bytes().startswith(b"%PDF")
    # the Russian key prints its numbers as the note does: decimal comma, true minus
    key = subprocess.run(["pdftotext", "-layout", str(out / "answer-key-table-1.pdf"), "-"],
                         capture_output=True, text=True, check=True).stdout
    assert re.search(r"\d,\d", key) and "\u2212" in key, key
    assert not re.search(r"\d\.\d", key) and not re.search(r"(?<![\w/])-\d", key), key
    # a re-run does not solve again what did not change
    import reportgen.commands.batch as b
    calls = []
    monkeypatch.setattr(b, "run_job", lambda job, _o, _a: calls.append(job.name) or b.Outcome(job.name))
    assert main(["batch", "--csv", str(src), "--answers", "-o", str(out), "-j", "1", "--quiet"]) == 1
    assert calls == []


def test_batch_refuses_a_folder_of_user_files(tmp_path):
    out = tmp_path / "mine"
    out.mkdir()
    (out / "thesis.txt").write_text("x", encoding="utf-8")
    before = _snapshot(tmp_path)
    assert main(["batch", "--table", "1", "--variants", "1", "--answers", "-o", str(out), "--quiet"]) == 2
    assert _snapshot(tmp_path) == before


def test_batch_progress_line(tmp_path):
    out = tmp_path / "k"
    p = subprocess.run([sys.executable, "-m", "reportgen", "batch", "--table", "3", "--variants", "1-3",
                        "--answers", "-o", str(out), "-j", "1"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "[3/3] failures: 0, ETA" in p.stderr


# ----------------------------------------------------------------------------------------- check
def test_check_marks_one_wrong_value(tmp_path, capsys):
    task = tmp_path / "t.toml"
    assert main(["new", "--table", "1", "--variant", "1", "-o", str(task)]) == 0
    from reportgen.control.analysis import control_work_of
    from reportgen.project import Project
    from reportgen.taskfile import load_task
    exact = control_work_of(Project(load_task(str(task)))).answers()
    good = tmp_path / "good.toml"
    good.write_text(f"omega2 = {exact['omega2'] * 1.03}\nvF = {exact['vF'] * 0.97}\nPy = {exact['Py']}\n",
                    encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(task), str(good)]) == 0
    bad = tmp_path / "bad.csv"
    bad.write_text(f"name,value\nomega2,{exact['omega2']}\naF,{exact['aF'] * 1.08}\n", encoding="utf-8")
    assert main(["check", str(task), str(bad)]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert any(ln.startswith("aF") and ln.endswith("неверно") for ln in lines)
    assert any(ln.startswith("omega2") and ln.endswith(" верно") for ln in lines)
    assert main(["check", str(task), str(bad), "--tolerance", "10"]) == 0
    wrong_sign = tmp_path / "s.toml"
    wrong_sign.write_text(f"omega2 = {-exact['omega2']}\n", encoding="utf-8")
    assert main(["check", str(task), str(wrong_sign)]) == 1
    unknown = tmp_path / "u.toml"
    unknown.write_text("omega9 = 1\n", encoding="utf-8")
    assert main(["check", str(task), str(unknown)]) == 2
    assert main(["check", str(task), str(tmp_path / "missing.toml")]) == 2



@pytest.mark.parametrize("sep", [";", "\t"])
def test_check_reads_a_spreadsheet_of_a_russian_locale(tmp_path, capsys, sep):
    """A spreadsheet in a ru/uk locale saves CSV with ``;`` (or a tab) and a decimal comma; the
    table is printed in the task's decimal mark; a decimal comma in TOML gets a hint."""
    task = tmp_path / "t.toml"
    assert main(["new", "--table", "1", "--variant", "1", "-o", str(task)]) == 0
    from reportgen.control.analysis import control_work_of
    from reportgen.project import Project
    from reportgen.taskfile import load_task
    exact = control_work_of(Project(load_task(str(task)))).answers()
    sheet = tmp_path / "answers.csv"
    comma = f"{exact['vF'] * 0.98:.4f}".replace(".", ",")
    sheet.write_text(f"vF{sep}{comma}\nomega2{sep}{exact['omega2'] * 1.5:.3f}\n", encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(task), str(sheet)]) == 1
    out = capsys.readouterr().out
    vf = next(ln for ln in out.splitlines() if ln.startswith("vF"))
    assert vf.endswith(" верно") and comma in vf and "." not in vf, vf
    assert any(ln.startswith("omega2") and ln.endswith("неверно") for ln in out.splitlines())
    toml = tmp_path / "a.toml"
    toml.write_text(f"vF = {comma}\n", encoding="utf-8")
    assert main(["check", str(task), str(toml)]) == 2
    assert "decimal point" in capsys.readouterr().err

# ------------------------------------------------------------------------------ single positions
NON_GRASHOF = dict(a=0.35, b=0.5, c=0.4, d=0.6)     # 0.35 + 0.6 > 0.5 + 0.4: the crank cannot turn fully


def _four_bar(tmp_path, extra: str = "", analysis=zoo.START_AT_ZERO) -> Path:
    text = zoo.four_bar(**NON_GRASHOF, phi_deg=100.0, omega=10.0, analysis=analysis,
                        links={2: {"mass": 2.0, "inertia": 0.05}, 3: {"mass": 2.0, "inertia": 0.05}}, extra=extra)
    p = tmp_path / "fb.toml"
    p.write_text(text, encoding="utf-8")
    return p


def test_single_position_of_a_crank_that_cannot_turn_fully(tmp_path):
    """Issue 11 item 6: refused before (the extreme positions were searched over the whole turn)."""
    p = _four_bar(tmp_path)
    assert main(["solve", str(p), "--at", "100", "--force-at", "100", "--json", str(tmp_path / "r.json")]) == 0
    r = json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))
    assert r["kinetostatics"]["phi_deg"] == pytest.approx(100.0)
    assert r["kinematics"]["phi_deg"] == [pytest.approx(100.0)]


def test_full_cycle_stages_are_refused_with_the_feasible_range(tmp_path, capsys):
    p = _four_bar(tmp_path, extra="[dynamics]\ndelta = 0.05\ncrank_inertia = 0.1\n")
    assert main(["solve", str(p), "--at", "100"]) == 2
    err = capsys.readouterr().err
    assert "[dynamics]" in err and "assembles only for φ1 in" in err and "…" in err
    p = _four_bar(tmp_path, analysis={"start": "extreme"})
    assert main(["solve", str(p)]) == 2
    assert "extreme" in capsys.readouterr().err


def test_feasible_range_of_the_non_grashof_four_bar():
    """The range where |AC| ≤ b + c, from the closed form |AC|² = a² + d² − 2ad·cos φ."""
    from reportgen.project import Project
    from reportgen.taskfile import loads_task
    pr = Project(loads_task(zoo.four_bar(**NON_GRASHOF, phi_deg=100.0, omega=10.0)))
    a, b, c, d = NON_GRASHOF.values()
    limit = math.degrees(math.acos((a * a + d * d - (b + c) ** 2) / (2 * a * d)))
    (lo, hi), = pr.feasible_deg
    assert not pr.full_cycle
    assert hi == pytest.approx(limit, abs=0.5) and lo == pytest.approx(360.0 - limit, abs=0.5)
