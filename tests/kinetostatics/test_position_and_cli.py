"""The analysed position (--force-at, force_position index, "max-load"), the near-dead-centre
warning, bad input, and `reportgen solve … --force-at`."""
from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from reportgen.errors import OptionError, ReportgenInputError, TaskError
from reportgen.kinetostatics import force_angle, kinetostatics_at
from reportgen.kinetostatics.analysis import MAX_LOAD_GRID, resistance_magnitude
from reportgen.project import Project

from .cases import EXAMPLES, example, four_bar

ROOT = EXAMPLES.parent


def test_force_position_index_and_force_at():
    p = example("press")                       # force_position = 2
    phi, idx = force_angle(p)
    assert idx == 2 and phi == pytest.approx(float(p.phi[2]))
    phi, idx = force_angle(p, 45.0)
    assert phi == pytest.approx(math.radians(45.0)) and idx is None
    phi, idx = force_angle(p, math.degrees(float(p.phi[5])))
    assert idx == 5


def test_force_position_with_at_names_the_task_grid():
    """--at replaces the analysed angles; force_position still names a position of [analysis]."""
    p = example("press", at_deg=[10.0, 20.0])
    phi, idx = force_angle(p)
    assert phi == pytest.approx(float(example("press").phi[2])) and idx is None
    p = example("press", at_deg=[10.0, math.degrees(float(example("press").phi[2]))])
    assert force_angle(p)[1] == 1


def test_force_position_out_of_range():
    from dataclasses import replace
    p = example("press")
    p2 = Project(replace(p.task, analysis=replace(p.task.analysis, force_position=8)))
    with pytest.raises(TaskError) as e:
        force_angle(p2)
    assert "analysis.force_position" in str(e.value)


@pytest.mark.parametrize("bad", [math.nan, math.inf])
def test_bad_force_at(bad):
    with pytest.raises(OptionError) as e:
        force_angle(example("press"), bad)
    assert "--force-at" in str(e.value)


def test_max_load_is_the_largest_resistance():
    text = (EXAMPLES / "press" / "task.toml").read_text(encoding="utf-8").replace(
        "force_position = 2", 'force_position = "max-load"')
    from reportgen.taskfile import loads_task
    p = Project(loads_task(text))
    phi, _ = force_angle(p)
    fine = np.linspace(0.0, 2 * math.pi, 4 * MAX_LOAD_GRID, endpoint=False)
    mag, _ = resistance_magnitude(p, p.kinematics_at(fine))
    at, _ = resistance_magnitude(p, p.kinematics_at(np.array([phi])))
    # the law rises linearly to 15 800 N at the end of the working stroke
    assert at[0] >= mag.max() * 0.995 and at[0] <= 15800.0 * (1 + 1e-12)


def test_max_load_without_resistance():
    p = four_bar(0.1, 0.35, 0.3, 0.4)
    from dataclasses import replace
    p2 = Project(replace(p.task, analysis=replace(p.task.analysis, force_position="max-load")))
    with pytest.raises(ReportgenInputError) as e:
        force_angle(p2)
    assert "analysis.force_position" in str(e.value)


def test_warning_near_a_dead_centre():
    p = four_bar(0.2, 0.3, 0.25, 0.3499)        # a + d just under b + c: μ ≈ 2° at φ = 180°
    near = kinetostatics_at(p, 180.0)
    far = kinetostatics_at(p, 90.0)
    assert near.transmission_deg["2-3"] < 5.0 and len(near.warnings) == 1 and "2-3" in near.warnings[0]
    assert far.warnings == ()
    # reactions grow like 1/sin μ
    r_near = np.hypot(*near.reactions.pair("R12").vector[0])
    r_far = np.hypot(*far.reactions.pair("R12").vector[0])
    assert r_near > 20 * r_far


def run(*args):
    return subprocess.run([sys.executable, "-m", "reportgen", *args], capture_output=True, text=True, cwd=ROOT,
                          timeout=300)


def test_cli_shaper_force_at_45(tmp_path):
    out = tmp_path / "r.json"
    r = run("solve", str(EXAMPLES / "shaper" / "task.toml"), "--force-at", "45", "--json", str(out))
    assert r.returncode == 0, r.stderr
    line = next(l for l in r.stdout.splitlines() if "kinetostatics" in l)
    assert "φ1 = 45.000°" in line and "(groups)" in line and "(Zhukovsky's lever)" in line
    ks = json.loads(out.read_text(encoding="utf-8"))["kinetostatics"]
    assert ks["phi_deg"] == pytest.approx(45.0)
    m, mz = ks["balancing_moment"], ks["balancing_moment_zhukovsky"]
    assert f"{m:.6g}" in line and f"{mz:.6g}" in line
    assert m == pytest.approx(mz, rel=1e-9)
    assert len(ks["cycle"]["balancing_moment"]) == len(ks["cycle"]["phi_deg"]) == 12
    # block 2 in the slot of link 3: R23 is square to the slot
    n = ks["pairs"]["R23"]["normal"]
    R = ks["reactions"]["R23"]
    assert abs(R[0] * n[1] - R[1] * n[0]) <= 1e-9 * math.hypot(*R)


def test_cli_bad_force_at():
    r = run("solve", str(EXAMPLES / "press" / "task.toml"), "--force-at", "nan", "--quiet")
    assert r.returncode == 2 and "--force-at" in r.stderr and "Traceback" not in r.stderr
