"""Parts of the note: each module here turns one stage of a ``Project`` into a subsection body.

A part module provides::

    NEEDS: tuple[str, ...]                 # the project stages it reads (enforced: compose passes
                                           # a reportgen.project.Needs view; another stage raises)
    def available(project) -> bool         # the task has what the part needs
    def content(project) -> PartContent    # template + context (+ figures, conclusions)

Its template (``templates/sections/<part>.tex.j2``) writes ``\\subsection{…}`` blocks only; it sees its
context as ``c`` plus the note's ``m`` (macros), ``s`` (strings), ``doc``, ``sym`` and ``figures``
(figure names must be unique across the note: prefix them with the part's name). The sections of the
note and the parts they are made of are listed in :mod:`latex_templates.compose`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping


@dataclass(frozen=True)
class PartContent:
    template: str
    context: Mapping[str, Any]
    figures: Mapping[str, Any] = field(default_factory=dict)
    conclusions: tuple[str, ...] = ()      # sentences (plain text, escaped) for the conclusions
