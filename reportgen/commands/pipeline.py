"""The stages of ``reportgen build`` and how they overlap (the build's critical path).

    main process   task → solve → note's sections, report.tex → figures (share 1) ─ results.json ─ join ─ join
    figures                                       (forked) figures (share 2) ─┘                    │      │
    sheets         (forked after solve, nice 3)  sheet 1 … sheet n: DXF + PNG preview ─────────────┘      │
    LaTeX          (passes on the figures' placeholders, beside the figures, until stable) → xdvipdfmx ┘

The sheets do not need the note, nor the note the sheets: on a machine with more than one processor
the sheets are drawn in a forked child process while the main process composes the note, and
LaTeX's passes run in the background while the main process writes results.json and waits. Every stage
records a :class:`Span` (start and end on the monotonic clock shared by the processes), so
``reportgen bench`` can print what ran in parallel and what waited. Nothing here decides what is
written: the outputs are the same bytes whether the stages overlap or not, and whether a sheet,
a figure or LaTeX's auxiliary files come from the build cache (:mod:`reportgen.cache`) or not.
"""
from __future__ import annotations

import os
import pickle
import signal
import sys
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator

from ..errors import BuildError
from ..project import Needs

MAIN, SHEETS, LATEX = "main", "sheets", "LaTeX"
#: The ``--latexmk`` default: the passes may then be driven directly (an early first pass); a
#: latexmk named by the user is run as it is.
DEFAULT_LATEXMK = "latexmk"
#: How much lower the sheets' process runs than the note's (``os.nice``): they wait for the
#: processors the note's figures and xelatex leave free, which shortens the build's critical path.
SHEETS_NICENESS = 3


@dataclass(frozen=True)
class Span:
    """One stage: its name, the lane it ran in and its start/end (s, ``time.perf_counter``)."""
    name: str
    lane: str
    start: float
    end: float

    @property
    def seconds(self) -> float:
        return self.end - self.start


@dataclass
class Timeline:
    """The spans of one build; prints each main-lane stage as it ends unless ``quiet``."""
    quiet: bool = False
    spans: list[Span] = field(default_factory=list)
    origin: float = field(default_factory=time.perf_counter)
    current: str | None = None   # the main-lane stage running (named when it fails)
    latex_passes: int = 0        # xelatex passes the note took
    latex_preamble_kept: bool = False   # pass 1 began on the last build's preamble (before the solve)

    @contextmanager
    def stage(self, name: str, lane: str = MAIN) -> Iterator[None]:
        t0 = time.perf_counter()
        if lane == MAIN:
            self.current = name
        if not self.quiet:
            print(f"  {name} …", end="", flush=True)
        try:
            yield
        except BaseException:
            if not self.quiet:
                print(" failed", flush=True)
            raise
        t1 = time.perf_counter()
        self.spans.append(Span(name, lane, t0, t1))
        if not self.quiet:
            print(f" {t1 - t0:.2f} s", flush=True)

    def add(self, span: Span) -> None:
        self.spans.append(span)
        if not self.quiet:
            # «note: LaTeX (in parallel)», not «(in parallel: LaTeX)» twice over
            where = "" if span.lane == MAIN else " (in parallel)" if span.lane in span.name \
                else f" (in parallel: {span.lane})"
            print(f"  {span.name}{where} … {span.seconds:.2f} s", flush=True)

    @property
    def times(self) -> dict[str, float]:
        """Seconds of each stage by name (what ``build`` returned before stages overlapped)."""
        return {s.name: s.seconds for s in self.spans}

    def critical_path(self) -> list[tuple[str, str, float, float]]:
        """(lane, stage, start, end) relative to the build's start, in order of start."""
        return [(s.lane, s.name, s.start - self.origin, s.end - self.origin)
                for s in sorted(self.spans, key=lambda s: (s.start, s.lane))]


def parallel_possible() -> bool:
    """Fork a child for the sheets only where fork exists and there is a second processor
    (``REPORTGEN_JOBS=1`` turns it off)."""
    if os.environ.get("REPORTGEN_JOBS", "").strip() == "1":
        return False
    return hasattr(os, "fork") and (os.cpu_count() or 1) > 1


def run(project: Any, tmp: Path, timeline: Timeline, *, pdf: bool, sheets: bool, latexmk: str,
        cache: Any = None) -> Any:
    """Solve, write the note, the sheets and results.json into ``tmp``; return the results."""
    from ..results import build_results, dumps

    early = pdf and latexmk == DEFAULT_LATEXMK
    # a rebuild's first xelatex pass reads the last build's preamble while the task is solved and
    # the note composed (it goes on into the body when the note's preamble is the same)
    started = _start_split_latex(tmp, cache) if early and cache is not None else None
    if early and started is None:
        started = _start_cold_latex(project, tmp)   # no kept preamble: the one the note will have
    pending = started
    child = None
    try:
        with timeline.stage("solve"):
            results = build_results(project)
        task = project.task
        todo: list[tuple[str, Any]] = []
        if sheets and parallel_possible():
            # forked before the main process imports matplotlib, ezdxf only in the sheets' process: it
            # lists and draws the sheets while the note is composed (the main process never needs ezdxf)
            with timeline.stage("before the sheets' fork"):
                _shared_imports(project)
                _shared_stages(project, cache)
                child = _Child.start(project, tmp, None, cache)
        elif sheets:
            todo = _sheet_list(project)
        if (task.mechanism is not None or task.gears is not None or task.planetary is not None
                or getattr(task, "crane", None) is not None):
            tex, pending = _note(project, tmp, timeline, early=early, cache=cache, started=started)
            if pdf and pending is None:
                pending = _start_latex(tex, latexmk, cache)
        elif pending is not None:           # no note to typeset
            pending.cancel()
            pending = None
        if todo and child is None:
            for span in draw_sheets(project, tmp, todo, cache, lane=MAIN):
                timeline.add(span)
        with timeline.stage("results.json"):
            (tmp / "results.json").write_text(dumps(results), encoding="utf-8")
        if child is not None:
            t0 = time.perf_counter()
            for span in child.join():
                timeline.add(span)
            timeline.spans.append(Span("wait for the sheets", MAIN, t0, time.perf_counter()))
            child = None
        if pending is not None:
            t0 = time.perf_counter()
            try:
                timeline.latex_passes = pending.wait().passes
            except BuildError as exc:
                raise BuildError("LaTeX", exc.problem, exc.kept) from None
            end = time.perf_counter()
            timeline.add(Span("note: LaTeX", LATEX, pending.started, end))
            timeline.spans.append(Span("wait for LaTeX", MAIN, t0, end))
            if cache is not None:
                cache.store_tex(tex.parent / "latex-build", _preamble(tex))
            pending = None
    finally:
        if child is not None:
            child.kill()
        if pending is not None:
            pending.cancel()
        if started is not None:
            started.cancel()        # stopped already unless the build failed while it waited
    return results


def _start_split_latex(tmp: Path, cache: Any) -> Any:
    """A rebuild's first xelatex pass, started on the preamble of the task's last build with that
    build's auxiliary files (:func:`latex_templates.build.start_split_passes`); None when the cache
    keeps no such build."""
    from latex_templates.build import BUILD_DIR, start_split_passes

    preamble = cache.tex_preamble()
    if preamble is None or not cache.restore_tex(tmp / BUILD_DIR):
        return None
    return start_split_passes(tmp / "report.tex", preamble)


def _start_cold_latex(project: Any, tmp: Path) -> Any:
    """A cold build's first xelatex pass, started before the solve on the preamble the note will
    have (:meth:`latex_templates.note.NoteBuilder.preamble`: the document's settings only), so that
    its ≈ 0.7 s run beside the solve and the sections instead of after report.tex is written; it
    goes on into the body only when report.tex's preamble is that text. None for a task without
    that note (the crane's has its own builder) or when the preamble cannot be made (the build
    then says why where it did before)."""
    from ..errors import ReportgenError

    task = project.task
    if getattr(task, "kind", "") == "crane" or (task.mechanism is None and task.gears is None
                                                 and task.planetary is None):
        return None
    from latex_templates import NoteBuilder
    from latex_templates.build import start_split_passes
    from latex_templates.render import Strings

    try:
        designation = Strings(task.document.language or "ru").designation(task.document)   # as _note_text's
        preamble = NoteBuilder(task.document, designation=designation).preamble()
    except ReportgenError:
        return None
    return None if preamble is None else start_split_passes(tmp / "report.tex", preamble, restored=False)


def _preamble(tex: Path) -> str | None:
    """The note's preamble through its line ``\\begin{document}`` (kept for the next rebuild)."""
    from latex_templates.passes import split_note

    try:
        parts = split_note(tex.read_text(encoding="utf-8"))
    except OSError:
        return None
    return parts[0] if parts is not None else None


def _shared_imports(project: Any) -> None:
    """Load what both the note and the sheets use (shapely, Jinja, the strings catalogue of the
    task's language) before the sheets' process is forked: the child inherits it instead of loading
    it a second time; the note would load it next anyway. What only one of them uses is loaded by
    that one after the fork, beside the other: matplotlib (≈ 0.3 s) by the note, ezdxf and the
    sheet modules (≈ 0.25 s) by the sheets (tests/speed/test_pipeline.py)."""
    import shapely.geometry  # noqa: F401

    from latex_templates.render import Strings
    Strings(project.task.document.language or "ru")


def _shared_stages(project: Any, cache: Any = None) -> None:
    """Compute before the fork the costly stages that both the note and a sheet read, so that the
    two processes do not each compute them: the meshing picture with its designations placed
    (≈ 0.2 s of CPU; section 4 and the gears' sheet, both made whenever the task has a gear pair).
    The note reads it anyway, so the main process does no more than it would; the cheaper scenes
    are left to whichever process reads them. Not when the build cache knows the picture's digest
    from the gear pair's (:meth:`reportgen.cache.BuildCache.scene_kept`): then section 4 and sheet
    4 are likely kept, and neither needs the picture."""
    if project.task.gears is not None and getattr(project.task, "kind", "") != "crane":
        if cache is not None and cache.scene_kept(project, "meshing"):
            return
        _ = project.scenes.meshing


def _sheet_list(project: Any) -> list[tuple[str, Any]]:
    from drawings.sheets import available_sheets
    return list(available_sheets(project))


def _note(project: Any, tmp: Path, timeline: Timeline, *, early: bool = False,
          cache: Any = None, started: Any = None) -> tuple[Path, Any]:
    """Compose the sections and write report.tex (once), then save the figures it refers to
    (split over two processes where there is a second processor).

    ``early`` (the passes driven directly, not by a latexmk the user named): xelatex's first pass
    starts before the figures are saved, on placeholders of their sizes (a figure kept by the
    build cache: its PDF), and goes on once they are (:mod:`latex_templates.passes`); with the
    auxiliary files of the task's last build restored from the cache and every figure of its
    placeholder's page box, that first pass is often the only one. ``started``: that first pass
    started already on the last build's preamble (:func:`_start_split_latex`), used when the
    note's preamble is the same, else stopped. Returned with report.tex, else None."""
    with timeline.stage("note: imports"):          # matplotlib, the parts (beside the sheets' own)
        _note_imports(project)
    from latex_templates.figures.saving import KeptFigure, queued
    from latex_templates.passes import media_box

    with queued(cache) as figures:
        tex = _note_text(project, tmp, timeline, cache, figures)
    pending = None
    split = None
    boxes: dict[Path, bytes | None] = {}
    from . import subset_cache
    if cache is not None and any(not isinstance(fig, KeptFigure) for fig, _ in figures.items):
        subset_cache.use(cache)                # a figure to save: its font subsets from the cache
    else:
        subset_cache.use(None)                 # (a process building again without the cache)
    try:
        if started is not None and early and started.note_written():
            pending = started                   # pass 1 has read its preamble
            timeline.latex_preamble_kept = started.restored
        elif started is not None:
            started.cancel()                    # another preamble: a pass on this note (aux files restored)
        if early and (len(figures) or pending is not None):
            if pending is None:
                if started is None or not started.restored:
                    _restore_latex(tex, cache)
                pending = _start_passes(tex)    # pass 1 reads its preamble meanwhile
            targets = [target for _, target in figures.items]
            with timeline.stage("note: figure sizes"):
                if parallel_possible():      # measured in two processes, each then saves its share
                    split = figures.start_split(_fork_figures_ready, cache)
                else:
                    figures.write_placeholders()
            boxes = {target: media_box(target) for target in targets}
            pending.placeholders_ready()
        with timeline.stage("note: figures"):
            if split is not None:
                split.finish()
            else:
                figures.save(fork=_fork_figures if parallel_possible() else None, cache=cache)
    except BaseException:
        if split is not None:
            split.cancel()
        if pending is not None:
            pending.cancel()
        raise
    if pending is not None:
        pending.figures_ready(same_boxes=all(box is not None and media_box(target) == box
                                             for target, box in boxes.items()))
    return tex, pending


def _note_imports(project: Any) -> None:
    """What the note's sections import — matplotlib with the note's style (≈ 0.35 s of CPU), the
    part modules of the document's sections, as ``compose`` would next — named as a stage of its
    own in the build's timeline."""
    import latex_templates.figures.saving  # noqa: F401
    from latex_templates.compose import DOCUMENT_SECTIONS, SECTIONS, part_module

    for _, parts in DOCUMENT_SECTIONS.get(getattr(project.task, "kind", "course-project"), SECTIONS):
        for name in parts:
            part_module(name)


def _restore_latex(tex: Path, cache: Any) -> None:
    """LaTeX's auxiliary files of the task's last build, when the cache keeps them."""
    from latex_templates.build import BUILD_DIR

    if cache is not None:
        cache.restore_tex(tex.parent / BUILD_DIR)


def _start_passes(tex: Path) -> Any:
    from latex_templates.build import start_passes

    try:
        return start_passes(tex, placeholders=False)
    except BuildError as exc:
        raise BuildError("LaTeX", exc.problem, exc.kept) from None


def _fork_figures(work: Any) -> "_Child":
    return _Child.fork(work, "note's figures")


def _fork_figures_ready(work: Any) -> "_Child":
    return _Child.fork(work, "note's figures", ready=True)


def _note_text(project: Any, tmp: Path, timeline: Timeline, cache: Any = None, queue: Any = None) -> Path:
    """Compose the sections (their figures drawn, queued for saving) and write report.tex. With
    the build cache, a section whose parts read what they read when it was kept is taken from it
    (:mod:`.note_cache`)."""
    from latex_templates import NoteBuilder
    from latex_templates.assignment import assignment_section, introduction_paragraphs
    from latex_templates.compose import compose
    from latex_templates.render import Strings

    if getattr(project.task, "kind", "") == "crane":       # the crane note (docs/crane.md)
        from latex_templates.parts.crane_document import note_builder
        with timeline.stage("note: sections"):
            return note_builder(project).render(tmp)
    with timeline.stage("note: sections"):
        strings = Strings(project.task.document.language or "ru")
        kept = None
        if cache is not None and queue is not None:
            from .note_cache import CachingNoteBuilder, KeptSections
            kept = KeptSections(cache, project, strings, queue)
        sections, left_out = compose(project, strings, kept=kept)
        options: dict[str, Any] = dict(designation=strings.designation(project.task.document),
                                       introduction=introduction_paragraphs(project, left_out),
                                       conclusions=[c for s in sections for c in s.conclusions],
                                       assignment=assignment_section(project))
        note = (NoteBuilder(project.task.document, **options) if kept is None
                else CachingNoteBuilder(project.task.document, kept=kept, **options))
        for s in sections:
            note.add_section(s.section)
        tex = note.render(tmp)
        if kept is not None:
            cache.sections_reused, cache.sections = len(kept.reused), len(sections)
        return tex


def _start_latex(tex: Path, latexmk: str, cache: Any) -> Any:
    from latex_templates.build import start_pdf

    if cache is not None:
        cache.restore_tex(tex.parent / "latex-build")
    try:
        return start_pdf(tex, latexmk=latexmk)
    except BuildError as exc:
        raise BuildError("LaTeX", exc.problem, exc.kept) from None


def draw_sheet(project: Any, mod: Any, number: int, count: int, trace: Any = None) -> Any:
    """Sheet ``number`` of ``count`` drawn by the sheet module ``mod``, in the task's language, with
    a view of the project that lets it read only the stages it declares in ``NEEDS`` (and, with a
    ``trace`` (:class:`reportgen.read_trace.Trace`), writes down what it reads)."""
    from drawings.words import language, use_catalogue
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings

    from ..read_trace import TracedNeeds

    use_catalogue(Strings)
    owner = f"sheet {mod.__name__}"
    view = Needs(project, mod.NEEDS, owner) if trace is None else TracedNeeds(project, mod.NEEDS, owner, trace)
    with language(project.task.document.language), \
            active_strings(Strings(project.task.document.language or "ru")):   # the sheet's words in the task's language
        return mod.draw(view, number, count)


#: Said of a sheet whose DXF and preview came from the build cache (its span's name ends so).
FROM_CACHE = " (from the cache)"


def sheet_identity(project: Any, mod: Any, stem: str, number: int, count: int) -> str:
    """What names a sheet in the build cache besides what it reads of the project: its module,
    file name, number and count, and the language it is drawn in (the code is added by the cache)."""
    return "|".join((mod.__name__, stem, str(number), str(count), project.task.document.language or "ru"))


def draw_sheets(project: Any, tmp: Path, todo: list[tuple[str, Any]], cache: Any = None, *,
                lane: str = SHEETS) -> Iterator[Span]:
    """Draw each sheet: the DXF, and its PNG preview from the document in memory (or the cache).
    With the cache, a sheet whose every read of the project (:mod:`reportgen.read_trace`) has the
    value it had when the cache kept it is copied, not drawn; its span's name ends in
    :data:`FROM_CACHE`."""
    from drawings.preview import render_png

    from ..read_trace import Trace

    folder = tmp / "sheets"
    folder.mkdir(exist_ok=True)
    for i, (stem, mod) in enumerate(todo, start=1):
        name = f"sheet {i}: {stem}"
        t0 = time.perf_counter()
        dxf = folder / f"{stem}.dxf"
        png = folder / f"{stem}.png"
        files = {"sheet.dxf": dxf, "sheet.png": png}
        identity = sheet_identity(project, mod, stem, i, len(todo))
        if cache is not None and cache.restore_sheet(identity, project, files):
            yield Span(name + FROM_CACHE, lane, t0, time.perf_counter())
            continue
        trace = Trace() if cache is not None else None
        sheet = draw_sheet(project, mod, i, len(todo), trace)
        sheet.save(dxf)
        if cache is None or not cache.restore_preview(dxf, png):
            render_png(sheet.doc, png, dpi=60)
            if cache is not None:
                cache.store_preview(dxf, png)
        if cache is not None and trace is not None and not trace.opaque:
            cache.store_sheet(identity, project, trace.reads, files)
        yield Span(name, lane, t0, time.perf_counter())


# -- child processes (the sheets, a share of the figures) ------------------------------------------

class _Child:
    """A forked process that does one part of the build (the sheets into ``tmp/sheets``, a share of
    the note's figures) and sends back its result, or the exception that stopped it (re-raised in
    the parent with its class and fields)."""

    def __init__(self, pid: int, fd: int, stage: str = "sheets", ready_fd: int | None = None) -> None:
        self.pid = pid
        self.fd = fd
        self.stage = stage
        self.ready_fd = ready_fd

    @classmethod
    def start(cls, project: Any, tmp: Path, todo: list[tuple[str, Any]] | None, cache: Any) -> "_Child":
        """Draw the sheets in a child process (``todo`` None: the sheets the task has, listed there)."""

        def work() -> list[Span]:
            # the sheets are off the critical path (solve → note → LaTeX): let the scheduler give
            # the note's processes and xelatex the processors first, the sheets the time left over
            _lower_priority(SHEETS_NICENESS)
            sheets = _sheet_list(project) if todo is None else todo
            return list(draw_sheets(project, tmp, sheets, cache)) if sheets else []

        return cls.fork(work, "sheets")

    @classmethod
    def fork(cls, work: Any, stage: str = "sheets", *, ready: bool = False) -> "_Child":
        """Run ``work()`` in a forked child; :meth:`join` returns its (picklable) result. With
        ``ready``, ``work(ready)`` gets a function to call when the parent may go on
        (:meth:`wait_ready` returns then, or when the child ends without calling it)."""
        r, w = os.pipe()
        ready_r, ready_w = os.pipe() if ready else (None, None)
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:  # pragma: no cover - the child (coverage does not follow a fork)
            os.close(r)
            status = 0
            try:
                signal.signal(signal.SIGINT, signal.SIG_DFL)
                try:
                    if ready_w is not None:
                        assert ready_r is not None
                        os.close(ready_r)
                        payload: tuple[str, Any] = ("ok", work(lambda: _say_ready(ready_w)))
                    else:
                        payload = ("ok", work())
                except BaseException as exc:  # noqa: BLE001 - everything goes back to the parent
                    payload = ("error", _portable(exc))
                data = pickle.dumps(payload)
                with os.fdopen(w, "wb") as f:
                    f.write(data)
            except BaseException:  # noqa: BLE001
                status = 1
            finally:
                os._exit(status)
        os.close(w)
        if ready_w is not None:
            os.close(ready_w)
        return cls(pid, r, stage, ready_r)

    def wait_ready(self) -> None:
        """Wait until the child calls ``ready()`` (see :meth:`fork`) or ends; an error it ended
        with is raised by :meth:`join`."""
        if self.ready_fd is not None:
            try:
                os.read(self.ready_fd, 1)
            finally:
                os.close(self.ready_fd)
                self.ready_fd = None

    def join(self) -> Any:
        self.wait_ready()
        with os.fdopen(self.fd, "rb") as f:
            data = f.read()
        _, status = os.waitpid(self.pid, 0)
        self.pid = 0
        if not data:
            raise BuildError(self.stage, f"the process working on the {self.stage} ended without a "
                                         f"result (wait status {status})")
        kind, value = pickle.loads(data)
        if kind == "ok":
            return value
        raise _rebuilt(value)

    def kill(self) -> None:
        if self.pid:
            try:
                os.kill(self.pid, signal.SIGTERM)
                os.waitpid(self.pid, 0)
            except (ProcessLookupError, ChildProcessError):
                pass
            for fd in (self.fd, self.ready_fd):
                try:
                    if fd is not None:
                        os.close(fd)
                except OSError:
                    pass
            self.ready_fd = None
            self.pid = 0


def _say_ready(fd: int) -> None:
    """The child's ``ready()``: one byte to the parent's :meth:`_Child.wait_ready`, once."""
    try:
        os.write(fd, b"1")
        os.close(fd)
    except OSError:
        pass


def _lower_priority(increment: int) -> None:
    try:
        os.nice(increment)
    except (AttributeError, OSError):   # no nice() on this system, or not allowed: same priority
        pass


def _portable(exc: BaseException) -> tuple[str, str, str, dict[str, Any]]:
    """An exception as (module, class, message, fields): reportgen's errors take their fields as
    constructor arguments, so they are rebuilt from these rather than unpickled."""
    fields = {}
    for k, v in vars(exc).items():
        try:
            pickle.dumps(v)
        except Exception:  # noqa: BLE001 - a field that cannot travel is left out
            continue
        fields[k] = v
    cls = type(exc)
    return cls.__module__, cls.__qualname__, str(exc), fields


def _rebuilt(value: tuple[str, str, str, dict[str, Any]]) -> BaseException:
    import importlib

    module, qualname, message, fields = value
    try:
        cls: Any = importlib.import_module(module)
        for part in qualname.split("."):
            cls = getattr(cls, part)
        exc = cls.__new__(cls)
        BaseException.__init__(exc, message)
        exc.__dict__.update(fields)
        return exc
    except Exception:  # noqa: BLE001
        return BuildError("sheets", f"{qualname}: {message}")
