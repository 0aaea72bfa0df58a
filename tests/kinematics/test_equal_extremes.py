"""An output that reaches its extreme value twice a turn (equal by construction): the extreme taken
does not depend on round-off. Found by tests/robustness: class3 scaled × 0.1 or × 100 (the same
mechanism) had its working stroke 206.2° from φ1 = 10.8° instead of 204.2° from 217.1°, so position 0
and the stroke under resistance moved by half a turn."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from reportgen.kinematics.extremes import _extreme_indices
from reportgen.project import Project
from reportgen.taskfile import load_task, loads_task

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests"))
from robustness.scaling import Factors, scaled  # noqa: E402


@pytest.mark.parametrize("eps", [-4e-16, 0.0, 4e-16])
def test_equal_maxima_the_last_before_the_minimum(eps):
    roots = [math.radians(d) for d in (10.8, 33.0, 61.2, 217.1)]
    rx = np.array([0.0115, 0.0053, 0.0115 + eps, -0.428])
    assert _extreme_indices(roots, rx, 1.0) == (2, 3)
    # turning the other way, the last maximum before the minimum is the other one
    assert _extreme_indices(roots, rx, -1.0) == (0, 3)


def test_distinct_maxima_are_not_tied():
    roots = [0.1, 1.0, 2.0, 4.0]
    rx = np.array([1.0, 0.5, 1.0 - 1e-6, -1.0])
    assert _extreme_indices(roots, rx, 1.0) == (0, 3)


@pytest.mark.parametrize("k", [0.1, 100.0])
def test_class3_scaled_has_the_examples_strokes(k):
    ref = Project(load_task(ROOT / "examples" / "class3" / "task.toml")).strokes
    s = Project(loads_task(scaled("class3", Factors(k=k)))).strokes
    assert s.working_deg == pytest.approx(ref.working_deg, abs=1e-9)
    assert s.phi_start == pytest.approx(ref.phi_start, abs=1e-9)
    assert s.stroke == pytest.approx(ref.stroke, abs=1e-12)
