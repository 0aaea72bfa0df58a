"""The Jinja2 environment for LaTeX: delimiters, escaping, filters, strings, formula helpers.

Delimiters (so that LaTeX braces stay LaTeX's)::

    \\VAR{expression}        output, LaTeX-escaped unless the value is trusted ``Tex``
    \\BLOCK{statement}       for/if/set/macro/import …
    \\#{comment}             template comment
    %# comment              line comment (removed)

Escaping: every value printed by ``\\VAR{}`` is escaped (``_ % & # $ { } ~ ^ \\``) unless it is
:class:`Tex` (``markupsafe.Markup``): macros, filters and catalogue strings return ``Tex``; a plain
``str`` from the caller (a title, a name) always prints literally. A float prints with a decimal
comma (the ``num`` filter). Mark your own LaTeX with the ``tex`` filter or :func:`tex`.
Avoid the ``~`` concatenation operator on user text inside ``\\VAR{}``: Jinja's autoescape joins
with HTML escaping there; print the pieces with separate ``\\VAR{}`` instead.
"""
from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

import jinja2
from markupsafe import Markup

from reportgen.balance import BalanceSolution
from reportgen.calc import CalcRecord, Var, unit_latex
from reportgen.errors import InternalError, OptionError

from . import numbers

LANGUAGES = {"ru": "russian", "uk": "ukrainian", "en": "english"}
FALLBACK_LANGUAGE = "ru"

_SPECIALS = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
    "%": r"\%", "_": r"\_", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}",
    '"': r"\textquotedbl{}",  # babel's Russian/Ukrainian make " a shorthand ("--- , "< …)
    "'": r"\textquotesingle{}", "`": r"\textasciigrave{}",  # else the font's mapping curls them
}
# TeX ligatures of the font mapping (-- --- `` '' ,, << >> !` ?`): broken with {} so text prints as typed
_LIGATURE_RE = re.compile(r"([-,<>!?])(?=[-,<>]|\\textasciigrave)")
_SPECIALS_RE = re.compile("|".join(re.escape(c) for c in _SPECIALS))


def _escape_text(text: str) -> str:
    out = _SPECIALS_RE.sub(lambda m: _SPECIALS[m.group(0)], text)
    return _LIGATURE_RE.sub(r"\1{}", out)


class Tex(Markup):
    """Trusted LaTeX source: printed as is by ``\\VAR{}``.

    The one escaping type of the note. Whatever is combined with a ``Tex`` — ``+``, ``%``,
    ``.format()``, ``.join()`` — is LaTeX-escaped unless it is already markup, so a fragment built in
    Python from user text (a title, a mechanism name) prints that text literally. (Plain
    ``markupsafe.Markup`` would escape for HTML: ``<`` → ``&lt;`` and ``%`` left as a TeX comment.)
    """

    __slots__ = ()

    @classmethod
    def escape(cls, s: Any) -> "Tex":
        return escape_latex(s)


def escape_latex(text: Any) -> Tex:
    """Text that prints literally in LaTeX (every special character escaped); markup passes."""
    if isinstance(text, Tex):
        return text
    if isinstance(text, Markup):
        return Tex(str(text))
    return Tex(_escape_text(str(text)))


def tex(source: Any) -> Tex:
    """Mark ``source`` as trusted LaTeX (printed without escaping)."""
    return Tex(str(source))


def _join(value: Iterable[Any], d: Any = "", attribute: Any = None) -> Tex:
    """The ``join`` filter: items and separator escaped as text unless markup."""
    items = [getattr(v, attribute) if attribute is not None else v for v in value]
    return escape_latex(d).join(escape_latex(v) for v in items)


def _replace(s: Any, old: str, new: str, count: int | None = None) -> Any:
    """The ``replace`` filter: markup stays markup, text stays text (escaped when printed)."""
    n = -1 if count is None else count
    if isinstance(s, Markup):
        return tex(str(s).replace(str(old), str(new), n))
    return str(s).replace(str(old), str(new), n)


def _finalize(value: Any) -> Any:
    """Applied to every ``\\VAR{}`` value before autoescape: escape text, format numbers."""
    if isinstance(value, Markup):
        return value if isinstance(value, Tex) else tex(value)
    if value is None:
        raise jinja2.UndefinedError("None printed into the note (give a value or test for it)")
    if isinstance(value, bool):
        return Tex(str(value))
    if isinstance(value, (int, float)):
        return Tex(numbers.num(value))
    return escape_latex(value)


# --------------------------------------------------------------------------- strings catalogue
class MissingString(InternalError, KeyError):
    """A key the strings catalogue of a language does not have (reportgen's own defect: every key
    exists in every language, tests/lang checks it): the build stops and names the key and the
    language; there is no fallback to another language."""

    def __init__(self, key: str, language: str) -> None:
        self.key = key
        self.language = language
        InternalError.__init__(self, "strings catalogue", f"no string {key!r} in the {language!r} catalogue "
                               f"(latex_templates/strings/{language}.toml or strings/{language}/*.toml)")

    def __str__(self) -> str:
        return RuntimeError.__str__(self)


_SNIPPET_MARKS = ("\\VAR{", "\\BLOCK{")
_CYRILLIC_RUN = re.compile(r"[А-Яа-яЁёІіЇїЄєҐґ]+")
_TEXT_IN_MATH = re.compile(r"(?P<pre>[_^]\{?)?\\text\{(?P<body>[^{}]*)\}")


def plural_index(language: str, n: float) -> int:
    """Which plural form a count takes: ru/uk 1 участок / 2 участка / 5 участков (0, 1, 2),
    a fraction takes the second form (2,5 участка); en 1 interval / 5 intervals (0, 1)."""
    if language == "en":
        return 0 if n == 1 else 1
    if float(n) != int(n):
        return 1
    k = abs(int(n))
    if k % 10 == 1 and k % 100 != 11:
        return 0
    if 2 <= k % 10 <= 4 and not 12 <= k % 100 <= 14:
        return 1
    return 2


class Strings:
    """The words of the note and the sheets in one language (``strings/<lang>.toml`` +
    ``strings/<lang>/*.toml``).

    In templates: ``\\VAR{s.headings.contents}`` or ``\\VAR{t("kinematics.plan_intro")}`` (a string
    holding ``\\VAR{}``/``\\BLOCK{}`` is a Jinja snippet rendered with the caller's context and the
    keyword arguments); a list stays a list (of ``Tex``). From Python: :meth:`text` renders a
    snippet with keyword arguments. A key missing in the language is a :class:`MissingString`
    naming the key and the language (no fallback to another language).
    """

    def __init__(self, language: str, overlay: str | None = None) -> None:
        """``overlay``: a table of the catalogue whose keys replace the same keys at the top level
        (``control.overrides``: the words of a control work where a course project has its own)."""
        if language not in LANGUAGES:
            raise OptionError("language", f"{language!r} has no strings catalogue", "one of " + ", ".join(LANGUAGES))
        self.language = language
        self._data = _load_strings(language)
        self.fallbacks: set[str] = set()     # always empty: kept for callers that report it
        self._overlay = overlay

    def _find(self, key: str) -> Any:
        found = _lookup(self._data, f"{self._overlay}.{key}") if self._overlay else None
        return found if found is not None else _lookup(self._data, key)

    def raw(self, key: str) -> Any:
        """The catalogue value at a dotted key (str, list or dict), unrendered; the overlay's
        value first where it has the key."""
        found = self._find(key)
        if found is None:
            raise MissingString(key, self.language)
        return found

    def has(self, key: str) -> bool:
        return self._find(key) is not None

    def decimal_mark(self) -> str:
        """The language's decimal mark in plain text (figures, sheets, the terminal): ``,`` or ``.``
        (the catalogue's ``format.decimal`` is its math-mode form, ``{,}`` or ``.``)."""
        return "," if self.raw("format.decimal") == "{,}" else "."

    def get(self, key: str) -> Any:
        """The string (or list, or table) at a dotted key, as ``Tex``."""
        return _as_tex(self.raw(key), key, self)

    def text(self, key: str, **values: Any) -> Tex:
        """The string at ``key`` with its ``\\VAR{name}`` placeholders filled from ``values``
        (numbers print with the language's decimal mark, plain strings escaped)."""
        value = self.raw(key)
        if not isinstance(value, str):
            raise InternalError("strings catalogue", f"{key!r} ({self.language}) is not a sentence")
        return render_snippet(self, key, value, values)

    def plural(self, n: float, key: str) -> Tex:
        """The form of the word at ``key`` (a list of forms) that agrees with the count ``n``."""
        forms = self.raw(key)
        if isinstance(forms, str):
            forms = [forms]
        i = plural_index(self.language, n)
        return Tex(forms[min(i, len(forms) - 1)])

    def count(self, n: float, key: str) -> Tex:
        """``n`` and the agreeing form of the word: «24~участка», «5~ділянок», «1~interval»."""
        from . import numbers as _numbers
        number = str(n) if isinstance(n, int) else _numbers.num(n)
        return Tex(number) + Tex("~") + self.plural(n, key)

    def math_word(self, word: str, table: str = "units") -> str:
        """A Russian word of a unit (table ``units``: ``м/с`` → ``m/s``) or of a symbol's subscript
        (table ``subscripts``: ``ур`` → ``b``) in this language; Russian keeps it. The whole word
        is looked up first, then each run of Cyrillic letters."""
        if self.language == FALLBACK_LANGUAGE or not _CYRILLIC_RUN.search(word):
            return word
        words = self.raw(table)
        if word in words:
            return words[word]
        out = []
        pos = 0
        for m in _CYRILLIC_RUN.finditer(word):
            out.append(word[pos:m.start()])
            if m.group(0) not in words:
                raise MissingString(f"{table}.{m.group(0)}", self.language)
            out.append(words[m.group(0)])
            pos = m.end()
        out.append(word[pos:])
        return "".join(out)

    def designation(self, document: Any, number: int | None = None) -> str:
        """The ЕСКД designation (ГОСТ 2.201) of the note (``number`` None) or of sheet ``number``:
        ``[document] code`` (its default, the catalogue's ``designation.default_code`` — a control
        work's ``document_defaults.control_code`` of table 0, variant 0 — is the language's, Latin
        letters in English) + the note's suffix (``.000 ПЗ``) or ``.<number:03d>``."""
        from dataclasses import replace

        from reportgen.task import Document
        if document is None:
            document = Document()
        if document.code == Document().code:          # not given: the language's default letters
            default = (str(self.raw("document_defaults.control_code")).format(table=0, variant=0)
                       if getattr(document, "kind", "") == "control-work"      # ТММ.КР.00.00 / TMM.CW.00.00
                       else str(self.get("designation.default_code")))
            document = replace(document, code=default)
        if number is None:
            return str(document.code) + str(self.get("designation.note_suffix"))
        return str(document.sheet_code(number))

    def titled(self, document: Any, key: str = "document_defaults.title") -> Any:
        """``document`` with the title the task left out (``[document] title`` at the core's default)
        in this language: the catalogue's ``key`` (a course project's ``document_defaults.title``,
        the crane's ``document_defaults.crane_title``, a control work's ``control.sheet.title``), so
        that an English note never prints the Russian default title (issue 12)."""
        from dataclasses import replace

        from reportgen.task import Document
        if document is None or getattr(document, "title", None) != Document().title:
            return document
        return replace(document, title=str(self.raw(key)))

    def symbol(self, name: str) -> str:
        """A solver's load name or a sheet label (``Fур``, ``Mи2``, ``Адв``) in this language:
        the Cyrillic runs through the ``subscripts`` table (``Fур`` → ``Fb``)."""
        return self.math_word(name, "subscripts")

    def localize_latex(self, source: str) -> str:
        """The rendered LaTeX in this language's conventions: ``\\text{}`` after ``_``/``^``
        through the ``subscripts`` table, other ``\\text{}`` (units) through ``units``; the decimal
        mark and the function names of the ``format`` table."""
        if self.language == FALLBACK_LANGUAGE:
            return source

        def repl(m: re.Match) -> str:
            pre, body = m.group("pre") or "", m.group("body")
            if pre:
                word = self.math_word(body, "subscripts")
            else:
                try:
                    word = self.math_word(body, "units")
                except MissingString:      # a subscript after other letters: F^{B}_{M\text{и}2}
                    word = self.math_word(body, "subscripts")
            return pre + "\\text{" + word + "}"

        source = _TEXT_IN_MATH.sub(repl, source)
        fmt = self.raw("format")
        if fmt.get("decimal", "{,}") != "{,}":
            source = source.replace("{,}", fmt["decimal"])
        for name, value in fmt.get("functions", {}).items():
            source = source.replace("\\operatorname{" + name + "}", value)
        return source

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        return self.get(name)


class _StringTable:
    """A table of the catalogue, read by attribute in templates."""

    def __init__(self, strings: Strings, prefix: str) -> None:
        self._strings = strings
        self._prefix = prefix

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        return self._strings.get(f"{self._prefix}.{name}")

    def __getitem__(self, name: str) -> Any:
        return self._strings.get(f"{self._prefix}.{name}")


def _as_tex(found: Any, key: str, strings: Strings) -> Any:
    if isinstance(found, dict):
        return _StringTable(strings, key)
    if isinstance(found, list):
        return [tex(x) for x in found]
    return tex(found)


def _lookup(data: Mapping[str, Any], key: str) -> Any:
    node: Any = data
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node


_SNIPPETS: dict[tuple[str, str], Any] = {}
_SNIPPET_ENV: list[Any] = []


def render_snippet(strings: Strings, key: str, value: str, context: Mapping[str, Any]) -> Tex:
    """Render a catalogue string: plain text as is, a Jinja snippet with ``context`` (+ ``s``)."""
    if not any(mark in value for mark in _SNIPPET_MARKS):
        return Tex(value)
    cache_key = (strings.language, key)
    if cache_key not in _SNIPPETS:
        if not _SNIPPET_ENV:
            _SNIPPET_ENV.append(make_environment())
        _SNIPPETS[cache_key] = _SNIPPET_ENV[0].from_string(value)
    ctx = {"s": strings, **context}
    return Tex(_SNIPPETS[cache_key].render(ctx).strip("\n"))


@jinja2.pass_context
def _t(ctx: Any, key: str, **values: Any) -> Tex:
    """Template global ``t("area.key", name=value)``: the catalogue string rendered with the
    template's context plus ``values``."""
    strings: Strings = ctx["s"]
    value = strings.raw(key)
    if not isinstance(value, str):
        raise InternalError("strings catalogue", f"{key!r} ({strings.language}) is not a sentence")
    return render_snippet(strings, key, value, {**ctx.get_all(), **values})


@jinja2.pass_context
def _plural(ctx: Any, n: float, key: str) -> Tex:
    return ctx["s"].plural(n, key)


@jinja2.pass_context
def _count(ctx: Any, n: float, key: str) -> Tex:
    return ctx["s"].count(n, key)


@jinja2.pass_context
def _ratio(ctx: Any, scale: Any) -> Tex:
    """A scale's ratio — a :class:`reportgen.gost_scales.Scale` (or an object with its ``text``,
    the meshing's DrawingScale) or its text as the core writes it («2,5:1», «1:2.5») — in the note's
    decimal mark: «2,5:1» in ru/uk, «2.5:1» in en (:meth:`reportgen.gost_scales.Scale.text`)."""
    from reportgen.gost_scales import Scale
    mark = ctx["s"].decimal_mark()
    return Tex(scale.text(mark) if hasattr(scale, "text") else Scale.parse(str(scale)).text(mark))


@jinja2.pass_context
def _unit_in_context(ctx: Any, unit: str) -> Tex:
    """A unit in running text, in the note's language (``м/с`` → ``m/s``)."""
    strings = ctx.get("s")
    return escape_latex(strings.math_word(str(unit)) if strings is not None else unit)


_STRING_CACHE: dict[str, dict[str, Any]] = {}


def _load_strings(language: str) -> dict[str, Any]:
    """The catalogue of a language: ``strings/<lang>.toml`` merged with every ``strings/<lang>/*.toml``.

    One file per area (``strings/ru/crane.toml``, ``strings/ru/control.toml`` …) keeps the catalogues
    of different documents apart; a key defined in two files is an error, never a silent override.
    """
    if language not in _STRING_CACHE:
        root = resources.files(__package__).joinpath("strings")
        files = [root.joinpath(f"{language}.toml")]
        area_dir = root.joinpath(language)
        if area_dir.is_dir():
            files += sorted((f for f in area_dir.iterdir() if f.name.endswith(".toml")),
                            key=lambda f: f.name)
        merged: dict[str, Any] = {}
        for path in files:
            if path.is_file():
                try:
                    data = tomllib.loads(path.read_text(encoding="utf-8"))
                except tomllib.TOMLDecodeError as exc:
                    raise InternalError("strings catalogue", f"{language}/{path.name}: {exc}") from None
                _merge_catalogue(merged, data, f"{language}/{path.name}", "")
        _STRING_CACHE[language] = merged
    return _STRING_CACHE[language]


def _merge_catalogue(into: dict[str, Any], data: Mapping[str, Any], source: str, prefix: str) -> None:
    for key, value in data.items():
        dotted = f"{prefix}{key}"
        if key in into:
            if isinstance(into[key], dict) and isinstance(value, dict):
                _merge_catalogue(into[key], value, source, dotted + ".")
                continue
            raise InternalError("strings catalogue", f"key {dotted!r} defined twice (again in {source})")
        into[key] = value


# --------------------------------------------------------------------------- symbols («где»)
@dataclass
class SymbolTracker:
    """Remembers which symbols the note has already explained in a «где» list.

    :meth:`first` returns the variables of a formula not explained before (in formula order, each
    symbol once) and marks them; variables with no ``meaning`` cannot be explained and are kept in
    :attr:`unexplained` so a section author can see them.
    """
    explained: set[str] = field(default_factory=set)
    unexplained: set[str] = field(default_factory=set)
    records: list[CalcRecord] = field(default_factory=list)
    balances: list[BalanceSolution] = field(default_factory=list)

    def shown(self, rec: CalcRecord) -> str:
        """Note that ``rec`` is printed (the ``calc`` macro calls this); returns ''."""
        self.records.append(rec)
        return ""

    def balanced(self, sol: BalanceSolution) -> str:
        """Note that a balance equation is printed (the ``balance`` macro calls this); returns ''."""
        self.balances.append(sol)
        return ""

    def first(self, variables: Iterable[Var]) -> list[Var]:
        out: list[Var] = []
        for v in variables:
            if v.latex in self.explained:
                continue
            if not v.meaning:
                self.unexplained.add(v.latex)
                continue
            self.explained.add(v.latex)
            self.unexplained.discard(v.latex)
            out.append(v)
        return out

    def define(self, latex: str) -> None:
        """Mark a symbol as explained in the running text."""
        self.explained.add(latex)
        self.unexplained.discard(latex)


# --------------------------------------------------------------------------- formula pieces
WIDE_FORMULA = 60   # visible characters above which a formula is split after the symbolic form


def visible_width(source: str) -> int:
    """A rough count of the characters a math formula shows (commands count one, braces none)."""
    text = re.sub(r"\\(left|right|text|operatorname|frac|sqrt)(?![A-Za-z])", "", source)
    text = re.sub(r"\\[A-Za-z]+|\\.", "x", text)
    text = re.sub(r"[{}^_ ]", "", text)
    return len(text)


@dataclass(frozen=True)
class CalcParts:
    """The LaTeX pieces of a record for the ``calc`` macro."""
    symbol: Tex
    symbolic: Tex | None      # None when it would repeat the substitution
    substituted: Tex | None   # None when it would repeat the result
    result: Tex
    wide: bool
    substituted_lines: tuple[Tex, ...] = ()   # the substitution broken at top-level + and −


#: A line of a split formula shows about this many characters (14 pt text on A4 with the frame).
LINE_WIDTH = 45


def break_sum(source: str, width: int = LINE_WIDTH, tail: int = 0) -> list[str]:
    """Break a LaTeX expression before top-level `` + `` / `` - `` (outside braces and
    \\left…\\right), greedily, so that each line shows at most about ``width`` characters and
    the last one leaves room for ``tail`` more (the `` = result`` the formula ends with)."""
    cuts: list[int] = []
    depth = 0
    i = 0
    while i < len(source):
        if source.startswith("\\left", i):
            depth += 1
            i += 5
            continue
        if source.startswith("\\right", i):
            depth -= 1
            i += 6
            continue
        ch = source[i]
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif depth == 0 and ch == " " and source[i + 1:i + 3] in ("+ ", "- ") and i > 0:
            cuts.append(i)
        i += 1
    bounds = [0] + cuts + [len(source)]
    terms = [source[a:b].strip() for a, b in zip(bounds[:-1], bounds[1:])]
    groups = _pack(terms, width)
    if tail and len(groups[-1]) > 1 and visible_width(" ".join(groups[-1])) + tail > width:
        groups[-1:] = _pack(groups[-1], max(width - tail, 1))
    return [" ".join(g) for g in groups]


def _pack(terms: list[str], width: int) -> list[list[str]]:
    """Terms grouped greedily into lines of at most about ``width`` visible characters."""
    groups: list[list[str]] = []
    for term in terms:
        if groups and visible_width(" ".join(groups[-1] + [term])) <= width:
            groups[-1].append(term)
        else:
            groups.append([term])
    return groups


def result_with_unit(rec: CalcRecord) -> str:
    """The printed result and its unit; an angle in degrees takes the sign without a space
    (``9{,}98^\\circ``, as every other angle of the note: issue 12, «= 9,98 °»)."""
    if rec.unit in ("°", "град"):
        return rec.result_number_latex() + "^\\circ"
    return rec.result_latex()


def calc_parts(rec: CalcRecord) -> CalcParts:
    """Symbol, symbolic form, substitution and result of a record, and whether to split it."""
    symbolic = rec.symbolic_latex()
    substituted = rec.substituted_latex()
    result_number = rec.result_number_latex()
    show_symbolic = symbolic != substituted
    show_substituted = substituted != result_number
    # the line as printed: symbol = symbolic = substitution = result (each «=» a character)
    width = visible_width(" = ".join([rec.symbol, *([symbolic] if show_symbolic else []),
                                      *([substituted] if show_substituted else []), result_with_unit(rec)]))
    wide = width > WIDE_FORMULA and show_symbolic and show_substituted
    lines: tuple[Tex, ...] = ()
    tail = visible_width("= " + result_with_unit(rec))
    if wide and visible_width(substituted) + tail > LINE_WIDTH:
        lines = tuple(Tex(p) for p in break_sum(substituted, tail=tail))
    return CalcParts(
        symbol=Tex(rec.symbol),
        symbolic=Tex(symbolic) if show_symbolic else None,
        substituted=Tex(substituted) if show_substituted else None,
        result=Tex(result_with_unit(rec)),
        wide=wide,
        substituted_lines=lines if len(lines) > 1 else (),
    )


def table_cell(value: Any, decimals: int | None = None) -> Tex:
    """A table cell: a number with ``decimals`` fixed places (or 4 significant digits), else text."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if decimals is not None:
            return Tex(numbers.fixed(value, decimals))
        return Tex(numbers.num(value))
    if value is None:
        return Tex("")
    return escape_latex(value)


#: Letters that the math font (TeX Gyre Termes Math) does not have: Latin-1 letters with diacritics,
#: Cyrillic (Russian, Ukrainian, Belarusian …). In math they print as the text font's italic.
MATH_TEXT_LETTERS: tuple[str, ...] = tuple(
    chr(c) for c in (*range(0x00C0, 0x0100), *range(0x0400, 0x0460), *range(0x0490, 0x04A0))
    if chr(c).isalpha() and c not in (0x00D7, 0x00F7))


def math_text_letters() -> str:
    """The preamble's ``\\mathtextletter{А}…`` for every letter of :data:`MATH_TEXT_LETTERS`."""
    return "".join(f"\\mathtextletter{{{ch}}}" for ch in MATH_TEXT_LETTERS)


#: Characters the text font lacks that a point name may hold (subscript digits): DejaVu Serif prints them.
FALLBACK_GLYPHS: tuple[str, ...] = tuple(chr(c) for c in range(0x2080, 0x208A))


def fallback_glyph_classes() -> str:
    """The preamble's ``\\XeTeXcharclass`₁=\\fallbackglyphclass`` lines."""
    return "\n".join(f"\\XeTeXcharclass`{ch}=\\fallbackglyphclass" for ch in FALLBACK_GLYPHS)


# --------------------------------------------------------------------------- environment
def make_environment(template_dirs: Sequence[Path | str] = ()) -> jinja2.Environment:
    """The Jinja environment: the package's templates, then ``template_dirs``; LaTeX delimiters."""
    loaders: list[jinja2.BaseLoader] = [jinja2.PackageLoader(__package__, "templates")]
    loaders += [jinja2.FileSystemLoader(str(d)) for d in template_dirs]
    env = jinja2.Environment(
        loader=jinja2.ChoiceLoader(loaders),
        block_start_string=r"\BLOCK{", block_end_string="}",
        variable_start_string=r"\VAR{", variable_end_string="}",
        comment_start_string=r"\#{", comment_end_string="}",
        line_comment_prefix="%#",
        trim_blocks=True, lstrip_blocks=True,
        autoescape=True, finalize=_finalize,
        undefined=jinja2.StrictUndefined,
        extensions=["jinja2.ext.do"],
        keep_trailing_newline=True,
    )
    env.filters.update(
        num=lambda v, digits=4: Tex(numbers.num(v, digits)),
        fixed=lambda v, decimals=2: Tex(numbers.fixed(v, decimals)),
        deg=lambda v, decimals=1: Tex(numbers.deg(v, decimals)),
        angle=lambda v, decimals=1: Tex(numbers.angle(v, decimals)),
        mnum=lambda v, digits=4: Tex(numbers.mnum(v, digits)),
        mfixed=lambda v, decimals=2: Tex(numbers.mfixed(v, decimals)),
        tex=tex, escape_latex=escape_latex, unit=_unit_in_context, plural=_plural, count=_count,
        e=escape_latex, escape=escape_latex, forceescape=escape_latex, join=_join, replace=_replace,
        unit_math=lambda u: Tex(unit_latex(u)),
        ratio=_ratio,
    )
    env.globals.update(tex=tex, calc_parts=calc_parts, cell=table_cell, math_text_letters=math_text_letters,
                       fallback_glyph_classes=fallback_glyph_classes, t=_t)
    from .jinja_cache import use_cache
    return use_cache(env)     # compiled templates from the build cache, when a build has one
