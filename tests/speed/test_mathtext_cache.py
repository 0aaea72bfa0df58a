"""One mathtext parse cache per process (latex_templates/figures/mathtext_cache.py): the same PDF
bytes as matplotlib's cache per parser, and a formula parsed once however many renderers draw it."""
from __future__ import annotations

import pytest
from matplotlib.mathtext import MathTextParser

from latex_templates.figures import mathtext_cache, new_figure
from latex_templates.figures.saving import save_pdf

LABELS = ["$a^{n}_{BA}$", r"$\omega_{1}$", r"$F_{\mathrm{ур}}$, $M_{1}$", "$A$", "$A$"]


def _figure(exact: bool):
    fig = new_figure(8, 5)
    ax = fig.add_subplot()
    for i, text in enumerate(LABELS):
        ax.text(0.1 + 0.15 * i, 0.5, text, style="italic" if i % 2 else "normal")
    ax.set_title(r"$\varepsilon_{2}$ — кривая")
    fig.reportgen_exact = exact
    return fig


def test_installed_with_the_note_figures():
    assert getattr(MathTextParser.__dict__["_parse_cached"], "reportgen_shared", False)


def test_the_same_bytes_as_matplotlibs_own_cache(tmp_path, monkeypatch):
    for exact in (False, True):
        shared = tmp_path / f"shared-{exact}.pdf"
        save_pdf(_figure(exact), shared)
        monkeypatch.setattr(MathTextParser, "_parse_cached", mathtext_cache.original)
        own = tmp_path / f"own-{exact}.pdf"
        save_pdf(_figure(exact), own)
        monkeypatch.undo()
        assert shared.read_bytes() == own.read_bytes()


def test_a_formula_is_parsed_once_whatever_the_renderer(tmp_path):
    cached = MathTextParser.__dict__["_parse_cached"]
    cached.cache_clear()
    save_pdf(_figure(False), tmp_path / "a.pdf")      # two renderers: the tight box, the drawing
    first = cached.cache_info()
    save_pdf(_figure(False), tmp_path / "b.pdf")
    second = cached.cache_info()
    assert second.misses == first.misses             # nothing parsed again for the second figure
    assert second.hits > first.hits
    assert first.misses <= len(set(LABELS)) + 1 + 8   # labels, title and tick labels, each once


#: The kinds of label the note's figures print (points, vectors with Cyrillic indices, forces,
#: angles, units), each at most PLAIN_PARSE_CHARS long.
NOTE_LABELS = ["$A$", "$O_{1}$", "$B_{0}$", "$a^{n}_{BA}$", r"$a^{\tau}_{CB}$", r"$F^{\prime}_{\mathrm{и}2}$",
               r"$F^{B}_{M\mathrm{и}3}$", r"$R^{\tau}_{12}$", r"$\omega_{1}$", r"$\varepsilon_{2}$",
               r"$M_{\mathrm{ур}}$, Н·м", r"$\varphi_1$, °", r"$\pi$", "$h_{16}$", r"$\Delta E$, Дж",
               r"$J_{\mathrm{пр}}$", r"$\frac{a}{b}$", r"$\sqrt{x}$", r"$x^{2}_{i}$'"]


def _matplotlibs_formulas() -> list[str]:
    """matplotlib's own test formulas (``math_tests`` of its installed test module), if shipped."""
    import ast
    from pathlib import Path

    import matplotlib

    path = Path(matplotlib.__file__).parent / "tests" / "test_mathtext.py"
    if not path.is_file():
        return []
    out: list[str] = []
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "math_tests" for t in node.targets):
            out += [v for v in ast.literal_eval(node.value) if isinstance(v, str)]
    return out


def _key(parse) -> tuple:
    """A parse's content, comparable (fonts by their file)."""
    if hasattr(parse, "image"):
        return (parse.ox, parse.oy, parse.width, parse.height, parse.depth, parse.image.tobytes())
    return (parse.width, parse.height, parse.depth,
            [(g[0].fname, *g[1:]) for g in parse.glyphs], list(parse.rects))


@pytest.mark.slow          # ~500 parses twice: seconds of CPU (docs/testing.md)
def test_a_short_formula_parses_the_same_without_pyparsings_memo():
    from matplotlib.font_manager import FontProperties
    from matplotlib.ft2font import LoadFlags

    plain = mathtext_cache.without_memo()
    assert plain is not None
    inner = mathtext_cache.original.__wrapped__
    formulas = [s for s in NOTE_LABELS + _matplotlibs_formulas() if len(s) <= mathtext_cache.PLAIN_PARSE_CHARS]
    assert len(formulas) > 40
    checked = 0
    for kind, dpi in (("path", 72), ("agg", 100)):
        parser = MathTextParser(kind)
        for s in formulas:
            for style in ("normal", "italic"):
                prop = FontProperties(size=9, style=style, math_fontfamily="stix")
                try:
                    memo = _key(inner(parser, s, dpi, prop, True, LoadFlags.NO_HINTING))
                except ValueError:          # a formula this mathtext rejects: rejected both ways
                    with plain(), pytest.raises(ValueError):
                        inner(parser, s, dpi, prop, True, LoadFlags.NO_HINTING)
                    continue
                with plain():
                    assert _key(inner(parser, s, dpi, prop, True, LoadFlags.NO_HINTING)) == memo, s
                checked += 1
    assert checked > 100


def test_the_memo_is_restored_after_a_plain_parse_even_a_failed_one():
    from matplotlib.ft2font import LoadFlags
    from pyparsing import ParserElement

    plain = mathtext_cache.without_memo()
    before = vars(ParserElement)["_parse"]
    with pytest.raises(ValueError):
        with plain():
            assert vars(ParserElement)["_parse"] is vars(ParserElement)["_parseNoCache"]
            mathtext_cache.original.__wrapped__(MathTextParser("path"), r"$\frac{a$", 72, None, True,
                                                LoadFlags.NO_HINTING)
    assert vars(ParserElement)["_parse"] is before
