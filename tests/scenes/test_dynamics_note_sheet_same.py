"""One construction drawn twice, section 3: the note's figures of the diagrams and sheet 3 draw the
same scenes (reportgen.scenes.dynamics). Read back from the sheet's DXF: the dimension KL of the
Wittenbauer diagram is the KL the note prints (and its flywheel's J follows from it), the polylines of
ΔE(φ), ΔE(J), J_red(φ), M_red(φ) and A_с(φ) and the tangents have the lengths of the note's figure
data, and the scales the sheet prints are the note's."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from drawings.sheets import dynamics as sheet3
from latex_templates import numbers
from latex_templates.parts import dynamics as part
from reportgen.scenes.scene import Polyline, Segment
from scene_readback import part_and_sheet, polyline_length

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "shaper", "conveyor")


@pytest.fixture(scope="module", params=EXAMPLES)
def built(request, tmp_path_factory):
    return part_and_sheet(request.param, part, sheet3, 3, tmp_path_factory.mktemp(request.param))


def _sheet_polylines(doc) -> list[float]:
    return [polyline_length([tuple(p)[:2] for p in e.get_points("xy")])
            for e in doc.modelspace().query("LWPOLYLINE[layer=='contour']")]


def _sheet_lines(doc) -> list[float]:
    return [math.dist(tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2])
            for e in doc.modelspace().query("LINE[layer=='contour']")]


def _texts(doc) -> list[str]:
    return [e.dxf.text for e in doc.modelspace().query("TEXT")]


def _number(s: str) -> float:
    return float(s.replace(",", ".").replace("\u2212", "-"))


def test_wittenbauer_KL_in_note_is_the_sheets_dimension(built):
    """One quantity, one rounding (issue 12: sheet 3 printed KL = 39,3 while the note's formula for
    J_гр used 39,337): KL read back from sheet 3's DIMENSION text is the KL the note prints, in its
    text and in the substitution of J_гр, and J_гр follows from that printed value."""
    project, content, doc = built
    c = content.context
    scene = content.figures["dyn_wittenbauer"].scene
    K, L = scene.entity("point:K"), scene.entity("point:L")
    assert math.dist(K.c, L.c) == pytest.approx(scene.values["KL_mm"], abs=1e-9)     # drawn, not only stated
    dims = [d for d in doc.modelspace().query("DIMENSION")
            if abs(d.get_measurement() - scene.values["KL_mm"]) < 1e-6]
    assert len(dims) == 1, "the dimension KL is not on sheet 3"
    printed = dims[0].dxf.text
    KL_sheet = _number(printed)
    KL_note = c["tg"]["KL"].value
    assert KL_note == KL_sheet, (KL_note, printed)
    J_gr = c["tg"]["J_gr"]
    assert printed.replace(",", "{,}") in J_gr.substituted_latex(), (printed, J_gr.substituted_latex())
    # the sentence «отрезок KL = … мм» prints it as the sheet does («80», not «80,0»: the shaper)
    assert numbers.mnum(KL_note) == printed.replace(",", "{,}"), (numbers.mnum(KL_note), printed)
    for lang in ("ru", "uk", "en"):
        text = (ROOT / "latex_templates" / "strings" / lang / "dynamics.toml").read_text(encoding="utf-8")
        assert "KL = \\VAR{c.tg.KL.value|mnum}" in text, lang
    # the flywheel of the graphical method follows from the printed KL and is results.json's
    mu_E = scene.scale("μE").value
    omega, delta = project.dynamics.omega_m, project.dynamics.delta_target
    assert J_gr.value == pytest.approx(KL_sheet * mu_E / (omega * omega * delta), rel=1e-12)
    assert J_gr.value == pytest.approx(scene.values["J_fly"], rel=1e-12)
    assert scene.values["J_fly"] == pytest.approx(project.dynamics.graphical.J_fly, rel=1e-12)


def test_curves_and_tangents_have_the_sheets_lengths(built):
    _, content, doc = built
    on_sheet = _sheet_polylines(doc)
    lines = _sheet_lines(doc)
    checked = 0
    for name, ids in (("dyn_wittenbauer", ("energy:curve", "curve", "inertia:curve")),
                      ("dyn_work", ("moment:curve", "work:curve", "energy:curve"))):
        scene = content.figures[name].scene
        for id_ in ids:
            e = scene.entity(id_)
            assert isinstance(e, Polyline)
            length = polyline_length(e.points)
            assert any(abs(x - length) < 1e-6 for x in on_sheet), (name, id_, length)
            checked += 1
        if name == "dyn_wittenbauer":
            for id_ in ("tangent:K", "tangent:L"):
                t = scene.entity(id_)
                assert isinstance(t, Segment)
                assert any(abs(x - t.length) < 1e-6 for x in lines), (id_, t.length)
    assert checked == 6


def test_scales_printed_by_note_are_the_sheets(built):
    _, content, doc = built
    sc = content.context["sc"]
    texts = _texts(doc)

    def printed(symbol: str) -> list[float]:
        return [_number(m.group(1)) for t in texts for m in re.finditer(symbol + r"(?: = μM·μφ·H)? = ([\d,]+)", t)]
    for symbol, key in (("μM", "mu_M"), ("μA", "mu_A"), ("μE", "mu_E"), ("μJ", "mu_J"), ("μφ", "mu_phi")):
        values = printed(symbol)
        assert values, symbol
        # the sheet prints 4 significant digits
        assert all(v == pytest.approx(sc[key].value, rel=5e-4) for v in values), (symbol, values, sc[key].value)
