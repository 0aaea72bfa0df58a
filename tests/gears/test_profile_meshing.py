"""Generated teeth against the analytic involute; the meshing picture's geometry."""
import math

import numpy as np
import pytest
from shapely.geometry import LineString, Point, Polygon

from reportgen.gears.checks import x_min
from reportgen.gears.meshing import contact_zones, meshing_picture, suggest_scale
from reportgen.gears.pair import solve_gear_pair
from reportgen.gears.profile import generate_tooth, pair_teeth

A20 = math.radians(20.0)


@pytest.fixture(scope="module")
def seed_pair():
    return solve_gear_pair(13, 26, 9.0, 0.63, 0.67)


@pytest.fixture(scope="module")
def seed_teeth(seed_pair):
    return pair_teeth(seed_pair)


def test_simulated_thickness_matches_analytic(seed_pair, seed_teeth):
    p = seed_pair
    t1, t2 = seed_teeth
    # pitch circle: s = m (π/2 + 2 x tg α); tip circle: sa from the involute function
    assert t1.thickness(t1.r) == pytest.approx(p.s1, abs=1e-3)
    assert t2.thickness(t2.r) == pytest.approx(p.s2, abs=1e-3)
    assert t1.thickness(p.da1 / 2 * (1 - 1e-7)) == pytest.approx(p.sa1, abs=2e-3)
    assert t2.thickness(p.da2 / 2 * (1 - 1e-7)) == pytest.approx(p.sa2, abs=2e-3)
    # the whole flank above the boundary point l lies on the involute (scallops < 1 µm per side)
    for t, rho_l, ra in ((t1, p.rho_l1, p.da1 / 2), (t2, p.rho_l2, p.da2 / 2)):
        r_l = math.hypot(t.rb, rho_l)
        dev = t.involute_deviation(np.linspace(r_l + 1e-3, ra * 0.999, 25))
        assert np.max(np.abs(dev)) < 1e-3


def test_root_circle_of_simulation(seed_pair, seed_teeth):
    for t, df in zip(seed_teeth, (seed_pair.df1, seed_pair.df2)):
        r_min = np.hypot(t.outline[:, 0], t.outline[:, 1]).min()
        assert r_min == pytest.approx(df / 2, abs=1e-5 * seed_pair.m)  # the rack tip line, sampled


def test_undercut_shows_in_simulation():
    # z = 8, x = 0: x_min = 1 − 8 sin²20°/2 = 0.532, the tooth is undercut just above the base circle
    m = 1.0
    t = generate_tooth(8, m, 0.0, A20, 1.0, 0.25, 0.38, 8 / 2 + m)
    dev = t.involute_deviation(np.linspace(t.rb * 1.001, t.rb * 1.05, 20))
    assert dev.min() < -0.01 * m
    # with x ≥ x_min the involute is intact from the base circle up
    x = float(x_min(8, A20, 1.0)) + 0.01
    t = generate_tooth(8, m, x, A20, 1.0, 0.25, 0.38, 4 + (1 + x) * m)
    dev = t.involute_deviation(np.linspace(t.rb * 1.001, t.ra * 0.995, 30))
    assert np.max(np.abs(dev)) < 2e-4 * m


def test_meshing_picture_contacts(seed_pair):
    p = seed_pair
    pic = meshing_picture(p)
    assert len(pic.teeth1) >= 3 and len(pic.teeth2) >= 3
    # εα from the drawing (a and b constructed in the frame) equals the analytic one
    assert pic.eps_alpha_drawn == pytest.approx(p.eps_alpha, rel=1e-10)
    # the pole is on the line of centres at rw1, N1P = rb1 tg αw
    P, N1, N2 = (np.array(pic.points[k]) for k in ("P", "N1", "N2"))
    assert P[1] == pytest.approx(p.dw1 / 2)
    assert np.linalg.norm(P - N1) == pytest.approx(p.n1p, rel=1e-12)
    assert np.linalg.norm(N2 - N1) == pytest.approx(p.g, rel=1e-12)
    # the pair at P touches: both outlines pass through P
    line1 = [LineString(t) for t in pic.teeth1]
    line2 = [LineString(t) for t in pic.teeth2]
    assert min(l.distance(Point(P)) for l in line1) < 2e-3
    assert min(l.distance(Point(P)) for l in line2) < 2e-3
    # teeth do not overlap (zero backlash, no interference): closing each outline with its centre
    poly1 = Polygon(np.vstack([np.asarray(t) for t in pic.teeth1] + [np.array([[0.0, 0.0]])])).buffer(0)
    poly2 = Polygon(np.vstack([np.asarray(t) for t in pic.teeth2] + [np.array([[0.0, p.aw]])])).buffer(0)
    assert poly1.intersection(poly2).area < 0.05 * p.m  # scallop slivers only (mm²)
    # the second pair, one pb from P along N1N2, is in contact too when it lies inside ab
    u = (N2 - N1) / np.linalg.norm(N2 - N1)
    a = np.array(pic.points["a"])
    for q in (P - p.pb * u, P + p.pb * u):
        if 0 <= (q - a) @ u <= p.ab:
            assert min(l.distance(Point(q)) for l in line1) < 2e-3
            assert min(l.distance(Point(q)) for l in line2) < 2e-3


def test_contact_zones():
    # 1 < εα < 2: double – single – double, the single zone is 2 pb − ab long
    z = contact_zones(1.5, 1.0)
    assert [n for *_, n in z] == [2, 1, 2]
    assert z[1][1] - z[1][0] == pytest.approx(0.5)
    # εα < 1: single contact and a gap
    assert [n for *_, n in contact_zones(0.8, 1.0)] == [1, 0]
    # 2 < εα < 3
    assert [n for *_, n in contact_zones(2.4, 1.0)] == [3, 2, 3, 2, 3]


def test_suggest_scale():
    assert suggest_scale(120.0, 300.0) == 2.5
    assert suggest_scale(500.0, 300.0) == 0.5
