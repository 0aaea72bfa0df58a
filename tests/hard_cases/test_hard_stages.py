"""Hard cases through the later stages (issue #8): each is either solved correctly — checked by
identities that do not depend on the solver (equilibrium of every link, the balancing moment by the
groups equal to Zhukovsky's lever, closed forms, exact scaling, the δ really achieved) — or refused
with the crank angle and the violated condition. The kinematics of the near change point, r/l = 0.99,
the cannot-assemble case and kinematic scaling are in tests/kinematics/test_hard_cases.py.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from reportgen import zoo
from reportgen.dynamics import dynamics_of, solve_dynamics
from reportgen.errors import AssemblyError, TaskError
from reportgen.gears.pair import solve_gear_pair
from reportgen.gears.results import gears_block
from reportgen.kinematics.constraints import all_pair_constraints, residual
from reportgen.kinetostatics import solve_reactions, zhukovsky_lever
from reportgen.project import Project
from reportgen.results import build_results, dumps
from reportgen.taskfile import load_task, loads_task

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
PHI = np.radians(np.arange(0.0, 360.0, 1.0))


# -- task texts ----------------------------------------------------------------------------------------

def four_bar(a: float, b: float, c: float, d: float, k: float = 1.0, phi_deg: float = 90.0,
             dynamics: str = "[dynamics]\ndelta = 0.05\ncrank_inertia = 0.5\n") -> str:
    """Crank–rocker O–A–B–C with masses, a resisting moment on the rocker and gravity off, every
    length × k (masses kept: forces ∝ k, moments and inertias ∝ k²)."""
    return zoo.four_bar(
        a * k, b * k, c * k, d * k, phi_deg=phi_deg, omega=12.0, name=None, g=0.0,
        links={1: {"mass": 2.0, "inertia": 0.01 * k * k}, 2: {"mass": 5.0, "inertia": 0.05 * k * k},
               3: {"mass": 4.0, "inertia": 0.04 * k * k}},
        loads=[{"kind": "resistance", "link": 3, "moment": 400.0 * k * k,
                "law": [[0.0, 0.3], [0.5, 1.0], [1.0, 0.3]], "stroke": "working"}],
        analysis={"positions": 12, "start": "extreme", "force_position": 3},
        extra=dynamics.replace("crank_inertia = 0.5", f"crank_inertia = {0.5 * k * k!r}"))


def slider_crank(r: float, l: float, e: float = 0.0, phi_deg: float = 30.0) -> str:
    return zoo.slider_crank(
        r, l, e, phi_deg=phi_deg, omega=15.0, name=None,
        links={2: {"mass": 6.0, "inertia": 0.08}, 3: {"mass": 20.0}},
        loads=[{"kind": "resistance", "link": 3, "force": 5000.0, "law": [[0.0, 0.0], [0.2, 1.0], [1.0, 1.0]],
                "stroke": "working"}],
        analysis={"positions": 12, "start": "extreme"}, extra="[dynamics]\ndelta = 0.04\ncrank_inertia = 0.3\n")


def slotted_lever(r: float, d: float, L: float = 1.0, phi_deg: float = 30.0) -> str:
    """Crank O–A (r) with O at (0, d) above the slotted link's pivot C; block 2 at A in the slot C→E."""
    return zoo.slotted_lever(
        r, d, L, phi_deg=phi_deg, omega=10.0, name=None, links={2: {"mass": 1.0}, 3: {"mass": 8.0, "inertia": 0.7}},
        loads=[{"kind": "moment", "link": 3, "value": -50.0}], analysis={"positions": 12, "start": 0.0})


# -- identities -----------------------------------------------------------------------------------------

def check_kinetostatics(project: Project, phi=PHI, tol: float = 1e-9):
    """Every link in equilibrium; the balancing moment of the groups equals Zhukovsky's lever; all
    finite. Tolerances relative to the largest force and moment in play."""
    kin = project.kinematics_at(phi)
    assert np.abs(residual(all_pair_constraints(project.linkage), np.asarray(kin.q))).max() < 1e-10 * _size(project)
    loads = project.loads_at(kin)
    r = solve_reactions(project.linkage, project.structure, kin, loads)
    z = zhukovsky_lever(project.linkage, kin, loads)
    M, Mz = np.asarray(r.balancing_moment), np.asarray(z.balancing_moment)
    assert np.isfinite(M).all() and np.isfinite(Mz).all()
    scale = np.abs(Mz).max()
    assert np.abs(M - Mz).max() <= tol * scale
    F_scale = max(float(np.hypot(*np.asarray(f.vector).T).max()) for f in loads.forces)
    for k in project.linkage.moving:
        F, Mk = r.residuals(k)
        assert np.isfinite(F).all() and np.isfinite(Mk).all()
        assert np.hypot(*np.asarray(F).T).max() <= tol * F_scale * 10
    return kin, r, z


def _size(project: Project) -> float:
    return max(math.hypot(*p) for p in project.linkage.sketch.values()) or 1.0


def check_results_finite(project: Project) -> dict:
    res = build_results(project)
    dumps(res)        # allow_nan=False: raises on NaN or infinity
    return res


# -- near change point, r/l = 0.99: through kinetostatics and dynamics ----------------------------------

def test_four_bar_near_change_point_kinetostatics_and_dynamics():
    s, l, p = 0.1, 0.35, 0.25
    q = (s + l) / 0.999 - p             # s + l = 0.999·(p + q)
    project = Project(loads_task(four_bar(s, p, q, l)))
    kin, r, z = check_kinetostatics(project)
    mu = kin.transmission_deg["2-3"]
    assert mu.min() < 6.0
    # the reactions grow like 1/sin μ near the toggle but stay finite and balanced
    worst = int(np.argmin(mu))
    R = max(float(np.hypot(*np.asarray(pr.vector)[worst])) for pr in r.pairs)
    assert math.isfinite(R) and R > 0
    d = dynamics_of(project)
    assert d.delta_achieved == pytest.approx(d.delta_target, rel=1e-6)
    assert d.J_flywheel > 0
    check_results_finite(project)


def test_slider_crank_r_over_l_099_kinetostatics_and_dynamics():
    project = Project(loads_task(slider_crank(0.099, 0.1, 0.0)))
    kin, r, z = check_kinetostatics(project)
    d = dynamics_of(project)
    assert d.delta_achieved == pytest.approx(d.delta_target, rel=1e-6)
    # one cycle's work of the resistance equals −F·s·∫law exactly (the stroke is 2r)
    assert project.strokes.stroke == pytest.approx(0.198, rel=1e-12)
    assert d.work_cycle == pytest.approx(-5000.0 * 0.198 * 0.9, rel=1e-9)
    check_results_finite(project)


# -- slotted link whose pivot nearly touches the crank circle -------------------------------------------

@pytest.mark.parametrize("ratio", [1.001, 0.999, 1.0 + 1e-5])
def test_slotted_link_pivot_near_crank_circle(ratio):
    """ω3 = r·ω1·(r + d·sin φ)/(r² + d² + 2rd·sin φ): up to r·ω1/|r − d| = 1000·ω1 (1e5·ω1) at φ1 = −90°."""
    r, w = 0.1, 10.0
    d = r * ratio
    project = Project(loads_task(slotted_lever(r, d)))
    phi = np.concatenate((PHI, [math.radians(270.0)]))
    kin, _, _ = check_kinetostatics(project, phi, tol=1e-8)
    one_sin = 1.0 + np.sin(phi)      # written without cancellation: r² + d² + 2rd·sin φ = (r − d)² + 2rd(1 + sin φ)
    w3 = r * w * ((r - d) + d * one_sin) / ((r - d) ** 2 + 2 * r * d * one_sin)
    assert np.allclose(kin.links[3].omega, w3, rtol=1e-9, atol=1e-12 * np.abs(w3).max())
    assert abs(kin.links[3].omega[-1]) == pytest.approx(r * w / abs(r - d), rel=1e-6)
    assert np.isfinite(np.asarray(kin.qdd)).all()
    check_results_finite(project)


# -- class III group near a singular position ----------------------------------------------------------

def _class3(r: float) -> Project:
    text = (EXAMPLES / "class3" / "task.toml").read_text(encoding="utf-8")
    text = text.replace("A = [0.1, 0.0]", f"A = [{r!r}, 0.0]").replace("length = 0.10", f"length = {r!r}")
    return Project(loads_task(text))


def test_class3_near_singular_position_is_solved_and_flagged():
    """A crank of 0.1170 m: 0.2 % below the length at which the triad jams (~0.11727 m)."""
    project = _class3(0.1170)
    kin, _, _ = check_kinetostatics(project, PHI, tol=1e-7)
    mu = kin.transmission_deg["2-3-4-5"]
    assert mu.min() < 10.0
    assert all(m < 5.0 for _, _, m in kin.near_singular)
    # velocities agree with a central difference of the positions (the solver never differentiates)
    phi = np.radians([30.0, 100.0, 200.0, 300.0])
    h = 1e-6
    qp, qm = project.kinematics_at(phi + h).q, project.kinematics_at(phi - h).q
    qd = project.kinematics_at(phi).qd
    fd = (np.asarray(qp) - np.asarray(qm)) / (2 * h) * project.model.omega
    assert np.abs(fd - np.asarray(qd)).max() < 1e-5 * np.abs(np.asarray(qd)).max()
    check_results_finite(project)


def test_class3_past_singular_position_is_refused_with_the_crank_angle():
    with pytest.raises(AssemblyError) as ei:
        _class3(0.1180).kinematics_at(PHI)
    e = ei.value
    assert e.group.startswith("III(2,3,4,5)") and 0.0 <= e.phi_deg <= 360.0
    assert "cannot be assembled at crank angle φ1 =" in str(e) and "residual" in e.inequality


# -- exact scaling through kinetostatics and dynamics --------------------------------------------------

@pytest.mark.parametrize("k", [1e-3, 1e3])
def test_scaled_mechanism_scales_exactly(k):
    """Lengths × k, inertias and moments × k², masses kept: forces × k, moments × k², J × k², δ alike."""
    base = Project(loads_task(four_bar(0.1, 0.35, 0.3, 0.4)))
    big = Project(loads_task(four_bar(0.1, 0.35, 0.3, 0.4, k=k)))
    phi = np.radians(np.arange(0.0, 360.0, 7.0))
    _, r1, _ = check_kinetostatics(base, phi)
    _, rk, _ = check_kinetostatics(big, phi)
    assert np.allclose(rk.balancing_moment, k * k * np.asarray(r1.balancing_moment), rtol=1e-9,
                       atol=1e-12 * k * k * np.abs(r1.balancing_moment).max())
    for p1, pk in zip(r1.pairs, rk.pairs):
        assert p1.name == pk.name
        f1 = np.asarray(p1.vector)
        assert np.allclose(np.asarray(pk.vector), k * f1, rtol=1e-9, atol=1e-12 * k * np.abs(f1).max())
    d1, dk = solve_dynamics(base), solve_dynamics(big)
    assert dk.J_flywheel == pytest.approx(k * k * d1.J_flywheel, rel=1e-9)
    assert dk.M_drive == pytest.approx(k * k * d1.M_drive, rel=1e-9)
    assert dk.delta_achieved == pytest.approx(d1.delta_achieved, rel=1e-7)
    assert np.allclose(dk.J_red, k * k * np.asarray(d1.J_red), rtol=1e-9)


@pytest.mark.parametrize("k", [1e-3, 1e3])
def test_scaled_gear_pair_scales_exactly(k):
    g1 = solve_gear_pair(13, 26, 9.0, 0.63, 0.67).geometry
    gk = solve_gear_pair(13, 26, 9.0 * k, 0.63, 0.67).geometry
    for name in ("aw", "a", "d1", "d2", "db1", "da1", "da2", "df1", "df2", "s1", "s2", "sa1", "sa2", "pb", "ab"):
        assert getattr(gk, name) == pytest.approx(k * getattr(g1, name), rel=1e-12), name
    assert gk.eps_alpha == pytest.approx(g1.eps_alpha, rel=1e-12)
    assert gk.alpha_w_deg == pytest.approx(g1.alpha_w_deg, rel=1e-13)


# -- gears with 6…9 teeth -------------------------------------------------------------------------------

def _gear_identities(pair) -> None:
    g = pair.geometry
    alpha = math.radians(g.alpha_deg)
    assert g.aw * math.cos(math.radians(g.alpha_w_deg)) == pytest.approx(g.a * math.cos(alpha), rel=1e-12)
    assert g.dw1 + g.dw2 == pytest.approx(2 * g.aw, rel=1e-12)
    assert g.db1 == pytest.approx(g.d1 * math.cos(alpha), rel=1e-12)
    assert g.eps_alpha == pytest.approx(g.ab / g.pb, rel=1e-12)
    assert g.pb == pytest.approx(math.pi * g.m * math.cos(alpha), rel=1e-12)
    block = gears_block(pair)
    dumps(block)     # no NaN or infinity (allow_nan=False)


@pytest.mark.parametrize("z1", [6, 7, 8, 9])
def test_small_pinion_unshifted_is_solved_and_its_undercut_reported(z1):
    pair = solve_gear_pair(z1, 2 * z1, 5.0, 0.0, 0.0)
    _gear_identities(pair)
    failed = [c for c in pair.checks if not c.passed]
    assert failed, "z < 17 without a shift must fail the undercut check"
    assert all(math.isfinite(c.value) and math.isfinite(c.limit) for c in pair.checks)


@pytest.mark.parametrize("z1", [6, 7, 8])
def test_small_pinion_auto_shifts_refused_with_the_inequalities(z1):
    with pytest.raises(TaskError) as ei:
        solve_gear_pair(z1, 2 * z1, 5.0, "auto", "auto")
    msg = str(ei.value)
    assert ei.value.path == "gears.x1"
    assert f"z1 = {z1}" in msg and "εα ≥ 1.2" in msg and "sa ≥ 0.25·m" in msg and "no undercut" in msg


def test_nine_teeth_auto_shifts_pass_every_check():
    pair = solve_gear_pair(9, 18, 5.0, "auto", "auto")
    _gear_identities(pair)
    assert all(c.passed for c in pair.checks), [c.title for c in pair.checks if not c.passed]
    assert pair.geometry.x1 > 0.4


# -- δ = 1/500 --------------------------------------------------------------------------------------------

def test_flywheel_for_delta_one_five_hundredth():
    text = (EXAMPLES / "press" / "task.toml").read_text(encoding="utf-8")
    assert "delta = 0.05" in text
    fine = Project(loads_task(text.replace("delta = 0.05", "delta = 0.002")))
    coarse = Project(load_task(EXAMPLES / "press" / "task.toml"))
    df, dc = dynamics_of(fine), dynamics_of(coarse)
    assert df.delta_achieved == pytest.approx(0.002, rel=1e-5)
    # J_fly + J_red,mean ∝ 1/δ for a small δ: 25 times the flywheel, within the variable part of J_red
    assert 20 * dc.J_flywheel < df.J_flywheel < 30 * dc.J_flywheel
    omega = np.asarray(df.motion.omega)
    assert np.isfinite(omega).all()
    assert (omega.max() - omega.min()) / df.omega_m == pytest.approx(0.002, rel=0.05)   # on the grid
    assert df.flywheel.radius > dc.flywheel.radius and math.isfinite(df.flywheel.mass)
    check_results_finite(fine)
