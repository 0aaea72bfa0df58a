"""The note figures' font subsets cut from a font read once (latex_templates/figures/font_subset.py):
every glyph asked for keeps its outline, hinting and advance; a figure prints the same pixels as
with fontTools' subsetter; a font without TrueType outlines goes to fontTools."""
from __future__ import annotations

import io
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from matplotlib import font_manager
from matplotlib.ft2font import FT2Font, LoadFlags

from latex_templates.figures import font_subset, new_figure, saving
from latex_templates.figures.font_subset import SourceFont, UnsupportedFont, source_font
from latex_templates.figures.saving import save_pdf

_MPL_FONTS = Path(font_manager.__file__).parent / "mpl-data" / "fonts" / "ttf"


def _note_fonts() -> list[str]:
    """The fonts the note's figures print with (the style's serif and its italic, mathtext's STIX)."""
    found = []
    for style in ("normal", "italic"):
        prop = font_manager.FontProperties(family=["Liberation Serif", "DejaVu Serif"], style=style)
        found.append(str(font_manager.findfont(prop, fallback_to_default=True)))
    found += [str(_MPL_FONTS / "STIXGeneral.ttf"), str(_MPL_FONTS / "STIXGeneralItalic.ttf")]
    return sorted(set(found))


def _glyph(font: FT2Font, gid: int, flags: LoadFlags) -> tuple:
    g = font.load_glyph(gid, flags=flags)
    vertices, codes = font.get_path()
    return g.horiAdvance, g.bbox, vertices.tobytes(), codes.tobytes()


def _glyph_sets(src: SourceFont) -> list[list[int]]:
    """A few letters, the composites (Й, ё, accented Latin: their components must follow), and
    ~600 spread over the whole font (all of a small one)."""
    cmap = src.font.getBestCmap()
    letters = sorted({src.ids[cmap[ord(c)]] for c in "AОо1,5ωЙйё" if ord(c) in cmap})
    composites = [i for i, n in enumerate(src.order) if src.glyf.glyphs[n].isComposite()][:150]
    return [letters, composites, list(range(0, len(src.order), max(1, len(src.order) // 600)))]


@pytest.mark.parametrize("path", _note_fonts())
def test_every_glyph_asked_for_keeps_its_outline_hinting_and_advance(path):
    src = source_font(path)
    assert src is not None
    original = FT2Font(path)
    for gids in _glyph_sets(src):
        data, index = src.subset(gids)
        assert sorted(index) == sorted(set(gids))
        cut = FT2Font(io.BytesIO(data))
        for gid in gids:
            if gid == 0:        # .notdef: emptied, as fontTools' subsetter empties it
                assert _glyph(cut, index[0], LoadFlags.NO_SCALE)[2] == b""
                continue
            for flags in (LoadFlags.NO_SCALE | LoadFlags.NO_HINTING, LoadFlags.DEFAULT):  # outline; hinted
                assert _glyph(cut, index[gid], flags) == _glyph(original, gid, flags), (path, gid, flags)


def test_a_subset_holds_the_asked_glyphs_and_their_components_only():
    path = next(p for p in _note_fonts() if "Liberation" in p or "DejaVu" in p)
    src = source_font(path)
    composite = next(i for i, n in enumerate(src.order) if src.glyf.glyphs[n].isComposite())
    parts = {src.ids[c] for c in src.glyf[src.order[composite]].getComponentNames(src.glyf)}
    data, index = src.subset([composite])
    cut = FT2Font(io.BytesIO(data))
    assert cut.num_glyphs == len({0, 1, 2, 3, composite} | parts)
    assert index == {composite: sorted({0, 1, 2, 3, composite} | parts).index(composite)}


def test_the_same_bytes_whatever_the_order_of_the_glyphs_asked_for():
    src = source_font(_note_fonts()[0])
    gids = _glyph_sets(src)[0] + _glyph_sets(src)[1][:20]
    assert src.subset(gids)[0] == src.subset(list(reversed(gids)))[0]


def test_a_font_without_truetype_outlines_goes_to_fonttools(tmp_path):
    from fontTools.fontBuilder import FontBuilder
    from fontTools.pens.t2CharStringPen import T2CharStringPen

    fb = FontBuilder(1000, isTTF=False)               # outlines in CFF: no glyf table
    fb.setupGlyphOrder([".notdef", "A"])
    fb.setupCharacterMap({ord("A"): "A"})
    pen = T2CharStringPen(500, None)
    pen.moveTo((0, 0))
    pen.lineTo((500, 700))
    pen.lineTo((500, 0))
    pen.closePath()
    fb.setupCFF("Test", {"FullName": "Test"}, {".notdef": pen.getCharString(), "A": pen.getCharString()}, {})
    fb.setupHorizontalMetrics({".notdef": (500, 0), "A": (500, 0)})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "Test", "styleName": "Regular"})
    fb.setupOS2()
    fb.setupPost()
    path = tmp_path / "test.otf"
    fb.save(str(path))
    with pytest.raises(UnsupportedFont) as info:
        SourceFont(str(path))
    assert "glyf" in info.value.reason and info.value.path == str(path)
    assert source_font(str(path)) is None


def _figure():
    fig = new_figure(8, 5)
    ax = fig.add_subplot()
    ax.plot([0, 1, 2], [0, 2, 1], label="$О_{1}$ кривая, Йё")
    ax.set_title(r"рисунок: $\omega_{1}$ = 1,5; $F_{\mathrm{ур}}$")
    ax.text(0.5, 0.5, "$A$, $B_{0}$", style="italic")
    ax.legend()
    return fig


@pytest.mark.slow          # runs poppler's pdftoppm (docs/testing.md)
@pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="poppler's pdftoppm is not installed")
def test_a_figure_prints_the_pixels_and_text_of_fonttools_subsets(tmp_path, monkeypatch):
    """The embedded fonts differ in bytes (no layout tables), never in what is printed."""
    from matplotlib.backends import _backend_pdf_ps as pdf_ps

    monkeypatch.setattr(saving, "_SUBSETS", {})
    saving.remember_font_subsets()                            # what saving the note's figures installs
    ours = pdf_ps.get_glyphs_subset
    assert getattr(ours, "reportgen_memo", False)
    save_pdf(_figure(), tmp_path / "cut.pdf")
    fonttools = ours
    while hasattr(fonttools, "reportgen_original"):     # under the memory (and the cut): matplotlib's
        fonttools = fonttools.reportgen_original
    monkeypatch.setattr(pdf_ps, "get_glyphs_subset", fonttools)
    save_pdf(_figure(), tmp_path / "fonttools.pdf")
    assert (tmp_path / "cut.pdf").read_bytes() != (tmp_path / "fonttools.pdf").read_bytes()
    pixels = {}
    for name in ("cut", "fonttools"):
        subprocess.run(["pdftoppm", "-r", "300", "-gray", str(tmp_path / f"{name}.pdf"), str(tmp_path / name)],
                       check=True)
        from PIL import Image
        pixels[name] = np.asarray(Image.open(next(tmp_path.glob(f"{name}-*.pgm"))))
        text = subprocess.run(["pdftotext", str(tmp_path / f"{name}.pdf"), "-"], capture_output=True, text=True)
        pixels[name + " text"] = text.stdout
    assert pixels["cut"].shape == pixels["fonttools"].shape
    assert np.array_equal(pixels["cut"], pixels["fonttools"])
    assert pixels["cut text"] == pixels["fonttools text"] and "кривая" in pixels["cut text"]


def test_sources_are_read_once_per_process():
    path = _note_fonts()[0]
    assert source_font(path) is source_font(path)
    assert (path, 0) in font_subset._SOURCES
