"""results.json's ``dynamics`` block: the contract's keys, and enough to re-integrate the motion."""
from __future__ import annotations

import json
import math

import numpy as np

from reportgen.project import Project
import pytest

from reportgen.dynamics import DynamicsInputError, dynamics_block, solve_dynamics
from reportgen.results import _clean, build_results, dumps

from .conftest import DYNAMIC_EXAMPLES, project_of

CONTRACT = ("phi_deg", "M_red", "J_red", "work_resistance", "work_drive", "delta_E", "M_drive", "J_flywheel",
            "delta_target", "delta_achieved", "flywheel")


@pytest.mark.parametrize("name", DYNAMIC_EXAMPLES)
def test_block_has_the_contract_keys(solved, name):
    p, r = solved[name]
    b = json.loads(dumps(_clean(dynamics_block(r))))
    assert list(b)[:len(CONTRACT)] == list(CONTRACT)
    for k in ("phi_deg", "M_red", "J_red", "work_resistance", "work_drive", "delta_E", "omega", "rotation_deg"):
        assert len(b[k]) >= 360
    assert set(b["flywheel"]) >= {"shape", "radius", "width", "mass"}
    assert b["flywheel"]["shape"] == p.task.dynamics.flywheel.shape
    assert b["phi_deg"][0] == pytest.approx(math.degrees(p.kinematics.phi[0]) % 360.0)
    assert all(0.0 <= x < 360.0 for x in b["phi_deg"])
    assert {c["method"] for c in b["comparison"]} == {"exact", "merzalov", "graphical"}


def reintegrate(b: dict) -> float:
    """δ from the block alone: ½(J_red + J_fly)ω² = ½J(0)ω0² + ΔE with ω_m = (ω_max + ω_min)/2."""
    J = np.asarray(b["J_red"]) + b["J_flywheel"]
    E = np.asarray(b["delta_E"])
    wm = b["omega_m"]
    lo, hi = -2 * E.min(), 10 * J.max() * wm * wm
    for _ in range(200):                                # bisection on u = J(0)·ω0²
        u = 0.5 * (lo + hi)
        w = np.sqrt((u + 2 * E) / J)
        lo, hi = (u, hi) if 0.5 * (w.max() + w.min()) < wm else (lo, u)
    w = np.sqrt((u + 2 * E) / J)
    return (w.max() - w.min()) / (0.5 * (w.max() + w.min()))


@pytest.mark.parametrize("name", DYNAMIC_EXAMPLES)
def test_anyone_can_reintegrate_the_motion_from_the_file(solved, name):
    p, r = solved[name]
    b = json.loads(dumps(_clean(dynamics_block(r))))
    assert reintegrate(b) == pytest.approx(b["delta_target"], rel=0.01)
    assert b["delta_achieved"] == pytest.approx(b["delta_target"], rel=1e-6)
    # ΔE is the sum of the two works, and the drive's work is linear
    np.testing.assert_allclose(np.asarray(b["work_drive"]) + b["work_resistance"], b["delta_E"], atol=1e-9)
    np.testing.assert_allclose(b["work_drive"], b["M_drive"] * np.radians(b["rotation_deg"]), rtol=1e-12)


def test_build_results_has_dynamics_only_with_the_section():
    p = project_of("crank-slider")
    out = build_results(p, ("structure", "kinematics", "dynamics"))
    assert "dynamics" in out and out["dynamics"]["delta_target"] == p.task.dynamics.delta
    assert "dynamics" not in build_results(p, ("structure", "kinematics"))
    # the class III example without its [dynamics] section
    import dataclasses
    p3 = Project(dataclasses.replace(project_of("class3").task, dynamics=None))
    assert p3.task.dynamics is None
    assert "dynamics" not in build_results(p3, ("structure", "kinematics", "dynamics"))
    with pytest.raises(DynamicsInputError) as e:
        solve_dynamics(p3)
    assert e.value.path == "dynamics"


@pytest.mark.parametrize("delta", [0.0, -0.1, 1.5, float("nan")])
def test_bad_delta_names_the_key(delta):
    import dataclasses
    from reportgen.project import Project
    p = project_of("crank-slider")
    task = dataclasses.replace(p.task, dynamics=dataclasses.replace(p.task.dynamics, delta=delta))
    with pytest.raises(DynamicsInputError) as e:
        solve_dynamics(Project(task))
    assert e.value.path == "dynamics.delta"


def test_negative_crank_inertia_names_the_key():
    import dataclasses
    from reportgen.project import Project
    p = project_of("crank-slider")
    task = dataclasses.replace(p.task, dynamics=dataclasses.replace(p.task.dynamics, crank_inertia=-1.0))
    with pytest.raises(DynamicsInputError) as e:
        solve_dynamics(Project(task))
    assert e.value.path == "dynamics.crank_inertia"


def test_same_task_same_numbers(solved):
    p, r = solved["press"]
    again = solve_dynamics(project_of("press"))
    assert dumps(_clean(dynamics_block(again))) == dumps(_clean(dynamics_block(r)))
