"""The scenes of section 3 (reportgen.scenes.dynamics) are the construction of the graphical
method: the two tangents from K and L leave every point of ΔE(J) between them and touch it at the
tangent positions, KL read back gives the replica's flywheel, the φ axes of M, A, ΔE and the turned
J_red(φ) have one length, and μω draws ω(φ) within its room."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from reportgen.dynamics.graphical import KL_DECIMALS
from reportgen.numbers import decimal_text

from reportgen.project import Project
from reportgen.scenes.dynamics import MU_E, MU_OMEGA
from reportgen.scenes.scene import Polyline, Segment
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module", params=("press", "shaper", "conveyor"))
def project(request):
    return Project(load_task(ROOT / "examples" / request.param / "task.toml"))


def _line_at(seg: Segment, x: float) -> float:
    (x0, y0), (x1, y1) = seg.a, seg.b
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0)


def test_tangents_bound_the_curve_and_touch_it(project):
    sc = project.scenes.dynamics
    w = sc.wittenbauer
    curve, up, lo = w.entity("curve"), w.entity("tangent:K"), w.entity("tangent:L")
    assert isinstance(curve, Polyline) and isinstance(up, Segment) and isinstance(lo, Segment)
    tol = 1e-9
    for x, y in curve.points:
        assert _line_at(lo, x) - tol <= y <= _line_at(up, x) + tol
    iK, iL = int(w.values["index_K"]), int(w.values["index_L"])
    assert curve.points[iK][1] == pytest.approx(_line_at(up, curve.points[iK][0]), abs=1e-9)
    assert curve.points[iL][1] == pytest.approx(_line_at(lo, curve.points[iL][0]), abs=1e-9)
    # the slopes are the course's ψ
    assert math.degrees(math.atan2(up.b[1] - up.a[1], up.b[0] - up.a[0])) == pytest.approx(w.values["psi_max_deg"])
    assert math.degrees(math.atan2(lo.b[1] - lo.a[1], lo.b[0] - lo.a[0])) == pytest.approx(w.values["psi_min_deg"])


def test_flywheel_read_back_from_KL(project):
    res = project.dynamics
    w = project.scenes.dynamics.wittenbauer
    KL = w.entity("KL")
    assert isinstance(KL, Segment)
    # KL is read off the drawing to its dimension's 0,1 mm, and J follows from the value read
    read = float(decimal_text(KL.length, KL_DECIMALS))
    assert w.values["KL_read_mm"] == read == res.graphical.KL_read_mm
    J = read * w.scale(MU_E).value / (res.omega_m ** 2 * res.delta_target)
    assert J == pytest.approx(res.graphical.J_fly, rel=1e-12)
    assert w.values["J_fly"] == pytest.approx(J, rel=1e-12)


def test_one_phi_axis_and_omega_within_its_room(project):
    sc = project.scenes.dynamics
    ends = []
    for s in (sc.moment, sc.work, sc.energy):
        c = s.entity("curve")
        assert isinstance(c, Polyline)
        ends.append(c.points[-1][0])
    j = sc.inertia.entity("curve")
    assert isinstance(j, Polyline)
    ends.append(-j.points[-1][1])
    assert max(ends) - min(ends) < 1e-9
    om = sc.omega
    c = om.entity("curve")
    assert isinstance(c, Polyline)
    room = project.boxes.diagrams.omega_height
    assert max(abs(p[1]) for p in c.points) <= room * (1 + 1e-9)
    band = om.entity("band:max")
    assert isinstance(band, Segment)
    assert band.a[1] * om.scale(MU_OMEGA).value == pytest.approx(om.values["omega_max"] - om.values["omega_m"])
