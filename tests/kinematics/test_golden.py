"""Golden values from independent sources: closed-form textbook formulas and published examples."""
from __future__ import annotations

import math

import numpy as np
import pytest

from reportgen.kinematics.extremes import find_strokes

from .zoo import four_bar, model_from_text, slider_crank, slotted_lever


def test_slotted_lever_extreme_positions_khurmi():
    """Khurmi & Gupta, «Theory of Machines», crank and slotted lever quick-return mechanism: fixed
    centres 240 mm apart, crank 120 mm → the slotted bar is inclined 30° to the vertical at its
    extreme positions and the cutting/return time ratio is 2 (240°/120°)."""
    m = model_from_text(slotted_lever(0.120, 0.240, L=0.5))
    st = find_strokes(m)
    assert st.output.kind == "rocker" and st.output.link == 3
    assert st.working_deg == pytest.approx(240.0, rel=1e-4)
    assert st.idle_deg == pytest.approx(120.0, rel=1e-4)
    assert st.time_ratio == pytest.approx(2.0, rel=1e-4)
    r = m.solve([st.phi_start, st.phi_end])
    incl = np.degrees(np.abs(r.links[3].angle - math.pi / 2))
    assert incl == pytest.approx([30.0, 30.0], rel=1e-4)
    assert math.degrees(st.stroke) == pytest.approx(60.0, rel=1e-4)


def test_slotted_lever_against_closed_form_and_coriolis():
    """ψ = atan2(A − C); ψ̇ = (A×Ȧ)/|A|²; the block's speed along the slot is (A·Ȧ)/|A| and the
    Coriolis acceleration 2·ψ̇·v_rel shows in the slot's angular acceleration (closed form below)."""
    r_, d, w = 0.1, 0.3, 12.0
    m = model_from_text(slotted_lever(r_, d, L=0.6, omega=w))
    phi = np.radians(np.arange(0.0, 360.0, 17.0))
    res = m.solve(phi)
    A = np.stack((r_ * np.cos(phi), d + r_ * np.sin(phi)), -1)
    Ad = w * np.stack((-r_ * np.sin(phi), r_ * np.cos(phi)), -1)
    Add = -w * w * np.stack((r_ * np.cos(phi), r_ * np.sin(phi)), -1)
    n2 = (A ** 2).sum(1)
    psi = np.arctan2(A[:, 1], A[:, 0])
    psid = (A[:, 0] * Ad[:, 1] - A[:, 1] * Ad[:, 0]) / n2
    # ψ̈ = (A×Ä)/|A|² − 2 (A·Ȧ)(A×Ȧ)/|A|⁴  — the second term is the Coriolis part
    psidd = (A[:, 0] * Add[:, 1] - A[:, 1] * Add[:, 0]) / n2 - 2 * (A * Ad).sum(1) * (A[:, 0] * Ad[:, 1] - A[:, 1] * Ad[:, 0]) / n2 ** 2
    assert np.allclose(np.unwrap(res.links[3].angle), np.unwrap(psi), atol=1e-12)
    assert np.allclose(res.links[3].omega, psid, rtol=1e-10, atol=1e-12)
    assert np.allclose(res.links[3].epsilon, psidd, rtol=1e-9, atol=1e-9)
    # the block turns with the slot
    assert np.allclose(res.links[2].omega, res.links[3].omega, atol=1e-12)


@pytest.mark.parametrize("e", [0.0, 0.03, -0.05])
def test_offset_slider_crank_closed_form(e):
    """x_B = r·cos φ + √(l² − (r·sin φ − e)²) (offset slider-crank, e.g. Uicker, Pennock & Shigley,
    «Theory of Machines and Mechanisms», §3), differentiated analytically."""
    r_, l, w = 0.1, 0.32, 25.0
    m = model_from_text(slider_crank(r_, l, e, omega=w))
    phi = np.radians(np.arange(3.0, 360.0, 11.0))
    res = m.solve(phi)
    s = r_ * np.sin(phi) - e
    root = np.sqrt(l * l - s * s)
    x = r_ * np.cos(phi) + root
    dx = -r_ * np.sin(phi) - s * r_ * np.cos(phi) / root              # dx/dφ
    ds = r_ * np.cos(phi)
    d2s = -r_ * np.sin(phi)
    d2x = -r_ * np.cos(phi) - (ds * ds + s * d2s) / root - (s * ds) ** 2 / root ** 3
    B = res.points["B"]
    assert np.allclose(B.pos[:, 0], x, atol=1e-13)
    assert np.allclose(B.pos[:, 1], e, atol=1e-13)
    assert np.allclose(B.vel[:, 0], dx * w, rtol=1e-11, atol=1e-12)
    assert np.allclose(B.acc[:, 0], d2x * w * w, rtol=1e-10, atol=1e-10)


def test_slider_crank_published_worksheet():
    """Slider-crank worksheet (crank a = 10 in, coupler b = 20 in, θ2 = 45°, ω2 = 1 rad/s):
    v4 = 9.744 in/s, ω3 = 0.378 rad/s, θ3 = 159.295° (coupler measured from B towards A)."""
    inch = 0.0254
    m = model_from_text(slider_crank(10 * inch, 20 * inch, 0.0, omega=1.0))
    res = m.solve([math.radians(45.0)])
    assert abs(res.points["B"].vel[0, 0]) / inch == pytest.approx(9.744, abs=5e-4)
    assert abs(res.links[2].omega[0]) == pytest.approx(0.378, abs=5e-4)
    A, B = res.points["A"].pos[0], res.points["B"].pos[0]
    theta3 = math.degrees(math.atan2(A[1] - B[1], A[0] - B[0]))
    assert theta3 == pytest.approx(159.295, abs=5e-4)


def _freudenstein(a, b, c, d, th2, branch):
    """θ4 of a four-bar from Freudenstein's equation K1·cos θ4 − K2·cos θ2 + K3 = cos(θ2 − θ4)
    (Norton, «Design of Machinery», §4.5), solved by the tangent half-angle substitution."""
    K1, K2, K3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    A = math.cos(th2) - K1 - K2 * math.cos(th2) + K3
    B = -2 * math.sin(th2)
    C = K1 - (K2 + 1) * math.cos(th2) + K3
    return 2 * math.atan2(-B + branch * math.sqrt(B * B - 4 * A * C), 2 * A)


@pytest.mark.parametrize("branch", [1.0, -1.0])
def test_four_bar_against_freudenstein(branch):
    a, b, c, d, w = 0.04, 0.12, 0.08, 0.10, 10.0
    m = model_from_text(four_bar(a, b, c, d, phi_deg=40.0, omega=w, branch=branch))
    for deg in range(0, 360, 30):
        th2 = math.radians(deg)
        res = m.solve([th2])
        th4 = res.links[3].angle[0]
        cands = [_freudenstein(a, b, c, d, th2, s) for s in (1.0, -1.0)]
        err = min(abs(math.remainder(th4 - t, 2 * math.pi)) for t in cands)
        assert err < 1e-12
        th3 = res.links[2].angle[0]
        # Norton eq. 6.18: ω3 = a·ω2·sin(θ4 − θ2) / (b·sin(θ3 − θ4)), ω4 = a·ω2·sin(θ2 − θ3) / (c·sin(θ4 − θ3))
        th4b = th4  # link 3 runs C → B, as Norton's rocker O4 → B
        assert res.links[2].omega[0] == pytest.approx(a * w * math.sin(th4b - th2) / (b * math.sin(th3 - th4b)), rel=1e-10)
        assert res.links[3].omega[0] == pytest.approx(a * w * math.sin(th2 - th3) / (c * math.sin(th4b - th3)), rel=1e-10)
