"""A TrueType font cut down to the glyphs a figure prints, for matplotlib's PDF backend (Type 42).

Matplotlib embeds, for every figure and every font it uses, a subset made by fontTools' general
subsetter: the whole font file parsed again each time (glyph table, metrics, glyph names, the
OpenType layout tables and their closure), ≈ 13 ms a subset, ~80 subsets in a press build — the
largest single item of the figures' CPU. A PDF viewer reads little of the embedded font: the PDF
gives every glyph by its number (``CIDToGIDMap``) and its width (``W``), so the OpenType layout
tables (GSUB, GPOS, GDEF, kern) are never read.

:class:`SourceFont` reads a font once per process and cuts a subset from the parsed tables: the
glyphs asked for, the four that TrueType recommends (.notdef, .null, CR, space, as matplotlib asks
fontTools for), and every component of a composite glyph (Й = И + breve); their outlines and
hinting instructions byte for byte, their advance widths and side bearings, the font's hinting
programs (``cvt``, ``fpgm``, ``prep``), ``OS/2``, ``gasp``, the names fontTools keeps (IDs 0–6,
Unicode platforms, English), the glyph names (``post``) and the Unicode ``cmap`` restricted to the
kept glyphs; ``.notdef`` is emptied as fontTools' default does. It is ~10× faster (≈ 1 ms) and
prints the same glyphs at the same places (``tests/speed/test_font_subset.py`` compares every
kept glyph's outline and advance with the original font's); the font's bytes differ from
fontTools' (no layout tables), so a figure's PDF is not byte-identical to one matplotlib writes
alone. A font this does not handle (outlines in CFF, no ``glyf``) goes to fontTools as before.
"""
from __future__ import annotations

import copy
import io
from typing import Any, Iterable

from reportgen.errors import ReportgenError

#: Tables copied as they are (hinting programs, metrics of the whole font, the grid-fitting table).
_RAW_TABLES = ("OS/2", "cvt ", "fpgm", "prep", "gasp")
#: The names fontTools' subsetter keeps by default (``name_IDs``: family, style, full name, version,
#: PostScript name, copyright, unique ID), of the Windows English and Unicode records.
_NAME_IDS = frozenset(range(7))
_NAME_LANGUAGE = 0x0409
#: The glyphs TrueType recommends every font to keep (.notdef, .null, CR, space: fontTools'
#: ``recommended_glyphs``, which matplotlib asks for).
_RECOMMENDED = range(4)


class UnsupportedFont(ReportgenError, ValueError):
    """The font is not one :class:`SourceFont` cuts (no TrueType outlines): fontTools subsets it."""

    def __init__(self, path: str, reason: str) -> None:
        super().__init__(f"{path}: {reason}")
        self.path = path
        self.reason = reason


class SourceFont:
    """A TrueType font read once; :meth:`subset` cuts subsets from its parsed tables."""

    def __init__(self, path: str, face: int = 0) -> None:
        from fontTools import ttLib

        font = ttLib.TTFont(path, fontNumber=face, lazy=True)
        missing = [t for t in ("glyf", "loca", "hmtx", "hhea", "head", "maxp", "cmap", "post") if t not in font]
        if missing:
            raise UnsupportedFont(path, "no " + ", ".join(missing) + " table")
        self.path = path
        self.font = font
        self.order: list[str] = font.getGlyphOrder()
        self.ids = {name: i for i, name in enumerate(self.order)}
        self.glyf = font["glyf"]
        self.metrics = font["hmtx"].metrics
        self.raw = {tag: font.reader[tag] for tag in _RAW_TABLES if tag in font.reader}
        self.cmaps = []                 # the Unicode subtables, each as glyph name → its code points
        for table in font["cmap"].tables:
            if table.isUnicode() and table.format in (4, 12):
                codes: dict[str, list[int]] = {}
                for code, name in table.cmap.items():
                    codes.setdefault(name, []).append(code)
                self.cmaps.append((table, codes))
        self.head, self.hhea, self.maxp, self.post = font["head"], font["hhea"], font["maxp"], font["post"]
        self.name = font["name"] if "name" in font else None

    def closure(self, gids: Iterable[int]) -> list[int]:
        """``gids`` with the recommended glyphs and every component of a composite, in font order."""
        n = len(self.order)
        keep = {g for g in gids if 0 <= g < n} | {g for g in _RECOMMENDED if g < n}
        todo = list(keep)
        while todo:
            name = self.order[todo.pop()]
            if not self.glyf.glyphs[name].isComposite():
                continue
            for component in self.glyf[name].getComponentNames(self.glyf):
                i = self.ids[component]
                if i not in keep:
                    keep.add(i)
                    todo.append(i)
        return sorted(keep)

    def subset(self, gids: Iterable[int]) -> tuple[bytes, dict[int, int]]:
        """The subset font's bytes and the map old glyph number → new for the glyphs asked for."""
        from fontTools import ttLib
        from fontTools.ttLib.tables._c_m_a_p import CmapSubtable
        from fontTools.ttLib.tables._g_l_y_f import Glyph
        from fontTools.ttLib.tables.DefaultTable import DefaultTable

        asked = [int(g) for g in gids]
        bad = [g for g in asked if not 0 <= g < len(self.order)]
        if bad:
            raise UnsupportedFont(self.path, f"no glyph {bad[0]}")
        order = [self.order[i] for i in self.closure(asked)]
        out = ttLib.TTFont(recalcBBoxes=False, recalcTimestamp=False)
        out.setGlyphOrder(order)
        glyf = ttLib.newTable("glyf")
        # a composite's components are named in its parsed form, so it is written with the new numbers
        glyf.glyphs = {name: (self.glyf[name] if self.glyf.glyphs[name].isComposite() else self.glyf.glyphs[name])
                       for name in order}
        glyf.glyphs[order[0]] = Glyph(b"")             # .notdef without an outline (fontTools' default)
        glyf.glyphOrder = order
        out["glyf"] = glyf
        out["loca"] = ttLib.newTable("loca")
        hmtx = ttLib.newTable("hmtx")
        hmtx.metrics = {name: self.metrics[name] for name in order}
        out["hmtx"] = hmtx
        for tag in ("head", "hhea", "maxp"):       # copies: compiling sets their counts and formats
            out[tag] = copy.copy(getattr(self, tag))
        post = copy.copy(self.post)
        post.extraNames, post.mapping = [], {}
        out["post"] = post
        cmap = ttLib.newTable("cmap")
        cmap.tableVersion, cmap.tables = 0, []
        for table, codes in self.cmaps:
            sub = CmapSubtable.newSubtable(table.format)
            sub.platformID, sub.platEncID, sub.language = table.platformID, table.platEncID, table.language
            sub.cmap = {code: name for name in order for code in codes.get(name, ())}
            if sub.cmap:
                cmap.tables.append(sub)
        out["cmap"] = cmap
        if self.name is not None:
            name_table = ttLib.newTable("name")
            name_table.names = [r for r in self.name.names if r.nameID in _NAME_IDS and r.isUnicode()
                                and (r.platformID == 0 or r.langID == _NAME_LANGUAGE)]
            out["name"] = name_table
        for tag, data in self.raw.items():
            raw = DefaultTable(tag)
            raw.data = data
            out[tag] = raw
        buf = io.BytesIO()
        out.save(buf, reorderTables=False)
        new = {name: i for i, name in enumerate(order)}
        return buf.getvalue(), {g: new[self.order[g]] for g in asked}


#: Fonts read in this process: (font file, face) → the parsed font, or the reason it is not cut here.
_SOURCES: dict[tuple[str, int], SourceFont | UnsupportedFont] = {}


def source_font(path: str, face: int = 0) -> SourceFont | None:
    """The font read once per process, or None when :class:`SourceFont` does not cut it."""
    key = (str(path), int(face))
    found = _SOURCES.get(key)
    if found is None:
        try:
            found = SourceFont(*key)
        except UnsupportedFont as exc:
            found = exc
        _SOURCES[key] = found
    return found if isinstance(found, SourceFont) else None


def cut_below(fonttools: Any) -> Any:
    """A ``get_glyphs_subset`` for matplotlib's PDF backend that cuts the subset from the font read
    once (:class:`SourceFont`) and asks ``fonttools`` (matplotlib's own, fontTools' subsetter) only
    for a font it does not cut: the bottom layer under the memory of subsets
    (:func:`.saving.remember_font_subsets`) and the build cache's subsets on disk
    (``reportgen/commands/subset_cache.py``). ``fonttools`` already such a layer: returned as is."""
    from contextlib import nullcontext

    if getattr(fonttools, "reportgen_cut", False):
        return fonttools

    def get_glyphs_subset(fontfile: Any, glyphs: Any) -> Any:
        source = source_font(str(fontfile), int(getattr(fontfile, "face_index", 0)))
        try:
            found = source.subset(sorted({int(g) for g in glyphs})) if source is not None else None
        except UnsupportedFont:
            found = None
        if found is None:
            return fonttools(fontfile, glyphs)
        return nullcontext(CutSubset(CutFont(found[0]), found[1]))

    get_glyphs_subset.reportgen_cut = True              # type: ignore[attr-defined]
    get_glyphs_subset.reportgen_original = fonttools    # type: ignore[attr-defined]
    return get_glyphs_subset


class CutFont:
    """A cut subset font as matplotlib's PDF backend uses it: only written out (``save``)."""

    def __init__(self, data: bytes) -> None:
        self.data = data

    def save(self, file: Any, **_options: Any) -> None:     # reorderTables: the bytes are final
        file.write(self.data)


class CutSubset:
    """What ``get_glyphs_subset`` yields: the subset font and the old → new glyph numbers."""

    def __init__(self, font: CutFont, glyph_index_map: dict[int, int]) -> None:
        self.font = font
        self.glyph_index_map = glyph_index_map
