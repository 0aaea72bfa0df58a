"""Previews by ezdxf's drawing add-on: a PNG of the paper size with ink where the sheet is drawn."""
from __future__ import annotations

import numpy as np
import pytest
from matplotlib import image

from drawings import preview


@pytest.fixture(scope="module")
def png(demo_dxf, tmp_path_factory):
    return preview.render_png(demo_dxf, tmp_path_factory.mktemp("png") / "demo.png", dpi=50)


def _ink(img, x0, y0, x1, y1, w_mm=841.0, h_mm=594.0):
    """Share of dark pixels in a sheet rectangle given in mm (origin lower-left)."""
    h, w = img.shape[:2]
    sub = img[int(h * (1 - y1 / h_mm)):int(h * (1 - y0 / h_mm)), int(w * x0 / w_mm):int(w * x1 / w_mm)]
    return float((sub[..., :3].mean(axis=-1) < 0.5).mean())


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
