"""One cache of matplotlib's mathtext parses for the whole process, instead of one per renderer.

Matplotlib caches a parsed formula (``MathTextParser._parse_cached``, 50 entries) under a key that
includes the parser object, and every renderer makes its own parser: a figure saved with a tight
bounding box parses each of its labels twice (one renderer measures, another draws), the sizes
measured while the labels are placed are parsed again, and the letters that every figure shares
(A, B, ω₁ …) are parsed again for every figure. Parsing (pyparsing) was about a fifth of the
note's figure time.

:func:`share_parses` keys the cache by what a parse depends on — the kind of output (vector or
raster), the formula, dpi, font properties, antialiasing, the glyph-loading flags and the
``mathtext.*`` settings — and not by the parser object, so the same formula is parsed once per
process. A parse is a pure function of that key, so the output is the same bytes (checked by
``tests/speed/test_mathtext_cache.py``). A matplotlib whose parser looks different is left alone.

A short formula (a figure's label: ``$F_{\\mathrm{и}2}$``, ``$a^{n}_{BA}$``) is parsed without
pyparsing's memo (packrat, which matplotlib switches on for the whole process): on a few characters
the memo's bookkeeping costs more than the little backtracking it saves — ≈ 30 % of the parse, which
is most of a label's cost — while a long formula can backtrack much and keeps it. The result is
the same (:data:`PLAIN_PARSE_CHARS`; compared for matplotlib's own test formulas and the note's
labels in the same test).
"""
from __future__ import annotations

import contextlib
import functools
from typing import Any

#: Formulas kept (a note has a few hundred distinct labels and axis texts).
CACHE_SIZE = 4096
#: A formula of at most this many characters is parsed without pyparsing's memo (see above).
PLAIN_PARSE_CHARS = 40

_installed = False
#: matplotlib's own ``_parse_cached`` (per parser object), kept for the tests' comparison.
original: Any = None


def share_parses() -> bool:
    """Install the process-wide parse cache (once); False when this matplotlib does not allow it."""
    global _installed, original
    if _installed:
        return True
    import matplotlib as mpl
    from matplotlib.mathtext import MathTextParser

    original = MathTextParser.__dict__.get("_parse_cached")
    inner = getattr(original, "__wrapped__", None)
    if inner is None or not hasattr(MathTextParser("path"), "_output_type"):
        return False
    settings = tuple(sorted(k for k in mpl.rcParams if k.startswith("mathtext.")))
    parsers: dict[str, Any] = {}

    plain = without_memo()

    @functools.lru_cache(CACHE_SIZE)
    def parsed(output_type: str, rc: tuple, s: str, dpi: float, prop: Any, antialiased: bool,
               flags: Any) -> Any:
        del rc                      # part of the key only: the parser reads the settings itself
        with plain() if plain is not None and len(s) <= PLAIN_PARSE_CHARS else contextlib.nullcontext():
            return inner(parsers[output_type], s, dpi, prop, antialiased, flags)

    def _parse_cached(self: Any, s: str, dpi: float, prop: Any, antialiased: bool, flags: Any) -> Any:
        kind = self._output_type
        parsers.setdefault(kind, self)
        rc = tuple(mpl.rcParams[k] for k in settings)
        return parsed(kind, rc, s, dpi, prop, antialiased, flags)

    original = MathTextParser.__dict__["_parse_cached"]
    _parse_cached.reportgen_shared = True  # type: ignore[attr-defined]
    _parse_cached.cache_info = parsed.cache_info  # type: ignore[attr-defined]
    _parse_cached.cache_clear = parsed.cache_clear  # type: ignore[attr-defined]
    MathTextParser._parse_cached = _parse_cached  # type: ignore[attr-defined]
    _installed = True
    return True


def without_memo() -> Any:
    """A context manager in which pyparsing parses without its memo (packrat), restoring it after;
    None when this pyparsing does not keep the memo as a switchable method (then nothing changes)."""
    from pyparsing import ParserElement

    table = vars(ParserElement)
    cached, uncached = table.get("_parseCache"), table.get("_parseNoCache")
    if cached is None or uncached is None:
        return None

    @contextlib.contextmanager
    def plain() -> Any:
        current = vars(ParserElement).get("_parse")
        if current is not cached:          # the memo is off already (or another parser mode)
            yield
            return
        ParserElement._parse = uncached
        try:
            yield
        finally:
            ParserElement._parse = current

    return plain
