"""ESKD drawing sheets as DXF (ezdxf): sheet framework, primitives, layout, previews.

Scene modules (one per sheet of the course project) build a :class:`Sheet`, ask it for views and
draw on them; see ``docs/drawings.md``.
"""
from .layout import Overlap, Rect, find_overlaps, pack
from .primitives import Canvas, Transform, format_number, format_significant
from .sheet import A1, A2, A3, Sheet, SheetFormat, TitleBlock, View

__all__ = ["A1", "A2", "A3", "Canvas", "Overlap", "Rect", "Sheet", "SheetFormat", "TitleBlock",
           "Transform", "View", "find_overlaps", "format_number", "format_significant", "pack"]
