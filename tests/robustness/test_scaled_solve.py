"""Every linkage example scaled — lengths × k, masses × m, crank speed × w, forces × f, each over four
decades (0.01 … 100) — is either solved by ``reportgen solve`` or refused with exit 2 and a one-line
message (never a traceback, never exit 1). A solved task obeys the identities the suite checks
(closure of every pair, equilibrium of every link, the balancing moment of the groups = Zhukovsky's
lever = the power balance of the loads: tests/hard_cases/test_hard_stages.check_kinetostatics and
reportgen.kinetostatics.virtual_power_moment) and the scaling laws against the example itself:
points' positions × k, velocities × k·w, accelerations × k·w², the links' ω × w and ε × w²; under
dynamic similarity (f = m·k·w², g × k·w²) every reaction × f, the balancing moment and M_drive × f·k,
J_flywheel × m·k², δ achieved unchanged."""
from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, strategies as st

from reportgen.cli import main
from reportgen.dynamics import dynamics_of
from reportgen.errors import ReportgenInputError
from reportgen.kinetostatics import solve_reactions, virtual_power_moment
from reportgen.project import Project
from reportgen.taskfile import load_task, loads_task

from .scaling import EXAMPLES, LINKAGE_EXAMPLES, Factors, robustness_settings, scaled, similar

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "hard_cases"))
from test_hard_stages import check_kinetostatics  # noqa: E402

#: One decade each way of a factor is drawn uniformly in its logarithm.
FACTOR = st.floats(-2.0, 2.0).map(lambda e: float(10.0 ** e))
#: Relative agreement of a scaled quantity with its law (the solvers converge to ~1e-12; the
#: positions of the strokes are found by a root search to EXTREME_XTOL).
REL = 1e-7
#: The crank angles at which the identities are checked: the analysed positions and a few more.
EXTRA_DEG = (17.0, 133.0, 251.0)
SETTINGS = robustness_settings()

_BASE: dict[str, Project] = {}


def base(name: str, g0: bool = False) -> Project:
    """The example itself (``g0``: without gravity, the reference of the similar tasks)."""
    key = name + (":g0" if g0 else "")
    if key not in _BASE:
        _BASE[key] = Project(loads_task(scaled(name, similar(1.0, 1.0, 1.0))) if g0 else
                             load_task(EXAMPLES / name / "task.toml"))
    return _BASE[key]


def solve_cli(tmp_path: Path, text: str, capsys) -> tuple[int, str, Path]:
    """``reportgen solve`` on the task text: its exit status, its stderr and the results' path."""
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    out = tmp_path / "results.json"
    if out.exists():
        out.unlink()
    capsys.readouterr()
    code = main(["solve", str(task), "--json", str(out), "--quiet"])
    return code, capsys.readouterr().err, out


def assert_refused_cleanly(code: int, err: str, out: Path, project_error: Exception | None) -> None:
    assert code == 2, f"exit {code}: {err}"
    assert "Traceback" not in err and err.strip().count("\n") == 0, err
    assert not out.exists(), "a refused task writes no results.json"
    assert isinstance(project_error, ReportgenInputError), repr(project_error)


def _angles(project: Project) -> np.ndarray:
    return np.concatenate((np.asarray(project.phi), np.radians(EXTRA_DEG)))


def check_identities(project: Project, phi: np.ndarray) -> None:
    kin, r, _ = check_kinetostatics(project, phi, tol=1e-8)
    vp = virtual_power_moment(project.loads_at(kin), kin)
    M = np.asarray(r.balancing_moment)
    assert np.abs(M - vp).max() <= 1e-8 * max(np.abs(vp).max(), np.abs(M).max())


def check_kinematic_laws(project: Project, ref: Project, phi: np.ndarray, k: float, w: float) -> None:
    a, b = project.kinematics_at(phi), ref.kinematics_at(phi)
    for name, pm in b.points.items():
        qm = a.points[name]
        for got, want, s in ((qm.pos, pm.pos, k), (qm.vel, pm.vel, k * w), (qm.acc, pm.acc, k * w * w)):
            want = np.asarray(want) * s
            np.testing.assert_allclose(np.asarray(got), want, rtol=REL, atol=REL * np.abs(want).max(),
                                       err_msg=f"point {name}")
    for i, lm in b.links.items():
        for got, want, s in ((a.links[i].omega, lm.omega, w), (a.links[i].epsilon, lm.epsilon, w * w)):
            want = np.asarray(want) * s
            np.testing.assert_allclose(np.asarray(got), want, rtol=REL, atol=REL * np.abs(want).max() + 1e-300,
                                       err_msg=f"link {i}")


def _project_or_error(text: str) -> tuple[Project | None, Exception | None]:
    from reportgen.results import build_results
    try:
        project = Project(loads_task(text))
        build_results(project)              # every stage results.json holds, as `solve` computes them
        return project, None
    except ReportgenInputError as exc:
        return None, exc


@SETTINGS
@given(name=st.sampled_from(LINKAGE_EXAMPLES), k=FACTOR, m=FACTOR, w=FACTOR, f=FACTOR)
def test_scaled_example_is_solved_or_refused(tmp_path, capsys, name, k, m, w, f):
    text = scaled(name, Factors(k, m, w, f))
    code, err, out = solve_cli(tmp_path, text, capsys)
    project, error = _project_or_error(text)
    if project is None:
        assert_refused_cleanly(code, err, out, error)
        return
    assert code == 0, err
    json.loads(out.read_text(encoding="utf-8"))
    phi = _angles(base(name))
    check_identities(project, phi)
    check_kinematic_laws(project, base(name), phi, k, w)
    assert np.allclose(project.phi, base(name).phi, rtol=0, atol=1e-9)      # the same positions


@SETTINGS
@given(name=st.sampled_from(LINKAGE_EXAMPLES), k=FACTOR, m=FACTOR, w=FACTOR)
def test_dynamically_similar_example_scales_every_force(name, k, m, w):
    fac = similar(k, m, w)
    project, error = _project_or_error(scaled(name, fac, drop=("gears", "planetary")))
    assert project is not None, error
    ref = base(name, g0=True)
    phi = _angles(ref)
    kin, kref = project.kinematics_at(phi), ref.kinematics_at(phi)
    r = solve_reactions(project.linkage, project.structure, kin, project.loads_at(kin))
    rr = solve_reactions(ref.linkage, ref.structure, kref, ref.loads_at(kref))
    want = np.asarray(rr.balancing_moment) * fac.f * k
    np.testing.assert_allclose(r.balancing_moment, want, rtol=REL, atol=REL * np.abs(want).max())
    for p, q in zip(r.pairs, rr.pairs):
        assert p.name == q.name
        want = np.asarray(q.vector) * fac.f
        np.testing.assert_allclose(p.vector, want, rtol=REL, atol=REL * np.abs(want).max(), err_msg=p.name)
    if ref.task.dynamics is not None:
        d, dr = dynamics_of(project), dynamics_of(ref)
        assert d.J_flywheel == pytest.approx(dr.J_flywheel * m * k * k, rel=1e-6)
        assert d.M_drive == pytest.approx(dr.M_drive * fac.f * k, rel=1e-9)
        assert d.delta_achieved == pytest.approx(dr.delta_achieved, rel=1e-6)
        # the sheet's scales are round numbers each (not similar), but the replica still reads the
        # flywheel within its own drawing accuracy (as tests/dynamics checks for the examples)
        assert abs(d.graphical.J_fly - d.J_flywheel) <= d.graphical.accuracy


def test_the_helper_scales_what_it_says():
    """Factors 1 give back the example; lengths × 2 double a link and a point, masses × 3 a mass."""
    import tomllib
    one = tomllib.loads(scaled("press", Factors()))
    two = tomllib.loads(scaled("press", Factors(k=2.0, m=3.0, w=5.0, f=7.0)))
    assert two["mechanism"]["points"]["A"] == [2 * x for x in one["mechanism"]["points"]["A"]]
    assert two["mechanism"]["link"][1]["length"] == 2 * one["mechanism"]["link"][1]["length"]
    assert two["mechanism"]["link"][1]["mass"] == 3 * one["mechanism"]["link"][1]["mass"]
    assert two["mechanism"]["link"][1]["inertia"] == pytest.approx(12 * one["mechanism"]["link"][1]["inertia"])
    assert two["mechanism"]["drive"]["omega"] == 5 * one["mechanism"]["drive"]["omega"]
    assert two["mechanism"]["load"][0]["force"] == 7 * one["mechanism"]["load"][0]["force"]
    assert two["mechanism"]["mass_rules"]["q"] == pytest.approx(1.5 * one["mechanism"]["mass_rules"]["q"])
    assert two["dynamics"]["crank_inertia"] == pytest.approx(12 * one["dynamics"]["crank_inertia"])
    assert two["gears"] == one["gears"] and two["mechanism"]["g"] == one["mechanism"]["g"]
