"""``[analysis] plan_positions``: read as given, refused with the key named (exit 2) when out of
range, repeated, without the kinetostatics position, or of the wrong type; left out it is None
(the default rule of ``Project.plan_positions``)."""
from __future__ import annotations

import subprocess
import sys

import pytest

from reportgen.taskfile import parse_task

from taskfile_cases import edit, example, expect_error

KEY = ("analysis", "plan_positions")


def test_left_out_is_the_default_rule():
    assert parse_task(example()).analysis.plan_positions is None


def test_given_positions_are_read():
    data = edit(example(), KEY, [2, 6])
    assert parse_task(data).analysis.plan_positions == (2, 6)


@pytest.mark.parametrize("value, path, fragments", [
    ([2, 8], "analysis.plan_positions[1]", ["got 8", "0…7"]),
    ([2, -1], "analysis.plan_positions[1]", ["0…7"]),
    ([2, 2], "analysis.plan_positions", ["a position twice", "distinct"]),
    ([1, 5], "analysis.plan_positions", ["without force_position = 2", "hold 2"]),
    ([], "analysis.plan_positions", ["has 0 elements", "1 to 3"]),
    ([2, 3, 4, 5], "analysis.plan_positions", ["has 4 elements", "1 to 3"]),
    ("auto", "analysis.plan_positions", ['the string "auto"', "an array"]),
    ([2, 6.0], "analysis.plan_positions[1]", ["the float 6.0"]),
])
def test_bad_plan_positions(value, path, fragments):
    expect_error(edit(example(), KEY, value), path, *fragments)


def test_max_load_needs_no_position_among_them():
    data = edit(edit(example(), ("analysis", "force_position"), "max-load"), KEY, [1, 5])
    assert parse_task(data).analysis.plan_positions == (1, 5)


def test_cli_exit_2_names_the_key(tmp_path):
    from pathlib import Path
    src = Path(__file__).resolve().parents[2] / "examples" / "press" / "task.toml"
    text = src.read_text(encoding="utf-8").replace("force_position = 2", "force_position = 2\nplan_positions = [3, 5]")
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "reportgen", "build", str(task), "-o", str(out), "--no-pdf"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 2, r.stderr
    assert "analysis.plan_positions" in r.stderr and "Traceback" not in r.stderr
    assert not out.exists()
