"""An ESKD drawing sheet: format, frame, ГОСТ 2.104 form 1 title block, graph 26, views.

Everything lives in modelspace at 1:1 mm (LibreCAD draws paperspace over modelspace). A scene
module asks the sheet for views; the sheet packs them into the free field and each view is a
:class:`~drawings.primitives.Canvas` mapping the scene's model units to sheet millimetres::

    sheet = Sheet.a1(task.document, title="Кинематический анализ", code="ТММ.КП.01", number=1, count=4)
    scheme = sheet.add_model_view("scheme", bounds=(-0.1, -0.2, 0.4, 0.15), scale=400)
    scheme.polyline([(0, 0), (0.1, 0.05)])
    sheet.save("sheet1.dxf")
"""
from __future__ import annotations

import os
from dataclasses import dataclass, replace
from typing import Any, Sequence

from ezdxf.document import Drawing
from shapely.geometry import Polygon, box

from . import style
from .layout import Overlap, Rect, Request, find_overlaps, pack
from .primitives import _ALIGN, _ALIGN_NAMES, Annotations, Canvas, Transform
from .words import tr
from reportgen.errors import InternalError, ParameterError
from reportgen.scenes.boxes import (EXTRA_H, EXTRA_W, FRAME_BOTTOM, FRAME_LEFT, FRAME_RIGHT,  # noqa: F401
                                    FRAME_TOP, SHEET_MM, TITLE_H, TITLE_W, free_field)
from reportgen.tolerances import AREA_EPS_MM2

# ---------------------------------------------------------------------------------------------
# formats and the title block grid


@dataclass(frozen=True)
class SheetFormat:
    """A sheet format (ГОСТ 2.301), landscape: ``width`` × ``height`` mm."""
    name: str
    width: float
    height: float


A1 = SheetFormat("A1", *SHEET_MM["A1"])
A2 = SheetFormat("A2", *SHEET_MM["A2"])
A3 = SheetFormat("A3", *SHEET_MM["A3"])

# The frame's offsets (ГОСТ 2.301), form 1 of ГОСТ 2.104 (185 × 55 mm) and graph 26 (70 × 14 mm) are
# numbers of the core (reportgen.scenes.boxes: the core arranges sheet 1's views in the same field).

# Lines of the title block in its own coordinates (mm from its lower-left corner):
# (x0, y0, x1, y1, thick). Left part: columns 7 | 10 | 23 | 15 | 10, eleven rows of 5 mm; right
# part: graph 2 (120 × 15) on top; graph 1 (70 × 25) | Лит. (3 × 5) / Масса (17) / Масштаб (18)
# with a 5 mm caption row and a 15 mm value row, Лист (20) | Листов (30); graph 3 (70 × 15) |
# graph 8 (50 × 15) at the bottom.
TITLE_LINES: tuple[tuple[float, float, float, float, bool], ...] = (
    # change records and the signature rows (left part)
    (0, 50, 65, 50, False), (0, 45, 65, 45, False), (0, 40, 65, 40, False),
    (0, 35, 65, 35, True), (0, 30, 65, 30, True),
    (0, 25, 65, 25, False), (0, 20, 65, 20, False), (0, 15, 65, 15, False),
    (0, 10, 65, 10, False), (0, 5, 65, 5, False),
    (7, 30, 7, 55, True), (17, 0, 17, 55, True), (40, 0, 40, 55, True),
    (55, 0, 55, 55, True), (65, 0, 65, 55, True),
    # right part
    (65, 40, 185, 40, True), (65, 15, 185, 15, True),
    (135, 0, 135, 40, True), (135, 35, 185, 35, True), (135, 20, 185, 20, True),
    (140, 20, 140, 35, False), (145, 20, 145, 35, False),
    (150, 20, 150, 40, True), (167, 20, 167, 40, True), (155, 15, 155, 20, True),
)

#: Fixed captions: (catalogue key ``sheets.<key>``, x, y of the cell's lower-left, cell width, cell height).
TITLE_CAPTIONS: tuple[tuple[str, float, float, float, float], ...] = (
    ("blk02", 0, 30, 7, 5), ("blk03", 7, 30, 10, 5), ("blk04", 17, 30, 23, 5),
    ("blk05", 40, 30, 15, 5), ("blk06", 55, 30, 10, 5),
    ("blk07", 0, 25, 17, 5), ("blk08", 0, 20, 17, 5), ("blk09", 0, 15, 17, 5),
    ("blk10", 0, 5, 17, 5), ("blk11", 0, 0, 17, 5),
    ("blk12", 135, 35, 15, 5), ("blk13", 150, 35, 17, 5), ("blk14", 167, 35, 18, 5),
)
CAPTION_HEIGHT = 2.5


@dataclass(frozen=True)
class TitleBlock:
    """What goes into the title block. ``title`` → graph 1, ``code`` → graph 2 and graph 26,
    ``organization``/``group`` → graph 8 (two lines), ``author``/``supervisor`` → Разраб./Пров.
    ``letter`` → Лит. (empty: the student letter of the language, ``У`` = учебный), ``scale`` → Масштаб (blank when views have several)."""
    title: str
    code: str
    number: int = 1
    count: int = 1
    author: str = ""
    supervisor: str = ""
    organization: str = ""
    group: str = ""
    scale: str = ""
    letter: str = ""
    mass: str = ""

    def __post_init__(self) -> None:
        if not (1 <= self.number <= self.count):
            raise ParameterError("sheet number", self.number, f"1…{self.count}")

    @classmethod
    def from_document(cls, document: Any, *, title: str, code: str, number: int = 1,
                      count: int = 1, scale: str = "", letter: str = "") -> "TitleBlock":
        """From a ``reportgen.task.Document``-like object (author, supervisor, organization, group)."""
        return cls(title=title, code=code, number=number, count=count,
                   author=getattr(document, "author", "") or "",
                   supervisor=getattr(document, "supervisor", "") or "",
                   organization=getattr(document, "organization", "") or "",
                   group=getattr(document, "group", "") or "",
                   scale=scale, letter=letter)


# ---------------------------------------------------------------------------------------------
# fitting text into cells


def _wrap(text: str, height: float, width: float, width_factor: float) -> list[str]:
    """Greedy word wrap; a newline in ``text`` always starts a new line."""
    lines: list[str] = []
    for paragraph in text.split("\n"):
        start = len(lines)
        for word in paragraph.split():
            if len(lines) > start and style.text_width(lines[-1] + " " + word,
                                                       height) * width_factor <= width:
                lines[-1] += " " + word
            else:
                lines.append(word)
    return lines or [""]


def fit_text(text: str, width: float, height: float, *, max_height: float,
             min_height: float = 2.5, max_lines: int = 1,
             min_width_factor: float = 0.7) -> tuple[list[str], float, float]:
    """Lines, text height and width factor that fit ``text`` into a ``width`` × ``height`` cell.

    Tries the ГОСТ sizes from ``max_height`` down; for each, letters of full width and then
    narrower ones down to ``min_width_factor``, one line first, then up to ``max_lines`` wrapped
    lines at a 1.6 × height pitch. As a last resort the smallest size is squeezed to fit.
    """
    sizes = [h for h in style.TEXT_HEIGHTS if min_height <= h <= max_height] or [min_height]
    for h in reversed(sizes):
        for wf in (1.0, 0.9, 0.8, min_width_factor):
            for n in range(1, max_lines + 1):
                lines = _wrap(text, h, width / wf, 1.0) if n > 1 or "\n" in text else [text]
                if len(lines) > n:
                    continue
                tall = h * (1 + 1.6 * (len(lines) - 1))
                wide = max(style.text_width(s, h) for s in lines) * wf
                if tall <= height and wide <= width:
                    return lines, h, wf
    # last resort: the smallest size, never dropping words; squeeze the letters to fit
    h = sizes[0]
    lines = _wrap(text, h, width / min_width_factor, 1.0)
    if len(lines) > max_lines:
        lines = lines[:max_lines - 1] + [" ".join(lines[max_lines - 1:])]
    wide = max(style.text_width(s, h) for s in lines)
    return lines, h, min(min_width_factor, width / wide)


# ---------------------------------------------------------------------------------------------
# views


def view_of(owner: str) -> str:
    """The view a canvas belongs to: ``plans_all/3`` (a part drawn as a canvas of its own) → ``plans_all``."""
    return owner.split("/", 1)[0]


#: The smallest height a view's caption is lettered down to, mm (ГОСТ 2.304 size 3.5).
TITLE_MIN_MM = 3.5


class _Recording:
    """A layout that writes into ``layout`` and keeps the handle of every entity added through it
    (``add_*``) in ``handles``: what a view drew, for the checks that no two views' drawings meet
    and that a view draws within its rectangle (tests/drawings/test_views_apart.py reads the
    entities back by these handles)."""

    def __init__(self, layout: Any, handles: list[str]) -> None:
        self._layout = layout
        self._handles = handles

    def __getattr__(self, name: str) -> Any:
        attr = getattr(self._layout, name)
        if not name.startswith("add_") or not callable(attr):
            return attr

        def add(*args: Any, **kwargs: Any) -> Any:
            made = attr(*args, **kwargs)
            entity = getattr(made, "dimension", made)         # a dimension's override holds it
            handle = getattr(getattr(entity, "dxf", None), "handle", None)
            if handle is not None:
                self._handles.append(str(handle))
            return made
        return add


class View(Canvas):
    """A placed view: a :class:`Canvas` whose ``rect`` (sheet mm) is reserved on the sheet;
    ``handles`` the DXF handles of everything it drew (through any canvas on its ``layout``).
    A part of a view drawn as a view of its own is named ``view/part`` (a small plan's cell,
    ``plans_all/3``): it is in :attr:`Sheet.all_views`, not in :attr:`Sheet.views`."""

    def __init__(self, sheet: "Sheet", name: str, rect: Rect, transform: Transform) -> None:
        self.handles: list[str] = []
        layout: Any = _Recording(sheet.msp, self.handles)      # the modelspace, keeping what it drew
        super().__init__(layout, transform, sheet.annotations, name)
        self.sheet = sheet
        self.rect = rect
        sheet.all_views[name] = self

    def title(self, text: str, height: float = 5.0) -> None:
        """A caption centred above the view (inside its rectangle's top margin). A caption wider
        than the view (a small mechanism's narrow scheme: the shaper × 0.02 wrote «Кинематическая
        схема механизма (12 положений)» 4 mm over the frame) is lettered down to 3.5 mm to fit the
        view, and kept within the frame."""
        r, frame = self.rect, self.sheet.frame
        width = style.text_width(text, height)
        if width > r.x1 - r.x0 and height > TITLE_MIN_MM:
            height = max(TITLE_MIN_MM, height * (r.x1 - r.x0) / width)
            width = style.text_width(text, height)
        half = width / 2 + 1.0
        x = r.center[0]
        if frame.x1 - frame.x0 > 2 * half:
            x = min(max(x, frame.x0 + half), frame.x1 - half)
        self.text_mm((x, r.y1 - height - 1.0), text, height, "bottom-center")


# ---------------------------------------------------------------------------------------------
# the sheet


class Sheet:
    """One ESKD sheet in a fresh ezdxf document: frame, title block, graph 26, views."""

    def __init__(self, fmt: SheetFormat, title_block: TitleBlock, *, margin: float = 5.0) -> None:
        self.format = fmt
        self.fields = title_block
        self.doc: Drawing = style.new_document(fmt.width, fmt.height)
        self.msp = self.doc.modelspace()
        self.annotations = Annotations()
        self.canvas = Canvas(self.msp, Transform(), self.annotations, "sheet")
        self.frame = Rect(FRAME_LEFT, FRAME_BOTTOM, fmt.width - FRAME_RIGHT, fmt.height - FRAME_TOP)
        self.title_rect = Rect(self.frame.x1 - TITLE_W, self.frame.y0, self.frame.x1,
                               self.frame.y0 + TITLE_H)
        self.extra_rect = Rect(self.frame.x0, self.frame.y1 - EXTRA_H, self.frame.x0 + EXTRA_W,
                               self.frame.y1)
        self.margin = margin
        #: The views packed on the sheet, by name.
        self.views: dict[str, View] = {}
        #: Every view and every part of one drawn as a view of its own (``plans_all/3``), by name.
        self.all_views: dict[str, View] = {}
        self._draw_format()

    @classmethod
    def a1(cls, document: Any, *, title: str, code: str, number: int = 1, count: int = 1,
           scale: str = "", letter: str = "") -> "Sheet":
        """An A1 landscape sheet whose title block is filled from a ``Document``."""
        return cls(A1, TitleBlock.from_document(document, title=title, code=code, number=number,
                                                count=count, scale=scale, letter=letter))

    #: «Масштаб» of a sheet whose views are schemes: ГОСТ 2.701 (п. 4.1.1) draws schemes without
    #: scale, so the cell says so with a dash instead of staying empty (or naming a false ratio).
    NO_SCALE = "—"

    def set_scale(self, label: str) -> None:
        """Fill «Масштаб» of the title block with the main view's scale (ГОСТ 2.104 graph 6,
        ГОСТ 2.109: the other views' scales are written at their titles); once per sheet."""
        if self.fields.scale or not label:
            return
        self.fields = replace(self.fields, scale=label)
        tx, ty = self.title_rect.x0, self.title_rect.y0
        self._cell_text(label, tx + 167, ty + 20, 18, 15, max_height=3.5)

    # -- the free field and views --------------------------------------------------------------
    @property
    def free_region(self) -> Polygon:
        """The frame's interior less the title block and graph 26, ``margin`` mm clear of all."""
        return free_field(self.format.width, self.format.height, self.margin)

    def add_view(self, name: str, width: float, height: float, *, preferred: str = "top-left",
                 gap: float = 10.0, scale: float = 1.0, origin: tuple[float, float] = (0.0, 0.0)
                 ) -> View:
        """Reserve ``width`` × ``height`` mm, packed near ``preferred``; model ``origin`` maps to
        the view's lower-left corner, ``scale`` sheet mm per model unit."""
        if name in self.views:
            raise InternalError("sheet", f"a view named {name!r} is already on it")
        placed = [v.rect for v in self.views.values()]
        rect = pack(self.free_region, [Request(name, width, height, preferred)], gap=gap,
                    placed=placed)[0]
        return self.place_view(name, rect, Transform(scale, origin, (rect.x0, rect.y0)))

    def add_model_view(self, name: str, bounds: Sequence[float], scale: float, *,
                       padding_mm: float = 15.0, preferred: str = "top-left",
                       gap: float = 10.0) -> View:
        """A view that shows model ``bounds`` (xmin, ymin, xmax, ymax) at ``scale`` sheet mm per
        model unit, with ``padding_mm`` around it for symbols, labels and dimensions."""
        xmin, ymin, xmax, ymax = map(float, bounds)
        w = (xmax - xmin) * scale + 2 * padding_mm
        h = (ymax - ymin) * scale + 2 * padding_mm
        view = self.add_view(name, w, h, preferred=preferred, gap=gap, scale=scale,
                             origin=(xmin, ymin))
        view.transform = Transform(scale, (xmin, ymin),
                                   (view.rect.x0 + padding_mm, view.rect.y0 + padding_mm))
        return view

    def place_view(self, name: str, rect: Rect, transform: Transform) -> View:
        """Put a view at an explicit rectangle (no packing; :meth:`overlaps` still checks it)."""
        view = View(self, name, rect, transform)
        self.views[name] = view
        return view

    # -- checks -------------------------------------------------------------------------------
    def overlaps(self) -> list[Overlap]:
        """Everything that overlaps: views with each other or with the title block / graph 26,
        views or texts outside the frame, texts with texts, texts of one view inside another."""
        found: list[Overlap] = []
        reserved = [("title block", self.title_rect.polygon()), ("graph 26", self.extra_rect.polygon())]
        views = [(f"view {n}", v.rect.polygon()) for n, v in self.views.items()]
        found += find_overlaps(views + reserved)
        inner = self.frame.polygon()
        for name, poly in views + list(self.annotations.boxes):
            outside = poly.difference(inner).area
            if outside > AREA_EPS_MM2:
                found.append(Overlap(name, "outside the frame", outside))
        found += find_overlaps(list(self.annotations.boxes))
        for name, poly in self.annotations.boxes:
            owner = view_of(name.split(":", 1)[0])
            for vname, vpoly in views + reserved:
                if vname == f"view {owner}":
                    continue
                area = poly.intersection(vpoly).area
                if area > AREA_EPS_MM2:
                    found.append(Overlap(name, vname, area))
        return found

    # -- output -------------------------------------------------------------------------------
    def save(self, path: str | os.PathLike[str]) -> Drawing:
        """Write the DXF (reproducibly: fixed dates and GUIDs) and return the document."""
        with style.reproducible():
            style.fix_classes_order(self.doc)
            self.doc.saveas(os.fspath(path))
        return self.doc

    # -- frame and title block ----------------------------------------------------------------
    def _line(self, p: tuple[float, float], q: tuple[float, float], thick: bool) -> None:
        self.msp.add_line(p, q, dxfattribs={"layer": "contour" if thick else "thin"})

    def _cell_text(self, text: str, x: float, y: float, w: float, h: float, *,
                   max_height: float, align: str = "center", max_lines: int = 1,
                   rotation: float = 0.0) -> None:
        if not text:
            return
        pad = 1.0
        lines, th, wf = fit_text(text, w - 2 * pad, h - 2 * 0.8, max_height=max_height,
                                 max_lines=max_lines)
        pitch = th * 1.6
        total = th + pitch * (len(lines) - 1)
        for i, s in enumerate(lines):
            cy = y + h / 2 + total / 2 - th / 2 - i * pitch
            if align == "left":
                pos, al = (x + pad, cy), "middle-left"
            else:
                pos, al = (x + w / 2, cy), "center"
            if rotation:
                # rotate about the cell centre
                cx0, cy0 = x + w / 2, y + h / 2
                pos = (2 * cx0 - pos[0], 2 * cy0 - pos[1])
                al = {"middle-left": "middle-right"}.get(al, al)
            ent = self.msp.add_text(style.dxf_literal(s), height=th, rotation=rotation, dxfattribs={
                "layer": "text", "style": style.TEXT_STYLE, "width": wf,
                "lineweight": style.text_lineweight(th)})
            ent.set_placement(pos, align=_ALIGN[_ALIGN_NAMES[al]])

    def _draw_format(self) -> None:
        f, fr = self.format, self.frame
        # the sheet edge (trim line) thin, the frame thick
        self.msp.add_lwpolyline([(0, 0), (f.width, 0), (f.width, f.height), (0, f.height)],
                                close=True, dxfattribs={"layer": "thin"})
        self.msp.add_lwpolyline([(fr.x0, fr.y0), (fr.x1, fr.y0), (fr.x1, fr.y1), (fr.x0, fr.y1)],
                                close=True, dxfattribs={"layer": "contour"})
        tx, ty = self.title_rect.x0, self.title_rect.y0
        self._line((tx, ty), (tx, ty + TITLE_H), True)
        self._line((tx, ty + TITLE_H), (tx + TITLE_W, ty + TITLE_H), True)
        for x0, y0, x1, y1, thick in TITLE_LINES:
            self._line((tx + x0, ty + y0), (tx + x1, ty + y1), thick)
        for key, x, y, w, h in TITLE_CAPTIONS:
            self._cell_text(tr(f"sheets.{key}"), tx + x, ty + y, w, h, max_height=CAPTION_HEIGHT,
                            align="left" if x == 0 and y < 30 else "center")
        fl = self.fields
        self._cell_text(tr("sheets.blk17"), tx + 135, ty + 15, 10, 5, max_height=CAPTION_HEIGHT, align="left")
        self._cell_text(str(fl.number), tx + 145, ty + 15, 10, 5, max_height=3.5)
        self._cell_text(tr("sheets.blk18"), tx + 155, ty + 15, 15, 5, max_height=CAPTION_HEIGHT, align="left")
        self._cell_text(str(fl.count), tx + 170, ty + 15, 15, 5, max_height=3.5)
        self._cell_text(fl.author, tx + 17, ty + 25, 23, 5, max_height=CAPTION_HEIGHT, align="left")
        self._cell_text(fl.supervisor, tx + 17, ty + 20, 23, 5, max_height=CAPTION_HEIGHT,
                        align="left")
        self._cell_text(fl.code, tx + 65, ty + 40, 120, 15, max_height=7.0)
        self._cell_text(fl.title, tx + 65, ty + 15, 70, 25, max_height=5.0, max_lines=3)
        self._cell_text(fl.letter or tr("sheets.blk01"), tx + 135, ty + 20, 5, 15, max_height=3.5)
        self._cell_text(fl.mass, tx + 150, ty + 20, 17, 15, max_height=3.5)
        self._cell_text(fl.scale, tx + 167, ty + 20, 18, 15, max_height=3.5)
        org = "\n".join(s for s in (fl.organization, tr("sheets.blk19", v1=fl.group) if fl.group else "") if s)
        self._cell_text(org, tx + 135, ty, 50, 15, max_height=3.5, max_lines=3)
        # graph 26: the designation turned by 180° in the upper-left corner
        er = self.extra_rect
        self._line((er.x0, er.y0), (er.x1, er.y0), True)
        self._line((er.x1, er.y0), (er.x1, er.y1), True)
        self._cell_text(fl.code, er.x0, er.y0, er.width, er.height, max_height=5.0, rotation=180.0)

    def title_block_texts(self) -> list[str]:
        """The strings written in the title block and graph 26 (for tests and reports)."""
        region = self.title_rect.expanded(0.01).polygon().union(self.extra_rect.expanded(0.01).polygon())
        out = []
        for e in self.msp.query("TEXT"):
            p = e.dxf.align_point if e.dxf.halign or e.dxf.valign else e.dxf.insert
            if region.contains(box(p[0], p[1], p[0], p[1]).centroid):
                out.append(e.dxf.text)
        return out


__all__ = ["A1", "A2", "A3", "Sheet", "SheetFormat", "TitleBlock", "View", "fit_text",
           "TITLE_LINES", "TITLE_CAPTIONS", "TITLE_W", "TITLE_H", "EXTRA_W", "EXTRA_H"]
