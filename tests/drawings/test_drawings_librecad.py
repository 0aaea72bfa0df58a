"""The demo sheet opened by a real CAD program: LibreCAD prints it on a non-blank page."""
from __future__ import annotations

import pytest
from matplotlib import image

from drawings import librecad

pytestmark = pytest.mark.slow

MISSING = librecad.missing_tools()


@pytest.mark.skipif(bool(MISSING), reason=f"not installed: {', '.join(MISSING)} "
                    "(apt-get install librecad poppler-utils)")
def test_librecad_draws_the_sheet(demo_dxf, tmp_path):
    result = librecad.check_sheet(demo_dxf, tmp_path, dpi=40)
    assert result.pdf.exists() and result.png.exists()
    assert result.drawn
    img = image.imread(result.png)
    h, w = img.shape[:2]
    assert w / h == pytest.approx(841 / 594, rel=0.02)  # the page is the sheet ($PLIMMAX)
    dark = img[..., :3].mean(axis=-1) < 0.5
    # the title block (lower right) has ink, the empty middle of the demo has none
    assert dark[int(h * 0.9):, int(w * 0.78):].mean() > 0.02
    assert dark[int(h * 0.33):int(h * 0.55), int(w * 0.48):int(w * 0.7)].mean() == 0.0


def test_missing_librecad_gives_a_clear_message(monkeypatch, tmp_path):
    monkeypatch.setattr(librecad.shutil, "which", lambda _name: None)
    with pytest.raises(Exception, match="librecad and pdftoppm not found on PATH"):
        librecad.dxf_to_pdf(tmp_path / "x.dxf", tmp_path)
