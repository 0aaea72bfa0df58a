"""Frame, ГОСТ 2.104 form 1 grid, title-block texts, reproducible DXF."""
from __future__ import annotations

import hashlib

import ezdxf
import pytest

from drawings import Sheet, TitleBlock
from drawings.sheet import A1, EXTRA_H, EXTRA_W, TITLE_H, TITLE_W, fit_text
from drawings import style

from demo_scene import FakeDocument, build_demo_sheet


def _lines_in(msp, x0, y0, x1, y1):
    out = []
    for e in msp.query("LINE"):
        s, t = e.dxf.start, e.dxf.end
        if all(x0 - 1e-6 <= p.x <= x1 + 1e-6 and y0 - 1e-6 <= p.y <= y1 + 1e-6 for p in (s, t)):
            out.append(((s.x - x0, s.y - y0), (t.x - x0, t.y - y0), e.dxf.layer))
    return out


@pytest.fixture(scope="module")
def sheet():
    return Sheet.a1(FakeDocument(), title="Силовой анализ механизма", code="ТММ.КП.02",
                    number=2, count=4, scale="1:2")


def test_frame_offsets(sheet):
    assert (sheet.frame.x0, sheet.frame.y0) == (20.0, 5.0)
    assert (sheet.frame.x1, sheet.frame.y1) == (A1.width - 5.0, A1.height - 5.0)
    polys = [list(e.get_points("xy")) for e in sheet.msp.query("LWPOLYLINE[layer=='contour']")]
    assert [(20.0, 5.0), (836.0, 5.0), (836.0, 589.0), (20.0, 589.0)] in [
        [tuple(map(float, p)) for p in poly] for poly in polys]


def test_title_block_is_185_by_55_in_the_lower_right_corner(sheet):
    r = sheet.title_rect
    assert (r.width, r.height) == (TITLE_W, TITLE_H) == (185.0, 55.0)
    assert (r.x1, r.y0) == (sheet.frame.x1, sheet.frame.y0)


def test_title_block_grid_of_form_1(sheet):
    r = sheet.title_rect
    lines = _lines_in(sheet.msp, r.x0, r.y0, r.x1, r.y1)
    verticals = {round(a[0], 6) for a, b, _ in lines if abs(a[0] - b[0]) < 1e-9}
    horizontals_left = {round(a[1], 6) for a, b, _ in lines
                        if abs(a[1] - b[1]) < 1e-9 and min(a[0], b[0]) < 1e-9}
    # columns 7 | 10 | 23 | 15 | 10 | 70 | Лит. 3×5 | 17 | 18, and Лист | Листов at 155
    assert verticals == {0.0, 7.0, 17.0, 40.0, 55.0, 65.0, 135.0, 140.0, 145.0, 150.0, 155.0, 167.0}
    # eleven rows of 5 mm in the left part
    assert horizontals_left == {5.0 * k for k in range(1, 12)}
    # right part: graph 2 is 15 mm high, graph 8 / graph 3 15 mm, Лит. caption row 5 mm
    right = {round(a[1], 6) for a, b, _ in lines
             if abs(a[1] - b[1]) < 1e-9 and max(a[0], b[0]) > 65.0 + 1e-9}
    assert right == {15.0, 20.0, 35.0, 40.0, 55.0}
    thick = {(a, b) for a, b, layer in lines if layer == "contour"}
    assert ((0.0, 30.0), (65.0, 30.0)) in thick and ((0.0, 35.0), (65.0, 35.0)) in thick
    assert ((0.0, 25.0), (65.0, 25.0)) not in thick


def test_title_block_texts(sheet):
    texts = sheet.title_block_texts()
    for caption in ("Изм.", "Лист", "№ докум.", "Подп.", "Дата", "Разраб.", "Пров.", "Т.контр.",
                    "Н.контр.", "Утв.", "Лит.", "Масса", "Масштаб", "Листов"):
        assert caption in texts, caption
    for value in ("Иванов И. И.", "Слободюк А. П.", "ТММ.КП.02", "2", "4", "1:2", "У", "гр. ТМ-21"):
        assert value in texts, value
    assert "Силовой анализ механизма" in " ".join(texts)
    assert texts.count("ТММ.КП.02") == 2  # graph 2 and graph 26


def test_graph_26_is_turned_by_180_degrees(sheet):
    er = sheet.extra_rect
    assert (er.width, er.height) == (EXTRA_W, EXTRA_H)
    assert (er.x0, er.y1) == (sheet.frame.x0, sheet.frame.y1)
    rotated = [e for e in sheet.msp.query("TEXT") if e.dxf.text == "ТММ.КП.02"
               and abs(e.dxf.rotation - 180.0) < 1e-9]
    assert len(rotated) == 1
    p = rotated[0].dxf.align_point
    assert er.x0 < p.x < er.x1 and er.y0 < p.y < er.y1


def test_texts_use_the_gost_style(sheet):
    assert {e.dxf.style for e in sheet.msp.query("TEXT")} == {style.TEXT_STYLE}


def test_sheet_number_validated():
    with pytest.raises(ValueError):
        TitleBlock(title="x", code="y", number=5, count=4)


@pytest.mark.parametrize("text,width,height,max_h,lines", [
    ("Кинематический анализ рычажного механизма", 68.0, 23.4, 5.0, 3),
    ("Слободюк А. П.", 21.0, 3.4, 2.5, 1),
    ("ТММ.КП.01.001", 118.0, 13.4, 7.0, 1),
])
def test_fit_text_fits_and_keeps_every_word(text, width, height, max_h, lines):
    out, h, wf = fit_text(text, width, height, max_height=max_h, max_lines=lines)
    assert len(out) <= lines
    assert " ".join(out).split() == text.split()
    assert max(style.text_width(s, h) for s in out) * wf <= width + 1e-9
    assert h * (1 + 1.6 * (len(out) - 1)) <= height + 1e-9


def test_demo_sheet_passes_audit(demo_dxf):
    doc = ezdxf.readfile(demo_dxf)
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]


def test_same_input_gives_the_same_bytes(tmp_path):
    a, b = tmp_path / "a.dxf", tmp_path / "b.dxf"
    build_demo_sheet().save(a)
    build_demo_sheet().save(b)
    assert hashlib.sha256(a.read_bytes()).digest() == hashlib.sha256(b.read_bytes()).digest()
    text = a.read_text(encoding="utf-8")
    assert "{00000000-0000-0000-0000-000000000000}" in text  # fixed $FINGERPRINTGUID/$VERSIONGUID
