"""The scene layer: the one round-scale rule, ГОСТ scales, the plan and positions scenes built from
the stages (pure: no plotting, no DXF)."""
from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from reportgen.plans import closure_error
from reportgen.project import Project
from reportgen.scenes.boxes import SceneBoxes
from reportgen.scenes.scales import (FORCE_SERIES, GOST_SCALES, PLAN_SERIES, gost_scale, round_scale,
                                     round_up)
from reportgen.scenes.scene import Arrow
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3")


def _mantissa(mu: float) -> float:
    return mu / 10.0 ** math.floor(math.log10(mu) + 1e-12)


@settings(suppress_health_check=[HealthCheck.too_slow], deadline=None)   # a loaded machine draws slowly
@given(st.floats(1e-6, 1e6), st.sampled_from([50.0, 100.0, 200.0, 450.0]),
       st.sampled_from([PLAN_SERIES, FORCE_SERIES]))
def test_round_scale_is_round_and_draws_within_the_box(value, max_mm, series):
    mu = round_scale(value, max_mm, series)
    assert value / mu <= max_mm * (1 + 1e-9)
    # the next smaller round value would overrun: the drawing is at least max/2.5 long
    assert value / mu > max_mm / 2.5 * (1 - 1e-9)
    assert any(math.isclose(_mantissa(mu), m, rel_tol=1e-9) or math.isclose(_mantissa(mu), 10 * m, rel_tol=1e-9)
               for m in series)


def test_round_scale_golden():
    # by hand: 3,29 м/с within 100 мм needs μ ≥ 0,0329 → 0,04 (82,3 мм); with 1, 2, 2.5, 5 → 0,05
    assert round_scale(3.29, 100.0) == 0.04
    assert round_scale(3.29, 100.0, FORCE_SERIES) == 0.05
    assert round_scale(98.7, 100.0) == 1.0
    assert round_scale(0.75, 300.0, FORCE_SERIES) == 0.0025
    assert round_up(0.0031) == 0.004
    assert round_up(0.0031, FORCE_SERIES) == 0.005


def test_gost_scale_largest_that_fits():
    k, text = gost_scale(0.9, 0.5, 414.0, 326.0)       # 0,9 м wide: 1:2,5 draws 360 mm
    assert (k, text) == (400.0, "1:2,5")
    assert all(1000.0 * p / r <= 400.0 for p, r in GOST_SCALES[GOST_SCALES.index((1, 2.5)):])


@pytest.fixture(scope="module", params=EXAMPLES)
def project(request):
    return Project(load_task(ROOT / "examples" / request.param / "task.toml"))


def test_plan_scenes_are_the_plans(project):
    v, a = project.plans
    for plan, scene in ((v, project.scenes.velocity_plan), (a, project.scenes.acceleration_plan)):
        assert closure_error(plan) < 1e-9
        assert scene.scale().value == plan.scale
        arrows = {e.id: e for e in scene.entities if isinstance(e, Arrow)}
        for c in plan.components:
            assert scene.values[c.name] == plan.measured_mm(c)
            # a computed component (aⁿ, aᵏ) shorter than LEGIBLE_MM is not laid off (docs/kinematics.md)
            assert (c.name in arrows) == plan.drawn(c)
            if c.name in arrows:
                assert arrows[c.name].length == pytest.approx(plan.length_mm(c), abs=1e-9)
        # every vector label sits at the middle of its own arrow
        for lb in scene.labels:
            if lb.role == "vector":
                e = arrows[lb.anchor]
                assert math.dist(lb.at, ((e.a[0] + e.b[0]) / 2, (e.a[1] + e.b[1]) / 2)) < 1e-9


def test_positions_scene_at_the_sheet_scale(project):
    sc = project.scenes.positions
    mu = sc.scale("μl")
    x0, y0, x1, y1 = sc.bounds()
    box = project.boxes.scheme
    # the labels' points and the hinge circles lie within the box the scale was chosen for
    assert x1 - x0 <= box[0] + 10.0 and y1 - y0 <= box[1] + 10.0
    lk = project.linkage
    l_crank = math.dist(lk.bodies[lk.drive_link].local[lk.drive_axis], lk.bodies[lk.drive_link].local[lk.drive_tip])
    assert sc.values[f"{lk.drive_axis}{lk.drive_tip}"] == pytest.approx(l_crank / mu.value)
    # the bold analysed position: each link drawn at its length / μl
    i = project.analysed
    for k in lk.moving:
        names = lk.bodies[k].points
        if len(names) == 2:
            seg = sc.entity(f"pos{i}:link{k}:{names[0]}{names[1]}")
            assert seg.length == pytest.approx(math.dist(*(lk.bodies[k].local[n] for n in names)) / mu.value)


def test_boxes_are_passed_in():
    p = Project(load_task(ROOT / "examples" / "press" / "task.toml"), boxes=SceneBoxes(scheme=(150.0, 120.0)))
    q = Project(load_task(ROOT / "examples" / "press" / "task.toml"))
    assert p.scenes.positions.scale().value > q.scenes.positions.scale().value


def test_lever_scene_draws_the_balancing_force(project):
    """F_ур is drawn on the lever at the image of the crank pin, and with it the lever balances:
    Σ (image × F) + Σ M·ω about the pole = 0 (Zhukovsky)."""
    import numpy as np

    from reportgen.scenes.lever import lever_scene
    ks = project.kinetostatics
    sc = lever_scene(ks, project.linkage)
    fb = sc.entity("force:Fур")
    pin = np.asarray(ks.lever.crank_pin_image)[0] / ks.graphical.lever.scale
    # drawn at the pin's image: pulling it (tail there) or pushing it (head there)
    assert min(math.dist(fb.a, tuple(pin)), math.dist(fb.b, tuple(pin))) < 1e-9
    F = np.asarray(ks.reactions.balancing_force)[0]
    d = np.subtract(fb.b, fb.a)
    assert float(np.dot(d, F)) > 0 and abs(float(d[0] * F[1] - d[1] * F[0])) < 1e-6 * float(np.hypot(*d) * np.hypot(*F))
    total = sum(float(np.asarray(f.moment)[0]) for f in ks.lever.forces)
    total += sum(float(np.asarray(x[2])[0]) for x in ks.lever.direct)
    total += float(np.asarray(ks.lever.crank_pin_image)[0] @ np.array([-F[1], F[0]])) * -1.0
    assert abs(total) < 1e-9 * max(1.0, sum(abs(float(np.asarray(f.moment)[0])) for f in ks.lever.forces))
    # every force is named beside its own arrow
    for lb in sc.labels:
        if lb.role == "vector" and lb.anchor.startswith("force:"):
            e = sc.entity(lb.anchor)
            assert lb.along == (e.a, e.b)


def test_polygon_scenes_name_their_own_vectors(project):
    from reportgen.scenes.forces import LEADER_MM, polygon_scene
    g = project.kinetostatics.graphical
    for poly in [gg.polygon for gg in g.groups] + [g.crank.polygon]:
        sc = polygon_scene(poly)
        assert sc.scale().value == poly.scale
        for lb in sc.labels:
            if lb.role != "vector":        # a detail's letter and heading (tests/scenes/test_polygons_legible.py)
                continue
            e = sc.entity(lb.anchor)
            assert lb.along == (e.a, e.b)
            assert lb.leader == (e.length < LEADER_MM)
        # the sides close the polygon: the last head is the first tail
        sides = [e for e in sc.entities if e.id.startswith("vec:")]
        assert math.dist(sides[0].a, sides[-1].b) < 0.5
