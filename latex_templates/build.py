"""Compile ``report.tex`` with latexmk + xelatex, reproducibly, and report what went wrong.

The PDF is reproducible: ``SOURCE_DATE_EPOCH`` (and ``FORCE_SOURCE_DATE``) fix every date
xelatex and xdvipdfmx write. Auxiliary files go to ``<out>/latex-build/``; the PDF is copied to
``<out>/report.pdf``. Errors are :class:`reportgen.errors.BuildError` with the ``!`` lines of the
log and the ``l.<n>`` context, and say where the .tex and .log are kept.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

from reportgen.errors import BuildError

from .passes import PASS_LINE

STAGE = "note (LaTeX)"
APT_INSTALL = ("sudo apt-get install texlive-latex-recommended texlive-lang-cyrillic "
               "texlive-xetex texlive-fonts-recommended latexmk fonts-liberation")
DEFAULT_SOURCE_DATE_EPOCH = "1767225600"   # 2026-01-01 00:00 UTC, when the caller sets none
BUILD_DIR = "latex-build"

_UNDEFINED_RE = re.compile(
    r"(LaTeX Warning: (Reference|Citation) .* undefined.*"
    r"|LaTeX Warning: There were undefined references.*"
    r"|LaTeX Warning: Label\(s\) may have changed.*)")
_MISSING_CHAR_RE = re.compile(r"Missing character: There is no .*")


@dataclass(frozen=True)
class BuildReport:
    """A finished build: where the files are, how long latexmk took, what it warned about."""
    pdf: Path
    tex: Path
    log: Path
    seconds: float
    warnings: tuple[str, ...] = ()
    passes: int = 0          # xelatex passes run (as the driver or latexmk reports them)


def build_pdf(tex_path: Path | str, *, latexmk: str = "latexmk", strict_references: bool = True,
              source_date_epoch: str | None = None) -> BuildReport:
    """Compile ``tex_path`` to a PDF next to it. Raise BuildError when TeX is missing or fails.

    ``strict_references``: unresolved references or citations are an error (else a warning).
    """
    return start_pdf(tex_path, latexmk=latexmk, strict_references=strict_references,
                     source_date_epoch=source_date_epoch).wait()


class PendingPdf:
    """latexmk running in the background (started by :func:`start_pdf`); :meth:`wait` joins it and
    checks the result as :func:`build_pdf` does. Python may draw other outputs meanwhile."""

    def __init__(self, tex: Path, proc: subprocess.Popen, strict_references: bool) -> None:
        self.tex = tex
        self.proc = proc
        self.strict_references = strict_references
        self.started = time.perf_counter()
        self._report: BuildReport | None = None

    def cancel(self) -> None:
        """Stop latexmk (and its xelatex) when the build fails elsewhere."""
        if self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, 15)
            except (ProcessLookupError, PermissionError):
                pass
            self.proc.wait()

    def wait(self) -> BuildReport:
        if self._report is not None:
            return self._report
        try:
            out, err = self.proc.communicate()
        except BaseException:
            self.cancel()
            raise
        seconds = time.perf_counter() - self.started
        tex, work = self.tex, self.tex.parent
        build_dir = work / BUILD_DIR
        log = build_dir / (tex.stem + ".log")
        log_text = log.read_text(encoding="utf-8", errors="replace") if log.is_file() else ""
        built = build_dir / (tex.stem + ".pdf")
        if self.proc.returncode != 0 or not built.is_file():
            excerpt = error_excerpt(log_text) or ((out or "") + (err or ""))[-2000:]
            raise BuildError(STAGE, f"xelatex stopped on an error:\n{excerpt}",
                             kept=f"the LaTeX source {tex} and the log {log}")
        undefined = sorted(set(m.group(0).strip() for m in _UNDEFINED_RE.finditer(log_text)))
        warnings = [m.group(0).strip() for m in _MISSING_CHAR_RE.finditer(log_text)]
        if undefined and self.strict_references:
            raise BuildError(STAGE, "unresolved references:\n" + "\n".join(undefined),
                             kept=f"the LaTeX source {tex}, the PDF {built} and the log {log}")
        warnings += undefined
        pdf = work / (tex.stem + ".pdf")
        shutil.copyfile(built, pdf)
        passes = sum(line.strip() == PASS_LINE or "of rule 'xelatex'" in line
                     for line in ((out or "") + "\n" + (err or "")).splitlines())
        self._report = BuildReport(pdf=pdf, tex=tex, log=log, seconds=seconds, warnings=tuple(warnings),
                                   passes=passes)
        return self._report


def start_pdf(tex_path: Path | str, *, latexmk: str = "latexmk", strict_references: bool = True,
              source_date_epoch: str | None = None) -> PendingPdf:
    """Start compiling ``tex_path`` (latexmk + xelatex, in its own process group) and return at once.

    An existing ``latex-build/`` beside the .tex (aux, toc, fdb of an earlier build of the same note)
    is reused: latexmk then runs only the passes the changes need.
    """
    tex = Path(tex_path).resolve()
    work = tex.parent
    exe = shutil.which(latexmk)
    if exe is None or shutil.which("xelatex") is None:
        missing = latexmk if exe is None else "xelatex"
        raise BuildError(STAGE, f"no TeX: '{missing}' was not found; install TeX Live with: "
                                f"{APT_INSTALL}", kept=f"the LaTeX source {tex}")
    build_dir = work / BUILD_DIR
    build_dir.mkdir(exist_ok=True)
    _write_provisional_toc(tex, build_dir)
    env = tex_env(source_date_epoch)
    cmd = [exe, "-xelatex", "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape",
           f"-outdir={BUILD_DIR}", tex.name]
    proc = subprocess.Popen(cmd, cwd=work, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, errors="replace", start_new_session=True)
    return PendingPdf(tex, proc, strict_references)


class PendingPasses(PendingPdf):
    """xelatex's first pass running on placeholder figures (:mod:`latex_templates.passes`);
    :meth:`figures_ready` lets it go on with the real ones; :meth:`wait` as for latexmk.
    ``preamble``: the preamble a split first pass reads (:func:`start_split_passes`), before the
    note is written (:meth:`note_written`); ``restored``: the last build's (its auxiliary files
    restored), else the one a cold build's note will have."""

    def __init__(self, tex: Path, proc: subprocess.Popen, strict_references: bool,
                 preamble: str | None = None, restored: bool = True) -> None:
        super().__init__(tex, proc, strict_references)
        self.preamble = preamble
        self.restored = restored     # a split pass on the last build's preamble and auxiliary files

    def note_written(self) -> bool:
        """The note is written: for a split first pass, write its body for the pass when its
        preamble is the one the pass reads; False when it is not (the caller cancels this pass
        and starts one on the note as it is). True at once for a pass on the whole note."""
        from .passes import BODY_FILE, split_note

        if self.preamble is None:
            return True
        parts = split_note(self.tex.read_text(encoding="utf-8"))
        if parts is None or parts[0] != self.preamble:
            return False
        build_dir = self.tex.parent / BUILD_DIR
        _write_provisional_toc(self.tex, build_dir)      # a cold build's (no .aux): before the body is read
        body = build_dir / BODY_FILE
        part = body.with_name(body.name + ".part")
        part.write_text(parts[1], encoding="utf-8")
        part.replace(body)
        return True

    def cancel(self) -> None:
        super().cancel()
        if self.preamble is not None:        # the split pass's files, when it was stopped before it ended
            from .passes import BODY_FILE, PREAMBLE_FILE

            for name in (PREAMBLE_FILE, BODY_FILE):
                (self.tex.parent / BUILD_DIR / name).unlink(missing_ok=True)

    def placeholders_ready(self) -> None:
        """The figures' placeholders are written: pass 1, its preamble read meanwhile, may go on
        into the document's body (:data:`latex_templates.passes.PLACEHOLDERS`)."""
        from .passes import PLACEHOLDERS

        stdin = self.proc.stdin
        if stdin is None:
            return
        try:
            stdin.write(PLACEHOLDERS.decode())
            stdin.flush()
        except (BrokenPipeError, OSError):   # the first pass failed already: wait() says why
            pass

    def figures_ready(self, same_boxes: bool = False) -> None:
        """The figures are saved; ``same_boxes``: each has its placeholder's page box, so that a
        first pass that left the auxiliary files as it found them is the last
        (:data:`latex_templates.passes.SAME_BOXES`)."""
        from .passes import FIGURES_REAL, SAME_BOXES

        stdin = self.proc.stdin
        if stdin is None:
            return
        try:
            stdin.write((SAME_BOXES if same_boxes else FIGURES_REAL).decode())
            stdin.close()
        except (BrokenPipeError, OSError):   # the first pass failed already: wait() says why
            pass
        self.proc.stdin = None


def start_passes(tex_path: Path | str, *, strict_references: bool = True,
                 source_date_epoch: str | None = None, placeholders: bool = True) -> PendingPasses:
    """Start the first xelatex pass of a cold build now, on the figures' placeholders (see
    :mod:`latex_templates.passes`); the passes after it wait for :meth:`PendingPasses.figures_ready`
    once stable on the placeholders. ``placeholders=False``: they are not written yet; pass 1 reads
    its preamble meanwhile and waits for :meth:`PendingPasses.placeholders_ready` at
    ``\\begin{document}``. Raise BuildError when TeX is missing."""
    import sys

    tex = Path(tex_path).resolve()
    work = tex.parent
    for program in ("xelatex", "xdvipdfmx"):
        if shutil.which(program) is None:
            raise BuildError(STAGE, f"no TeX: '{program}' was not found; install TeX Live with: "
                                    f"{APT_INSTALL}", kept=f"the LaTeX source {tex}")
    build_dir = work / BUILD_DIR
    build_dir.mkdir(exist_ok=True)
    _write_provisional_toc(tex, build_dir)
    driver = Path(__file__).with_name("passes.py")      # by path: no package import, stdlib only
    proc = subprocess.Popen([sys.executable, str(driver), tex.name, BUILD_DIR], cwd=work,
                            env=tex_env(source_date_epoch), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, errors="replace", start_new_session=True)
    pending = PendingPasses(tex, proc, strict_references)
    if placeholders:
        pending.placeholders_ready()
    return pending


def start_split_passes(tex_path: Path | str, preamble: str, *, strict_references: bool = True,
                       source_date_epoch: str | None = None, restored: bool = True) -> PendingPasses | None:
    """Start a first xelatex pass before its note is written, on ``preamble`` (ending with the line
    ``\\begin{document}``): a rebuild's, on the last build's preamble with the auxiliary files of
    that build restored in ``latex-build/`` already; with ``restored=False``, a cold build's, on
    the preamble the note will have (:meth:`latex_templates.note.NoteBuilder.preamble`) and no
    auxiliary files. It reads the preamble (≈ 0.7 s of a pass) while the note is composed, then
    waits. :meth:`PendingPasses.note_written` gives it the note's body when the note's preamble is
    the same (and, with no auxiliary files, writes the provisional contents first); the passes
    then go on as :func:`start_passes`'s. None when TeX is missing (the build's ordinary start says
    so) or the names do not allow a split pass."""
    import sys

    from .passes import PREAMBLE_FILE, first_pass_command, split_stub

    tex = Path(tex_path).resolve()
    work = tex.parent
    build_dir = work / BUILD_DIR
    if (any(shutil.which(program) is None for program in ("xelatex", "xdvipdfmx"))
            or first_pass_command(tex.name, BUILD_DIR, split=True) is None
            or (restored and not (build_dir / (tex.stem + ".aux")).is_file())):
        return None
    build_dir.mkdir(exist_ok=True)
    (build_dir / PREAMBLE_FILE).write_text(split_stub(preamble, BUILD_DIR), encoding="utf-8")
    driver = Path(__file__).with_name("passes.py")
    proc = subprocess.Popen([sys.executable, str(driver), tex.name, BUILD_DIR, "--split"], cwd=work,
                            env=tex_env(source_date_epoch), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, errors="replace", start_new_session=True)
    return PendingPasses(tex, proc, strict_references, preamble, restored)


def _write_provisional_toc(tex: Path, build_dir: Path) -> None:
    if not (build_dir / (tex.stem + ".aux")).exists():
        toc = provisional_toc(tex.read_text(encoding="utf-8"))
        if toc.strip():
            (build_dir / (tex.stem + ".toc")).write_text(toc, encoding="utf-8")


def tex_env(source_date_epoch: str | None) -> dict[str, str]:
    """The environment of xelatex and xdvipdfmx: every date they write fixed (reproducible bytes)."""
    env = dict(os.environ)
    env["SOURCE_DATE_EPOCH"] = source_date_epoch or env.get("SOURCE_DATE_EPOCH", DEFAULT_SOURCE_DATE_EPOCH)
    env["FORCE_SOURCE_DATE"] = "1"
    return env


_HEADING_RE = re.compile(r"\\(notestructheading|section|subsection|subsubsection)\{")


def provisional_toc(tex_text: str) -> str:
    """A table of contents with the note's headings and placeholder page numbers, written before
    the first xelatex pass of a cold build.

    Without it the first pass typesets an empty contents page, every later page moves when the
    contents appear, and latexmk needs three passes; with it the first pass already paginates
    as the last one, so the second pass (page numbers filled in) is also the confirming one.
    It is only a head start: latexmk still reruns until the auxiliary files stop changing, so
    the PDF is the same whatever this guesses.
    """
    body = tex_text.split("\\begin{document}", 1)[-1]
    counters = [0, 0, 0]
    lines = []
    for m in _HEADING_RE.finditer(body):
        title = _braced(body, m.end() - 1)
        if title is None:
            continue
        kind = m.group(1)
        if kind == "notestructheading":
            lines.append(f"\\contentsline {{section}}{{{title}}}{{0}}{{section*.0}}%")
            continue
        level = ("section", "subsection", "subsubsection").index(kind)
        counters[level] += 1
        counters[level + 1:] = [0] * (2 - level)
        number = ".".join(str(c) for c in counters[:level + 1])
        lines.append(f"\\contentsline {{{kind}}}{{\\numberline {{{number}}}{title}}}{{0}}{{{kind}.{number}}}%")
    return "\n".join(lines) + "\n"


def _braced(text: str, start: int) -> str | None:
    """The contents of the brace group opening at ``text[start]`` (nested braces kept)."""
    depth = 0
    for i in range(start, min(len(text), start + 2000)):
        c = text[i]
        if c == "\\":
            continue
        if c == "{" and (i == 0 or text[i - 1] != "\\"):
            depth += 1
        elif c == "}" and text[i - 1] != "\\":
            depth -= 1
            if depth == 0:
                return text[start + 1:i]
    return None


def error_excerpt(log_text: str, context_lines: int = 1) -> str:
    """The ``!`` error lines of a TeX log up to their ``l.<n>`` line (plus ``context_lines``)."""
    lines = log_text.splitlines()
    out: list[str] = []
    i = 0
    while i < len(lines):
        if lines[i].startswith("!"):
            j = i
            while j < len(lines) and j < i + 30 and not re.match(r"^l\.\d+", lines[j]):
                j += 1
            end = min(j + 1 + context_lines, len(lines))
            out.extend(lines[i:end])
            i = end
        else:
            i += 1
    return "\n".join(out)
