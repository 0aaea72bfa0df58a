"""The group method and Zhukovsky's lever (virtual power) give the same balancing moment at every
position of every example; the turned plan's moments are the powers of the forces."""
from __future__ import annotations

import math

import numpy as np
import pytest

from reportgen.kinetostatics import (balancing_cycle, balancing_moment_cycle, solve_reactions,
                                     virtual_power_moment, zhukovsky_lever)
from reportgen.kinetostatics.zhukovsky import point_velocity

from .cases import EXAMPLE_NAMES, example, four_bar

REL = 1e-9


def scale_of(m: np.ndarray) -> float:
    return float(np.abs(m).max())


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_zhukovsky_equals_groups_over_the_cycle(name):
    p = example(name)
    for phi in (p.phi, np.linspace(0.0, 2 * math.pi, 360, endpoint=False)):
        cyc = balancing_cycle(p, phi)
        s = scale_of(cyc.groups)
        assert s > 0
        assert np.abs(cyc.groups - cyc.zhukovsky).max() <= REL * s
        # and both equal the virtual power of the loads computed by reportgen.loads.power
        kin = p.kinematics_at(phi)
        vp = virtual_power_moment(p.loads_at(kin), kin)
        assert np.abs(cyc.groups - vp).max() <= REL * s


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_lever_moment_is_power_of_each_force(name):
    """Turning the plan by −90°: the moment of F about the pole at the image of its point is F·v."""
    p = example(name)
    kin = p.kinematics
    loads = p.loads_at(kin)
    lever = zhukovsky_lever(p.linkage, kin, loads)
    by_name = {f.name: f for f in loads.forces}
    for lf in lever.forces:
        if lf.name in by_name:
            f = by_name[lf.name]
            v = point_velocity(kin, f.link, np.asarray(f.point))
            pw = (np.asarray(f.vector) * v).sum(1)
            assert np.allclose(lf.moment, pw, rtol=1e-12, atol=1e-12 * max(1.0, np.abs(pw).max()))
            # |image| is |v|, turned clockwise: image·v = 0
            assert np.allclose((lf.image * v).sum(1), 0.0, atol=1e-12 * max(1.0, np.abs(v).max() ** 2))
    # a couple replaced by two forces at the ends of its link: their moments add up to M·ω
    for m in loads.moments:
        pair = [lf for lf in lever.forces if lf.source == m.name]
        if pair:
            tot = pair[0].moment + pair[1].moment
            assert np.allclose(tot, np.asarray(m.value) * np.asarray(kin.qd)[:, m.link, 2],
                               atol=1e-9 * max(1.0, np.abs(tot).max()))


def test_cycle_function_for_dynamics():
    p = example("press")
    phi = np.linspace(0, 2 * math.pi, 36, endpoint=False)
    m = balancing_moment_cycle(p, phi)
    assert m.shape == (36,)
    static = balancing_moment_cycle(p, phi, inertia=False)
    # without inertia: −(power of the external loads)/ω1
    kin = p.kinematics_at(phi)
    assert np.allclose(static, virtual_power_moment(p.loads_at(kin, inertia=False), kin),
                       rtol=1e-9, atol=1e-9 * np.abs(static).max())
    assert not np.allclose(m, static)


def test_four_bar_moment_ratio():
    """A couple M3 on the rocker of a four-bar, no other load but gravity and inertia switched off:
    M_ур = −M3·ω3/ω1 (the ratio of angular speeds from the kinematics)."""
    p = four_bar(0.1, 0.35, 0.3, 0.4, moment=-30.0)
    phi = np.radians(np.arange(0.0, 360.0, 7.5))
    kin = p.kinematics_at(phi)
    from reportgen.loads import constant_loads
    loads = constant_loads(p.task.mechanism, kin)
    r = solve_reactions(p.linkage, p.structure, kin, loads)
    w3 = np.asarray(kin.links[3].omega)
    assert np.allclose(r.balancing_moment, 30.0 * w3 / kin.omega1, rtol=1e-9, atol=1e-9 * 30)
    # the coupler carries no load: R12 runs along AB
    A, B = np.asarray(kin.points["A"].pos), np.asarray(kin.points["B"].pos)
    R12 = r.pair("R12").vector
    d = B - A
    assert np.allclose(R12[:, 0] * d[:, 1] - R12[:, 1] * d[:, 0], 0.0, atol=1e-9 * np.abs(R12).max() * 0.35)
