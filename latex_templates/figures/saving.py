"""Saving the note's matplotlib figures as PDF: at once, or queued and saved later in two processes.

A figure's PDF is a pure function of the figure: no timestamp or producer (``metadata``), the
tight bounding box unless the figure is drawn at a true scale (``fig.reportgen_exact``). Saving is
most of the note's time (drawing each figure, subsetting its fonts), and the figures are
independent, so ``reportgen build`` queues them while the note's text is rendered
(:func:`queued`) and then saves the queue split over two processes (:meth:`FigureQueue.save`):
the same bytes whichever process writes a figure.
"""
from __future__ import annotations

import sys
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterator

#: The metadata that would make a PDF differ from run to run (None: not written).
PDF_METADATA = {"CreationDate": None, "ModDate": None, "Producer": None}


def save_pdf(fig: Any, target: Path) -> None:
    """Write ``fig`` to ``target`` as PDF (reproducible bytes) and let pyplot forget it."""
    exact = getattr(fig, "reportgen_exact", False)
    fig.savefig(target, format="pdf", bbox_inches=None if exact else "tight", metadata=PDF_METADATA)
    _release(fig)


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

    def add(self, fig: Any, target: Path) -> None:
        self.items.append((fig, target))

    def __len__(self) -> int:
        return len(self.items)

    def shares(self, parts: int) -> list[list[tuple[Any, Path]]]:
        """The queue split into ``parts`` shares of about equal work (largest first onto the least
        loaded share; a figure's work is estimated by its number of artists, texts counted thrice)."""
        from matplotlib.text import Text

        weighed = []
        for i, (fig, target) in enumerate(self.items):
            artists = fig.findobj()
            weight = len(artists) + 2 * sum(isinstance(a, Text) for a in artists)
            weighed.append((-weight, i, fig, target))
        weighed.sort(key=lambda w: (w[0], w[1]))
        loads = [0] * parts
        out: list[list[tuple[Any, Path]]] = [[] for _ in range(parts)]
        for w, _, fig, target in weighed:
            k = loads.index(min(loads))
            loads[k] -= w
            out[k].append((fig, target))
        return out

    def save(self, *, fork: Callable[[Callable[[], Any]], Any] | None = None) -> None:
        """Save every queued figure. ``fork(work)``, when given, runs ``work`` in a second process
        and returns a handle whose ``join()`` waits for it (and re-raises its error): that process
        saves one share while this one saves the other."""
        items, self.items = self.items, []
        if fork is None or len(items) < 2:
            for fig, target in items:
                save_pdf(fig, target)
            return
        queue = FigureQueue(items)
        mine, theirs = queue.shares(2)
        child = fork(lambda: _save_all(theirs))
        try:
            _save_all(mine)
        except BaseException:
            child.kill()
            raise
        child.join()
        for fig, _ in theirs:        # saved by the other process: forget them here too
            _release(fig)


def _save_all(items: list[tuple[Any, Path]]) -> int:
    for fig, target in items:
        save_pdf(fig, target)
    return len(items)


_QUEUE: FigureQueue | None = None


@contextmanager
def queued() -> Iterator[FigureQueue]:
    """While open, :func:`place` queues figures instead of saving them; the caller saves the queue."""
    global _QUEUE
    previous, _QUEUE = _QUEUE, FigureQueue()
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
