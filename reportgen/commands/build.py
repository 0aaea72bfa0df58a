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
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import BuildError, OptionError, ReportgenInputError
from ..project import Project
from ..taskfile import load_task

if TYPE_CHECKING:
    from .pipeline import Timeline


def register(sub) -> None:
    p = sub.add_parser("build", help="build the note (PDF), the sheets (DXF + PNG) and results.json")
    p.add_argument("task", help="the task file (TOML)")
    p.add_argument("-o", "--out", required=True, metavar="OUT", help="output folder (replaced as a whole)")
    p.add_argument("--quiet", action="store_true", help="no progress on stdout")
    p.add_argument("--no-pdf", action="store_true", help="write report.tex and figures but do not run LaTeX")
    p.add_argument("--no-sheets", action="store_true", help="do not draw the DXF sheets")
    p.add_argument("--latexmk", default="latexmk", help="the latexmk program (default: latexmk)")
    p.add_argument("--no-cache", action="store_true",
                   help="neither read nor write the build cache (default: $XDG_CACHE_HOME/reportgen)")
    p.add_argument("--watch", action="store_true",
                   help="build, then rebuild whenever the task file changes (Ctrl-C ends)")
    p.set_defaults(func=run)


def build(task_path: str, out: Path, *, quiet: bool = False, pdf: bool = True, sheets: bool = True,
          latexmk: str = "latexmk", cache: bool = False, timeline: "Timeline | None" = None) -> dict[str, float]:
    """Build everything into ``out``; returns the time of each stage (``timeline`` gets the spans:
    what ran in parallel, see :mod:`reportgen.commands.pipeline`); ``cache``: read and write the
    build cache (:mod:`reportgen.cache`; the command line's default)."""
    from .. import cache as build_cache
    from . import pipeline

    progress = timeline if timeline is not None else pipeline.Timeline(quiet)
    with progress.stage("task"):
        task = load_task(task_path)
    project = Project(task)
    out = out.resolve()
    parent = out.parent
    if not parent.is_dir():
        raise OptionError("--out", f"the folder {parent} does not exist", "a path in an existing folder")
    store = build_cache.open_cache(task_path, pdf=pdf, sheets=sheets, latexmk=latexmk) if cache else None
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".tmp", dir=parent))
    try:
        if store is not None and store.restore_build(tmp):
            progress.spans.append(pipeline.Span("from the cache", pipeline.MAIN, progress.origin, time.perf_counter()))
            if not quiet:
                print("  unchanged task: outputs from the cache", flush=True)
        else:
            pipeline.run(project, tmp, progress, pdf=pdf, sheets=sheets, latexmk=latexmk, cache=store)
            if store is not None:
                store.store_build(tmp)
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
    if args.watch:
        from .watch import watch
        return watch(args, build)
    build(args.task, out, quiet=args.quiet, pdf=not args.no_pdf, sheets=not args.no_sheets, latexmk=args.latexmk,
          cache=not args.no_cache)
    if not args.quiet:
        made = (["report.pdf"] if not args.no_pdf else ["report.tex"]) + ([] if args.no_sheets else ["sheets/"])
        print(f"done in {time.perf_counter() - t0:.1f} s: " + ", ".join(f"{out}/{m}" for m in made + ["results.json"]))
    return 0
