"""Masses and moments of inertia from [mechanism.mass_rules] (course manual, seed 001)."""
from __future__ import annotations

import math

import pytest

from reportgen.errors import TaskError
from reportgen.task import MassRules
from reportgen.taskfile import load_task, parse_task

from taskfile_cases import SLOTTED, edit, example

approx = pytest.approx


def test_slotted_defaults_by_hand():
    m = load_task(SLOTTED).mechanism          # q = 20, slider_factor = 4, triangle_factor = 2.5 (default)
    crank = m.link(1)                          # O–B, length 0.10 given
    assert crank.mass == approx(20 * 0.10) and crank.inertia == approx(2.0 * 0.10**2 / 12)
    assert not crank.mass_given and not crank.inertia_given
    block = m.link(2)                          # a block: slider rule, no inertia
    assert block.mass == approx(4 * 2.0) and block.inertia == 0.0
    tri = m.link(3)                            # C–E–G: CE = 0.58 given, CG and EG from the sketch
    ce, cg, eg = 0.58, math.hypot(0.30, 0.50), math.hypot(0.14, 0.05)
    perimeter, longest = ce + cg + eg, max(ce, cg, eg)
    assert longest == cg
    assert tri.mass == approx(20 * perimeter)
    assert tri.inertia == approx(2.5 * (20 * longest) * longest**2 / 12)
    coupler = m.link(4)                        # G–F from the sketch: 0.25
    assert coupler.mass == approx(20 * 0.25) and coupler.inertia == approx(5.0 * 0.25**2 / 12)
    assert m.link(5).mass == approx(8.0) and m.link(5).inertia == 0.0
    assert m.mass_rules == MassRules(q=20.0, slider_factor=4.0, triangle_factor=2.5)


def test_rules_use_given_length_not_sketch():
    data = example()
    for ln in data["mechanism"]["link"]:
        ln.pop("mass", None)
        ln.pop("inertia", None)
    data["mechanism"]["link"][1]["length"] = 0.5   # the sketch says |AB| ≈ 0.331
    m = parse_task(data).mechanism
    assert m.link(2).mass == approx(10 * 0.5) and m.link(2).inertia == approx(5.0 * 0.25 / 12)
    assert m.link(1).mass == approx(1.1)
    assert m.link(5).mass == approx(6 * 1.1)       # slider: factor × mass of link 1


def test_slider_uses_given_drive_mass_and_missing_rules_table_uses_defaults():
    data = example()
    del data["mechanism"]["mass_rules"]
    del data["mechanism"]["link"][4]["mass"]
    data["mechanism"]["link"][0]["mass"] = 3.0
    m = parse_task(data).mechanism
    assert m.mass_rules == MassRules()
    assert m.link(5).mass == approx(6.0 * 3.0) and not m.link(5).mass_given


def test_given_mass_without_inertia_bar_and_triangle():
    data = example(SLOTTED)
    links = data["mechanism"]["link"]
    links[0]["mass"] = 3.0
    links[2]["mass"] = 12.0
    m = parse_task(data).mechanism
    assert m.link(1).inertia == approx(3.0 * 0.01 / 12) and m.link(1).mass_given
    assert not m.link(1).inertia_given
    ce, cg, eg = 0.58, math.hypot(0.30, 0.50), math.hypot(0.14, 0.05)
    per_metre = 12.0 / (ce + cg + eg)
    assert m.link(3).inertia == approx(2.5 * per_metre * cg * cg**2 / 12)


def test_given_inertia_wins_and_slider_may_have_zero_inertia():
    data = example(SLOTTED)
    data["mechanism"]["link"][2]["inertia"] = 0.7
    data["mechanism"]["link"][4]["inertia"] = 0
    data["mechanism"]["link"][1]["inertia"] = 0.001
    m = parse_task(data).mechanism
    assert m.link(3).inertia == 0.7 and m.link(3).inertia_given and not m.link(3).mass_given
    assert m.link(5).inertia == 0.0 and m.link(5).inertia_given
    assert m.link(2).inertia == 0.001


def test_straight_three_point_bar_is_a_bar():
    data = example(SLOTTED)
    data["mechanism"]["link"][2]["lengths"] = {"CE": 0.6, "EG": 0.2, "CG": 0.4}   # C–G–E on a line
    m = parse_task(data).mechanism
    assert m.link(3).mass == approx(20 * 0.6)
    assert m.link(3).inertia == approx(12.0 * 0.36 / 12)


def test_two_point_slider_gets_the_slider_rule_but_the_drive_never_does():
    data = example(SLOTTED)
    data["mechanism"]["link"][3]["kind"] = "slider"     # G–F, wording "slider"
    data["mechanism"]["link"][0]["kind"] = "slider"     # the drive keeps the bar rule
    m = parse_task(data).mechanism
    assert m.link(1).mass == approx(2.0)
    assert m.link(4).mass == approx(4 * 2.0) and m.link(4).inertia == 0.0


def test_mass_rules_values_are_used():
    data = example(SLOTTED)
    edit(data, ("mechanism", "mass_rules"), {"q": 8.0, "slider_factor": 18.0, "triangle_factor": 3.0})
    m = parse_task(data).mechanism
    cg = math.hypot(0.30, 0.50)
    assert m.link(1).mass == approx(0.8) and m.link(2).mass == approx(18 * 0.8)
    assert m.link(3).inertia == approx(3.0 * 8.0 * cg**3 / 12)


def test_non_finite_rule_results_are_refused():
    data = example(SLOTTED)
    data["mechanism"]["mass_rules"]["slider_factor"] = 1e308
    data["mechanism"]["link"][0]["mass"] = 1e10
    with pytest.raises(TaskError) as info:
        parse_task(data)
    assert info.value.path == "mechanism.link[1].mass" and "not finite" in str(info.value)
