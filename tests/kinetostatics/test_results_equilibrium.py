"""Equilibrium of every link re-checked from results.json alone (RESULTS_FORMAT.md: every force on
every link with its point of application), at the task's force position and at other angles."""
from __future__ import annotations

import json

import numpy as np
import pytest

from reportgen.results import build_results, dumps

from .cases import EXAMPLE_NAMES, example

REL = 1e-9


def cross2(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def block(name: str, force_at=None) -> dict:
    data = json.loads(dumps(build_results(example(name), ("kinetostatics",), force_at_deg=force_at)))
    return data["kinetostatics"]


def check_links(ks: dict) -> None:
    assert ks["links"], "no links"
    for k, link in ks["links"].items():
        F = np.zeros(2)
        M = 0.0
        fscale = mscale = 0.0
        o = np.asarray(link["forces"][0]["point"])        # any point: take the first force's
        for f in link["forces"]:
            p, v = np.asarray(f["point"]), np.asarray(f["vector"])
            assert p.shape == (2,) and v.shape == (2,)
            F += v
            m = float(cross2(p - o, v))
            M += m
            fscale += float(np.hypot(*v))
            mscale += abs(m)
        for m in link["moments"]:
            M += m["value"]
            mscale += abs(m["value"])
        assert np.hypot(*F) <= REL * fscale, (k, F, fscale)
        assert abs(M) <= REL * max(mscale, fscale * 1e-3), (k, M, mscale)


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
@pytest.mark.parametrize("force_at", [None, 45.0, 163.0, 301.5])
def test_every_link_in_equilibrium(name, force_at):
    check_links(block(name, force_at))


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_reaction_names_and_signs(name):
    """R12 in `reactions` is the force of 1 on 2; link 2 lists R12, link 1 lists R21 = −R12, at one point."""
    ks = block(name)
    listed = {(k, f["name"]): f for k, link in ks["links"].items() for f in link["forces"]}
    for rname, vec in ks["reactions"].items():
        lo, hi = ks["pairs"][rname]["links"]
        assert rname == f"R{lo}{hi}" and lo < hi
        on_hi = listed[(str(hi), f"R{lo}{hi}")]
        assert on_hi["vector"] == pytest.approx(vec, abs=0)
        if lo != 0:
            on_lo = listed[(str(lo), f"R{hi}{lo}")]
            assert on_lo["vector"] == pytest.approx([-v for v in vec], abs=0)
            assert on_lo["point"] == on_hi["point"]
    # every pair of the mechanism is reported: p1 pairs (a joint of k links is k − 1 pairs)
    data = json.loads(dumps(build_results(example(name), ("structure",))))
    assert len(ks["reactions"]) == data["structure"]["p1"]


def test_press_pairs_and_the_balancing_force():
    ks = block("press", 90.0)
    assert set(ks["reactions"]) == {"R01", "R12", "R23", "R03", "R24", "R45", "R05"}   # B joins 2, 3 and 4
    assert ks["phi_deg"] == pytest.approx(90.0)
    # the slider's normal reaction is square to the horizontal guide, and acts at D (all its loads do)
    assert ks["reactions"]["R05"][0] == pytest.approx(0.0, abs=1e-9)
    d5 = next(f for f in ks["links"]["5"]["forces"] if f["name"] == "R05")
    g5 = next(f for f in ks["links"]["5"]["forces"] if f["name"] == "G5")
    assert d5["point"] == pytest.approx(g5["point"], abs=1e-12)
    # F_ур at the crank pin, square to the crank, M = F·l
    fb = ks["balancing_force"]
    crank = ks["links"]["1"]["forces"]
    pin = next(f for f in crank if f["name"] == "Fур")
    o = next(f for f in crank if f["name"] == "R01")["point"]
    r = np.subtract(pin["point"], o)
    assert float(np.dot(r, pin["vector"])) == pytest.approx(0.0, abs=1e-9 * np.hypot(*pin["vector"]))
    assert float(cross2(r, pin["vector"])) == pytest.approx(ks["balancing_moment"], rel=1e-12)
    assert fb["value"] * np.hypot(*r) == pytest.approx(ks["balancing_moment"], rel=1e-12)
    # R01 under a pure driving couple differs from R01 with F_ур by exactly F_ур
    assert np.subtract(ks["frame_reaction_with_moment"], ks["reactions"]["R01"]) == pytest.approx(pin["vector"])


def test_prismatic_point_of_action_carries_the_couple():
    """The ram's guide takes a moment when a load misses the ram's point: it shows as the shift of
    the point of action of R05 along the guide, by x = m/N."""
    from reportgen.kinetostatics import solve_reactions
    from reportgen.loads import Force, LoadSet
    p = example("crank-slider")
    kin = p.kinematics_at(np.radians([40.0, 100.0]))
    B = np.asarray(kin.points["B"].pos)
    # a horizontal force 0.03 m above the slider's point B
    loads = LoadSet((Force("F3", 3, "K", B + [0.0, 0.03], np.tile([-800.0, 0.0], (2, 1)), "force"),), ())
    r = solve_reactions(p.linkage, p.structure, kin, loads)
    R03 = r.pair("R03")
    N = R03.vector[:, 1]
    x = R03.point[:, 0] - B[:, 0]
    # about B, the slider: the force's moment (−800·… ) balanced by N·x
    assert np.allclose(N * x + 0.03 * 800.0, 0.0, atol=1e-9 * 800)
    assert np.allclose(R03.point[:, 1], 0.02)                 # on the guide line y = e
    for k in (1, 2, 3):
        F, M = r.residuals(k)
        assert np.abs(F).max() < 1e-9 * 800 and np.abs(M).max() < 1e-9 * 800
