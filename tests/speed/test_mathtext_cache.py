"""One mathtext parse cache per process (latex_templates/figures/mathtext_cache.py): the same PDF
bytes as matplotlib's cache per parser, and a formula parsed once however many renderers draw it."""
from __future__ import annotations

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
