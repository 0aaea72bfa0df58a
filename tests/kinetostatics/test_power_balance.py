"""Random slider-cranks with masses, inertia and gravity: the balancing moment equals the power
balance M_ур·ω1 = dT/dt − Σ P_ext, with the kinetic energy T = Σ(½m·v_S² + ½J·ω²) differentiated
numerically along the crank angle — independent of the d'Alembert loads of reportgen.loads."""
from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings, strategies as st

from reportgen.kinetostatics import balancing_moment_cycle, virtual_power_moment

from .cases import slider_crank


def kinetic_energy(p, phi):
    kin = p.kinematics_at(phi)
    T = np.zeros(phi.size)
    for k in p.linkage.moving:
        b = p.linkage.bodies[k]
        v = np.asarray(kin.coms[k].vel)
        T += 0.5 * b.mass * (v * v).sum(1) + 0.5 * b.inertia * np.asarray(kin.links[k].omega) ** 2
    return T


@settings(max_examples=30, deadline=None)
@given(r=st.floats(0.05, 0.2), lam=st.floats(1.5, 5.0), e_frac=st.floats(-0.3, 0.3), omega=st.floats(2.0, 40.0),
       sgn=st.sampled_from([1.0, -1.0]), m2=st.floats(0.5, 20.0), m3=st.floats(0.5, 30.0),
       force=st.floats(-3000.0, 3000.0), phi_deg=st.floats(0.0, 360.0))
def test_balancing_moment_is_the_power_balance(r, lam, e_frac, omega, sgn, m2, m3, force, phi_deg):
    p = slider_crank(r, lam * r, e_frac * r, omega=sgn * omega, m2=m2, j2=m2 * (lam * r) ** 2 / 12, m3=m3,
                     force=force)
    phi = np.array([math.radians(phi_deg)])
    M = balancing_moment_cycle(p, phi)
    h = 1e-5
    dT = (kinetic_energy(p, phi + h) - kinetic_energy(p, phi - h)) / (2 * h)     # dT/dφ
    kin = p.kinematics_at(phi)
    M_ext = virtual_power_moment(p.loads_at(kin, inertia=False), kin)  # −P_ext/ω1
    expected = dT + M_ext                     # M·ω1 = ω1·dT/dφ − P_ext
    scale = abs(force) * r + m3 * omega ** 2 * r * r + m2 * omega ** 2 * r * r + 1.0
    assert abs(M[0] - expected[0]) <= 1e-6 * scale
