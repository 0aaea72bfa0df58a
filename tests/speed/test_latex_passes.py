"""xelatex's first pass on placeholders while the figures are saved (latex_templates/passes.py,
FigureQueue.write_placeholders): the tight box measured first and then saved gives the bytes of a
"tight" save, a placeholder has the figure's size, the driver waits for the figures and stops when
told to, a failed pass keeps the .tex and the log and says where, and the early start writes the
same PDF as latexmk."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from latex_templates import passes
from latex_templates.build import start_passes
from latex_templates.figures import new_figure
from latex_templates.figures.saving import FigureQueue, page_size_pt, save_pdf, tight_box
from reportgen.commands import build as build_cmd
from reportgen.commands import pipeline
from reportgen.errors import BuildError

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"
HAVE_TEX = all(shutil.which(p) for p in ("xelatex", "xdvipdfmx", "latexmk"))
needs_tex = pytest.mark.skipif(not HAVE_TEX, reason="TeX Live (xelatex, xdvipdfmx, latexmk) is not installed")


def _figure(i: int, exact: bool = False):
    fig = new_figure(9, 6)
    ax = fig.add_subplot()
    ax.plot([0, 1, 2 + i], [0, i, 1], label=f"$\\omega_{{{i}}}$ кривая")
    ax.set_title(f"рисунок {i}: $F_{{ур}}$ = {i},5")
    ax.legend()
    fig.reportgen_exact = exact
    return fig


def test_a_measured_tight_box_saves_the_bytes_of_a_tight_save(tmp_path):
    tight, measured = tmp_path / "tight.pdf", tmp_path / "measured.pdf"
    save_pdf(_figure(3), tight)
    fig = _figure(3)
    box = tight_box(fig)
    assert box is not None and 0 < box.width < 9 / 2.54 + 1 and 0 < box.height < 6 / 2.54 + 1
    save_pdf(fig, measured, box)
    assert measured.read_bytes() == tight.read_bytes()


def test_the_measuring_draws_nothing_and_leaves_the_figure_as_it_was(tmp_path):
    fig = _figure(1)
    tight_box(fig)
    assert "get_tightbbox" not in vars(fig)            # the recording hook is gone
    save_pdf(fig, tmp_path / "a.pdf")                   # still saves, as "tight"
    save_pdf(_figure(1), tmp_path / "b.pdf")
    assert (tmp_path / "a.pdf").read_bytes() == (tmp_path / "b.pdf").read_bytes()


@pytest.mark.skipif(shutil.which("pdfinfo") is None, reason="poppler-utils is not installed")
def test_a_placeholder_has_the_size_of_the_saved_figure(tmp_path):
    queue = FigureQueue()
    figs = [_figure(0), _figure(1, exact=True)]
    for i, fig in enumerate(figs):
        queue.add(fig, tmp_path / f"f{i}.pdf")
    queue.write_placeholders()
    placeholders = {p.name: _page_size(p) for p in tmp_path.glob("f*.pdf")}
    queue.save()
    assert not list(tmp_path.glob(".*.part"))          # saved by renaming a whole file into place
    for name, size in placeholders.items():
        real = _page_size(tmp_path / name)
        assert size == pytest.approx(real, abs=1e-3), name
    assert placeholders["f1.pdf"] == pytest.approx((9 / 2.54 * 72, 6 / 2.54 * 72), abs=1e-3)
    assert page_size_pt(figs[1]) == pytest.approx(placeholders["f1.pdf"], abs=1e-3)


def _page_size(pdf: Path) -> tuple[float, float]:
    out = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, check=True).stdout
    line = next(l for l in out.splitlines() if l.startswith("Page size:"))
    w, _, h = line.split(":", 1)[1].split()[:3]
    return float(w), float(h)


MINIMAL = "\\documentclass{article}\\begin{document}\\tableofcontents\\section{A}x\\end{document}\n"


@needs_tex
@pytest.mark.parametrize("go, status", [(b"1", 0), (b"", passes.CANCELLED)])
def test_the_driver_waits_for_the_figures_and_stops_when_told(tmp_path, go, status):
    (tmp_path / "n.tex").write_text(MINIMAL, encoding="utf-8")
    (tmp_path / "b").mkdir()
    proc = subprocess.run([sys.executable, str(Path(passes.__file__)), "n.tex", "b"], cwd=tmp_path,
                          input=go, capture_output=True)
    assert proc.returncode == status
    # stopped before the placeholders were said to be there: pass 1 never read the document's body
    assert (tmp_path / "b" / "n.aux").is_file() == (status == 0)
    assert (tmp_path / "b" / "n.pdf").is_file() == (status == 0)
    if status == 0:                                    # the contents line needed a second pass
        assert "A" in (tmp_path / "b" / "n.toc").read_text(encoding="utf-8")


@needs_tex
def test_a_failed_first_pass_keeps_the_tex_and_the_log_and_says_where(tmp_path):
    tex = tmp_path / "bad.tex"
    tex.write_text("\\documentclass{article}\\begin{document}\\undefinedmacro\\end{document}\n", encoding="utf-8")
    pending = start_passes(tex)
    pending.figures_ready()
    with pytest.raises(BuildError) as exc:
        pending.wait()
    assert "undefinedmacro" in exc.value.problem
    assert str(tex) in exc.value.kept and "bad.log" in exc.value.kept
    assert tex.is_file() and (tmp_path / "latex-build" / "bad.log").is_file()


@needs_tex
def test_the_early_first_pass_writes_the_pdf_latexmk_writes(tmp_path, monkeypatch):
    monkeypatch.setenv("REPORTGEN_CACHE", "off")
    early, late = pipeline.Timeline(quiet=True), pipeline.Timeline(quiet=True)
    build_cmd.build(str(PRESS), tmp_path / "early", quiet=True, sheets=False, timeline=early)
    build_cmd.build(str(PRESS), tmp_path / "late", quiet=True, sheets=False,
                    latexmk=shutil.which("latexmk"), timeline=late)     # a named latexmk: run as it is
    assert "note: figure sizes" in early.times and "note: figure sizes" not in late.times
    assert (tmp_path / "early" / "report.pdf").read_bytes() == (tmp_path / "late" / "report.pdf").read_bytes()
    assert (tmp_path / "early" / "latex-build" / "report.fdb_latexmk").exists() is False
    assert (tmp_path / "late" / "latex-build" / "report.fdb_latexmk").is_file()


@needs_tex
def test_a_first_pass_that_leaves_the_aux_files_as_it_found_them_is_the_last_when_the_boxes_are_the_same(tmp_path):
    """SAME_BOXES: no pass after the first when it found the auxiliary files of an earlier build
    (stable) — and the passes go on when it did not (the contents line needs a second pass)."""
    (tmp_path / "n.tex").write_text(MINIMAL, encoding="utf-8")
    (tmp_path / "b").mkdir()

    env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", FORCE_SOURCE_DATE="1")   # no dates in the PDF

    def drive(go: bytes) -> list[str]:
        proc = subprocess.run([sys.executable, str(Path(passes.__file__)), "n.tex", "b"], cwd=tmp_path,
                              input=go, capture_output=True, text=False, env=env)
        assert proc.returncode == 0
        return [line for line in proc.stdout.decode().splitlines() if line == passes.PASS_LINE]

    assert len(drive(passes.SAME_BOXES)) == 2      # no aux files yet: the first pass wrote them
    first = (tmp_path / "b" / "n.pdf").read_bytes()
    assert len(drive(passes.SAME_BOXES)) == 1      # the aux files of that build: stable after one pass
    assert (tmp_path / "b" / "n.pdf").read_bytes() == first
    assert len(drive(passes.FIGURES_REAL)) == 2    # the figures' boxes not known to be the same: a pass on them


def test_a_placeholder_writes_the_page_box_a_saved_figure_has(tmp_path):
    """What SAME_BOXES rests on: the placeholder of a figure and the figure saved have the same
    ``/MediaBox`` bytes (matplotlib's number format), and a file with another box differs."""
    queue = FigureQueue()
    figs = [_figure(0), _figure(1, exact=True), _figure(2)]
    for i, fig in enumerate(figs):
        queue.add(fig, tmp_path / f"f{i}.pdf")
    queue.write_placeholders()
    boxes = {p.name: passes.media_box(p) for p in tmp_path.glob("f*.pdf")}
    queue.save()
    for name, box in boxes.items():
        assert box is not None and passes.media_box(tmp_path / name) == box, name
    assert passes.media_box(tmp_path / "f0.pdf") != passes.media_box(tmp_path / "f1.pdf")   # tight, and not
    (tmp_path / "odd.pdf").write_bytes(passes.placeholder_pdf(10.0, 20.0).replace(b"/Resources", b"/Rotate 90 /Resources"))
    assert passes.media_box(tmp_path / "odd.pdf") is None        # a box xelatex might read otherwise


def _pass_lines_before_the_byte(tmp_path: Path, count: int, go: bytes) -> tuple[int, int]:
    """Start the driver on MINIMAL, say that the placeholders are there, wait (≤ 120 s) until it has
    begun ``count`` passes without being told anything more, then say ``go``; (the passes it ran in
    all, its exit status)."""
    import select
    import time

    (tmp_path / "n.tex").write_text(MINIMAL, encoding="utf-8")
    (tmp_path / "b").mkdir(exist_ok=True)
    env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", FORCE_SOURCE_DATE="1")
    proc = subprocess.Popen([sys.executable, str(Path(passes.__file__)), "n.tex", "b"], cwd=tmp_path, env=env,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    assert proc.stdin is not None
    proc.stdin.write(passes.PLACEHOLDERS)
    proc.stdin.flush()
    seen, deadline = 0, time.monotonic() + 120
    try:
        while seen < count and time.monotonic() < deadline:
            ready, _, _ = select.select([proc.stdout], [], [], 1.0)
            if ready:
                line = proc.stdout.readline()
                if not line:
                    break
                seen += line.decode().strip() == passes.PASS_LINE
        assert seen == count, f"{seen} passes began before the figures were said to be saved, not {count}"
        out, _ = proc.communicate(go, timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    return seen + sum(line == passes.PASS_LINE for line in out.decode().splitlines()), proc.returncode


@needs_tex
def test_the_passes_go_on_on_the_placeholders_until_stable_and_same_boxes_ends_them(tmp_path):
    """A cold build's two passes run beside the figures' saving: the second (the contents line
    filled in) begins before the byte, and with SAME_BOXES no pass follows it."""
    total, status = _pass_lines_before_the_byte(tmp_path, 2, passes.SAME_BOXES)
    assert status == 0 and total == 2
    assert "A" in (tmp_path / "b" / "n.toc").read_text(encoding="utf-8")
    assert (tmp_path / "b" / "n.pdf").is_file()


@needs_tex
def test_figures_real_means_one_more_pass_after_the_placeholders_were_stable(tmp_path):
    """FIGURES_REAL (a box may differ): the passes on the placeholders do not count, one more runs
    on the real figures (stable there: the last)."""
    total, status = _pass_lines_before_the_byte(tmp_path, 2, passes.FIGURES_REAL)
    assert status == 0 and total == 3


@needs_tex
def test_the_driver_stops_after_the_pass_running_when_the_build_fails(tmp_path):
    total, status = _pass_lines_before_the_byte(tmp_path, 2, b"")
    assert status == passes.CANCELLED and total == 2
    assert not (tmp_path / "b" / "n.pdf").exists()


FIGURED = ("\\documentclass{article}\\usepackage{graphicx}\\begin{document}\\tableofcontents\\section{A}"
           "\\includegraphics{f.pdf}\\label{a} \\pageref{a}\\end{document}\n")


@needs_tex
def test_the_waiting_first_pass_writes_the_xdv_and_aux_files_of_a_plain_pass(tmp_path):
    """Pass 1 started before the placeholders (the wait hook, the job's name, ``\\input``) makes the
    bytes that latexmk's own pass makes."""
    (tmp_path / "n.tex").write_text(FIGURED, encoding="utf-8")
    (tmp_path / "f.pdf").write_bytes(passes.placeholder_pdf(100.5, 70.25))
    env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", FORCE_SOURCE_DATE="1")
    made = {}
    for name, cmd in (("plain", passes.xelatex_command("n.tex", "plain")),
                      ("waiting", passes.first_pass_command("n.tex", "waiting"))):
        (tmp_path / name).mkdir()
        proc = subprocess.run(cmd, cwd=tmp_path, env=env, input=b"\n", capture_output=True)
        assert proc.returncode == 0, proc.stdout[-2000:]
        made[name] = {p.name: p.read_bytes() for p in (tmp_path / name).iterdir() if p.suffix != ".log"}
    assert set(made["plain"]) == {"n.aux", "n.toc", "n.xdv"}
    assert made["waiting"] == made["plain"]
    assert passes.first_pass_command("my note.tex", "b") is None      # \input would read another name


def _children(pid: int) -> list[int]:
    out = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            out.append(int(stat.parent.name))
    return out


@needs_tex
@pytest.mark.skipif(not Path("/proc/self/syscall").exists(), reason="needs Linux's /proc/PID/syscall")
def test_pass_1_waits_for_the_placeholders_at_begin_document(tmp_path):
    """Started before the placeholders are there, pass 1 stops reading its standard input (the
    wait hook, at ``\\begin{document}``: its preamble read) and has not begun the body (no .aux);
    told, it goes on and the build ends as usual."""
    import time

    (tmp_path / "n.tex").write_text(FIGURED, encoding="utf-8")
    (tmp_path / "b").mkdir()
    env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", FORCE_SOURCE_DATE="1")
    proc = subprocess.Popen([sys.executable, str(Path(passes.__file__)), "n.tex", "b"], cwd=tmp_path, env=env,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    try:
        waiting, deadline = False, time.monotonic() + 120
        while not waiting and time.monotonic() < deadline:
            time.sleep(0.2)
            for child in _children(proc.pid):
                try:
                    call = (Path("/proc") / str(child) / "syscall").read_text().split()
                except OSError:
                    continue
                waiting = call[:2] == ["0", "0x0"]          # read(0, …): xelatex waits on its input
        assert waiting and proc.poll() is None
        assert not (tmp_path / "b" / "n.aux").exists()
        (tmp_path / "f.pdf").write_bytes(passes.placeholder_pdf(100.5, 70.25))
        out, _ = proc.communicate(passes.PLACEHOLDERS + passes.SAME_BOXES, timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 0
    assert sum(line == passes.PASS_LINE for line in out.decode().splitlines()) == 2
    assert (tmp_path / "b" / "n.pdf").is_file()


@needs_tex
def test_an_error_in_the_preamble_is_reported_while_pass_1_waits_for_the_placeholders(tmp_path):
    tex = tmp_path / "bad.tex"
    tex.write_text("\\documentclass{article}\\usepackage{nosuchpackagexyz}\\begin{document}x\\end{document}\n",
                   encoding="utf-8")
    pending = start_passes(tex, placeholders=False)
    pending.proc.wait(timeout=120)                        # nothing said: the error ends the driver
    with pytest.raises(BuildError) as exc:
        pending.wait()
    assert "nosuchpackagexyz" in exc.value.problem
    assert str(tex) in exc.value.kept and "bad.log" in exc.value.kept


@needs_tex
def test_the_split_first_pass_writes_the_xdv_and_aux_files_of_a_plain_pass(tmp_path):
    """A rebuild's pass 1 reads the last build's preamble before the note is written, then the
    note's body from a file of its own (``passes.split_stub``): the bytes of a plain pass."""
    text = "\\documentclass{article}\\usepackage{graphicx}\n\\begin{document}\n" + FIGURED.split("\\begin{document}")[1]
    (tmp_path / "n.tex").write_text(text, encoding="utf-8")
    (tmp_path / "f.pdf").write_bytes(passes.placeholder_pdf(100.5, 70.25))
    preamble, body = passes.split_note(text)
    assert preamble.endswith("\\begin{document}\n") and preamble + body == text
    env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", FORCE_SOURCE_DATE="1")
    made = {}
    for name, cmd in (("plain", passes.xelatex_command("n.tex", "plain")),
                      ("split", passes.first_pass_command("n.tex", "split", split=True))):
        (tmp_path / name).mkdir()
        if name == "split":
            (tmp_path / name / passes.PREAMBLE_FILE).write_text(passes.split_stub(preamble, name), encoding="utf-8")
            (tmp_path / name / passes.BODY_FILE).write_text(body, encoding="utf-8")
        proc = subprocess.run(cmd, cwd=tmp_path, env=env, input=b"\n", capture_output=True)
        assert proc.returncode == 0, proc.stdout[-2000:]
        made[name] = {p.name: p.read_bytes() for p in (tmp_path / name).iterdir()
                      if p.suffix != ".log" and not p.name.startswith(passes.SPLIT_PREFIX)}
    assert set(made["plain"]) == {"n.aux", "n.toc", "n.xdv"}
    assert made["split"] == made["plain"]
    assert passes.split_note("\\documentclass{article}\\begin{document}x\\end{document}\n") is None


@needs_tex
def test_a_split_first_pass_on_another_preamble_is_stopped_and_leaves_the_aux_files(tmp_path):
    """The note's preamble is not the one the split pass read: ``note_written`` says so, the pass
    is stopped (its two files removed, the restored auxiliary files as they were)."""
    from latex_templates.build import BUILD_DIR, start_split_passes

    tex = tmp_path / "report.tex"
    build_dir = tmp_path / BUILD_DIR
    build_dir.mkdir()
    (build_dir / "report.aux").write_text("\\relax \n", encoding="utf-8")
    pending = start_split_passes(tex, "\\documentclass{article}\n\\begin{document}\n")
    assert pending is not None
    tex.write_text("\\documentclass[12pt]{article}\n\\begin{document}\nx\n\\end{document}\n", encoding="utf-8")
    assert not pending.note_written()
    pending.cancel()
    assert sorted(p.name for p in build_dir.iterdir() if not p.name.endswith(".log")) == ["report.aux"]
    assert (build_dir / "report.aux").read_text(encoding="utf-8") == "\\relax \n"


@needs_tex
def test_pass_2_begun_ahead_writes_the_bytes_of_pass_2_run_after_pass_1(tmp_path):
    """The standby pass 2 (its preamble read beside pass 1's body, in a folder of its own, given
    the auxiliary files pass 1 wrote) leaves the build folder as the plain pass 2 does: the same
    .xdv, auxiliary files and PDF, the same count of passes; and when pass 1 is the last (its
    auxiliary files stable), the standby is stopped and its folder removed."""
    (tmp_path / "f.pdf").write_bytes(passes.placeholder_pdf(100.5, 70.25))
    made, lines = {}, {}
    for standby in ("1", "0"):
        work = tmp_path / f"standby{standby}"
        work.mkdir()
        (work / "n.tex").write_text(FIGURED.replace("f.pdf", "../f.pdf"), encoding="utf-8")
        (work / "b").mkdir()
        env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", FORCE_SOURCE_DATE="1",
                   **{passes.STANDBY_ENV: standby})
        for run in ("first", "again"):         # no aux files: two passes; then the stable one alone
            proc = subprocess.run([sys.executable, str(Path(passes.__file__)), "n.tex", "b"], cwd=work,
                                  input=passes.SAME_BOXES, capture_output=True, env=env)
            assert proc.returncode == 0, proc.stderr[-2000:]
            lines[standby, run] = proc.stdout.decode().count(passes.PASS_LINE)
            assert not (work / "b" / passes.STANDBY_DIR).exists()
            made[standby, run] = {p.name: p.read_bytes() for p in (work / "b").iterdir() if p.suffix != ".log"}
    assert set(made["0", "first"]) == {"n.aux", "n.toc", "n.xdv", "n.pdf"}
    assert lines["1", "first"] == lines["0", "first"] == 2
    assert lines["1", "again"] == lines["0", "again"] == 1
    assert made["1", "first"] == made["0", "first"] and made["1", "again"] == made["0", "again"]
    assert "A" in made["1", "first"]["n.toc"].decode()


@needs_tex
def test_a_standby_pass_is_stopped_with_the_driver_when_the_build_fails(tmp_path):
    """The build fails after pass 1 began its body (the placeholders said, then the input closed
    without a word of the figures): the driver stops after pass 1, and so does the standby pass 2,
    which had begun — its folder removed, no PDF."""
    import time

    (tmp_path / "n.tex").write_text(FIGURED, encoding="utf-8")
    (tmp_path / "f.pdf").write_bytes(passes.placeholder_pdf(100.5, 70.25))
    (tmp_path / "b").mkdir()
    proc = subprocess.Popen([sys.executable, str(Path(passes.__file__)), "n.tex", "b"], cwd=tmp_path,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    try:
        assert proc.stdin is not None
        proc.stdin.write(passes.PLACEHOLDERS)
        proc.stdin.flush()
        standby, deadline = tmp_path / "b" / passes.STANDBY_DIR, time.monotonic() + 120
        while not standby.is_dir() and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.02)
        assert standby.is_dir()                     # pass 2 began ahead, beside pass 1's body
        out, _ = proc.communicate(b"", timeout=120)  # the build failed: the input closed
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == passes.CANCELLED
    assert out.decode().count(passes.PASS_LINE) == 1
    assert not standby.exists()
    assert not (tmp_path / "b" / "n.pdf").exists()
