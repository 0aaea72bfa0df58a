"""[gears] eps_min and sa_min: task keys with documented defaults; a failed given pair gets the
passing pair of its blocking contour (issue 12: «the failed gear check»)."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from reportgen.errors import TaskError
from reportgen.gears.pair import from_task, passing_alternative
from reportgen.project import Project
from reportgen.task import Gears
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]


def _task(tmp_path, extra: str):
    f = tmp_path / "task.toml"
    f.write_text(f"[gears]\nz1 = 13\nz2 = 26\nmodule = 9.0\nx1 = 0.63\nx2 = 0.67\n{extra}\n", encoding="utf-8")
    return load_task(f)


def test_defaults_are_the_documented_ones(tmp_path):
    g = _task(tmp_path, "").gears
    assert (g.eps_min, g.sa_min) == (1.2, 0.25)
    doc = (ROOT / "docs" / "task-format-notes.md").read_text(encoding="utf-8")
    assert "eps_min" in doc and "sa_min" in doc and "1.2" in doc and "0.25" in doc


def test_keys_reach_the_checks(tmp_path):
    pair = from_task(_task(tmp_path, "eps_min = 1.05\nsa_min = 0.3").gears)
    assert pair.eps_min == 1.05 and pair.check("contact_ratio").limit == 1.05
    assert pair.check("sharpening1").limit == pytest.approx(0.3 * 9.0)


@pytest.mark.parametrize("line, key", [("eps_min = 0.5", "gears.eps_min"), ("sa_min = -0.1", "gears.sa_min"),
                                       ("eps_min = \"big\"", "gears.eps_min")])
def test_bad_limits_name_the_key(tmp_path, line, key):
    with pytest.raises(TaskError) as err:
        _task(tmp_path, line)
    assert key in str(err.value)


def test_press_uses_seed_000_limit_and_passes_its_own_checks():
    project = Project(load_task(ROOT / "examples" / "press" / "task.toml"))
    assert project.task.gears.eps_min == 1.05
    assert project.gears.all_passed, [c.name for c in project.gears.checks if not c.passed]


def test_a_failing_given_pair_gets_the_passing_pair_of_its_contour():
    given = from_task(Gears(z1=13, z2=26, module=9.0, x1=0.63, x2=0.67))      # εα = 1,152 < 1,2
    assert not given.all_passed
    alt = passing_alternative(given)
    assert alt is not None and alt.all_passed
    assert (alt.eps_min, alt.sa_min_factor) == (given.eps_min, given.sa_min_factor)
    assert alt.shift_choice is not None
    assert passing_alternative(alt) is None                                  # a passing pair needs none
    assert passing_alternative(replace(given, checks=alt.checks)) is None     # all passed → none
