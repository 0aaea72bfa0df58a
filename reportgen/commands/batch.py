"""``reportgen batch``: a teacher's run over many variants.

    reportgen batch --table T [--variants 1,3-5] [--answers] -o OUT [-j N]
    reportgen batch --tasks DIR   [--answers] -o OUT [-j N]     every *.toml of DIR
    reportgen batch --csv FILE    [--answers] -o OUT [-j N]     rows "table,variant"

Each variant is one job in a pool of processes (``-j``, default: the core count); a live progress
line shows done/total, failures and the time left. A failing variant is reported in the summary and
never stops the others (exit 1 if any failed). OUT gets ``answers.csv`` (one row per variant), a
one-page answer key per table (``answer-key-table-T.pdf``; ``answer-key.pdf`` for task folders) and,
without ``--answers``, each variant's full build in ``OUT/<name>/``. A re-run skips the variants whose
inputs did not change (their hash is kept in ``OUT/reportgen-batch.json``, the manifest).

OUT must be new, empty or an earlier batch output (the manifest): reportgen writes only files the
manifest lists and never deletes a file it did not write.
"""
from __future__ import annotations

import argparse
import csv
import hashlib
import io
import json
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path

from .. import __version__
from ..errors import OptionError, ReportgenError
from .solve import write_atomic

MANIFEST = "reportgen-batch.json"


def register(sub) -> None:
    p = sub.add_parser("batch", help="answer keys (and notes) for many variants, in parallel")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--table", type=int, metavar="T", help="a control-work table 1…22 (or 0: all tables)")
    src.add_argument("--tasks", metavar="DIR", help="a folder of task files (*.toml)")
    src.add_argument("--csv", metavar="FILE", help='a CSV of variants: columns "table" and "variant"')
    p.add_argument("--variants", metavar="LIST", help="with --table: e.g. 1,3-5 (default: all ten)")
    p.add_argument("--answers", action="store_true", help="only the answer keys (no notes, no sheets)")
    p.add_argument("-o", "--out", required=True, metavar="OUT", help="output folder")
    p.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1, metavar="N",
                   help="processes (default: the core count)")
    p.add_argument("--quiet", action="store_true", help="no progress line")
    p.set_defaults(func=run)


@dataclass(frozen=True)
class Job:
    name: str                 # e.g. "t01-v03" or a task file's stem
    table: int | None
    variant: int | None
    text: str | None          # the task text; None when the variant cannot be built (see error)
    error: str | None = None

    def key(self, answers_only: bool) -> str:
        h = hashlib.sha256()
        h.update(f"{__version__}|{answers_only}|{self.table}|{self.variant}|".encode())
        h.update((self.text or self.error or "").encode())
        return h.hexdigest()


@dataclass
class Outcome:
    name: str
    row: dict | None = None
    error: str | None = None
    files: list[str] = field(default_factory=list)


def parse_variants(text: str | None) -> list[int]:
    if not text:
        return list(range(1, 11))
    out: list[int] = []
    try:
        for part in text.split(","):
            a, _, b = part.strip().partition("-")
            out += list(range(int(a), int(b or a) + 1))
    except ValueError:
        raise OptionError("--variants", f"got {text!r}", "numbers 1…10 and ranges, e.g. 1,3-5") from None
    if not out or any(not 1 <= v <= 10 for v in out):
        raise OptionError("--variants", f"got {text!r}", "numbers 1…10 and ranges, e.g. 1,3-5")
    return list(dict.fromkeys(out))


def variant_job(t: int, v: int) -> Job:
    from ..control.sketch import VariantGeometryError
    from ..control.tables import table
    from ..control.task_text import task_text
    from .new import task_words
    tab = table(t)
    var = tab.variant(v)
    name = f"t{t:02d}-v{v:02d}"
    if var.flag:
        return Job(name, t, v, None, f"cannot form the mechanism: {var.flag}")
    try:
        return Job(name, t, v, task_text(tab, var, words=task_words("ru", t, v)))
    except VariantGeometryError as exc:
        return Job(name, t, v, None, str(exc))


def collect_jobs(args) -> list[Job]:
    if args.table is not None:
        from ..control.tables import tables
        nums = [t.number for t in tables()] if args.table == 0 else [args.table]
        if args.table != 0 and not 1 <= args.table <= len(tables()):
            raise OptionError("--table", f"got {args.table}", f"a table 1…{len(tables())}, or 0 for all")
        return [variant_job(t, v) for t in nums for v in parse_variants(args.variants)]
    if args.variants:
        raise OptionError("--variants", "given without --table", "--table T --variants LIST")
    if args.tasks is not None:
        d = Path(args.tasks)
        if not d.is_dir():
            raise OptionError("--tasks", f"{d} is not a folder", "a folder of task files (*.toml)")
        files = sorted(d.glob("*.toml"))
        if not files:
            raise OptionError("--tasks", f"{d} holds no *.toml", "a folder of task files")
        return [Job(f.stem, None, None, f.read_text(encoding="utf-8")) for f in files]
    path = Path(args.csv)
    if not path.is_file():
        raise OptionError("--csv", f"{path} is not a file", 'a CSV with columns "table" and "variant"')
    jobs = []
    with path.open(encoding="utf-8", newline="") as f:
        reader = csv.DictReader(f)
        if not reader.fieldnames or not {"table", "variant"} <= set(reader.fieldnames):
            raise OptionError("--csv", f"columns {reader.fieldnames}", 'a header with "table" and "variant"')
        for i, r in enumerate(reader, start=2):
            try:
                t, v = int(r["table"]), int(r["variant"])
            except (TypeError, ValueError):
                raise OptionError("--csv", f"line {i}: {r}", "integer table and variant") from None
            if not 1 <= v <= 10:
                raise OptionError("--csv", f"line {i}: variant {v}", "a variant 1…10")
            jobs.append(variant_job(t, v))
    return jobs


def run_job(job: Job, out: str, answers_only: bool) -> Outcome:
    """One variant: its answers row and, unless ``answers_only``, its full build in ``out/<name>``."""
    if job.text is None:
        return Outcome(job.name, error=job.error)
    try:
        from ..control.analysis import control_work_of
        from ..project import Project
        from ..taskfile import loads_task
        task = loads_task(job.text, source=job.name)
        res = control_work_of(Project(task))
        cw = task.control_work
        row = {"name": job.name, "table": job.table or (cw.table if cw and cw.table else ""),
               "variant": job.variant or (cw.variant if cw and cw.variant else ""), **res.answers()}
        files: list[str] = []
        if not answers_only:
            import tempfile
            from .build import build
            with tempfile.TemporaryDirectory() as tmpd:
                tp = Path(tmpd) / f"{job.name}.toml"
                tp.write_text(job.text, encoding="utf-8")
                build(str(tp), Path(out) / job.name, quiet=True)
            (Path(out) / job.name / "task.toml").write_text(job.text, encoding="utf-8")
            files.append(job.name + "/")
        return Outcome(job.name, row=row, files=files)
    except ReportgenError as exc:
        return Outcome(job.name, error=str(exc))
    except Exception as exc:       # one variant's failure never stops the others
        return Outcome(job.name, error=f"{type(exc).__name__}: {exc}")


def _check_out(out: Path) -> dict:
    """The earlier manifest of OUT, or {} for a new/empty folder; refuse anything else."""
    if out.exists() and not out.is_dir():
        raise OptionError("-o", f"{out} is a file", "a new folder, an empty one, or an earlier batch output")
    if not out.exists():
        if not out.parent.is_dir():
            raise OptionError("-o", f"the folder {out.parent} does not exist", "a path in an existing folder")
        return {}
    m = out / MANIFEST
    if m.is_file():
        try:
            return json.loads(m.read_text(encoding="utf-8"))
        except ValueError:
            raise OptionError("-o", f"{m} is not a reportgen manifest", "a new or empty folder") from None
    if any(out.iterdir()):
        raise OptionError("-o", f"{out} holds files reportgen did not write (no {MANIFEST})",
                          "a new folder, an empty one, or an earlier batch output")
    return {}


class ProgressLine:
    """``[done/total] failures: k, ETA s`` rewritten in place on stderr."""

    def __init__(self, total: int, quiet: bool):
        self.total, self.quiet, self.t0 = total, quiet, time.perf_counter()
        self.done = self.failed = 0

    def step(self, failed: bool) -> None:
        self.done += 1
        self.failed += failed
        if self.quiet:
            return
        dt = time.perf_counter() - self.t0
        eta = dt / self.done * (self.total - self.done)
        sys.stderr.write(f"\r  [{self.done}/{self.total}] failures: {self.failed}, ETA {eta:.0f} s   ")
        sys.stderr.flush()

    def end(self) -> None:
        if not self.quiet:
            sys.stderr.write("\n")


def rows_csv(rows: list[dict]) -> str:
    cols: list[str] = []
    for r in rows:
        cols += [k for k in r if k not in cols]
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=cols, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    return buf.getvalue()


def batch(jobs: list[Job], out: Path, *, answers_only: bool, workers: int, quiet: bool = False) -> list[Outcome]:
    old = _check_out(out)
    out.mkdir(exist_ok=True)
    cached = old.get("jobs", {}) if old.get("answers_only") == answers_only or answers_only else {}
    todo, outcomes = [], {}
    for j in jobs:
        c = cached.get(j.name)
        if c and c.get("key") == j.key(answers_only) and (c.get("row") or c.get("error")) and \
                all((out / f).exists() for f in c.get("files", [])):
            outcomes[j.name] = Outcome(j.name, row=c.get("row"), error=c.get("error"), files=c.get("files", []))
        else:
            todo.append(j)
    progress = ProgressLine(len(jobs), quiet)
    for _ in outcomes:
        progress.step(False)
    if workers <= 1 or len(todo) <= 1:
        for j in todo:
            o = run_job(j, str(out), answers_only)
            outcomes[j.name] = o
            progress.step(o.error is not None)
    else:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            futs = {pool.submit(run_job, j, str(out), answers_only): j for j in todo}
            for f in as_completed(futs):
                o = f.result()
                outcomes[o.name] = o
                progress.step(o.error is not None)
    progress.end()
    ordered = [outcomes[j.name] for j in jobs]
    rows = [o.row for o in ordered if o.row]
    written = set(old.get("written", []))
    write_atomic(str(out / "answers.csv"), rows_csv(rows), option="-o")
    written.add("answers.csv")
    from .answer_key import write_keys
    written |= set(write_keys(ordered, jobs, out))
    manifest = {"reportgen": __version__, "answers_only": answers_only,
                "written": sorted(written | {f for o in ordered for f in o.files}),
                "jobs": {**old.get("jobs", {}),
                         **{j.name: {"key": j.key(answers_only), "row": o.row, "error": o.error, "files": o.files}
                            for j, o in zip(jobs, ordered)}}}
    write_atomic(str(out / MANIFEST), json.dumps(manifest, ensure_ascii=False, indent=1) + "\n", option="-o")
    return ordered


def run(args: argparse.Namespace) -> int:
    if args.jobs < 1:
        raise OptionError("-j", f"got {args.jobs}", "a number of processes ≥ 1")
    jobs = collect_jobs(args)
    t0 = time.perf_counter()
    out = Path(args.out)
    outcomes = batch(jobs, out, answers_only=args.answers, workers=args.jobs, quiet=args.quiet)
    failed = [o for o in outcomes if o.error]
    print(f"{len(outcomes) - len(failed)} of {len(outcomes)} variants done in {time.perf_counter() - t0:.1f} s "
          f"→ {out}/answers.csv")
    for o in failed:
        print(f"  failed: {o.name}: {o.error}")
    return 1 if failed else 0
