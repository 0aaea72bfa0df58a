"""xelatex's passes driven directly (``python -m latex_templates.passes``), so that the first pass can
run while the note's figures are still being saved.

The first pass of a cold build only writes the auxiliary files (contents, labels, page numbers);
xelatex reads nothing of a figure but its size. ``reportgen build`` therefore writes a placeholder
of each figure at its final size (:func:`placeholder_pdf`), starts this driver, saves the real
figures meanwhile and then writes one byte to the driver's standard input. Meanwhile the driver
runs the passes on the placeholders until the auxiliary files stop changing — latexmk's rule:
a pass that leaves them as it found them is the last — and then waits for that byte.

The byte ``2`` says that every real figure has the page box of its placeholder, written the same
way (:func:`media_box`; a figure kept by the build cache is its real PDF already). xelatex reads
nothing of a figure but that box — the ``.xdv`` names the file, ``xdvipdfmx`` embeds it — so the
passes on the placeholders typeset the real figures: the stable pass already made is the last
(for a rebuild whose auxiliary files the cache restored, often pass 1), and only ``xdvipdfmx``
runs once the figures are there. A cold build of the press thus runs its two passes beside the
figures' saving instead of one of them after it.

The byte ``1`` (a box may differ, or could not be read): the passes go on on the real figures
until the auxiliary files are stable, at least one of them after the byte, and ``xdvipdfmx``
makes the PDF from the last. The commands are latexmk's own, so the PDF is the same bytes; a
placeholder of a slightly wrong size costs at most one more pass, never a different PDF.

With no auxiliary files at the start (a cold build: pass 1 writes the .aux, so a second pass
follows), pass 2 is started as soon as pass 1 has read its preamble and reads its own meanwhile,
in a folder of its own, waiting at ``\begin{document}`` until pass 1 has ended
(:class:`_NextPass`): the same command and bytes, without its preamble after pass 1.

Standard input closed without that byte (the build failed elsewhere): the driver stops (status 3)
after the pass running. Exit status: 0, or the failing program's status (its log says why).
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any, Callable

#: Passes on the real figures before giving up on stable auxiliary files (latexmk's default is 5).
MAX_PASSES = 5
#: Files of the output folder that are not auxiliary input of the next pass.
_NOT_AUX = {".log", ".xdv", ".fls", ".pdf", ".fdb_latexmk"}
CANCELLED = 3
#: The split first pass's two files in the build folder (:func:`split_note`): not auxiliary files,
#: removed when that pass ends.
SPLIT_PREFIX = ".reportgen-"
PREAMBLE_FILE, BODY_FILE = SPLIT_PREFIX + "preamble.tex", SPLIT_PREFIX + "body.tex"
#: The folder (in the build folder) of a cold build's second pass while it is started early.
NEXT_DIR = SPLIT_PREFIX + "next"
_BEGIN_DOCUMENT = "\\begin{document}"


def xelatex_command(tex_name: str, build_dir: str) -> list[str]:
    """The xelatex pass latexmk -xelatex runs (without ``-recorder``: it only writes the .fls)."""
    return ["xelatex", "-no-pdf", "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape",
            f"-output-directory={build_dir}", tex_name]


def xdvipdfmx_command(stem: str, build_dir: str) -> list[str]:
    return ["xdvipdfmx", "-E", "-o", f"{build_dir}/{stem}.pdf", f"{build_dir}/{stem}.xdv"]


def _aux_state(build_dir: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(build_dir.iterdir())
            if p.is_file() and p.suffix not in _NOT_AUX and not p.name.startswith(SPLIT_PREFIX)}


def split_note(text: str) -> tuple[str, str] | None:
    """A note's text as (its preamble through the line ``\\begin{document}``, the lines after it),
    or None when no line is exactly ``\\begin{document}``. A rebuild's first pass reads the
    preamble of the last build's note before the new note is written (:func:`split_stub`) and the
    new note's body once it is, when its preamble is the same text."""
    start = 0
    while True:
        end = text.find("\n", start)
        if end < 0:
            return None
        if text[start:end] == _BEGIN_DOCUMENT:
            return text[:end + 1], text[end + 1:]
        start = end + 1


def split_stub(preamble: str, build_dir: str) -> str:
    """What the split first pass reads (:data:`PREAMBLE_FILE`): ``preamble`` (ending with the line
    ``\\begin{document}``), then the body file read by TeX's own ``\\input`` (``\\@@input``, LaTeX's
    file hooks left out): TeX reads the same lines as from the whole note, one file deeper — the
    same .xdv and auxiliary bytes (tests/speed/test_latex_passes.py)."""
    return preamble + f"\\csname @@input\\endcsname {build_dir}/{BODY_FILE}\n"


def _run(cmd: list[str], cwd: Path) -> int:
    return subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL).returncode


#: What the build writes to the driver's standard input: the placeholders are written (pass 1 may
#: read the document's body; optional, the other two say it too); the figures are saved, real; they
#: are real and each has its placeholder's page box (:func:`media_box`).
PLACEHOLDERS, FIGURES_REAL, SAME_BOXES = b"P", b"1", b"2"


class Signal:
    """What the build says on the driver's standard input (:data:`PLACEHOLDERS`, then
    :data:`FIGURES_REAL` or :data:`SAME_BOXES`; anything else or the end of the input: stop, ``b""``),
    read by a thread so that the driver can go on with passes meanwhile."""

    def __init__(self, read1: Callable[[], bytes]) -> None:
        self._said: bytes | None = None
        self.placed = threading.Event()          # the placeholders are there (or it is too late for them)
        self._done = threading.Event()
        threading.Thread(target=self._read, args=(read1,), daemon=True).start()

    def _read(self, read1: Callable[[], bytes]) -> None:
        said = b""
        try:
            while True:
                said = read1()
                if said != PLACEHOLDERS:
                    break
                self.placed.set()
        finally:
            self._said = said if said in (FIGURES_REAL, SAME_BOXES) else b""
            self.placed.set()
            self._done.set()

    def poll(self) -> bytes | None:
        """What was said of the figures, or None while nothing was."""
        return self._said if self._done.is_set() else None

    def wait(self) -> bytes:
        self._done.wait()
        return self._said or b""


def drive(tex: Path, build_dir_name: str, read1: Callable[[], bytes], *, split: bool = False) -> int:
    """The passes until the auxiliary files are stable on figures known to have their real page
    boxes, then xdvipdfmx. Returns an exit status.

    ``read1`` reads one byte of what the build says (:class:`Signal`). Pass 1 starts at once and
    waits at ``\\begin{document}`` for the placeholders (:func:`_first_pass`). While nothing is said
    of the figures (they are being saved), the passes go on on the placeholders until the auxiliary
    files are stable there: a pass that left them as it found them is not followed by another.
    ``split``: pass 1 reads :data:`PREAMBLE_FILE` (the last build's preamble, or the one a cold
    build's note will have, started before the note is written) and then :data:`BODY_FILE`, which
    the build writes before the placeholders; both are removed when pass 1 ends (when a second
    pass was started early from them, when it ends). The passes after it read the note itself.
    :data:`SAME_BOXES` makes every pass count as one on the real figures (xelatex reads nothing of
    a figure but its page box, the same in both): a stable pass already made is the last.
    :data:`FIGURES_REAL` (a box may differ) counts only the passes started after it was said, so at
    least one more runs."""
    work = tex.parent
    build_dir = work / build_dir_name
    signal = Signal(read1)
    before = _aux_state(build_dir) if build_dir.is_dir() else None
    said_at_start: bytes | None = None               # what was said when the last pass started
    real_passes = early_passes = 0
    # no .aux yet: pass 1 writes it, so a second pass follows; it reads its preamble early
    cold = f"{tex.stem}.aux" not in (before or {})
    following: list[_NextPass] = []
    try:
        while True:
            # pass 1 counts as one on the placeholders whenever the byte came (the build starts the
            # driver before it saves the figures): the count of passes does not depend on a race
            said_at_start = signal.poll() if early_passes + real_passes else None
            if early_passes + real_passes:
                status = following.pop().run() if following else None
                if status is None:
                    status = _xelatex(tex, build_dir_name)
            else:
                status = _first_pass(tex, build_dir_name, signal, split,
                                     (lambda: following.append(_NextPass(tex, build_dir_name, split))) if cold else None)
            if split and not following:
                _remove_split_files(build_dir)
            if status != 0:
                return status
            result = _after_pass(build_dir, before, signal, said_at_start, early_passes, real_passes)
            if isinstance(result, int):
                return result
            before, early_passes, real_passes, done = result
            if done:
                break
    finally:
        for waiting in following:
            waiting.stop()
        if split:
            _remove_split_files(build_dir)
    return _run(xdvipdfmx_command(tex.stem, build_dir_name), work)


def _remove_split_files(build_dir: Path) -> None:
    for name in (PREAMBLE_FILE, BODY_FILE):
        (build_dir / name).unlink(missing_ok=True)


def _after_pass(build_dir: Path, before: dict[str, bytes] | None, signal: Signal, said_at_start: bytes | None,
                early_passes: int, real_passes: int) -> int | tuple[dict[str, bytes], int, int, bool]:
    """After a pass: the auxiliary files now, the passes counted, and whether it was the last
    (latexmk's rule, :func:`drive`); :data:`CANCELLED` when the build stopped."""
    if said_at_start:
        real_passes += 1
    else:
        early_passes += 1
    after = _aux_state(build_dir)
    stable = after == before
    said = signal.poll()
    if said is None and (stable or early_passes >= MAX_PASSES):
        said = signal.wait()                     # nothing more to do on the placeholders
    if said is not None and not said:
        return CANCELLED
    on_real = said == SAME_BOXES or (said == FIGURES_REAL and said_at_start == FIGURES_REAL)
    return after, early_passes, real_passes, (stable and on_real) or real_passes >= MAX_PASSES


#: The line the driver writes on its standard output after each xelatex pass (counted by the build).
PASS_LINE = "xelatex pass"


def _xelatex(tex: Path, build_dir_name: str) -> int:
    print(PASS_LINE, flush=True)
    return _run(xelatex_command(tex.name, build_dir_name), tex.parent)


#: What a waiting pass writes on its terminal (and log) when it has read its preamble.
PREAMBLE_READ = "reportgen: preamble read"
#: What pass 1 does at ``\begin{document}`` (the hook's last code, before the .aux is read): say
#: that the preamble is read (:data:`PREAMBLE_READ`), then wait for a line on xelatex's standard
#: input, written once the placeholders are there. The terminal is read in ``\errorstopmode``
#: only (a read is fatal in nonstop mode); nothing is typeset.
WAIT_HOOK = (r"\AddToHook{begindocument/before}{\immediate\write16{" + PREAMBLE_READ + "}"
             r"\errorstopmode\read-1to\reportgenplaceholders\nonstopmode}")
_SIMPLE_NAME = re.compile(r"[A-Za-z0-9_.-]+\.tex")


def next_pass_command(tex_name: str, build_dir: str, *, split: bool = False) -> list[str] | None:
    """Pass 2 of a cold build started early (:class:`_NextPass`): pass 1's command (its preamble
    read, then a wait at ``\\begin{document}``; ``split``: from the split pass's two files)
    writing into :data:`NEXT_DIR` inside ``build_dir``, where pass 1's auxiliary files are copied
    before it goes on."""
    cmd = first_pass_command(tex_name, build_dir, split=split)
    if cmd is None:
        return None
    return [f"-output-directory={build_dir}/{NEXT_DIR}" if a.startswith("-output-directory=") else a for a in cmd]


def first_pass_command(tex_name: str, build_dir: str, *, split: bool = False) -> list[str] | None:
    """Pass 1 as :func:`xelatex_command`, that reads the preamble at once and waits at
    ``\\begin{document}`` (:data:`WAIT_HOOK`): the same .xdv and auxiliary files (the job's name
    given, the file read by ``\\input``), the preamble's ≈ 0.7 s spent while the build writes the
    figures' placeholders. ``split``: the preamble read from :data:`PREAMBLE_FILE`, the body then
    from :data:`BODY_FILE` (:func:`split_stub`). None for a file name that ``\\input`` would read
    otherwise."""
    if not _SIMPLE_NAME.fullmatch(tex_name) or not _SIMPLE_NAME.fullmatch(f"{build_dir}.tex"):
        return None
    source = f"{build_dir}/{PREAMBLE_FILE}" if split else tex_name
    return ["xelatex", "-no-pdf", "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape",
            f"-output-directory={build_dir}", f"-jobname={tex_name[:-4]}", WAIT_HOOK + r"\input " + source]


def _said_when_read(stream: Any, when_read: Callable[[], None]) -> None:
    """Read a waiting pass's terminal output to its end, calling ``when_read()`` at its first
    :data:`PREAMBLE_READ` (the pass waits then: it is still running)."""
    marker = PREAMBLE_READ.encode()
    said = False
    for line in stream:
        if not said and line.rstrip() == marker:
            said = True
            when_read()
    stream.close()


class _NextPass:
    """Pass 2 of a cold build, started while pass 1 runs: it reads its preamble (≈ 0.7 s of its
    ≈ 1.2 s) beside pass 1's body and the figures' saving, writing into :data:`NEXT_DIR`, and
    waits at ``\\begin{document}`` (:data:`WAIT_HOOK`) — before the auxiliary files are read —
    until pass 1 has ended. Its preamble reads no auxiliary file, so it is the pass latexmk would
    start then: :meth:`run` copies pass 1's auxiliary files into its folder, lets it go on, and
    moves what it wrote (auxiliary files, .xdv, log) back into the build folder. Only for a build
    without auxiliary files, where pass 1 writes the .aux and a second pass always follows. After
    a split pass 1 it reads the same two files (kept until it has ended)."""

    def __init__(self, tex: Path, build_dir_name: str, split: bool = False) -> None:
        self.tex = tex
        self.build_dir = tex.parent / build_dir_name
        self.folder = self.build_dir / NEXT_DIR
        self.proc: subprocess.Popen | None = None
        cmd = next_pass_command(tex.name, build_dir_name, split=split)
        if cmd is None:
            return
        shutil.rmtree(self.folder, ignore_errors=True)
        self.folder.mkdir()
        self.proc = subprocess.Popen(cmd, cwd=tex.parent, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL)

    def run(self) -> int | None:
        """Pass 2 on pass 1's auxiliary files; None when it could not be started early (or stopped
        on an error in its preamble: the caller runs the pass as usual, which says why)."""
        proc = self.proc
        if proc is None or proc.poll() is not None:
            self.stop()
            return None
        for name in _aux_state(self.build_dir):
            shutil.copyfile(self.build_dir / name, self.folder / name)
        print(PASS_LINE, flush=True)
        try:
            assert proc.stdin is not None
            proc.stdin.write(b"\n")
            proc.stdin.close()
        except OSError:                               # stopped already: its status and log say why
            pass
        status = proc.wait()
        self.proc = None
        for made in sorted(self.folder.iterdir()):
            os.replace(made, self.build_dir / made.name)
        self.stop()
        return status

    def stop(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        self.proc = None
        shutil.rmtree(self.folder, ignore_errors=True)


def _first_pass(tex: Path, build_dir_name: str, signal: Signal, split: bool = False,
                when_read: Callable[[], None] | None = None) -> int:
    """Pass 1, started at once and let on into the document's body once the placeholders are
    there; stopped (:data:`CANCELLED`) when the build fails before. ``when_read()`` is called
    once it has read its preamble (waiting for the placeholders, or not)."""
    cmd = first_pass_command(tex.name, build_dir_name, split=split)
    if cmd is None:
        signal.placed.wait()
        return CANCELLED if signal.poll() == b"" else _xelatex(tex, build_dir_name)
    print(PASS_LINE, flush=True)
    proc = subprocess.Popen(cmd, cwd=tex.parent, stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE if when_read is not None else subprocess.DEVNULL)
    reader = None
    if when_read is not None:
        assert proc.stdout is not None
        reader = threading.Thread(target=_said_when_read, args=(proc.stdout, when_read), daemon=True)
        reader.start()
    try:
        return _let_on(proc, signal)
    finally:
        if reader is not None:
            reader.join()        # when_read() has returned, if it was called: nothing starts later


def _let_on(proc: subprocess.Popen, signal: Signal) -> int:
    """Let a waiting pass 1 go on once the placeholders are there; its exit status."""
    while not signal.placed.wait(0.05):
        if proc.poll() is not None:               # stopped on an error in the preamble
            break
    if proc.poll() is None and signal.poll() == b"":
        proc.kill()
        proc.wait()
        return CANCELLED
    try:
        assert proc.stdin is not None
        proc.stdin.write(b"\n")
        proc.stdin.close()
    except OSError:                               # stopped already: its status and log say why
        pass
    return proc.wait()


def _pdf_number(x: float) -> bytes:
    """A number as matplotlib writes it into a PDF (``%.10f``, trailing zeros dropped)."""
    return (b"%.10f" % x).rstrip(b"0").rstrip(b".")


def placeholder_pdf(width_pt: float, height_pt: float) -> bytes:
    """A one-page PDF of the given size with nothing on it (what xelatex reads of a figure); its
    page box written as matplotlib writes a figure's (:func:`media_box` compares them)."""
    objects = [b"<< /Type /Catalog /Pages 2 0 R >>",
               b"<< /Type /Pages /Kids [3 0 R] /Count 1 >>",
               b"<< /Type /Page /Parent 2 0 R /MediaBox [ 0 0 " + _pdf_number(width_pt) + b" "
               + _pdf_number(height_pt) + b" ] /Contents 4 0 R /Resources << >> >>",
               b"<< /Length 0 >>\nstream\n\nendstream"]
    out = bytearray(b"%PDF-1.4\n")
    offsets = []
    for i, body in enumerate(objects, start=1):
        offsets.append(len(out))
        out += b"%d 0 obj\n" % i + body + b"\nendobj\n"
    xref = len(out)
    out += b"xref\n0 %d\n0000000000 65535 f \n" % (len(objects) + 1)
    for off in offsets:
        out += b"%010d 00000 n \n" % off
    out += b"trailer\n<< /Size %d /Root 1 0 R >>\nstartxref\n%d\n%%%%EOF\n" % (len(objects) + 1, xref)
    return bytes(out)


def media_box(pdf: Path) -> bytes | None:
    """The page box of a one-page PDF as written (``/MediaBox [ 0 0 w h ]``: the placeholder's and
    matplotlib's; read from the file's head, where both write it), or None when there is none
    there, or a second box (a page's own, a crop box, a rotation) that xelatex might read."""
    import re

    try:
        with open(pdf, "rb") as f:
            head = f.read(4096)
            size = f.seek(0, 2)
        whole = head if size <= len(head) else pdf.read_bytes()
    except OSError:
        return None
    boxes = re.findall(rb"/MediaBox\s*\[([^\]]*)\]", whole)
    if len(boxes) != 1 or re.search(rb"/(CropBox|Rotate|UserUnit|Count\s+(?!1\b)\d)", whole):
        return None
    return b" ".join(boxes[0].split())


def _byte_from_stdin() -> bytes:
    return sys.stdin.buffer.read(1)


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    split = args[2:] == ["--split"]
    if len(args) != 2 and not split:
        print("usage: python -m latex_templates.passes TEX BUILD_DIR [--split]", file=sys.stderr)
        return 2
    return drive(Path(args[0]).resolve(), args[1], _byte_from_stdin, split=split)


if __name__ == "__main__":
    sys.exit(main())
