"""DXF → PNG / SVG previews with ezdxf's drawing add-on (white paper, true lineweights).

The PNG is rendered by matplotlib (Agg) at the paper size read from ``$PLIMMAX``, so a 0.7 mm line
is 0.7 mm on the paper at any ``dpi``; the SVG by ezdxf's own SVG backend on a page of the same
size. Both are deterministic for the same DXF.
"""
from __future__ import annotations

import contextlib
import os
from pathlib import Path
from typing import Iterator

import ezdxf
from ezdxf.document import Drawing

MM_PER_INCH = 25.4


def _load(source: str | os.PathLike[str] | Drawing) -> Drawing:
    if isinstance(source, Drawing):
        return source
    return ezdxf.readfile(os.fspath(source))


@contextlib.contextmanager
def _preview_lettering(doc: Drawing) -> Iterator[None]:
    """Text styles that name osifont name its completed copy while the preview is drawn
    (:mod:`drawings.sheet_font`: osifont draws «ё», «Э» as a box); the document is restored after."""
    from .sheet_font import preview_font
    from .style import TEXT_STYLE_FONT, ensure_sheet_font
    ensure_sheet_font()
    font = preview_font()
    changed = [st for st in doc.styles if st.dxf.get("font", "") == TEXT_STYLE_FONT]
    for st in changed:
        st.dxf.font = font
    try:
        yield
    finally:
        for st in changed:
            st.dxf.font = TEXT_STYLE_FONT


def paper_size(doc: Drawing) -> tuple[float, float]:
    """The paper (mm) from ``$PLIMMAX`` − ``$PLIMMIN``; the modelspace extents if unset."""
    lo = doc.header.get("$PLIMMIN", (0.0, 0.0))
    hi = doc.header.get("$PLIMMAX", (0.0, 0.0))
    w, h = float(hi[0]) - float(lo[0]), float(hi[1]) - float(lo[1])
    if w > 1.0 and h > 1.0:
        return w, h
    from ezdxf import bbox
    ext = bbox.extents(doc.modelspace())
    return float(ext.size.x), float(ext.size.y)


def _fixed_limits(ax) -> None:
    """Skip the data-limit bookkeeping of every added artist: the view is set to the paper below
    (autoscaling off), so the limits are never read, and updating them took half the preview's time
    (the Bézier extremes of every glyph outline of the text)."""
    ax._update_patch_limits = _ignore
    ax._update_line_limits = _ignore
    ax.update_datalim = _ignore


def _ignore(*_args: object, **_kwargs: object) -> None:
    return None


def render_png(source: str | os.PathLike[str] | Drawing, png_path: str | os.PathLike[str],
               *, dpi: int = 100) -> Path:
    """Render the modelspace of a DXF (path or document) to a PNG on white paper.

    The sheets' entities are drawn straight with Pillow (:mod:`drawings.raster`, several times
    faster); a document with anything that module does not draw goes through ezdxf's drawing
    add-on and matplotlib (:func:`render_png_ezdxf`)."""
    from . import raster
    from .sheet_font import completed_font, preview_font
    from .style import ensure_sheet_font

    doc = _load(source)
    ensure_sheet_font()
    font = completed_font()
    if raster.unsupported(doc, os.fspath(font) if font is not None else None) is None:
        assert font is not None
        return raster.render_png(doc, png_path, dpi=dpi, font_path=os.fspath(font), font_name=preview_font())
    return render_png_ezdxf(doc, png_path, dpi=dpi)


def render_png_ezdxf(source: str | os.PathLike[str] | Drawing, png_path: str | os.PathLike[str],
                     *, dpi: int = 100) -> Path:
    """Render the modelspace with ezdxf's drawing add-on (matplotlib, Agg): every entity ezdxf
    knows, the letters as outline paths."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from ezdxf.addons.drawing import Frontend, RenderContext
    from ezdxf.addons.drawing.config import Configuration
    from ezdxf.addons.drawing.matplotlib import MatplotlibBackend
    from ezdxf.addons.drawing.properties import LayoutProperties

    doc = _load(source)
    w, h = paper_size(doc)
    fig = plt.figure(figsize=(w / MM_PER_INCH, h / MM_PER_INCH), dpi=dpi)
    try:
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_axis_off()
        _fixed_limits(ax)
        msp = doc.modelspace()
        with _preview_lettering(doc):
            ctx = RenderContext(doc)
            props = LayoutProperties.from_layout(msp)
            props.set_colors("#FFFFFF")
            Frontend(ctx, MatplotlibBackend(ax, adjust_figure=False),
                     config=Configuration(lineweight_scaling=72.0 / MM_PER_INCH,
                                           min_lineweight=0.5)).draw_layout(
                msp, finalize=True, layout_properties=props)
        lo = doc.header.get("$PLIMMIN", (0.0, 0.0))
        ax.set_xlim(float(lo[0]), float(lo[0]) + w)
        ax.set_ylim(float(lo[1]), float(lo[1]) + h)
        ax.set_aspect("equal")
        fig.savefig(os.fspath(png_path), dpi=dpi, facecolor="#FFFFFF", metadata={"Software": None})
    finally:
        plt.close(fig)
    return Path(png_path)


def render_svg(source: str | os.PathLike[str] | Drawing, svg_path: str | os.PathLike[str]) -> Path:
    """Render the modelspace to an SVG page of the paper size (ezdxf's SVG backend)."""
    from ezdxf.addons.drawing import Frontend, RenderContext, layout, svg
    from ezdxf.addons.drawing.properties import LayoutProperties

    doc = _load(source)
    w, h = paper_size(doc)
    msp = doc.modelspace()
    backend = svg.SVGBackend()
    props = LayoutProperties.from_layout(msp)
    props.set_colors("#FFFFFF")
    with _preview_lettering(doc):
        Frontend(RenderContext(doc), backend).draw_layout(msp, layout_properties=props)
    page = layout.Page(w, h, layout.Units.mm, margins=layout.Margins.all(0))
    text = backend.get_string(page, settings=layout.Settings(fit_page=True))
    Path(svg_path).write_text(text, encoding="utf-8")
    return Path(svg_path)


def ink_fraction(png_path: str | os.PathLike[str], threshold: float = 0.5) -> float:
    """Share of pixels darker than ``threshold`` (0 = white … 1) in a PNG: 0.0 for a blank page."""
    import numpy as np
    from matplotlib import image

    img = image.imread(os.fspath(png_path))
    if img.dtype.kind in "ui":
        img = img / float(np.iinfo(img.dtype).max)
    rgb = img[..., :3] if img.ndim == 3 else img[..., None]
    lum = rgb.mean(axis=-1)
    if img.ndim == 3 and img.shape[-1] == 4:  # transparent pixels count as paper
        lum = np.where(img[..., 3] < 0.5, 1.0, lum)
    return float((lum < threshold).mean())
