"""The explanatory note: Jinja2 LaTeX templates, number formatting and the LaTeX build.

Public API (see docs/note.md)::

    from latex_templates import NoteBuilder, Section
    note = NoteBuilder(document, language="ru")
    note.add_section(Section(key="kinematics", title="…", template="sections/kinematics.tex.j2",
                             context={...}, figures={"plan": matplotlib_figure}))
    note.render(out_dir)          # -> Path of report.tex
    note.build(out_dir)           # -> BuildReport (pdf, log, seconds, warnings)
"""
from __future__ import annotations

from .build import BuildReport, build_pdf
from .note import FigureRef, NoteBuilder, Section
from .render import Strings, SymbolTracker, Tex, escape_latex, make_environment, tex

__all__ = ["NoteBuilder", "Section", "FigureRef", "BuildReport", "build_pdf", "Strings",
           "SymbolTracker", "Tex", "tex", "escape_latex", "make_environment"]
