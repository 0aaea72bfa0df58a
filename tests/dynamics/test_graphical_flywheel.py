"""The graphical replica (seed 000's construction) and the flywheel's sizes."""
from __future__ import annotations

import math

import numpy as np
import pytest

from reportgen.dynamics import DynamicsInputError, GraphLayout, ProjectCycle, flywheel_size, graphical_replica
from reportgen.dynamics.graphical import (NICE, READING_MM, flywheel_from_KL, nice_ceil, tangent_slopes,
                                          work_scale)

from .conftest import DYNAMIC_EXAMPLES
from reportgen.scenes.boxes import DEFAULT as DEFAULT_BOXES


def test_seed000_formulas():
    """Seed 000, section 3: μA = 25·0.032725·60 = 49.088 J/mm (its «0.32725» lost a zero);
    ψmax = 15.494°, ψmin = 14.08° for μJ = 0.04, μE = 24.544, ω = 18, δ = 0.05;
    J = 102.418·24.544/(18²·0.05) = 155.17 kg·m²; the disk R = (2J/(πρψ))^0.2 = 0.416 m."""
    assert work_scale(25.0, 0.032725, 60.0) == pytest.approx(49.088, abs=1e-3)
    tmax, tmin = tangent_slopes(0.04, 24.544, 18.0, 0.05)
    assert math.degrees(math.atan(tmax)) == pytest.approx(15.494, abs=1e-3)
    assert math.degrees(math.atan(tmin)) == pytest.approx(14.08, abs=1e-2)
    J = flywheel_from_KL(102.418, 24.544, 18.0, 0.05)
    assert J == pytest.approx(155.17, abs=0.01)
    d = flywheel_size(155.17, "disk", 7860.0, 1.0)
    assert 0.416 <= d.radius < 0.417          # the seed truncates 0.4167 to 0.416
    assert d.width == d.radius


@pytest.mark.parametrize("name", DYNAMIC_EXAMPLES)
def test_replica_agrees_with_exact_within_its_drawing_accuracy(solved, name):
    p, r = solved[name]
    g = r.graphical
    assert abs(g.J_fly - r.J_flywheel) <= g.accuracy
    # the reading error alone is half a millimetre of KL
    assert g.accuracy >= READING_MM * g.mu_E / (r.omega_m ** 2 * r.delta_target)


@pytest.mark.parametrize("name", ["press", "shaper"])
def test_replica_converges_with_more_positions(solved, name):
    p, r = solved[name]
    cyc = ProjectCycle(p)
    errs = [abs(graphical_replica(cyc, r.delta_target, n, layout=DEFAULT_BOXES.diagrams).J_fly - r.J_flywheel) for n in (12, 48, 192)]
    assert errs[2] < errs[0]
    assert errs[2] < 0.01 * r.J_flywheel


@pytest.mark.parametrize("name", DYNAMIC_EXAMPLES)
def test_replica_construction_is_consistent(solved, name):
    p, r = solved[name]
    g = r.graphical
    lay = GraphLayout()
    # positions: from 0 to 2π, the break angles included
    assert g.theta[0] == 0.0 and g.theta[-1] == pytest.approx(2 * math.pi)
    for b in r.breaks:
        assert np.min(np.abs(g.theta - b)) < 1e-12
    # chords: each is parallel to the ray from the pole to the middle ordinate
    np.testing.assert_allclose(np.diff(g.a_mm), g.mid_mm * np.diff(g.x) / g.H, atol=1e-9)
    assert g.mu_A == pytest.approx(g.mu_M * g.mu_phi * g.H)
    assert g.mu_E == pytest.approx(g.mu_A / g.enlargement)
    # the drive's work closes the cycle: ΔE returns to 0
    assert g.e_mm[0] == 0.0 and abs(g.e_mm[-1]) < 1e-9
    # round scales, and the diagrams fit their room on the sheet
    for mu in (g.mu_M, g.mu_J):
        mant = mu / 10 ** math.floor(math.log10(mu))
        assert any(abs(mant - m) < 1e-9 for m in NICE)
    assert np.abs(g.M_mm).max() <= lay.m_height + 1e-9
    assert np.abs(g.a_mm).max() <= lay.a_height + 1e-9
    assert g.e_mm.max() - g.e_mm.min() <= lay.e_height + 1e-9 or g.enlargement == 1
    assert g.j_mm.max() <= lay.j_width + 1e-9
    assert g.H % lay.pole_step == 0
    # the tangents: every point on or under the upper, on or over the lower; KL = K − L
    tmax, tmin = math.tan(math.radians(g.psi_max_deg)), math.tan(math.radians(g.psi_min_deg))
    assert np.all(g.e_mm - g.j_mm * tmax <= g.K_mm + 1e-9)
    assert np.all(g.e_mm - g.j_mm * tmin >= g.L_mm - 1e-9)
    assert g.KL_mm == pytest.approx(g.K_mm - g.L_mm)
    assert g.psi_max_deg > g.psi_min_deg


def test_replica_tangents_agree_with_the_exact_tangent_points(solved):
    """On a fine replica the tangent positions are next to the exact tangent points θ_K, θ_L."""
    p, r = solved["conveyor"]
    g = graphical_replica(ProjectCycle(p), r.delta_target, 360, layout=DEFAULT_BOXES.diagrams)
    assert abs(g.theta[g.index_K] - r.exact.theta_K) < math.radians(2.0)
    assert abs(g.theta[g.index_L] - r.exact.theta_L) < math.radians(2.0)


@pytest.mark.parametrize("x, expected", [(23.0, 25.0), (0.031, 0.04), (5.0, 5.0), (6.0, 10.0), (0.0011, 0.002)])
def test_nice_ceil(x, expected):
    assert nice_ceil(x) == pytest.approx(expected)


@pytest.mark.parametrize("J", [0.5, 58.3, 155.17])
@pytest.mark.parametrize("psi", [0.2, 1.0])
def test_disk_and_rim_give_back_their_J(J, psi):
    d = flywheel_size(J, "disk", 7860.0, psi)
    assert d.mass * d.radius ** 2 / 2 == pytest.approx(J, rel=1e-12)
    assert d.mass == pytest.approx(7860.0 * math.pi * d.radius ** 2 * d.width, rel=1e-12)
    assert d.width == pytest.approx(psi * d.radius)
    rim = flywheel_size(J, "rim", 7860.0, psi)
    R, r_ = rim.radius, rim.inner_radius
    assert rim.thickness == pytest.approx(0.15 * R) and r_ == pytest.approx(R - rim.thickness)
    assert rim.width == pytest.approx(psi * rim.thickness)
    assert rim.mass == pytest.approx(7860.0 * rim.width * math.pi * (R * R - r_ * r_), rel=1e-12)
    assert rim.mass * (R * R + r_ * r_) / 2 == pytest.approx(J, rel=1e-12)
    assert rim.mass < d.mass and rim.radius > d.radius      # a rim carries J with less metal
    # a "rim" as thick as its radius is the disk
    full = flywheel_size(J, "rim", 7860.0, psi, rim_thickness_ratio=1.0)
    assert full.radius == pytest.approx(d.radius) and full.mass == pytest.approx(d.mass)


@pytest.mark.parametrize("kwargs, key", [
    ({"shape": "cone"}, "dynamics.flywheel.shape"),
    ({"density": 0.0}, "dynamics.flywheel.density"),
    ({"density": float("nan")}, "dynamics.flywheel.density"),
    ({"width_ratio": -1.0}, "dynamics.flywheel.width_ratio"),
])
def test_bad_flywheel_input_names_the_key(kwargs, key):
    with pytest.raises(DynamicsInputError) as e:
        flywheel_size(10.0, **kwargs)
    assert e.value.path == key and key in str(e.value)
