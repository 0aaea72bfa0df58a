"""``reportgen build TASK -o OUT/``: the note (PDF + .tex + figures), the sheets (DXF + PNG) and
results.json.

Everything is written into a temporary folder beside OUT and moved into place at the end, so a
failure never leaves a half-written OUT. A failed LaTeX run keeps its folder as ``OUT.failed/`` (the
.tex and the log) and says where; bad input (exit 2) leaves nothing behind. Which folders OUT may
be (new, empty or an earlier reportgen output with its manifest) is ``outdir.py``'s rule.
"""
from __future__ import annotations

import argparse
import shutil
import tempfile
import time
import traceback
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import BuildError, ReportgenError, ReportgenInputError
from ..project import Project
from ..taskfile import load_task
from .outdir import check_output_folder, keep_failed, replace_folder
from .modes import as_made_ordinarily

if TYPE_CHECKING:
    from .pipeline import Timeline

ERROR_LOG = "error.log"  # in OUT.failed/ when a stage other than LaTeX failed


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


def _designation(task) -> str:
    """The designation of the note: [document] code with the language's suffix (« ПЗ»; docs/languages.md)."""
    from latex_templates.render import Strings
    return Strings(task.document.language or "ru").designation(task.document)


def build(task_path: str, out: Path, *, quiet: bool = False, pdf: bool = True, sheets: bool = True,
          latexmk: str = "latexmk", cache: bool = False, timeline: "Timeline | None" = None) -> dict[str, float]:
    """Build everything into ``out``; returns the time of each stage (``timeline`` gets the spans:
    what ran in parallel, see :mod:`reportgen.commands.pipeline`); ``cache``: read and write the
    build cache (:mod:`reportgen.cache`; the command line's default).

    ``out`` must pass the output-folder rule (:mod:`reportgen.commands.outdir`) before anything is
    written."""
    from latex_templates.jinja_cache import active as compiled_templates

    from .. import cache as build_cache
    from . import pipeline

    progress = timeline if timeline is not None else pipeline.Timeline(quiet)
    with progress.stage("task"):
        task = load_task(task_path)
    project = Project(task)
    out = check_output_folder(out, Path(task_path))
    store = build_cache.open_cache(task_path, pdf=pdf, sheets=sheets, latexmk=latexmk) if cache else None
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.parent))
    as_made_ordinarily(tmp, directory=True)
    try:
        with compiled_templates(store.root if store is not None else None):
            _build_into(tmp, project, progress, store, quiet=quiet, pdf=pdf, sheets=sheets, latexmk=latexmk)
    except ReportgenInputError:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    except BuildError as exc:
        failed = keep_failed(tmp, out)
        kept = (exc.kept or "").replace(str(tmp), str(failed)) or str(failed)
        raise BuildError(exc.stage, exc.problem.replace(str(tmp), str(failed)), kept) from None
    except Exception as exc:  # any other failure of a stage (a ReportgenError or a bug): keep what was made
        (tmp / ERROR_LOG).write_text(traceback.format_exc(), encoding="utf-8")
        failed = keep_failed(tmp, out)
        problem = str(exc) if isinstance(exc, ReportgenError) else f"{type(exc).__name__}: {exc}"
        raise BuildError(progress.current or "build", problem,
                         f"what was made, in {failed} ({ERROR_LOG}: the error and where it happened)") from None
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    replace_folder(tmp, out)
    return progress.times


def _build_into(tmp: Path, project: Project, progress: "Timeline", store, *, quiet: bool, pdf: bool,
                sheets: bool, latexmk: str) -> None:
    """The outputs into ``tmp``: from the cache when the task is unchanged, else built (and kept)."""
    from . import pipeline

    if store is not None and store.restore_build(tmp):
        progress.spans.append(pipeline.Span("from the cache", pipeline.MAIN, progress.origin, time.perf_counter()))
        if not quiet:
            print("  unchanged task: outputs from the cache", flush=True)
        return
    pipeline.run(project, tmp, progress, pdf=pdf, sheets=sheets, latexmk=latexmk, cache=store)
    if store is not None:
        store.store_build(tmp)
        if not quiet:
            print("  " + reuse_line(store, progress), flush=True)


def reuse_line(store, progress: "Timeline") -> str:
    """What a build with the cache took from it: «figures: N from the cache, M saved and kept;
    sections: J of T from the cache; sheets: K of S from the cache; xelatex passes: P», the passes
    followed by «(the first begun on the kept preamble)» when pass 1 read the last build's preamble
    before the note was written (docs/build.md)."""
    from .pipeline import FROM_CACHE

    sheets = [s for s in progress.spans if s.name.startswith("sheet ")]
    reused = sum(s.name.endswith(FROM_CACHE) for s in sheets)
    passes = f"; xelatex passes: {progress.latex_passes}" if progress.latex_passes else ""
    if passes and progress.latex_preamble_kept:
        passes += " (the first begun on the kept preamble)"
    sections = f"sections: {store.sections_reused} of {store.sections} from the cache; " if store.sections else ""
    return (f"figures: {store.figures_reused} from the cache, {store.figures_saved} saved and kept; "
            f"{sections}sheets: {reused} of {len(sheets)} from the cache{passes}")


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
