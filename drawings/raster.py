"""A sheet's PNG preview drawn straight with Pillow: the DXF entities the sheets are made of.

ezdxf's drawing add-on turns every letter into an outline path and hands each entity to matplotlib
as an artist; on the press that was 0.3–0.6 s of CPU per sheet, most of it spent on the text. The
sheets use a handful of entity types (LINE, LWPOLYLINE without bulges or widths, CIRCLE, ARC,
SOLID, TEXT, and DIMENSION blocks of LINE, MTEXT and the filled arrow INSERT), so this module draws
those directly, resolved by ezdxf's own rules:

- colour, lineweight and line type BYLAYER / BYBLOCK, layer «0» in a block as the block's layer,
  ACI 7 black on the white paper; line widths as the matplotlib preview drew them (the lineweight
  in mm on the paper, at least 0.5 pt);
- line-type patterns cut by ezdxf's ``LineTypeRenderer`` with the ``$LTSCALE`` and entity scales;
- text laid out by ezdxf's ``simplified_text_chunks`` (alignment, width factor, rotation, cap
  height = the text height) and lettered by FreeType from the same font file (the previews' font,
  :func:`drawings.sheet_font.preview_font`).

The page is drawn at :data:`SUPERSAMPLE` × the resolution without anti-aliasing and reduced by a
box filter, which anti-aliases lines and letters much as Agg did. A document with anything else in
it (another entity type, a bulge, a true colour, a font other than the sheets') gets ``None`` from
:func:`unsupported`'s caller and is drawn by ezdxf's add-on as before.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterator

from ezdxf.document import Drawing

from reportgen.tolerances import ABS_ROUNDOFF, MM_EPS, RTOL_EQUAL

MM_PER_INCH = 25.4
#: The page is drawn at this multiple of the preview's resolution and reduced (anti-aliasing).
SUPERSAMPLE = 5
#: The thinnest line, as the matplotlib preview's ``min_lineweight`` (points).
MIN_LINEWEIGHT_PT = 0.5
#: DXF's "default" lineweight (1/100 mm) where an entity or layer says DEFAULT.
DEFAULT_LINEWEIGHT = 25
#: What an arc or a circle cut by a line type is flattened to: the largest distance (px of the
#: supersampled page) between the curve and its chords.
FLATTEN_PX = 0.25

#: Pillow (a dependency of matplotlib) lays out text at a fractional size from 10.1 on.
MIN_PILLOW = (10, 1)

_DRAWN = frozenset({"LINE", "LWPOLYLINE", "CIRCLE", "ARC", "SOLID", "TEXT", "MTEXT", "DIMENSION", "INSERT"})
_SKIPPED = frozenset({"POINT"})   # the dimensions' definition points (layer Defpoints): never drawn


@dataclass(frozen=True)
class _Context:
    """What an entity inside a block reference inherits (BYBLOCK, layer «0»), and where it goes."""
    layer: str | None = None           # the reference's layer (for entities on layer «0»)
    color: int = 7
    lineweight: int = DEFAULT_LINEWEIGHT
    linetype: str = "Continuous"
    matrix: tuple[float, float, float, float, float, float] | None = None   # block → WCS (a, b, c, d, e, f)


def _walk(doc: Drawing, entities: Any, ctx: _Context) -> Iterator[tuple[Any, _Context]]:
    """Every drawable entity with the context it is drawn in (block references opened)."""
    for e in entities:
        kind = e.dxftype()
        if kind == "DIMENSION":
            block = e.get_geometry_block()
            if block is None:
                yield e, ctx          # reported as unsupported
                continue
            yield from _walk(doc, block, _inherit(doc, e, ctx, ctx.matrix))
        elif kind == "INSERT":
            yield e, ctx              # checked by unsupported(); opened here
            yield from _walk(doc, doc.blocks.get(e.dxf.name), _inherit(doc, e, ctx, _insert_matrix(e, ctx)))
        else:
            yield e, ctx


def _inherit(doc: Drawing, e: Any, ctx: _Context, matrix: Any) -> _Context:
    return _Context(layer=_layer_name(e, ctx), color=_color(doc, e, ctx), lineweight=_lineweight(doc, e, ctx),
                    linetype=_linetype(doc, e, ctx), matrix=matrix)


def _insert_matrix(e: Any, ctx: _Context) -> tuple[float, float, float, float, float, float]:
    sx, sy = float(e.dxf.get("xscale", 1.0)), float(e.dxf.get("yscale", 1.0))
    a = math.radians(float(e.dxf.get("rotation", 0.0)))
    ca, sa = math.cos(a), math.sin(a)
    ix, iy = float(e.dxf.insert.x), float(e.dxf.insert.y)
    m = (ca * sx, -sa * sy, sa * sx, ca * sy, ix, iy)
    if ctx.matrix is not None:
        m = _compose(ctx.matrix, m)
    return m


def _compose(p: tuple[float, ...], q: tuple[float, ...]) -> tuple[float, float, float, float, float, float]:
    """p ∘ q for affine maps (a, b, c, d, e, f): x' = a x + b y + e, y' = c x + d y + f."""
    a, b, c, d, e, f = p
    qa, qb, qc, qd, qe, qf = q
    return (a * qa + b * qc, a * qb + b * qd, c * qa + d * qc, c * qb + d * qd,
            a * qe + b * qf + e, c * qe + d * qf + f)


def _layer_name(e: Any, ctx: _Context) -> str:
    name = e.dxf.get("layer", "0")
    return ctx.layer if name == "0" and ctx.layer is not None else name


def _color(doc: Drawing, e: Any, ctx: _Context) -> int:
    c = int(e.dxf.get("color", 256))
    if c == 0:
        return ctx.color
    if c == 256:
        layer = doc.layers.get(_layer_name(e, ctx))
        return abs(int(layer.dxf.get("color", 7))) if layer is not None else 7
    return c


def _lineweight(doc: Drawing, e: Any, ctx: _Context) -> int:
    lw = int(e.dxf.get("lineweight", -1))
    if lw == -2:
        return ctx.lineweight
    if lw == -1:
        layer = doc.layers.get(_layer_name(e, ctx))
        lw = int(layer.dxf.get("lineweight", -3)) if layer is not None else -3
    return DEFAULT_LINEWEIGHT if lw < 0 else lw


def _linetype(doc: Drawing, e: Any, ctx: _Context) -> str:
    lt = e.dxf.get("linetype", "BYLAYER")
    if lt.upper() == "BYBLOCK":
        return ctx.linetype
    if lt.upper() == "BYLAYER":
        layer = doc.layers.get(_layer_name(e, ctx))
        return layer.dxf.get("linetype", "Continuous") if layer is not None else "Continuous"
    return lt


def _lw_points(e: Any) -> Any:
    """An LWPOLYLINE's vertices as an (n, 5) array: x, y, start width, end width, bulge (read
    without ezdxf's per-point formatting, which took most of a gear sheet's preview)."""
    import numpy as np
    return np.asarray(e.lwpoints.values, dtype=float).reshape(-1, 5)


def _gray(aci: int) -> int | None:
    """The ACI colour as a grey level on white paper (7 is black there); None for a colour."""
    if aci == 7:
        return 0
    from ezdxf.colors import aci2rgb
    r, g, b = aci2rgb(aci)
    return r if r == g == b else None


def unsupported(doc: Drawing, font: str | None) -> str | None:
    """Why this module cannot draw ``doc`` (the first thing it cannot draw), or None if it can.

    ``font``: the previews' font file (None when it is not installed)."""
    from .style import TEXT_STYLE_FONT

    if font is None:
        return "no preview font"
    if _pillow_version() < MIN_PILLOW:
        return "Pillow older than 10.1 (no fractional font sizes)"
    for e, ctx in _walk(doc, doc.modelspace(), _Context()):
        kind = e.dxftype()
        if kind in _SKIPPED:
            continue
        if kind not in _DRAWN:
            return kind
        if e.dxf.hasattr("true_color") or e.dxf.get("invisible", 0):
            return f"{kind}: true colour or invisible"
        layer = doc.layers.get(_layer_name(e, ctx))
        if layer is not None and (layer.is_off() or layer.is_frozen()):
            return f"{kind} on a layer that is off or frozen"
        if _gray(_color(doc, e, ctx)) is None:
            return f"{kind}: a colour other than black or grey"
        if kind == "DIMENSION":
            return "DIMENSION without a block"
        if kind == "INSERT":
            if doc.blocks.get(e.dxf.name) is None or e.dxf.get("column_count", 1) != 1 \
                    or e.dxf.get("row_count", 1) != 1 or len(e.attribs) or \
                    abs(float(e.dxf.get("xscale", 1.0)) - float(e.dxf.get("yscale", 1.0))) > 0.0 \
                    or any(b.dxftype() not in ("SOLID", "LINE", "LWPOLYLINE") for b in doc.blocks.get(e.dxf.name)):
                return "INSERT of something other than a uniform block of lines and solids"
            continue
        if kind == "LWPOLYLINE":
            if e.dxf.get("const_width", 0.0) or _lw_points(e)[:, 2:].any():
                return "LWPOLYLINE with bulges or widths"
        if kind in ("TEXT", "MTEXT"):
            if ctx.matrix is not None:
                return f"{kind} in a block reference"
            style = doc.styles.get(e.dxf.get("style", "Standard"))
            if style is None or style.dxf.get("font", "") != TEXT_STYLE_FONT:
                return f"{kind} in a style other than the sheets'"
            ext = e.dxf.get("extrusion", (0.0, 0.0, 1.0))
            if tuple(ext) != (0.0, 0.0, 1.0):
                return f"{kind} with an extrusion"
            if kind == "TEXT" and (e.dxf.get("text_generation_flag", 0) or e.dxf.get("oblique", 0.0)
                                   or e.dxf.get("halign", 0) in (3, 5)):
                return "TEXT mirrored, oblique, aligned or fitted"
            if kind == "MTEXT":
                from ezdxf.addons.drawing.frontend import is_complex_mtext
                if is_complex_mtext(e) or "\n" in e.plain_text() or e.dxf.get("width", 0.0):
                    return "MTEXT with formatting, several lines or a box width"
        if kind in ("CIRCLE", "ARC") and ctx.matrix is not None:
            return f"{kind} in a block reference"
        ext = e.dxf.get("extrusion", (0.0, 0.0, 1.0)) if kind in ("CIRCLE", "ARC", "LWPOLYLINE", "SOLID") else None
        if ext is not None and tuple(ext) != (0.0, 0.0, 1.0):
            return f"{kind} with an extrusion"
    return None


def _pillow_version() -> tuple[int, ...]:
    import PIL
    return tuple(int(p) for p in PIL.__version__.split(".")[:2] if p.isdigit())


@dataclass(frozen=True)
class _FontMetrics:
    """The preview font in its own units: em, and ezdxf's cap height and baseline (from «A», «x»)."""
    units_per_em: float
    cap_height: float
    baseline: float


@lru_cache(maxsize=4)
def _font_metrics(path: str) -> _FontMetrics:
    from ezdxf.fonts.ttfonts import TTFontRenderer
    from fontTools.ttLib import TTFont

    font = TTFont(path, lazy=True)
    m = TTFontRenderer(font).font_measurements
    return _FontMetrics(float(font["head"].unitsPerEm), float(m.cap_height), float(m.baseline))


class _Page:
    """The supersampled page: mm on the paper → pixels, and the drawing of each kind of entity."""

    def __init__(self, doc: Drawing, dpi: int, font_path: str, font_name: str) -> None:
        from ezdxf.addons.drawing.unified_text_renderer import UnifiedTextRenderer
        from ezdxf.fonts import fonts
        from PIL import Image, ImageDraw

        from .preview import paper_size

        self.doc = doc
        w, h = paper_size(doc)
        lo = doc.header.get("$PLIMMIN", (0.0, 0.0))
        self.x0, self.y1 = float(lo[0]), float(lo[1]) + h
        self.k = dpi / MM_PER_INCH * SUPERSAMPLE                 # px per mm
        self.size = (int(w / MM_PER_INCH * dpi), int(h / MM_PER_INCH * dpi))
        self.image = Image.new("L", (self.size[0] * SUPERSAMPLE, self.size[1] * SUPERSAMPLE), 255)
        self.draw = ImageDraw.Draw(self.image)
        self.min_width = MIN_LINEWEIGHT_PT / 72.0 * dpi * SUPERSAMPLE
        self.ltscale = float(doc.header.get("$LTSCALE", 1.0))
        self.patterns: dict[tuple[str, float], list[float]] = {}
        self.font_path = font_path
        self.metrics = _font_metrics(font_path)
        self.text_engine = UnifiedTextRenderer()
        self.face = fonts.FontFace(filename=font_name)
        self.fonts: dict[float, Any] = {}

    # -- geometry ---------------------------------------------------------------------------------
    def px(self, x: float, y: float, m: Any = None) -> tuple[float, float]:
        if m is not None:
            x, y = m[0] * x + m[1] * y + m[4], m[2] * x + m[3] * y + m[5]
        return (x - self.x0) * self.k, (self.y1 - y) * self.k

    def width(self, lineweight: int) -> int:
        return max(1, round(max(lineweight / 100.0 * self.k, self.min_width)))

    def pattern(self, name: str, scale: float) -> list[float]:
        """ezdxf's on-off sequence of the line type (mm), [] for a continuous line."""
        key = (name, scale)
        if key not in self.patterns:
            lt = self.doc.linetypes.get(name)
            raw = list(lt.simplified_line_pattern()) if lt is not None else []
            pat = [max(v * scale, 0.1 * self.ltscale) for v in raw] if len(raw) >= 2 else []
            if len(pat) % 2:
                pat.pop()
            self.patterns[key] = pat
        return self.patterns[key]

    # -- entities ---------------------------------------------------------------------------------
    def entity(self, e: Any, ctx: _Context) -> None:
        kind = e.dxftype()
        if kind in _SKIPPED or kind in ("INSERT", "DIMENSION"):
            return
        fill = _gray(_color(self.doc, e, ctx)) or 0
        if kind == "TEXT" or kind == "MTEXT":
            self.text(e, fill)
            return
        if kind == "SOLID":
            v = [e.dxf.vtx0, e.dxf.vtx1, e.dxf.get("vtx3", e.dxf.vtx2), e.dxf.vtx2]
            pts = [self.px(p.x, p.y, ctx.matrix) for p in v]
            self.draw.polygon(pts, fill=fill)
            return
        w = self.width(_lineweight(self.doc, e, ctx))
        pat = self.pattern(_linetype(self.doc, e, ctx), float(e.dxf.get("ltscale", 1.0)) * self.ltscale)
        if kind == "LINE":
            s, t = e.dxf.start, e.dxf.end
            self.path([(s.x, s.y), (t.x, t.y)], ctx.matrix, fill, w, pat)
        elif kind == "LWPOLYLINE":
            pts = [(float(x), float(y)) for x, y in _lw_points(e)[:, :2].tolist()]
            if e.closed and len(pts) > 2:
                pts.append(pts[0])
            self.path(pts, ctx.matrix, fill, w, pat)
        elif kind == "CIRCLE":
            c, r = e.dxf.center, float(e.dxf.radius)
            if not pat:
                cx, cy = self.px(c.x, c.y)
                rr = r * self.k
                self.draw.ellipse((cx - rr - w / 2, cy - rr - w / 2, cx + rr + w / 2, cy + rr + w / 2),
                                  outline=fill, width=w)
            else:
                self.path(self.arc_points(c.x, c.y, r, 0.0, 360.0), None, fill, w, pat)
        elif kind == "ARC":
            c, r = e.dxf.center, float(e.dxf.radius)
            a0, a1 = float(e.dxf.start_angle) % 360.0, float(e.dxf.end_angle) % 360.0
            if a1 <= a0:
                a1 += 360.0
            self.path(self.arc_points(c.x, c.y, r, a0, a1), None, fill, w, pat)

    def arc_points(self, cx: float, cy: float, r: float, a0: float, a1: float) -> list[tuple[float, float]]:
        rr = r * self.k
        step = 2.0 * math.acos(max(-1.0, 1.0 - FLATTEN_PX / rr)) if rr > FLATTEN_PX else math.pi / 2
        n = max(4, math.ceil(math.radians(a1 - a0) / step))
        return [(cx + r * math.cos(math.radians(a0 + (a1 - a0) * i / n)),
                 cy + r * math.sin(math.radians(a0 + (a1 - a0) * i / n))) for i in range(n + 1)]

    def path(self, pts: list[tuple[float, float]], m: Any, fill: int, w: int, pat: list[float]) -> None:
        """A polyline in mm (through ``m``), solid or cut into dashes by ezdxf's line-type renderer."""
        if m is not None:
            pts = [(m[0] * x + m[1] * y + m[4], m[2] * x + m[3] * y + m[5]) for x, y in pts]
        if not pat:
            self.draw.line(self.snapped([self.px(x, y) for x, y in pts], w), fill=fill, width=w,
                           joint="curve" if len(pts) > 2 else None)
            return
        from ezdxf.math import Vec2
        from ezdxf.render.linetypes import LineTypeRenderer

        renderer = LineTypeRenderer(pat)
        for s, t in renderer.line_segments([Vec2(p) for p in pts]):
            self.draw.line(self.snapped([self.px(s.x, s.y), self.px(t.x, t.y)], w), fill=fill, width=w)

    def snapped(self, pts: list[tuple[float, float]], w: int) -> list[tuple[float, float]]:
        """Matplotlib's snapping, which the ezdxf preview had: a path of only horizontal and vertical
        segments is moved to the preview's pixel grid — centres of pixels for a line about an odd
        number of pixels wide, their edges for an even one — so a thin frame or table line is one
        dark pixel wide rather than two grey ones."""
        eps = MM_EPS * self.k
        if any(abs(x0 - x1) > eps and abs(y0 - y1) > eps for (x0, y0), (x1, y1) in zip(pts, pts[1:])):
            return pts
        s = SUPERSAMPLE
        offset = 0.5 if round(w / s) % 2 else 0.0
        return [((math.floor(x / s + 0.5) + offset) * s, (math.floor(y / s + 0.5) + offset) * s) for x, y in pts]

    def font(self, cap_height_mm: float) -> Any:
        """The preview font at the em size that makes its cap height (ezdxf's: «A») the text height."""
        from PIL import ImageFont

        ppem = cap_height_mm * self.k * self.metrics.units_per_em / self.metrics.cap_height
        key = round(ppem, 6)
        if key not in self.fonts:
            self.fonts[key] = ImageFont.truetype(self.font_path, size=ppem, layout_engine=ImageFont.Layout.BASIC)
        return self.fonts[key]

    def text(self, e: Any, fill: int) -> None:
        """TEXT / MTEXT: ezdxf's layout (one transform per line: left end of the baseline at the
        origin, the cap height as the unit), lettered by FreeType."""
        from ezdxf.addons.drawing.frontend import MIN_CAP_HEIGHT
        from ezdxf.addons.drawing.pipeline import prepare_string_for_rendering
        from ezdxf.addons.drawing.text import simplified_text_chunks

        if e.dxftype() == "TEXT" and e.dxf.height < MIN_CAP_HEIGHT:
            return
        for line, transform, cap_height in simplified_text_chunks(e, self.text_engine, font_face=self.face):
            if not line.strip():
                continue
            line = prepare_string_for_rendering(line, e.dxftype())
            font = self.font(cap_height)
            # ezdxf draws the glyphs with the font's baseline («x») at y = 0 of the line's frame
            base_y = -self.metrics.baseline * cap_height / self.metrics.cap_height
            ox, oy = self._wcs(transform, 0.0, base_y)
            ux, uy = self._wcs(transform, 1.0, base_y)
            vx, vy = self._wcs(transform, 0.0, base_y + 1.0)
            # the line's frame on the page, per mm of the frame: u along the baseline, v up
            ax, ay = (ux - ox) * self.k, -(uy - oy) * self.k
            bx, by = (vx - ox) * self.k, -(vy - oy) * self.k
            px, py = self.px(ox, oy)
            eps = RTOL_EQUAL * self.k
            if abs(ax - self.k) < eps and abs(ay) < eps and abs(bx) < eps and abs(by + self.k) < eps:
                self.draw.text((px, py), line, font=font, fill=fill, anchor="ls")
            else:
                self._transformed_text(line, font, fill, px, py, (ax, ay, bx, by))

    @staticmethod
    def _wcs(transform: Any, x: float, y: float) -> tuple[float, float]:
        p = transform.transform((x, y, 0.0))
        return float(p.x), float(p.y)

    def _transformed_text(self, line: str, font: Any, fill: int, px: float, py: float,
                          frame: tuple[float, float, float, float]) -> None:
        """Letter a line in an upright image at the page's scale, then map it onto the page
        (width factor, rotation) with an affine transform."""
        from PIL import Image, ImageDraw

        left, top, right, bottom = font.getbbox(line, anchor="ls")
        left, top, right, bottom = left - 2, top - 2, right + 2, bottom + 2
        src = Image.new("L", (right - left, bottom - top), 0)
        ImageDraw.Draw(src).text((-left, -top), line, font=font, fill=255, anchor="ls")
        ax, ay, bx, by = frame
        # source pixel (i, j), anchor at (-left, -top): frame u = (i + left) / k mm, v = -(j + top) / k mm
        # page = (px, py) + u·(ax, ay) + v·(bx, by)
        k = self.k
        a11, a12, a21, a22 = ax / k, -bx / k, ay / k, -by / k      # d(page)/d(i, j)
        t1 = px + a11 * left + a12 * top
        t2 = py + a21 * left + a22 * top
        corners = [(a11 * i + a12 * j + t1, a21 * i + a22 * j + t2)
                   for i, j in ((0, 0), (src.width, 0), (0, src.height), (src.width, src.height))]
        x0 = math.floor(min(c[0] for c in corners))
        y0 = math.floor(min(c[1] for c in corners))
        x1 = math.ceil(max(c[0] for c in corners))
        y1 = math.ceil(max(c[1] for c in corners))
        det = a11 * a22 - a12 * a21
        if abs(det) < ABS_ROUNDOFF or x1 <= x0 or y1 <= y0:
            return
        # inverse: source = A⁻¹ (page − t), page = (x0 + x, y0 + y)
        i11, i12, i21, i22 = a22 / det, -a12 / det, -a21 / det, a11 / det
        cx, cy = x0 - t1, y0 - t2
        data = (i11, i12, i11 * cx + i12 * cy, i21, i22, i21 * cx + i22 * cy)
        patch = src.transform((x1 - x0, y1 - y0), Image.Transform.AFFINE, data, resample=Image.Resampling.BILINEAR)
        self.image.paste(fill, (x0, y0, x1, y1), patch)

    def save(self, png_path: str | os.PathLike[str]) -> Path:
        # one channel: the sheets are black and grey on white (:func:`unsupported` sends anything
        # in colour to ezdxf), and a grey PNG is half the bytes and a third of the encoding time
        self.image.reduce(SUPERSAMPLE).save(os.fspath(png_path), format="PNG")
        return Path(png_path)


def render_png(doc: Drawing, png_path: str | os.PathLike[str], *, dpi: int, font_path: str,
               font_name: str) -> Path:
    """Draw the modelspace of ``doc`` (which :func:`unsupported` accepted) into a PNG of the paper
    at ``dpi``, lettered with the font file ``font_path`` (``font_name`` as ezdxf knows it)."""
    page = _Page(doc, dpi, font_path, font_name)
    for e, ctx in _walk(doc, doc.modelspace(), _Context()):
        page.entity(e, ctx)
    return page.save(png_path)
