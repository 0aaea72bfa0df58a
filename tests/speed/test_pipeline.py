"""The overlapped build (sheets in a forked process, LaTeX in the background): failures come back
with their class and fields, the watch loop, the provisional table of contents."""
from __future__ import annotations

import argparse
import threading
import time
from pathlib import Path

import pytest

from latex_templates.build import provisional_toc
from reportgen.commands import build as build_cmd
from reportgen.commands import pipeline
from reportgen.commands.watch import watch
from reportgen.errors import TaskError

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"


def _fail_in_the_sheets(monkeypatch):
    import drawings.sheets as sheets_pkg

    original = sheets_pkg.available_sheets

    class Broken:
        NEEDS: tuple[str, ...] = ()         # a sheet declares the stages it reads (reportgen.project.Needs)

        @staticmethod
        def draw(*_args):
            raise TaskError("mechanism.link[1].length", "made up for the test", "a positive length")

    monkeypatch.setattr(pipeline, "_sheet_list", lambda p: [("broken", Broken)] + list(original(p)))
    monkeypatch.setattr(pipeline, "_note", lambda *_, **__: (None, None))


@pytest.mark.parametrize("jobs", ["2", "1"])
def test_an_error_in_the_sheets_comes_back_with_its_class_and_fields(tmp_path, monkeypatch, jobs):
    monkeypatch.setenv("REPORTGEN_JOBS", jobs)
    _fail_in_the_sheets(monkeypatch)
    with pytest.raises(TaskError) as exc:
        build_cmd.build(str(PRESS), tmp_path / "out", quiet=True, pdf=False)
    assert exc.value.path == "mechanism.link[1].length" and exc.value.expected == "a positive length"
    assert "made up for the test" in str(exc.value)
    # bad input leaves nothing behind
    assert list(tmp_path.iterdir()) == []


def test_the_sheets_run_in_parallel_with_the_note(tmp_path, monkeypatch):
    monkeypatch.setenv("REPORTGEN_JOBS", "2")
    monkeypatch.setattr(pipeline, "_note", lambda *_, **__: (time.sleep(0.3), None))
    timeline = pipeline.Timeline(quiet=True)
    build_cmd.build(str(PRESS), tmp_path / "out", quiet=True, pdf=False, timeline=timeline)
    lanes = {s.lane for s in timeline.spans}
    assert lanes == {pipeline.MAIN, pipeline.SHEETS}
    sheets = [s for s in timeline.spans if s.lane == pipeline.SHEETS]
    solve = next(s for s in timeline.spans if s.name == "solve")
    assert len(sheets) == len(list((tmp_path / "out" / "sheets").glob("*.dxf"))) == 4
    assert all(s.start >= solve.end for s in sheets)   # forked after the solve
    assert [r[1] for r in timeline.critical_path()][:2] == ["task", "solve"]


def test_provisional_toc_numbers_headings_as_latex_does():
    tex = r"""\newcommand{\notestructheading}[1]{#1}
\begin{document}
\notestructheading{Введение}
\section{Первый {\itshape раздел}}\label{a}
\subsection{Один}
\subsubsection{Деталь}
\subsection{Два}
\section{Второй}
\subsection{Три}
\notestructheading{Заключение}
\end{document}"""
    lines = provisional_toc(tex).splitlines()
    assert lines == [
        r"\contentsline {section}{Введение}{0}{section*.0}%",
        r"\contentsline {section}{\numberline {1}Первый {\itshape раздел}}{0}{section.1}%",
        r"\contentsline {subsection}{\numberline {1.1}Один}{0}{subsection.1.1}%",
        r"\contentsline {subsubsection}{\numberline {1.1.1}Деталь}{0}{subsubsection.1.1.1}%",
        r"\contentsline {subsection}{\numberline {1.2}Два}{0}{subsection.1.2}%",
        r"\contentsline {section}{\numberline {2}Второй}{0}{section.2}%",
        r"\contentsline {subsection}{\numberline {2.1}Три}{0}{subsection.2.1}%",
        r"\contentsline {section}{Заключение}{0}{section*.0}%",
    ]


def _args(task: Path, out: Path) -> argparse.Namespace:
    return argparse.Namespace(task=str(task), out=str(out), quiet=True, no_pdf=True, no_sheets=True,
                              latexmk="latexmk", no_cache=True)


def test_watch_rebuilds_when_the_task_changes(tmp_path):
    task = tmp_path / "task.toml"
    task.write_text("a = 1\n", encoding="utf-8")
    seen = []

    def fake_build(path, *_args, **_kw):
        seen.append(Path(path).read_text(encoding="utf-8"))
        if len(seen) == 1:   # the student edits the file after the first build
            threading.Timer(0.05, lambda: task.write_text("a = 22\n", encoding="utf-8")).start()

    assert watch(_args(task, tmp_path / "out"), fake_build, max_builds=2, poll=0.01) == 0
    assert seen == ["a = 1\n", "a = 22\n"]


def test_watch_reports_a_bad_task_and_ends_cleanly_on_ctrl_c(tmp_path, capsys):
    task = tmp_path / "task.toml"
    task.write_text("a = 1\n", encoding="utf-8")
    calls = []

    def fake_build(*_args, **_kw):
        calls.append(1)
        if len(calls) == 1:
            threading.Timer(0.05, lambda: task.write_text("a = 2\n", encoding="utf-8")).start()
            raise TaskError("a", "made up", "b")
        raise KeyboardInterrupt

    assert watch(_args(task, tmp_path / "out"), fake_build, poll=0.01) == 0
    out = capsys.readouterr().out
    assert "error: a: made up" in out and "stopped watching" in out


PROBE_MAIN_IMPORTS = """
import json, sys
from pathlib import Path
from reportgen.commands import build as build_cmd, pipeline
pipeline._note = lambda *_, **__: (None, None)       # the sheets only: what the main process imports for them
build_cmd.build(sys.argv[1], Path(sys.argv[2]), quiet=True, pdf=False)
print(json.dumps({"ezdxf": "ezdxf" in sys.modules, "sheets": "drawings.sheets" in sys.modules,
                  "dxf": len(list(Path(sys.argv[2], "sheets").glob("*.dxf")))}))
"""


def test_the_sheets_process_lists_and_imports_the_sheets_itself(tmp_path):
    """The sheets' process is forked before the note's imports: ezdxf and the sheet modules are
    imported there, never by the main process (they were, to list the sheets, on the critical path)."""
    import json
    import os
    import subprocess
    import sys

    env = dict(os.environ, REPORTGEN_JOBS="2")
    out = subprocess.run([sys.executable, "-c", PROBE_MAIN_IMPORTS, str(PRESS), str(tmp_path / "out")],
                         capture_output=True, text=True, cwd=tmp_path, env=env, timeout=600)
    assert out.returncode == 0, out.stderr
    report = json.loads(out.stdout.strip().splitlines()[-1])
    assert report == {"ezdxf": False, "sheets": False, "dxf": 4}
