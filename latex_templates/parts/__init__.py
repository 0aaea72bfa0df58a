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


def strings_of(project):
    """The strings catalogue of the task's language (``[document] language``, default ru)."""
    from ..render import Strings
    return Strings(project.task.document.language or "ru")


_ACTIVE: list = []


class active_strings:
    """``with active_strings(strings):`` — the catalogue that :func:`tr` reads while the parts of
    a note are made (:func:`latex_templates.compose.compose` sets it)."""

    def __init__(self, strings) -> None:
        self.strings = strings

    def __enter__(self):
        _ACTIVE.append(self.strings)
        return self.strings

    def __exit__(self, *exc) -> None:
        _ACTIVE.pop()


def active():
    """The catalogue of the note being made (Russian outside :func:`compose`)."""
    from ..render import Strings
    return _ACTIVE[-1] if _ACTIVE else Strings("ru")


def decimal_mark() -> str:
    """The decimal mark of the active language for plain text (figures): ``,`` or ``.``."""
    return active().decimal_mark()


def unit(text: str) -> str:
    """A unit (or any text with units) in the active language: ``м/с`` → ``m/s``."""
    return active().math_word(text)


def tr(key: str, **values):
    """The catalogue sentence ``key`` of the active language with its ``\\VAR{name}`` filled: string
    values are the parts' own LaTeX (printed as is), numbers get the language's decimal mark (a part
    called outside :func:`compose` speaks Russian)."""
    from markupsafe import Markup
    # the parts' values are LaTeX they built (symbols, point names as the f-strings printed them)
    values = {k: Markup(v) if isinstance(v, str) else v for k, v in values.items()}
    return active().text(key, **values)
