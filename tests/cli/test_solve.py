"""`reportgen solve` end to end: results.json per RESULTS_FORMAT.md, exit statuses, no traceback."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "reportgen", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT, timeout=300)


def test_version():
    r = run("--version")
    assert r.returncode == 0 and r.stdout.startswith("reportgen ")


def test_press_results(tmp_path):
    out = tmp_path / "out.json"
    r = run("solve", str(EXAMPLES / "press" / "task.toml"), "--json", str(out))
    assert r.returncode == 0, r.stderr
    assert "I(0,1) → II(2,3) → II(4,5)" in r.stdout
    data = json.loads(out.read_text(encoding="utf-8"))
    assert data["format"] == "reportgen-results/1"
    s = data["structure"]
    assert (s["n"], s["p1"], s["p2"], s["W"]) == (5, 7, 0, 1)
    assert [g["links"] for g in s["groups"]] == [[1], [2, 3], [4, 5]]
    k = data["kinematics"]
    n = len(k["phi_deg"])
    assert n == 8
    for name in ("O", "A", "B", "C", "D"):
        for key in ("pos", "vel", "acc"):
            assert len(k["points"][name][key]) == n and len(k["points"][name][key][0]) == 2
    for link in ("1", "2", "3", "4", "5"):
        assert set(k["links"][link]) == {"angle_deg", "omega", "epsilon"}
    assert set(k["transmission_angle_deg"]) == {"2-3", "4-5"}
    assert 185.0 < k["extremes"]["working_stroke_deg"] < 195.0
    # position 0 is the start of the working stroke; the crank runs at ω1 = 18 rad/s
    assert k["phi_deg"][0] == pytest.approx(k["extremes"]["phi_start_deg"] % 360.0)
    assert k["links"]["1"]["omega"] == [18.0] * n


def test_at_angles(tmp_path):
    out = tmp_path / "o.json"
    r = run("solve", str(EXAMPLES / "shaper" / "task.toml"), "--json", str(out), "--at", "0", "45", "90")
    assert r.returncode == 0, r.stderr
    k = json.loads(out.read_text(encoding="utf-8"))["kinematics"]
    assert k["phi_deg"] == pytest.approx([0.0, 45.0, 90.0])


def test_same_task_same_bytes(tmp_path):
    a, b = tmp_path / "a.json", tmp_path / "b.json"
    run("solve", str(EXAMPLES / "conveyor" / "task.toml"), "--json", str(a), "--quiet")
    run("solve", str(EXAMPLES / "conveyor" / "task.toml"), "--json", str(b), "--quiet")
    assert a.read_bytes() == b.read_bytes()


@pytest.mark.parametrize("text, fragment", [
    ("[mechanism]\nname = 1\n", "mechanism"),
    ("[mechanis]\n", "mechanism"),
    ("this is not toml ===", "line"),
])
def test_bad_input_exit_2_without_traceback(tmp_path, text, fragment):
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    out = tmp_path / "o.json"
    r = run("solve", str(task), "--json", str(out))
    assert r.returncode == 2
    assert "Traceback" not in r.stderr and fragment in r.stderr
    assert not out.exists()


def test_cannot_assemble_is_exit_2(tmp_path):
    text = (EXAMPLES / "crank-slider" / "task.toml").read_text(encoding="utf-8")
    text = text.replace("length = 0.30", "length = 0.09")     # rod shorter than the crank
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    r = run("solve", str(task), "--json", str(tmp_path / "o.json"))
    assert r.returncode == 2, r.stderr
    assert "cannot be assembled" in r.stderr and "φ1" in r.stderr and "Traceback" not in r.stderr


def test_missing_file_is_exit_2(tmp_path):
    r = run("solve", str(tmp_path / "nope.toml"))
    assert r.returncode == 2 and "Traceback" not in r.stderr
