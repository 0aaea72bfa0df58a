"""The note's figures queued while report.tex is rendered and saved over two processes
(latex_templates/figures/saving.py): the same bytes as saving them one by one, every figure
written once, and an error in the other process comes back with its class and fields."""
from __future__ import annotations

import os

import pytest

from latex_templates.figures import new_figure
from latex_templates.figures.saving import FigureQueue, place, queued, save_pdf
from reportgen.commands import pipeline
from reportgen.errors import InternalError


def _figures(n: int) -> list:
    figs = []
    for i in range(n):
        fig = new_figure(8, 5)
        ax = fig.add_subplot()
        ax.plot([0, 1, 2 + i], [0, i, 1], label=f"$О_{{{i}}}$ кривая {i}")
        ax.set_title(f"рисунок {i}: ω₁ = {i},5")
        ax.legend()
        if i % 2:
            fig.reportgen_exact = True     # a scene's figure: its exact size, no tight box
        figs.append(fig)
    return figs


def _saved_one_by_one_and_queued(tmp_path):
    """Five figures saved one by one into ``seq/``, and the same five queued for ``par/``; fonts
    subset the one way a build subsets them (the queue installs it; a test run alone had the
    one-by-one saves on fontTools' subsetter, other bytes)."""
    from latex_templates.figures.saving import remember_font_subsets

    remember_font_subsets()
    seq, par = tmp_path / "seq", tmp_path / "par"
    seq.mkdir()
    par.mkdir()
    for i, fig in enumerate(_figures(5)):
        save_pdf(fig, seq / f"f{i}.pdf")
    queue = FigureQueue()
    for i, fig in enumerate(_figures(5)):
        queue.add(fig, par / f"f{i}.pdf")
    return seq, par, queue


def test_two_processes_write_the_bytes_of_one_by_one_saving(tmp_path):
    seq, par, queue = _saved_one_by_one_and_queued(tmp_path)
    queue.save(fork=pipeline._fork_figures)
    assert len(queue) == 0
    names = sorted(p.name for p in seq.iterdir())
    assert names == sorted(p.name for p in par.iterdir()) and len(names) == 5
    for name in names:
        assert (seq / name).read_bytes() == (par / name).read_bytes(), name


def test_shares_hold_every_figure_once_and_balance_the_work(tmp_path):
    figs = _figures(6)
    queue = FigureQueue()
    for i, fig in enumerate(figs):
        queue.add(fig, tmp_path / f"f{i}.pdf")
    a, b = queue.shares(2)
    assert sorted(id(f) for f, _ in a + b) == sorted(id(f) for f in figs)
    assert a and b


def test_place_saves_at_once_outside_a_queue_and_queues_inside(tmp_path):
    fig, later = _figures(2)
    place(fig, tmp_path / "now.pdf")
    assert (tmp_path / "now.pdf").is_file()
    with queued() as queue:
        place(later, tmp_path / "later.pdf")
    assert not (tmp_path / "later.pdf").exists() and len(queue) == 1
    queue.save()
    assert (tmp_path / "later.pdf").read_bytes().startswith(b"%PDF")


class _Broken:
    """A figure whose saving fails (in whichever process gets it)."""

    def findobj(self):
        return []

    def savefig(self, *_args, **_kwargs):
        raise InternalError("figure saving", f"made up for the test in process {os.getpid()}")


@pytest.mark.parametrize("position", [0, 3])
def test_an_error_while_saving_comes_back_with_its_class_and_fields(tmp_path, position):
    queue = FigureQueue()
    for i, fig in enumerate(_figures(4)):
        queue.add(fig, tmp_path / f"f{i}.pdf")
    queue.items.insert(position, (_Broken(), tmp_path / "broken.pdf"))
    with pytest.raises(InternalError) as info:
        queue.save(fork=pipeline._fork_figures)
    assert info.value.what == "figure saving"
    assert "made up for the test" in info.value.detail


def test_a_font_subset_made_once_writes_the_bytes_of_one_made_anew(tmp_path, monkeypatch):
    """remember_font_subsets: each font and glyph set is cut once per process, from the font read
    once (latex_templates/figures/font_subset.py, not fontTools' subsetter, for TrueType fonts), and
    a figure whose fonts and glyphs an earlier one used gets the same PDF bytes from memory."""
    from matplotlib.backends import _backend_pdf_ps as pdf_ps

    from latex_templates.figures import saving
    from latex_templates.figures.font_subset import SourceFont

    monkeypatch.setattr(saving, "_SUBSETS", {})
    fonttools = pdf_ps.get_glyphs_subset                # matplotlib's, unless a save installed ours
    while hasattr(fonttools, "reportgen_original"):
        fonttools = fonttools.reportgen_original
    by_fonttools, cut = [], []

    def counted(fontfile, glyphs):
        by_fonttools.append(str(fontfile))
        return fonttools(fontfile, glyphs)

    subset = SourceFont.subset

    def cut_counted(self, gids):
        cut.append(self.path)
        return subset(self, gids)

    monkeypatch.setattr(pdf_ps, "get_glyphs_subset", counted)
    monkeypatch.setattr(SourceFont, "subset", cut_counted)
    save_pdf(_figures(1)[0], tmp_path / "plain.pdf")           # fontTools every time
    plain_count = len(by_fonttools)
    saving.remember_font_subsets()
    save_pdf(_figures(1)[0], tmp_path / "first.pdf")           # cut and remembered
    assert plain_count > 0 and len(by_fonttools) == plain_count and len(cut) == plain_count
    save_pdf(_figures(1)[0], tmp_path / "again.pdf")           # from memory
    assert len(cut) == plain_count and len(by_fonttools) == plain_count
    assert (tmp_path / "again.pdf").read_bytes() == (tmp_path / "first.pdf").read_bytes()


def test_split_writes_every_placeholder_first_then_the_bytes_of_one_by_one_saving(tmp_path):
    """start_split (the build's cold path): when it returns, every figure has a placeholder of its
    page (its box is the saved figure's), and finish() leaves the bytes of saving one by one."""
    from latex_templates.passes import media_box

    seq, par, queue = _saved_one_by_one_and_queued(tmp_path)
    split = queue.start_split(pipeline._fork_figures_ready)
    assert split.mine and split.theirs
    # each target, not the folder's listing: the other process may already be saving its share
    # (an atomic write's hidden «.fN.pdf.part» beside the targets)
    names = [f"f{i}.pdf" for i in range(5)]
    placeholders = {name: media_box(par / name) for name in names}
    assert all(box is not None for box in placeholders.values()), placeholders
    split.finish()
    assert sorted(p.name for p in par.iterdir()) == names        # no partial file left behind
    for name, box in placeholders.items():
        assert (seq / name).read_bytes() == (par / name).read_bytes(), name
        assert media_box(par / name) == box, name


@pytest.mark.parametrize("position", [0, 3])
def test_an_error_in_a_split_comes_back_with_its_class_and_fields(tmp_path, position):
    """Before the other process is ready (measuring) or after (saving): the build's error either way."""
    queue = FigureQueue()
    for i, fig in enumerate(_figures(4)):
        queue.add(fig, tmp_path / f"f{i}.pdf")
    broken = _Broken()
    broken.get_tightbbox = broken.savefig        # type: ignore[attr-defined]  # fails when measured too
    queue.items.insert(position, (broken, tmp_path / "broken.pdf"))
    with pytest.raises(InternalError) as info:
        queue.start_split(pipeline._fork_figures_ready).finish()
    assert info.value.what == "figure saving"
    assert "made up for the test" in info.value.detail
