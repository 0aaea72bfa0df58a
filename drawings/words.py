"""The words of the sheets in the task's language: the same catalogue as the note
(``latex_templates/strings/<lang>/sheets.toml``), read as plain text.

``with language("uk"):`` around drawing a sheet (the build command does it); :func:`tr` gives a
sheet sentence with its ``\\VAR{name}`` placeholders filled (values are printed as given),
:func:`symbol` a solver's load name in the language's notation (``Fур`` → ``Fb`` in English),
:func:`decimal_mark` the mark of numbers (``,`` for ru/uk, ``.`` for en).
"""
from __future__ import annotations

from contextlib import contextmanager
from typing import Any, Callable, Iterator

from reportgen.errors import InternalError

_STACK: list = []
#: The catalogue loader (``latex_templates.render.Strings``: one loader for the note and the sheets),
#: given by the command layer with :func:`use_catalogue` — the sheets never import the note.
_CATALOGUE: list[Callable[[str], Any]] = []


def use_catalogue(factory: Callable[[str], Any]) -> None:
    """Read the sheets' words with ``factory(language)`` (the command layer passes the note's
    catalogue loader, so that both speak from the same ``latex_templates/strings``)."""
    _CATALOGUE[:] = [factory]


def _new(code: str) -> Any:
    if not _CATALOGUE:
        raise InternalError("drawings.words", "no catalogue: the command layer calls use_catalogue() first")
    return _CATALOGUE[0](code)


def _strings():
    return _STACK[-1] if _STACK else _new("ru")


@contextmanager
def language(code: str | None) -> Iterator[None]:
    """Draw the sheets inside this block in ``code`` (default Russian)."""
    _STACK.append(_new(code or "ru"))
    try:
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


def tr_list(key: str) -> list[str]:
    """A list of the catalogue (a table's header row, ``crane.sheet.drive.head``) as plain text."""
    value = _strings().raw(key)
    if not isinstance(value, list):
        raise InternalError("drawings.words", f"{key!r} is not a list in the catalogue")
    return [str(x) for x in value]


def symbol(name: str) -> str:
    """A load or label name with Russian subscript words (``Fур``, ``Mпр``, ``Адв``) in this language."""
    return _strings().symbol(name)


def unit(text: str) -> str:
    """A unit (``(м/с)/мм``) in this language."""
    return _strings().math_word(text)


def decimal_mark() -> str:
    return _strings().decimal_mark()


def designation(document, number: int) -> str:
    """The designation of sheet ``number`` (title block graph 2 and 26) from ``[document] code``,
    e.g. ``<code>.002`` (the default code in the language's letters: ``TMM.CP.00.00.002`` in English)."""
    return _strings().designation(document, number)
