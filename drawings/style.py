"""Layers, ГОСТ 2.303 line types, the ГОСТ 2.304-like text style and the ESKD dimension style.

Everything a sheet DXF needs before the first entity is drawn: :func:`new_document` builds a
reproducible R2013 document in millimetres with these tables and the matching ``$…`` header
variables (LibreCAD reads the header, not only the style tables).
"""
from __future__ import annotations

import contextlib
from dataclasses import dataclass
from functools import lru_cache
from typing import Iterator

import ezdxf
from ezdxf.document import Drawing

#: LibreCAD chooses the font of a TEXT by the *name* of its text style; OpenGostTypeB-Regular.lff
#: ships with librecad-data. ezdxf 1.4.5 cannot parse that .lff, so the style's font *file* is a TTF
#: that ezdxf (the PNG previews) and other CAD programs render instead: osifont (Debian
#: ``fonts-osifont``), an ISO 3098 CAD font — the lettering ГОСТ 2.304 follows — with Cyrillic,
#: Ukrainian and Greek glyphs. So every place that shows a sheet letters it ГОСТ-like.
TEXT_STYLE = "OpenGostTypeB-Regular"
TEXT_STYLE_FONT = "osifont.ttf"
#: Text boxes are measured with DejaVu Sans Mono: its advance is nearly LibreCAD's OpenGost type B
#: (measured: 231 vs 234 mm for a 38-character line at 7 mm) and wider than osifont's (43.5 vs
#: 49.6 mm for «ТММ.КП 12345» at 5 mm), so a box holds its text in every renderer.
MEASURE_FONT = "DejaVuSansMono.ttf"

#: The dimension style of every sheet.
DIM_STYLE = "ESKD"

#: ГОСТ 2.304 font sizes (height of capitals, mm).
TEXT_HEIGHTS = (2.5, 3.5, 5.0, 7.0, 10.0, 14.0)

#: Standard DXF lineweights, 1/100 mm.
_LINEWEIGHTS = (13, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200, 211)


@dataclass(frozen=True)
class LineType:
    """A line type: DXF name (one LibreCAD knows), description, dash pattern in mm.

    ``pattern`` lists dashes (> 0), gaps (< 0) and dots (0), ezdxf-style without the total.
    """
    name: str
    description: str
    pattern: tuple[float, ...]

    @property
    def total(self) -> float:
        return sum(abs(x) for x in self.pattern)


#: ГОСТ 2.303 lines under the names LibreCAD draws. Dash and gap lengths are the mid-range of the
#: standard for an A1 sheet (thin dash-dot: dashes 5–30, gaps 3–5 mm; dashed: 2–8 / 1–2 mm).
LINETYPES: tuple[LineType, ...] = (
    LineType("CENTER", "Штрихпунктирная тонкая (оси) ____ . ____ .", (20.0, -1.5, 0.5, -1.5)),
    LineType("DASHED", "Штриховая (невидимый контур) _ _ _ _", (5.0, -1.5)),
    LineType("DASHDOT", "Штрихпунктирная утолщённая __ . __ .", (6.0, -1.5, 0.5, -1.5)),
    LineType("DIVIDE", "Штрихпунктирная с двумя точками ____ . . ____",
             (20.0, -1.5, 0.5, -1.5, 0.5, -1.5)),
)


@dataclass(frozen=True)
class LayerSpec:
    """A layer: name, DXF line type, lineweight in 1/100 mm, ACI colour, what it holds."""
    name: str
    linetype: str
    lineweight: int
    color: int
    purpose: str


#: Line width of the main contour (ГОСТ 2.303 ``s``) and of thin lines, mm.
CONTOUR_WIDTH = 0.7
THIN_WIDTH = 0.35

LAYERS: tuple[LayerSpec, ...] = (
    LayerSpec("contour", "Continuous", 70, 7, "сплошная основная: links, frame, title-block outline"),
    LayerSpec("thin", "Continuous", 35, 7, "сплошная тонкая: hatching, title-block grid, leaders"),
    LayerSpec("axis", "CENTER", 35, 7, "штрихпунктирная тонкая: axes and centre lines"),
    LayerSpec("hidden", "DASHED", 35, 7, "штриховая: hidden contours"),
    LayerSpec("phantom", "DIVIDE", 35, 7, "штрихпунктирная с двумя точками: extreme positions"),
    LayerSpec("dimensions", "Continuous", 35, 7, "dimensions"),
    LayerSpec("text", "Continuous", 35, 7, "texts and labels"),
    LayerSpec("vectors", "Continuous", 50, 7, "vectors of plans and force polygons"),
    LayerSpec("construction", "Continuous", 25, 8, "construction lines of plans and diagrams"),
)
LAYER_NAMES = tuple(spec.name for spec in LAYERS)


def nearest_lineweight(width_mm: float) -> int:
    """The standard DXF lineweight (1/100 mm) nearest to ``width_mm``."""
    target = width_mm * 100.0
    return min(_LINEWEIGHTS, key=lambda lw: (abs(lw - target), lw))


def text_lineweight(height: float) -> int:
    """Stroke width of ГОСТ type B text, d = h/10, never thinner than 0.25 mm (1/100 mm)."""
    return nearest_lineweight(max(height / 10.0, 0.25))


@lru_cache(maxsize=64)
def _font(height: float):
    from ezdxf.fonts import fonts
    return fonts.make_font(MEASURE_FONT, height)


@lru_cache(maxsize=1)
def ensure_sheet_font() -> bool:
    """Make ezdxf know the sheet font (its font cache may predate the font's installation): rebuild
    the cache once if the font is missing. False when the font is not installed (ezdxf then falls
    back to its default font; `make system` installs fonts-osifont)."""
    from ezdxf.fonts import fonts
    if fonts.font_manager.has_font(TEXT_STYLE_FONT):
        return True
    fonts.build_system_font_cache()
    return fonts.font_manager.has_font(TEXT_STYLE_FONT)


#: LibreCAD's OpenGost type B is proportional: measured against the TTF advance it ran 0.88–1.03
#: for lower case and digits, 1.10 for Cyrillic capitals, 1.28 for W/M. Text boxes use the TTF
#: width × this margin, so what fits the box fits in both renderers except runs of W and M.
WIDTH_MARGIN = 1.1


@lru_cache(maxsize=16384)
def text_width(text: str, height: float) -> float:
    """Width (mm) of a one-line ``text`` of capital height ``height`` in the sheet text style,
    conservatively (TTF advance × :data:`WIDTH_MARGIN`). Remembered: the label placers ask for the
    same few texts tens of thousands of times (sheet 1: 55 000 calls, 140 distinct)."""
    if not text:
        return 0.0
    return float(_font(round(height, 6)).text_width(text)) * WIDTH_MARGIN


@contextlib.contextmanager
def reproducible() -> Iterator[None]:
    """Make ezdxf write fixed dates, GUIDs and marker strings (same input → same bytes)."""
    old = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        yield
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = old


def fix_classes_order(doc: Drawing) -> None:
    """Register the CLASSES section's entries in a fixed order before the document is written.

    ezdxf adds one class per entity type in use while saving, iterating a set of type names, so
    the section's order (and the file's bytes) followed PYTHONHASHSEED. Registered here first —
    ezdxf's required classes, then the rest sorted by name — saving finds them all present.
    """
    doc.commit_pending_changes()
    doc.classes.add_required_classes(doc.dxfversion)
    classes = doc.classes.classes
    names = _required_class_names(doc.dxfversion)
    required = sorted((k for k in classes if k[0] in names), key=lambda k: (names.index(k[0]), k))
    rest = sorted(k for k in classes if k[0] not in names)
    ordered = {k: classes[k] for k in required + rest}
    classes.clear()
    classes.update(ordered)


def _required_class_names(dxfversion: str) -> list[str]:
    from ezdxf.sections.classes import REQ_R2004, REQUIRED_CLASSES
    return list(REQUIRED_CLASSES.get(dxfversion, REQ_R2004))


def new_document(paper_width: float, paper_height: float) -> Drawing:
    """A new R2013 document in mm with the sheet's layers, line types, text and dimension styles."""
    with reproducible():
        doc = ezdxf.new("R2013", setup=False, units=ezdxf.units.MM)
    _setup_linetypes(doc)
    _setup_layers(doc)
    _setup_text_style(doc)
    _setup_dimstyle(doc)
    _setup_header(doc, paper_width, paper_height)
    return doc


def _setup_linetypes(doc: Drawing) -> None:
    for lt in LINETYPES:
        if lt.name in doc.linetypes:
            doc.linetypes.remove(lt.name)
        doc.linetypes.add(lt.name, pattern=[lt.total, *lt.pattern], description=lt.description)


def _setup_layers(doc: Drawing) -> None:
    for spec in LAYERS:
        doc.layers.add(spec.name, color=spec.color, linetype=spec.linetype,
                       lineweight=spec.lineweight)


def _setup_text_style(doc: Drawing) -> None:
    doc.styles.add(TEXT_STYLE, font=TEXT_STYLE_FONT)
    standard = doc.styles.get("Standard")
    standard.dxf.font = TEXT_STYLE_FONT


#: The ESKD dimension style: ГОСТ 2.307 — 3.5 mm text above the dimension line, 3.5 mm filled
#: arrows, extension lines from the object and 2 mm beyond the dimension line, decimal comma,
#: trailing zeros suppressed. Keys are DIMSTYLE attributes and, with ``$`` + upper case, header vars.
DIMSTYLE_VALUES: dict[str, float | int | str] = {
    "dimtxt": 3.5,      # text height
    "dimasz": 3.5,      # arrow size
    "dimexe": 2.0,      # extension beyond the dimension line
    "dimexo": 0.0,      # offset of the extension line from the object
    "dimgap": 1.0,      # gap text ↔ dimension line
    "dimdli": 7.0,      # spacing of baseline dimensions (ГОСТ: ≥ 7 mm)
    "dimtad": 1,        # text above the line
    "dimjust": 0,       # centred along the line
    "dimtih": 0,        # text aligned with the line inside…
    "dimtoh": 0,        # …and outside the extension lines
    "dimdsep": ord(","),  # decimal comma
    "dimdec": 2,        # decimals
    "dimzin": 8,        # suppress trailing zeros
    "dimlunit": 2,      # decimal units
    "dimscale": 1.0,
    "dimlfac": 1.0,
    "dimtfac": 1.0,
    "dimtxsty": TEXT_STYLE,
    "dimlwd": 35,       # dimension-line weight
    "dimlwe": 35,       # extension-line weight
    "dimclrd": 0,       # colours BYBLOCK
    "dimclre": 0,
    "dimclrt": 0,
    "dimatfit": 3,
    "dimtmove": 0,
    "dimtofl": 1,       # a dimension line between the extension lines even when text is outside
}


def _setup_dimstyle(doc: Drawing) -> None:
    dimstyle = doc.dimstyles.new(DIM_STYLE)
    for key, value in DIMSTYLE_VALUES.items():
        dimstyle.dxf.set(key, value)


def _setup_header(doc: Drawing, paper_width: float, paper_height: float) -> None:
    h = doc.header
    for key, value in DIMSTYLE_VALUES.items():
        h["$" + key.upper()] = value
    h["$DIMSTYLE"] = DIM_STYLE
    h["$TEXTSTYLE"] = TEXT_STYLE
    h["$TEXTSIZE"] = 3.5
    h["$INSUNITS"] = 4        # millimetres
    h["$MEASUREMENT"] = 1     # metric
    h["$LUNITS"] = 2
    h["$LUPREC"] = 2
    h["$LTSCALE"] = 1.0
    h["$CELTSCALE"] = 1.0
    h["$PSLTSCALE"] = 0
    h["$LWDISPLAY"] = 1
    # ezdxf rewrites $LIMMIN/MAX, $PLIMMIN/MAX and $EXTMIN/MAX from the layouts on save
    w, hh = float(paper_width), float(paper_height)
    msp = doc.modelspace()
    msp.dxf.limmin, msp.dxf.limmax = (0.0, 0.0), (w, hh)
    msp.dxf.extmin, msp.dxf.extmax = (0.0, 0.0, 0.0), (w, hh, 0.0)
    paper = doc.active_layout()
    paper.page_setup(size=(w, hh), margins=(0, 0, 0, 0), units="mm", scale=(1, 1))
    paper.dxf.limmin, paper.dxf.limmax = (0.0, 0.0), (w, hh)
    h["$PLIMMIN"] = (0.0, 0.0)
    h["$PLIMMAX"] = (float(paper_width), float(paper_height))
    h["$LIMMIN"] = (0.0, 0.0)
    h["$LIMMAX"] = (float(paper_width), float(paper_height))
    h["$EXTMIN"] = (0.0, 0.0, 0.0)
    h["$EXTMAX"] = (float(paper_width), float(paper_height), 0.0)


#: Characters the sheet font (osifont) lacks, written with the nearest one it has.
FONT_SUBSTITUTES = {"\u2032": "'", "\u2033": "''"}


def dxf_literal(text: str) -> str:
    """Text as the DXF TEXT entity must hold it to print literally: ``%%d``, ``%%c``, ``%%p`` are
    control codes (°, ⌀, ±), so every ``%`` of a ``%%`` run is written ``%%%``; ``^`` followed by a
    character is a control character (``^I`` a tab), so ``^`` is written ``^ `` (caret-space prints
    a caret; a user's "x ^ y" keeps its spaces); characters the sheet font lacks (the prime of «2′»)
    take their :data:`FONT_SUBSTITUTES`."""
    for ch, sub in FONT_SUBSTITUTES.items():
        text = text.replace(ch, sub)
    text = text.replace("%%", "%%%%%%") if "%%" in text else text
    return text.replace("^", "^ ")
