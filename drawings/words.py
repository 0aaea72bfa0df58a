"""The words of the sheets in the task's language: the same catalogue as the note
(``latex_templates/strings/<lang>/sheets.toml``), read as plain text.

``with language("uk"):`` around drawing a sheet (the build command does it); :func:`tr` gives a
sheet sentence with its ``\\VAR{name}`` placeholders filled (values are printed as given),
:func:`symbol` a solver's load name in the language's notation (``Fур`` → ``Fb`` in English),
:func:`decimal_mark` the mark of numbers (``,`` for ru/uk, ``.`` for en).
"""
from __future__ import annotations

from contextlib import contextmanager
from typing import Iterator

_STACK: list = []


def _strings():
    from latex_templates.render import Strings
    return _STACK[-1] if _STACK else Strings("ru")


@contextmanager
def language(code: str | None) -> Iterator[None]:
    """Draw the sheets inside this block in ``code`` (default Russian)."""
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings
    strings = Strings(code or "ru")
    _STACK.append(strings)
    try:
        with active_strings(strings):       # the note's helpers that sheets reuse speak it too
            yield
    finally:
        _STACK.pop()


def current() -> str:
    return _strings().language


def tr(key: str, **values) -> str:
    """The catalogue sentence ``key`` (``sheets.…``) as plain text, placeholders filled with ``values``."""
    from markupsafe import Markup
    values = {k: Markup(v) if isinstance(v, str) else v for k, v in values.items()}
    return str(_strings().text(key, **values))


def symbol(name: str) -> str:
    """A load or label name with Russian subscript words (``Fур``, ``Mпр``, ``Адв``) in this language."""
    return _strings().symbol(name)


def unit(text: str) -> str:
    """A unit (``(м/с)/мм``) in this language."""
    return _strings().math_word(text)


def decimal_mark() -> str:
    return "," if _strings().raw("format.decimal") == "{,}" else "."


def designation(document, number: int) -> str:
    """The designation of sheet ``number`` (title block graph 2 and 26) from ``[document] code``,
    e.g. ``<code>.002`` (the default code in the language's letters: ``TMM.CP.00.00.002`` in English)."""
    return _strings().designation(document, number)
