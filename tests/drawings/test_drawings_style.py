"""Document tables and header variables that LibreCAD and ezdxf rely on."""
from __future__ import annotations

import ezdxf
import pytest

from drawings import style


@pytest.fixture()
def doc():
    return style.new_document(841.0, 594.0)


def test_new_document_passes_audit(doc):
    assert not doc.audit().has_errors


def test_layers_have_gost_lineweights_and_linetypes(doc):
    contour = doc.layers.get("contour")
    assert contour.dxf.lineweight == 70
    assert doc.layers.get("thin").dxf.lineweight == 35
    assert doc.layers.get("axis").dxf.linetype == "CENTER"
    assert doc.layers.get("hidden").dxf.linetype == "DASHED"
    for name in ("contour", "thin", "axis", "hidden", "dimensions", "text", "construction"):
        assert name in doc.layers


def test_linetypes_use_names_librecad_knows(doc):
    for name in ("CENTER", "DASHED", "DASHDOT", "DIVIDE"):
        assert name in doc.linetypes
    center = next(lt for lt in style.LINETYPES if lt.name == "CENTER")
    assert 5.0 <= center.pattern[0] <= 30.0  # ГОСТ 2.303 dash of a thin dash-dot line


def test_dimstyle_mirrored_in_header(doc):
    dimstyle = doc.dimstyles.get(style.DIM_STYLE)
    assert dimstyle.dxf.dimtxt == pytest.approx(3.5)
    assert dimstyle.dxf.dimasz == pytest.approx(3.5)
    assert dimstyle.dxf.dimdsep == ord(",")
    assert doc.header["$DIMSTYLE"] == style.DIM_STYLE
    assert doc.header["$DIMTXT"] == pytest.approx(3.5)
    assert doc.header["$DIMASZ"] == pytest.approx(3.5)
    assert doc.header["$DIMDSEP"] == ord(",")


def test_header_survives_save(doc, tmp_path):
    path = tmp_path / "empty.dxf"
    with style.reproducible():
        doc.saveas(path)
    back = ezdxf.readfile(path)
    assert tuple(back.header["$PLIMMAX"])[:2] == (841.0, 594.0)
    assert back.header["$INSUNITS"] == 4
    assert back.header["$DIMDSEP"] == ord(",")
    assert back.styles.get(style.TEXT_STYLE).dxf.font == style.TEXT_STYLE_FONT


def test_text_width_grows_with_text_and_height():
    a = style.text_width("ТММ", 3.5)
    assert a > 0
    assert style.text_width("ТММ-ТММ", 3.5) > a
    assert style.text_width("ТММ", 7.0) == pytest.approx(2 * a, rel=1e-6)
    assert style.text_width("", 5.0) == 0.0


def test_text_lineweight_is_a_tenth_of_height():
    assert style.text_lineweight(7.0) == 70
    assert style.text_lineweight(3.5) == 35
    assert style.text_lineweight(2.5) == 25


def test_percent_codes_print_literally():
    """A user's «%%d» must not become «°» on a sheet (DXF TEXT control codes)."""
    from ezdxf.tools.text import plain_text
    from drawings.style import dxf_literal
    for s in ("Иванов %%d", "50 %", "%%c%%p", "a%%%b", "x ^ y", "a^b^^c"):
        assert plain_text(dxf_literal(s)) == s
