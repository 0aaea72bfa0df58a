"""The note's sections kept by the build cache under what their parts read, so that a rebuild
composes and renders again only the sections an edit reaches (:mod:`reportgen.cache`,
``sections/``).

A section's text is a function of what its parts read of the project (recorded as they compute
their content, :class:`reportgen.read_trace.TracedNeeds`, as a sheet's reads are), the task's
``[document]`` (the templates read it), the language and its catalogue, the code — and of the
symbols the sections before it explained: each formula's «где» list explains only the symbols
not explained earlier in the note (:class:`latex_templates.render.SymbolTracker`). So an entry
keeps the section as rendered with the explained symbols before and after it; a rebuild whose
section reads the same values takes the text when the note has explained the same symbols by
then (else it computes the section's content after all, as without the cache), copies the
section's figures (kept under their content keys) and explains what the section explained.
Nothing is kept of a section whose reads cannot be replayed (opaque), one of whose figures has
no content key, or whose conclusions are not plain text.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from latex_templates.compose import ComposedSection
from latex_templates.note import NoteBuilder, Section
from latex_templates.render import Tex

from ..read_trace import Trace, TracedNeeds


def _symbols_state(symbols: Any) -> list[list[str]]:
    """The explained and the unexplained symbols of a :class:`SymbolTracker`, JSON-able."""
    return [sorted(symbols.explained), sorted(symbols.unexplained)]


class KeptSections:
    """One build's view of the kept sections: given to :func:`latex_templates.compose.compose`
    (``kept``) and to :class:`CachingNoteBuilder`. ``queue``: the build's figure queue (the
    figures a section placed are the queue's new items)."""

    def __init__(self, cache: Any, project: Any, strings: Any, queue: Any) -> None:
        self.cache, self.project, self.strings, self.queue = cache, project, strings, queue
        self.traces: dict[str, Trace] = {}
        self.composed: dict[str, ComposedSection] = {}
        self.kept: dict[str, tuple[dict, Callable[[], ComposedSection]]] = {}
        self.names: dict[str, tuple[str, ...]] = {}
        self.reused: list[str] = []

    def identity(self, key: str, names: tuple[str, ...]) -> str:
        """What names a section besides what it reads: the kind of document, its key, its parts, the
        language and the catalogue overlay (the code is added by the cache)."""
        overlay = getattr(self.strings, "_overlay", None) or ""
        kind = getattr(self.project.task, "kind", "")
        return "|".join(("section", str(kind), key, ",".join(names), self.strings.language, str(overlay)))

    def view(self, key: str, name: str, mod: Any) -> Any:
        """The project as part ``name`` of section ``key`` reads it: its reads recorded."""
        trace = self.traces.setdefault(key, Trace())
        trace.add(("task", "document"))         # the templates read [document] (``doc``)
        return TracedNeeds(self.project, mod.NEEDS, f"part {name}", trace)

    def section(self, key: str, title: str, names: tuple[str, ...],
                make: Callable[[], ComposedSection]) -> ComposedSection:
        """Section ``key`` of the parts ``names``: its kept text when the cache keeps one for these
        reads' values (and the PDF of each of its figures), else ``make()`` (its content computed)."""
        self.names[key] = names
        data = self.cache.restore_section(self.identity(key, names), self.project)
        if data is not None and all(self.cache.figure_sizes(k) is not None for _, k in data["figures"]):
            self.kept[key] = (data, make)
            conclusions = tuple(Tex(text) if kind == "tex" else text for kind, text in data["conclusions"])
            return ComposedSection(Section(key=key, title=title, body=data["body"]), names, conclusions)
        made = self.composed[key] = make()
        return made

    def render(self, sec: Section, fresh: Callable[[Section], Any], symbols: Any, out: Path) -> Any:
        """Render ``sec`` (``fresh``: the builder's own rendering): a kept section's text when the
        note explained the same symbols before it (its figures copied), else the section rendered
        and kept."""
        before = _symbols_state(symbols)
        kept = self.kept.pop(sec.key, None)
        if kept is not None:
            data, make = kept
            if data["before"] == before and self._copy_figures(data, out):
                symbols.explained, symbols.unexplained = set(data["after"][0]), set(data["after"][1])
                self.reused.append(sec.key)
                return fresh(sec)              # a section of ready text: nothing to place
            made = self.composed[sec.key] = make()
            sec = made.section
        if sec.key not in self.composed:
            return fresh(sec)
        placed_before = len(self.queue.items)
        rendered = fresh(sec)
        self._store(sec, str(rendered.body), before, _symbols_state(symbols), self.queue.items[placed_before:])
        return rendered

    def _copy_figures(self, data: dict, out: Path) -> bool:
        folder = out / "figures"
        folder.mkdir(parents=True, exist_ok=True)
        return all(self.cache.restore_figure(key, folder / name) for name, key in data["figures"])

    def _store(self, sec: Section, body: str, before: list, after: list, placed: list) -> None:
        from latex_templates.figures.saving import content_key

        trace = self.traces.get(sec.key)
        composed = self.composed[sec.key]
        if trace is None or trace.opaque or len(placed) != len(sec.figures):
            return
        figures = []
        for fig, target in placed:
            key = content_key(fig)
            if key is None:
                return
            figures.append((Path(target).name, key))
        conclusions = []
        for c in composed.conclusions:
            if type(c) not in (str, Tex):
                return
            conclusions.append(("tex" if isinstance(c, Tex) else "str", str(c)))
        data = {"body": body, "before": before, "after": after, "figures": figures, "conclusions": conclusions}
        self.cache.store_section(self.identity(sec.key, self.names[sec.key]), self.project, trace.reads, data)


class CachingNoteBuilder(NoteBuilder):
    """A :class:`NoteBuilder` whose sections go through :class:`KeptSections`."""

    def __init__(self, *args: Any, kept: KeptSections, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.kept = kept

    def _render_section(self, env: Any, sec: Section, base: dict[str, Any], out: Path) -> Any:
        parent = super()._render_section
        return self.kept.render(sec, lambda s: parent(env, s, base, out), self.symbols, out)
