"""One construction drawn twice (issue 13): the free-body diagrams of section 2 and sheet 2 are the
same scenes (:mod:`reportgen.scenes.free_body`). For every example with a linkage, each group's
(and the crank's) figure in the note carries its scene, and every arrow of it — tail and tip — is on
sheet 2's DXF at the same place relative to the others (one translation per view), the hinges
too; the arrows' lengths follow the one schematic rule; the μl the note prints is the scene's and
the sheet's."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from drawings.sheets import kinetostatics as sheet2
from latex_templates.parts import kinetostatics as part
from reportgen.scenes.scene import Arrow, Circle
from scene_readback import common_shift, dxf_arrows, part_and_sheet

EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3")
#: An arrow shorter than this is all head on the sheet (a couple's head): not read back.
SHAFT_MM = 6.0


@pytest.fixture(scope="module", params=EXAMPLES)
def built(request, tmp_path_factory):
    return part_and_sheet(request.param, part, sheet2, 2, tmp_path_factory.mktemp(request.param))


def _figures(content) -> dict:
    names = [n for n in content.figures if n.startswith("kst_group_") or n == "kst_crank"]
    assert names, "the note has no free-body diagram"
    return {n: content.figures[n] for n in names}


def test_free_body_arrows_same_in_note_and_sheet(built):
    _, content, doc = built
    drawn = dxf_arrows(doc)
    circles = [np.array(e.dxf.center)[:2] for e in doc.modelspace().query("CIRCLE")]
    for name, fig in _figures(content).items():
        scene = getattr(fig, "scene", None)
        assert scene is not None, f"{name}: the note's figure is not drawn from a scene"
        arrows = [(np.asarray(e.a), np.asarray(e.b)) for e in scene.entities
                  if isinstance(e, Arrow) and e.length > SHAFT_MM]
        assert len(arrows) >= 3, name
        t = common_shift(arrows, drawn)
        assert t is not None, f"{name}: the note's arrows are not the sheet's"
        for e in scene.entities:
            if isinstance(e, Circle) and e.hinge:
                c = np.asarray(e.c) + t
                assert any(float(np.hypot(*(c - q))) < 0.01 for q in circles), (name, e.id)


def test_free_body_arrow_lengths_follow_the_rule(built):
    """The largest force ARROW_MM long, the others √ of their share, none under MIN_ARROW_MM."""
    from reportgen.scenes.free_body import ARROW_MM, MIN_ARROW_MM, schematic_length
    _, content, _ = built
    for name, fig in _figures(content).items():
        scene = getattr(fig, "scene", None)
        assert scene is not None, f"{name}: the note's figure is not drawn from a scene"
        forces = {e.id: e for e in scene.entities if isinstance(e, Arrow) and e.id.startswith("force:")}
        mags = {i: scene.values[i] for i in forces}
        top = max(mags.values())
        assert max(e.length for e in forces.values()) == pytest.approx(ARROW_MM), name
        for i, e in forces.items():
            assert e.length >= MIN_ARROW_MM - 1e-9
            assert e.length == pytest.approx(schematic_length(mags[i], top)), (name, i)


def test_mu_l_printed_is_the_scenes_and_the_sheets(built):
    _, content, doc = built
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    on_sheet = {float(m.group(1).replace(",", ".")) for t in texts if (m := re.match(r"μl = ([\d,]+) м/мм", t))}
    mu = content.context["mu_l"].value
    for name, fig in _figures(content).items():
        assert math.isclose(fig.scene.scale("μl").value, mu, rel_tol=1e-12), name
    assert mu in on_sheet, (mu, on_sheet)


def test_schematic_length_is_monotone_and_bounded():
    from reportgen.scenes.free_body import ARROW_MM, MIN_ARROW_MM, schematic_length
    mags = [0.0, 1e-3, 1.0, 10.0, 250.0, 1e4]
    lengths = [schematic_length(m, 1e4) for m in mags]
    assert lengths == sorted(lengths)
    assert lengths[0] == MIN_ARROW_MM and lengths[-1] == ARROW_MM
    assert schematic_length(2500.0, 1e4) == pytest.approx(max(MIN_ARROW_MM, ARROW_MM * 0.5))
