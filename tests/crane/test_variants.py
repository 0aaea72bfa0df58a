"""Other cranes than the example: a single polyspast, an odd ratio, no open gear, the ПБ 10-382-00
rules, two brakes, two driven wheels — each computes, renders a note whose formulas re-evaluate and
draws sheets that overlap nothing."""
from __future__ import annotations

import dataclasses as dc

import pytest

from reportgen.calc import evaluate_displayed
from reportgen.project import Project

from .helpers import example_task


def _variant(name: str):
    task = example_task()
    cr = task.crane
    h, t = cr.hoist, cr.trolley
    if name == "single-odd-no-gear":
        h = dc.replace(h, polyspast=dc.replace(h.polyspast, ratio=3, branches=1), open_gear=None,
                       drum=dc.replace(h.drum, ring_width_mm=0.0),
                       reducer=dc.replace(h.reducer, ratio=80.0), capacity_t=20.0, hook_mass_kg=500.0)
        cr = dc.replace(cr, rules="PB-10-382-00")
    elif name == "pb-two-brakes":
        h = dc.replace(h, brake=dc.replace(h.brake, count=2))
        cr = dc.replace(cr, rules="PB-10-382-00", group="4М")
    elif name == "four-wheels":
        t = dc.replace(t, wheels=4, driven_wheels=2)
    elif name == "even-single":
        h = dc.replace(h, polyspast=dc.replace(h.polyspast, ratio=4, branches=1))
    return dc.replace(task, crane=dc.replace(cr, hoist=h, trolley=t))


@pytest.mark.parametrize("name", ["single-odd-no-gear", "pb-two-brakes", "four-wheels", "even-single"])
def test_variant_renders_and_draws(name, tmp_path):
    from drawings.sheets import available_sheets
    from latex_templates.parts.crane_document import note_builder
    project = Project(_variant(name))
    calc = project.crane
    for _, mech in calc.mechanisms:
        assert all(evaluate_displayed(r).ok for r in mech.records.values())
    note = note_builder(project)
    note.render(tmp_path)
    assert note.symbols.unexplained == set()
    for i, (stem, mod) in enumerate(available_sheets(project), start=1):
        sheet = mod.draw(project, i, 2)
        assert sheet.overlaps() == [], (name, stem)


def test_two_brakes_each_hold_with_1_25():
    calc = Project(_variant("pb-two-brakes")).crane
    assert calc.hoist.value("T_br") == pytest.approx(1.25 * calc.hoist.value("T_st"))
    assert calc.rules.iso_class == "M6" and calc.rules.rope_factor == 5.6


def test_single_polyspast_has_no_smooth_middle_part():
    calc = Project(_variant("single-odd-no-gear")).crane
    assert "l_0max" not in calc.hoist.records
    assert calc.hoist.value("L_dr") == pytest.approx(calc.hoist.value("l_n") + 2 * 130)
    assert calc.hoist.value("u_mech") == pytest.approx(80.0 * 3)
