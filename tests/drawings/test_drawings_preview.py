"""Previews by ezdxf's drawing add-on: a PNG of the paper size with ink where the sheet is drawn."""
from __future__ import annotations

import numpy as np
import pytest
from matplotlib import image

import ezdxf

from drawings import preview, raster
from drawings.sheet_font import completed_font


@pytest.fixture(scope="module")
def png(demo_dxf, tmp_path_factory):
    return preview.render_png(demo_dxf, tmp_path_factory.mktemp("png") / "demo.png", dpi=50)


def _ink(img, x0, y0, x1, y1, w_mm=841.0, h_mm=594.0):
    """Share of dark pixels in a sheet rectangle given in mm (origin lower-left)."""
    h, w = img.shape[:2]
    sub = img[int(h * (1 - y1 / h_mm)):int(h * (1 - y0 / h_mm)), int(w * x0 / w_mm):int(w * x1 / w_mm)]
    grey = sub[..., :3].mean(axis=-1) if sub.ndim == 3 else sub     # a grey PNG or an RGB(A) one
    return float((grey < 0.5).mean())


def test_png_has_paper_size_and_is_not_blank(png):
    img = image.imread(png)
    assert img.shape[1] == pytest.approx(841 / 25.4 * 50, abs=2)
    assert img.shape[0] == pytest.approx(594 / 25.4 * 50, abs=2)
    assert 0.002 < preview.ink_fraction(png) < 0.2


def test_png_draws_title_block_and_leaves_the_free_field_white(png):
    img = image.imread(png)
    assert _ink(img, 651, 5, 836, 60) > 0.05        # the title block
    assert _ink(img, 20, 575, 90, 589) > 0.02       # graph 26
    assert _ink(img, 400, 250, 600, 400) == 0.0     # nothing placed in the middle of the demo


def test_svg_is_written(demo_dxf, tmp_path):
    svg = preview.render_svg(demo_dxf, tmp_path / "demo.svg")
    text = svg.read_text(encoding="utf-8")
    assert text.startswith("<?xml") or text.startswith("<svg")
    assert 'width="841mm"' in text and 'height="594mm"' in text


def test_ink_fraction_of_a_blank_page_is_zero(tmp_path):
    blank = np.ones((20, 30, 3))
    image.imsave(tmp_path / "blank.png", blank)
    assert preview.ink_fraction(tmp_path / "blank.png") == 0.0


def _gray(png):
    img = image.imread(png)
    return img[..., :3].mean(axis=-1) if img.ndim == 3 else img


def test_the_fast_preview_reads_as_ezdxfs(demo_dxf, tmp_path):
    """drawings/raster.py draws the sheets' entities itself (lines, circles, solids, text laid out by
    ezdxf's rules); its page matches ezdxf's drawing add-on to within anti-aliasing: the same ink
    in the same places, blurred by a pixel."""
    from scipy import ndimage

    doc = ezdxf.readfile(demo_dxf)
    assert raster.unsupported(doc, str(completed_font())) is None
    fast = _gray(preview.render_png(doc, tmp_path / "fast.png", dpi=60)) < 0.5
    slow = _gray(preview.render_png_ezdxf(doc, tmp_path / "slow.png", dpi=60)) < 0.5
    assert fast.shape == slow.shape
    assert 0.8 < fast.sum() / slow.sum() < 1.2
    near = ndimage.binary_dilation(slow, iterations=1)
    assert (fast & ~near).sum() < 0.02 * fast.sum()          # no ink where ezdxf has none
    near_fast = ndimage.binary_dilation(fast, iterations=1)
    assert (slow & ~near_fast).sum() < 0.02 * slow.sum()     # nothing left out


def test_a_document_with_other_entities_goes_to_ezdxf(tmp_path):
    doc = ezdxf.new()
    doc.modelspace().add_ellipse((10, 10), major_axis=(5, 0), ratio=0.5)
    doc.header["$PLIMMAX"] = (30.0, 20.0)
    assert raster.unsupported(doc, str(completed_font())) == "ELLIPSE"
    png = preview.render_png(doc, tmp_path / "e.png", dpi=50)
    assert 0.0 < preview.ink_fraction(png) < 0.1               # drawn all the same, by ezdxf
