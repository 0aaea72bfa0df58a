"""``reportgen build TASK -o OUT/``: the note (PDF + .tex + figures), the sheets (DXF + PNG) and
results.json.

Everything is written into a temporary folder beside OUT and moved into place at the end, so a
failure never leaves a half-written OUT. A failed LaTeX run keeps its folder as ``OUT.failed/`` (the
.tex and the log) and says where; bad input (exit 2) leaves nothing behind.
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path

from ..errors import BuildError, OptionError, ReportgenInputError
from ..project import Project
from ..results import build_results, dumps
from ..taskfile import load_task


def register(sub) -> None:
    p = sub.add_parser("build", help="build the note (PDF), the sheets (DXF + PNG) and results.json")
    p.add_argument("task", help="the task file (TOML)")
    p.add_argument("-o", "--out", required=True, metavar="OUT", help="output folder (replaced as a whole)")
    p.add_argument("--quiet", action="store_true", help="no progress on stdout")
    p.add_argument("--no-pdf", action="store_true", help="write report.tex and figures but do not run LaTeX")
    p.add_argument("--no-sheets", action="store_true", help="do not draw the DXF sheets")
    p.add_argument("--latexmk", default="latexmk", help="the latexmk program (default: latexmk)")
    p.set_defaults(func=run)


class Progress:
    """Prints each stage with the time it took."""

    def __init__(self, quiet: bool):
        self.quiet = quiet
        self.times: dict[str, float] = {}

    @contextmanager
    def stage(self, name: str):
        t0 = time.perf_counter()
        if not self.quiet:
            print(f"  {name} …", end="", flush=True)
        try:
            yield
        except BaseException:
            if not self.quiet:
                print(" failed", flush=True)
            raise
        dt = time.perf_counter() - t0
        self.times[name] = dt
        if not self.quiet:
            print(f" {dt:.2f} s", flush=True)


def _designation(task) -> str:
    return "ТММ.КП.00.00.000 ПЗ"


def build(task_path: str, out: Path, *, quiet: bool = False, pdf: bool = True, sheets: bool = True,
          latexmk: str = "latexmk") -> dict[str, float]:
    """Build everything into ``out``; returns the time of each stage."""
    progress = Progress(quiet)
    with progress.stage("task"):
        task = load_task(task_path)
    project = Project(task)
    out = out.resolve()
    parent = out.parent
    if not parent.is_dir():
        raise OptionError("--out", f"the folder {parent} does not exist", "a path in an existing folder")
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".tmp", dir=parent))
    try:
        with progress.stage("solve"):
            results = build_results(project)
        if task.mechanism is not None or task.gears is not None or task.planetary is not None:
            _note(project, tmp, progress, pdf, latexmk)
        if sheets:
            _sheets(project, tmp, progress)
        (tmp / "results.json").write_text(dumps(results), encoding="utf-8")
    except BuildError as exc:
        failed = out.with_name(out.name + ".failed")
        shutil.rmtree(failed, ignore_errors=True)
        tmp.rename(failed)
        kept = (exc.kept or "").replace(str(tmp), str(failed)) or str(failed)
        raise BuildError(exc.stage, exc.problem.replace(str(tmp), str(failed)), kept) from None
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    _replace_dir(tmp, out)
    return progress.times


def _note(project: Project, tmp: Path, progress: Progress, pdf: bool, latexmk: str) -> None:
    from latex_templates import NoteBuilder
    from latex_templates.assignment import assignment_section, introduction_paragraphs
    from latex_templates.compose import compose

    with progress.stage("note: sections and figures"):
        from latex_templates.render import Strings
        sections, left_out = compose(project, Strings(project.task.document.language or "ru"))
        note = NoteBuilder(project.task.document, designation=_designation(project.task),
                           introduction=introduction_paragraphs(project, left_out),
                           conclusions=[c for s in sections for c in s.conclusions],
                           assignment=assignment_section(project))
        for s in sections:
            note.add_section(s.section)
        note.render(tmp)
    if pdf:
        with progress.stage("note: LaTeX"):
            try:
                note.build(tmp, latexmk=latexmk)
            except BuildError as exc:
                raise BuildError("LaTeX", exc.problem, exc.kept) from None


def _sheets(project: Project, tmp: Path, progress: Progress) -> None:
    from drawings.preview import render_png
    from drawings.sheets import available_sheets

    from ..project import Needs

    todo = available_sheets(project)
    if not todo:
        return
    folder = tmp / "sheets"
    folder.mkdir()
    for i, (stem, mod) in enumerate(todo, start=1):
        with progress.stage(f"sheet {i}: {stem}"):
            sheet = mod.draw(Needs(project, mod.NEEDS, f"sheet {mod.__name__}"), i, len(todo))
            dxf = folder / f"{stem}.dxf"
            sheet.save(dxf)
            render_png(dxf, folder / f"{stem}.png", dpi=60)


def _replace_dir(tmp: Path, out: Path) -> None:
    """Move ``tmp`` to ``out``, replacing an old ``out`` only once the new one is complete."""
    old = None
    if out.exists():
        old = out.with_name(f".{out.name}.old-{os.getpid()}")
        out.rename(old)
    tmp.rename(out)
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)


def run(args: argparse.Namespace) -> int:
    out = Path(args.out)
    if not args.quiet:
        print(f"reportgen build {args.task} → {out}/")
    t0 = time.perf_counter()
    build(args.task, out, quiet=args.quiet, pdf=not args.no_pdf, sheets=not args.no_sheets, latexmk=args.latexmk)
    if not args.quiet:
        made = (["report.pdf"] if not args.no_pdf else ["report.tex"]) + ([] if args.no_sheets else ["sheets/"])
        print(f"done in {time.perf_counter() - t0:.1f} s: " + ", ".join(f"{out}/{m}" for m in made + ["results.json"]))
    return 0
