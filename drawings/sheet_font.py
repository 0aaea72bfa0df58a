"""The sheets' lettering where osifont lacks a letter: a completed copy of the font for the previews.

osifont (Debian ``fonts-osifont``, the TTF the sheets' text style names) maps «ё», «Ё», «Э» and «э»
to an empty box (measured in its 2019 release: one four-point contour as tall as a capital), so
«подъёма» showed a box on the crane's sheet. :func:`completed_font` writes a copy of the installed
font with those four letters built from its own glyphs — «ё» = «е» + the combining diaeresis placed
as in its «ë», «Ё» likewise from «Ë»; «Э», «э» = «С», «с» mirrored with a bar (the hyphen, shortened)
— under the file name :data:`COMPLETED_FONT`, which the previews use in place of osifont
(:func:`drawings.preview.render_png`). The DXF keeps naming osifont.ttf: LibreCAD letters the sheets
with its own OpenGost type B (which has every Cyrillic letter) and other CAD programs find osifont.

:func:`drawable` tells whether a character has a real glyph in the font the previews use; the
lettering test checks every text of every example's sheets with it.
"""
from __future__ import annotations

import os
import tempfile
from functools import lru_cache
from pathlib import Path

from .style import TEXT_STYLE_FONT

#: The installed sheet font (Debian fonts-osifont).
OSIFONT = Path("/usr/share/fonts/truetype/osifont/osifont.ttf")
#: The completed copy's file name (what the previews' text style names).
COMPLETED_FONT = "osifont-reportgen.ttf"
#: Format of the copy: bump when the construction below changes (the file is rebuilt).
_VERSION = 4


def _folder() -> Path:
    """Where the copy lives: ``$XDG_CACHE_HOME/reportgen/fonts`` (``~/.cache/…``), else the temp folder."""
    base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "reportgen" / "fonts"
    try:
        base.mkdir(parents=True, exist_ok=True)
        probe = base / ".writable"
        probe.touch()
        return base
    except OSError:
        fallback = Path(tempfile.gettempdir()) / f"reportgen-fonts-{os.getuid()}"
        fallback.mkdir(parents=True, exist_ok=True)
        return fallback


def _is_placeholder(font, glyph_name: str) -> bool:
    """A glyph drawn as an empty box: one contour of at most five points, taller than half an em."""
    glyf = font["glyf"]
    g = glyf[glyph_name]
    if g.isComposite() or g.numberOfContours != 1:
        return False
    coords = g.getCoordinates(glyf)[0]
    if len(coords) > 5:
        return False
    ys = [y for _, y in coords]
    return max(ys) - min(ys) > 0.5 * font["head"].unitsPerEm


def _component(name: str, x: float, y: float, transform=None):
    from fontTools.ttLib.tables._g_l_y_f import GlyphComponent
    c = GlyphComponent()
    c.glyphName = name
    c.x, c.y = int(round(x)), int(round(y))
    c.flags = 0
    if transform is not None:
        c.transform = transform
    return c


def _composite(font, components, width_of: str):
    from fontTools.ttLib.tables._g_l_y_f import Glyph
    g = Glyph()
    g.numberOfContours = -1
    g.components = components
    g.recalcBounds(font["glyf"])
    return g, (font["hmtx"][width_of][0], g.xMin)


def _bounds(font, name: str) -> tuple[int, int, int, int]:
    g = font["glyf"][name]
    g.recalcBounds(font["glyf"])
    return g.xMin, g.yMin, g.xMax, g.yMax


def _inner_edge(glyph, glyphs, x0: float, x1: float, y: float) -> float:
    """Mirrored about the glyph's middle, the x where its right stroke begins at height ``y``
    (scanning from the right: inside the stroke, then out of it)."""
    from fontTools.pens.pointInsidePen import PointInsidePen
    inside_seen = False
    x = x1
    while x > (x0 + x1) / 2:
        pen = PointInsidePen(glyphs, (x0 + x1 - x, y))        # the unmirrored glyph's point
        glyph.draw(pen)
        if pen.getResult():
            inside_seen = True
        elif inside_seen:
            return x
        x -= 1.0
    return x1


def _build(source: Path, target: Path) -> None:
    from fontTools.ttLib import TTFont
    font = TTFont(source)
    cmap = font.getBestCmap()
    glyf, hmtx = font["glyf"], font["hmtx"]
    new = {}
    # ё, Ё: the Cyrillic letter with the diaeresis where the Latin ë, Ë carry it
    for cyr, base, latin, latin_base in (("ё", "е", "ë", "e"), ("Ё", "Е", "Ë", "E")):
        mark = next(c for c in glyf[cmap[ord(latin)]].components if c.glyphName != cmap[ord(latin_base)])
        shift = _bounds(font, cmap[ord(base)])[0] - _bounds(font, cmap[ord(latin_base)])[0]
        new[cyr] = _composite(font, [_component(cmap[ord(base)], 0, 0),
                                     _component(mark.glyphName, mark.x + shift, mark.y)], cmap[ord(base)])
    # Э, э: С, с mirrored about their middle, with a bar from a third of the width to the bowl;
    # drawn as plain outlines (ezdxf's renderer misplaces transformed components), the mirrored
    # contours reversed where needed so that both parts wind the same way (no hole where they meet)
    from fontTools.pens.areaPen import AreaPen
    from fontTools.pens.reverseContourPen import ReverseContourPen
    from fontTools.pens.transformPen import TransformPen
    from fontTools.pens.ttGlyphPen import TTGlyphPen
    glyphs = font.getGlyphSet()
    bar = cmap[ord("-")]
    bx0, by0, bx1, by1 = _bounds(font, bar)
    for cyr, base in (("Э", "С"), ("э", "с")):
        x0, y0, x1, y1 = _bounds(font, cmap[ord(base)])
        mirror = (-1, 0, 0, 1, x0 + x1, 0)
        dy = (y0 + y1) / 2 - (by0 + by1) / 2
        # the bar ends at the bowl's inner edge (renderers fill text even-odd: no overlap)
        left, right = x0 + 0.35 * (x1 - x0), _inner_edge(glyphs[cmap[ord(base)]], glyphs, x0, x1, (y0 + y1) / 2)
        sx = (right - left) / (bx1 - bx0)
        bowl_area, bar_area = AreaPen(glyphs), AreaPen(glyphs)
        glyphs[cmap[ord(base)]].draw(TransformPen(bowl_area, mirror))
        glyphs[bar].draw(bar_area)
        reverse = (bowl_area.value > 0) != (bar_area.value > 0)
        pen = TTGlyphPen(None)
        glyphs[cmap[ord(base)]].draw(TransformPen(ReverseContourPen(pen) if reverse else pen, mirror))
        glyphs[bar].draw(TransformPen(pen, (sx, 0, 0, 1, left - sx * bx0, dy)))
        glyph = pen.glyph()
        glyph.recalcBounds(glyf)
        new[cyr] = (glyph, (hmtx[cmap[ord(base)]][0], glyph.xMin))
    for ch, (glyph, metrics) in new.items():
        name = cmap[ord(ch)]
        if not _is_placeholder(font, name):
            continue                      # a later osifont has the letter: keep it
        glyf[name] = glyph
        hmtx[name] = metrics
    for record in font["name"].names:
        if record.nameID in (1, 3, 4, 6, 16):
            family = "osifont-reportgen" if record.nameID == 6 else "osifont reportgen"
            record.string = family
    tmp = target.with_suffix(".tmp")
    font.save(tmp)
    tmp.replace(target)


@lru_cache(maxsize=1)
def completed_font() -> Path | None:
    """The completed copy of osifont (built on first use, registered with ezdxf's font manager);
    None when osifont is not installed (`make system`)."""
    if not OSIFONT.is_file():
        return None
    folder = _folder() / f"v{_VERSION}-{OSIFONT.stat().st_size}-{int(OSIFONT.stat().st_mtime)}"
    folder.mkdir(parents=True, exist_ok=True)
    target = folder / COMPLETED_FONT
    if not target.is_file():
        _build(OSIFONT, target)
    from ezdxf.fonts import fonts
    fonts.font_manager.scan_folder(folder)
    return target


def preview_font() -> str:
    """The font file name the previews letter the sheets with: the completed copy, else osifont."""
    return COMPLETED_FONT if completed_font() is not None else TEXT_STYLE_FONT


@lru_cache(maxsize=1)
def _drawable_set() -> frozenset[int]:
    from fontTools.ttLib import TTFont
    path = completed_font() or OSIFONT
    font = TTFont(path)
    return frozenset(cp for cp, name in font.getBestCmap().items() if not _is_placeholder(font, name))


def drawable(ch: str) -> bool:
    """``ch`` has a real glyph (not a missing one, not osifont's empty box) in the previews' font;
    white space always counts as drawable."""
    return ch.isspace() or ord(ch) in _drawable_set()
