"""Saving the note's matplotlib figures as PDF: at once, or queued and saved later in two processes.

A figure's PDF is a pure function of the figure: no timestamp or producer (``metadata``), the
tight bounding box unless the figure is drawn at a true scale (``fig.reportgen_exact``). Saving is
most of the note's time (drawing each figure, subsetting its fonts), and the figures are
independent, so ``reportgen build`` queues them while the note's text is rendered
(:func:`queued`) and then saves the queue split over two processes (:meth:`FigureQueue.save`):
the same bytes whichever process writes a figure.
"""
from __future__ import annotations

import os
import sys
from contextlib import contextmanager, nullcontext
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterator

from reportgen.errors import ReportgenError

#: The metadata that would make a PDF differ from run to run (None: not written).
PDF_METADATA = {"CreationDate": None, "ModDate": None, "Producer": None}


def save_pdf(fig: Any, target: Path, box: Any = None) -> None:
    """Write ``fig`` to ``target`` as PDF (reproducible bytes) and let pyplot forget it; ``box``:
    its tight bounding box measured already (:func:`tight_box`), the same bytes as "tight"."""
    exact = getattr(fig, "reportgen_exact", False)
    target = Path(target)
    part = target.with_name(f".{target.name}.part")  # then renamed: a reader sees a whole file
    fig.savefig(part, format="pdf", bbox_inches=None if exact else (box or "tight"), metadata=PDF_METADATA)
    os.replace(part, target)
    _release(fig)


class _Measured(ReportgenError):
    """Stops a save once the tight bounding box is known (:func:`tight_box`); never leaves it."""


def tight_box(fig: Any) -> Any:
    """The padded tight bounding box (inches) that saving ``fig`` as PDF with ``bbox_inches="tight"``
    computes: matplotlib's own computation, stopped before anything is drawn. Saving afterwards with
    this box skips that computation and writes the same bytes (tests/speed/test_figure_saving.py)."""
    import io

    import matplotlib as mpl

    found: dict[str, Any] = {}
    measure = fig.get_tightbbox

    def record(*args: Any, **kwargs: Any) -> Any:
        found["box"] = measure(*args, **kwargs)
        raise _Measured("the tight box is measured")

    fig.get_tightbbox = record
    try:
        fig.savefig(io.BytesIO(), format="pdf", bbox_inches="tight", metadata=PDF_METADATA)
    except _Measured:
        pass
    finally:
        del fig.get_tightbbox
    if "box" not in found:           # pragma: no cover - a matplotlib that computes it elsewhere
        return None
    pad = mpl.rcParams["savefig.pad_inches"]
    return found["box"].padded(pad, pad)


def page_size_pt(fig: Any, box: Any = None) -> tuple[float, float]:
    """The size (pt) of ``fig``'s PDF page: its figure size at a true scale, else its tight box."""
    if getattr(fig, "reportgen_exact", False) or box is None:
        w, h = fig.get_size_inches()
    else:
        w, h = box.width, box.height
    return float(w) * 72.0, float(h) * 72.0


def artists(fig: Any) -> list[Any]:
    """The artists of ``fig`` as ``findobj`` lists them, but not looking inside an axis: an axis
    makes its ticks when first asked for them, and asking made ~340 ticks in the scene figures,
    whose axes are off and never draw them (0.2 s of the note's CPU). What a part adds to a
    figure (lines, texts, patches) belongs to its axes, not to an axis, so it is counted."""
    from matplotlib.axis import Axis

    out: list[Any] = []
    stack = [fig]
    while stack:
        a = stack.pop()
        out.append(a)
        children = getattr(a, "get_children", None)
        if children is not None and not isinstance(a, Axis):
            stack.extend(reversed(children()))
    return out


def mark_content(fig: Any) -> None:
    """Note that ``fig`` is now whole as its ``reportgen_key`` describes it (:func:`content_key`)."""
    fig.reportgen_artists = len(artists(fig))


def content_key(fig: Any) -> str | None:
    """The figure's content key (a scene figure's, :func:`latex_templates.figures.scene.figure_key`),
    or None: a figure without one, or one that had artists added after it was keyed."""
    key = getattr(fig, "reportgen_key", None)
    if isinstance(fig, KeptFigure):
        return key
    if key is None or len(artists(fig)) != getattr(fig, "reportgen_artists", -1):
        return None
    return key


@dataclass
class KeptFigure:
    """Stands for a scene figure whose PDF the build cache keeps (:func:`kept_figure`): it carries
    what the note reads of the figure (its sizes) and makes the real figure only when the kept
    PDF cannot be copied after all (:meth:`make`)."""
    reportgen_key: str
    sizes: dict[str, float]
    make: Callable[[], Any]
    reportgen_exact: bool = True

    @property
    def width_cm(self) -> float:
        return self.sizes["width_cm"]

    @property
    def reportgen_reduction(self) -> float:
        return self.sizes["reduction"]

    def get_size_inches(self) -> tuple[float, float]:
        return self.sizes["width_in"], self.sizes["height_in"]

    def get_figwidth(self) -> float:
        return self.sizes["width_in"]

    def get_figheight(self) -> float:
        return self.sizes["height_in"]

    def savefig(self, *args: Any, **kwargs: Any) -> None:
        self.make().savefig(*args, **kwargs)


def figure_sizes(fig: Any) -> dict[str, float]:
    """What the note reads of a kept figure (:class:`KeptFigure`), kept beside its PDF in the build
    cache: its size in inches, whether it is drawn at a true scale (``exact``; a plot is saved at
    its tight box), and a scene figure's width and reduction."""
    w, h = fig.get_size_inches()
    sizes = {"exact": float(bool(getattr(fig, "reportgen_exact", False))), "width_in": float(w), "height_in": float(h)}
    if getattr(fig, "width_cm", None) is not None:
        sizes["width_cm"] = float(fig.width_cm)
    if getattr(fig, "reportgen_reduction", None) is not None:
        sizes["reduction"] = float(fig.reportgen_reduction)
    return sizes


def content_keys_read() -> bool:
    """Will anything read a figure's content key (:func:`content_key`)? Not in a build that queues
    the figures without a cache (``--no-cache``): there, digesting each scene (≈ 0.1 s of the
    note's CPU on the press) is skipped; elsewhere — a build with a cache, a caller outside a
    build — the key is made."""
    return _QUEUE is None or _QUEUE.cache is not None


def kept_figure(key: str, make: Callable[[], Any]) -> Any:
    """A :class:`KeptFigure` when the build that queues the note's figures (:func:`queued`) has a
    cache keeping the figure with content ``key``; else None (the caller makes the figure)."""
    cache = _QUEUE.cache if _QUEUE is not None else None
    sizes = cache.figure_sizes(key) if cache is not None else None
    if sizes is None:
        return None
    return KeptFigure(key, sizes, make, reportgen_exact=bool(sizes.get("exact", 1.0)))


def _release(fig: Any) -> None:
    """Let pyplot forget a figure once it is saved (its memory is freed; saving again still works)."""
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        try:
            plt.close(fig)
        except (TypeError, ValueError):
            pass


@dataclass
class FigureQueue:
    """Figures waiting to be saved, in the order the note placed them."""
    items: list[tuple[Any, Path]] = field(default_factory=list)
    boxes: dict[int, Any] = field(default_factory=dict)   # id(fig) → its measured tight box
    cache: Any = None    # the build cache, whose kept scene figures stand in for made ones (kept_figure)

    def add(self, fig: Any, target: Path) -> None:
        self.items.append((fig, target))

    def write_placeholders(self) -> None:
        """Measure each figure's page and write an empty PDF of that size at its target, for a
        first LaTeX pass while the figures are saved (:mod:`latex_templates.passes`); the measured
        tight boxes are kept, so saving does not compute them again."""
        for i, (fig, target) in enumerate(self.items):
            if isinstance(fig, KeptFigure):     # the kept PDF itself, when it is still there
                if self.cache is not None and self.cache.copy_figure(fig.reportgen_key, target):
                    continue
                fig = fig.make()
                self.items[i] = (fig, target)
            self._placeholder(fig, target)

    def _placeholder(self, fig: Any, target: Path) -> None:
        from ..passes import placeholder_pdf

        box = None
        if not getattr(fig, "reportgen_exact", False):
            box = self.boxes[id(fig)] = tight_box(fig)
        target.write_bytes(placeholder_pdf(*page_size_pt(fig, box)))

    def start_split(self, fork: Callable[[Callable[[Callable[[], None]], Any]], Any],
                    cache: Any = None) -> "SplitSave":
        """What :meth:`write_placeholders` then :meth:`save` do, over two processes from the start:
        ``fork(work)`` runs ``work(ready)`` in a second process, which measures its share's pages,
        writes their placeholders, calls ``ready()`` and saves its share, while this process
        measures the other share's pages and writes theirs. Returns when every placeholder is
        written (a figure the cache keeps: its real PDF); :meth:`SplitSave.finish` saves this
        process's share and joins the other. The same files as the two calls (the measuring was
        the build's critical path, ≈ 0.45 s on the press, in one process)."""
        items, self.items = self.items, []
        keys = {id(fig): content_key(fig) for fig, _ in items} if cache is not None else {}
        todo = []
        for fig, target in items:
            if isinstance(fig, KeptFigure):     # the kept PDF itself, when it is still there
                if cache is not None and cache.restore_figure(fig.reportgen_key, target):
                    continue
                fig = fig.make()
            else:
                key = keys.get(id(fig))
                if key and cache.restore_figure(key, target):
                    _release(fig)
                    continue
            todo.append((fig, target))
        if len(todo) < 2:
            for fig, target in todo:
                self._placeholder(fig, target)
            return SplitSave(self, todo, [], None, cache)
        mine, theirs = FigureQueue(todo).shares(2)
        _import_pdf_saving()          # once, before the fork: not in each process after it

        def work(ready: Callable[[], None]) -> int:
            for fig, target in theirs:
                self._placeholder(fig, target)
            ready()
            return _save_all(theirs, self.boxes)

        child = fork(work)
        try:
            for fig, target in mine:
                self._placeholder(fig, target)
            child.wait_ready()
        except BaseException:
            child.kill()
            raise
        return SplitSave(self, mine, theirs, child, cache)

    def __len__(self) -> int:
        return len(self.items)

    def shares(self, parts: int) -> list[list[tuple[Any, Path]]]:
        """The queue split into ``parts`` shares of about equal work (largest first onto the least
        loaded share; a figure's work is estimated by its number of artists, texts counted thrice)."""
        from matplotlib.text import Text

        weighed = []
        for i, (fig, target) in enumerate(self.items):
            drawn = artists(fig)
            weight = len(drawn) + 2 * sum(isinstance(a, Text) for a in drawn)
            weighed.append((-weight, i, fig, target))
        weighed.sort(key=lambda w: (w[0], w[1]))
        loads = [0] * parts
        out: list[list[tuple[Any, Path]]] = [[] for _ in range(parts)]
        for w, _, fig, target in weighed:
            k = loads.index(min(loads))
            loads[k] -= w
            out[k].append((fig, target))
        return out

    def save(self, *, fork: Callable[[Callable[[], Any]], Any] | None = None, cache: Any = None) -> None:
        """Save every queued figure. ``fork(work)``, when given, runs ``work`` in a second process
        and returns a handle whose ``join()`` waits for it (and re-raises its error): that process
        saves one share while this one saves the other. ``cache`` (a
        :class:`reportgen.cache.BuildCache`): a figure with a content key found there is copied
        instead of saved, and each keyed figure saved is stored there."""
        items, self.items = self.items, []
        keys = {id(fig): content_key(fig) for fig, _ in items} if cache is not None else {}
        todo = []
        for fig, target in items:
            key = keys.get(id(fig))
            if key and cache.restore_figure(key, target):
                _release(fig)
            else:
                todo.append((fig.make() if isinstance(fig, KeptFigure) else fig, target))
        self._save(todo, fork)
        for fig, target in todo:
            key = content_key(fig) if cache is not None else None
            if key and target.is_file():
                cache.store_figure(key, target, figure_sizes(fig))

    def _save(self, items: list[tuple[Any, Path]], fork: Any) -> None:
        boxes = self.boxes
        if fork is None or len(items) < 2:
            _save_all(items, boxes)
            return
        queue = FigureQueue(items)
        mine, theirs = queue.shares(2)
        _import_pdf_saving()
        child = fork(lambda: _save_all(theirs, boxes))
        try:
            _save_all(mine, boxes)
        except BaseException:
            child.kill()
            raise
        child.join()
        for fig, _ in theirs:        # saved by the other process: forget them here too
            _release(fig)


@dataclass
class SplitSave:
    """The figures of :meth:`FigureQueue.start_split` with their placeholders written: this
    process's share to save (:meth:`finish`), the other share saved by ``child``."""
    queue: FigureQueue
    mine: list[tuple[Any, Path]]
    theirs: list[tuple[Any, Path]]
    child: Any
    cache: Any = None

    def finish(self) -> None:
        """Save this process's share, join the other process and keep each keyed figure saved."""
        try:
            _save_all(self.mine, self.queue.boxes)
        except BaseException:
            self.cancel()
            raise
        if self.child is not None:
            self.child.join()
            self.child = None
        for fig, _ in self.theirs:       # saved by the other process: forget them here too
            _release(fig)
        if self.cache is not None:
            for fig, target in self.mine + self.theirs:
                key = content_key(fig)
                if key and target.is_file():
                    self.cache.store_figure(key, target, figure_sizes(fig))

    def cancel(self) -> None:
        """Stop the other process (the build failed elsewhere)."""
        if self.child is not None:
            self.child.kill()
            self.child = None


#: The font tables matplotlib's PDF backend subsets (fontTools imports a table's module when it
#: first reads one).
_FONT_TABLES = ("GDEF", "GPOS", "GSUB", "OS/2", "cmap", "cvt ", "fpgm", "gasp", "glyf", "head", "hhea", "hmtx",
                "kern", "loca", "maxp", "name", "post", "prep")


def _import_pdf_saving() -> None:
    """Import what saving a PDF imports (matplotlib's PDF backend, fontTools' subsetter and its font
    tables, ≈ 150 modules, ≈ 0.1 s of CPU) in this process, so that processes forked from it to
    save figures inherit them instead of each importing them."""
    import matplotlib.backends.backend_pdf  # noqa: F401
    from fontTools import ttLib

    for tag in _FONT_TABLES:
        ttLib.getTableClass(tag)


#: Subset fonts made in this process: (font file, face, glyphs) → (font bytes, glyph numbers).
_SUBSETS: dict[tuple[str, int, frozenset[int]], tuple[bytes, dict[int, int]]] = {}
#: Subsets kept (the oldest forgotten first): a note makes ~70 distinct ones of 10–100 kB, and a
#: process that builds many notes (``--watch``, ``batch``) must not grow without bound.
KEEP_SUBSETS = 512


def remember_font_subsets() -> None:
    """Let matplotlib's PDF backend subset each font for a set of glyphs once per process, cut
    from the font read once (:mod:`.font_subset`).

    Every figure embeds a subset of each font it uses. fontTools' subsetter parses the whole font
    file for each (≈ 13 ms, ~80 on the press: the figures' largest CPU item); :mod:`.font_subset`
    reads each font once per process and cuts a subset in ≈ 1 ms, the same glyphs (a font it does
    not handle goes to fontTools as before). A third of the subsets are the same font with the same
    glyphs as an earlier figure's (the digits and letters of the axes' and scenes' labels); a subset
    is a pure function of the font file, the face and the glyph set, so the bytes made once are
    written again: the same PDF bytes (tests/speed/test_figure_saving.py)."""
    from matplotlib.backends import _backend_pdf_ps as pdf_ps

    from .font_subset import CutFont, CutSubset, cut_below

    original = pdf_ps.get_glyphs_subset
    if getattr(original, "reportgen_memo", False):
        return
    if not hasattr(original, "reportgen_original"):    # no layer under it yet (the build cache's
        original = cut_below(original)                  # subsets on disk put the cut under theirs)

    def get_glyphs_subset(fontfile: Any, glyphs: Any) -> Any:
        key = (str(fontfile), int(getattr(fontfile, "face_index", 0)), frozenset(int(g) for g in glyphs))
        found = _SUBSETS.get(key)
        if found is None:
            with original(fontfile, glyphs) as subset:
                found = (pdf_ps.font_as_file(subset.font).getvalue(), dict(subset.glyph_index_map))
            _SUBSETS[key] = found
            if len(_SUBSETS) > KEEP_SUBSETS:
                del _SUBSETS[next(iter(_SUBSETS))]
        return nullcontext(CutSubset(CutFont(found[0]), dict(found[1])))

    get_glyphs_subset.reportgen_memo = True          # type: ignore[attr-defined]
    get_glyphs_subset.reportgen_original = original  # type: ignore[attr-defined]
    pdf_ps.get_glyphs_subset = get_glyphs_subset


def _save_all(items: list[tuple[Any, Path]], boxes: dict[int, Any] | None = None) -> int:
    remember_font_subsets()
    for fig, target in items:
        save_pdf(fig, target, (boxes or {}).get(id(fig)))
    return len(items)


_QUEUE: FigureQueue | None = None


@contextmanager
def queued(cache: Any = None) -> Iterator[FigureQueue]:
    """While open, :func:`place` queues figures instead of saving them; the caller saves the queue
    (with ``cache``, the build cache: scene figures it keeps are not made, :func:`kept_figure`)."""
    global _QUEUE
    previous, _QUEUE = _QUEUE, FigureQueue(cache=cache)
    try:
        yield _QUEUE
    finally:
        _QUEUE = previous


def place(fig: Any, target: Path) -> None:
    """Save ``fig`` to ``target`` now, or queue it inside :func:`queued`."""
    if _QUEUE is not None:
        _QUEUE.add(fig, target)
    else:
        save_pdf(fig, target)
