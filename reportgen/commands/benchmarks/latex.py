"""Where an xelatex pass of the note spends its time (``reportgen bench``, issue 16): starting xelatex
with its format, the note's preamble (class, packages, fonts), the body, and xdvipdfmx.

The note is built once without sheets; then each program is run a few times on its files and the
best wall and CPU times are kept (the machine is shared). The preamble is measured on the note's own
preamble with an empty body, the start on an empty ``article``; the body is the whole pass minus
the preamble. These say what a dumped format could save (docs/build.md: the packages only, not the
fonts' set-up) and what the passes beside the figures hide.
"""
from __future__ import annotations

import math
import os
import resource
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

from reportgen.errors import BuildError

from .tables import Table, sec

#: A document with nothing in it: the time xelatex takes to start and load its format.
_EMPTY = "\\documentclass{article}\\begin{document}\\end{document}\n"


def _best(cmd: list[str], cwd: Path, env: dict[str, str], repeat: int) -> tuple[float, float]:
    """(best wall time, best CPU time) of ``repeat`` runs of ``cmd``, s; raise on a failed run."""
    wall = cpu = math.inf
    for _ in range(repeat):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        r = subprocess.run(cmd, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        wall = min(wall, time.perf_counter() - t0)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = min(cpu, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime))
        if r.returncode != 0:
            raise BuildError("bench: LaTeX pass", f"{cmd[0]} stopped with status {r.returncode}")
    return wall, cpu


def pass_table(task_path: Path, quick: bool, repeat: int = 3) -> Table:
    """One xelatex pass of the task's note, split into start, preamble and body; xdvipdfmx."""
    t = Table("latex-pass", f"One xelatex pass of the note of `{task_path.parent.name}/{task_path.name}`: "
              f"where its time goes (best of {repeat} runs)", ["part", "wall, s", "CPU, s"])
    if quick or not all(shutil.which(p) for p in ("xelatex", "xdvipdfmx")):
        t.notes.append("not measured: " + ("--quick" if quick else "xelatex or xdvipdfmx not found"))
        return t
    from latex_templates.build import BUILD_DIR, tex_env
    from latex_templates.passes import xdvipdfmx_command, xelatex_command

    from ..build import build

    with tempfile.TemporaryDirectory(prefix="reportgen-bench-") as tmp:
        out = Path(tmp) / "out"
        try:
            build(str(task_path), out, quiet=True, pdf=True, sheets=False, cache=False)
            tex = (out / "report.tex").read_text(encoding="utf-8")
            (out / "preamble.tex").write_text(tex.split("\\begin{document}", 1)[0]
                                              + "\\begin{document}\n\\end{document}\n", encoding="utf-8")
            (out / "empty.tex").write_text(_EMPTY, encoding="utf-8")
            (out / "alone").mkdir()
            env = tex_env(None)
            start = _best(xelatex_command("empty.tex", "alone"), out, env, repeat)
            preamble = _best(xelatex_command("preamble.tex", "alone"), out, env, repeat)
            whole = _best(xelatex_command("report.tex", BUILD_DIR), out, env, repeat)
            pdf = _best(xdvipdfmx_command("report", BUILD_DIR), out, env, repeat)
        except Exception as exc:  # noqa: BLE001 - a benchmark reports, it does not hide the other tables
            t.notes.append(f"not measured: {type(exc).__name__}: {str(exc).splitlines()[0][:300]}")
            return t
    t.add("xelatex started, its format loaded (an empty article)", sec(start[0]), sec(start[1]))
    t.add("the note's preamble (class, packages, fonts' set-up)",
          sec(preamble[0] - start[0]), sec(preamble[1] - start[1]))
    t.add("the note's body (whole pass − preamble − start)", sec(whole[0] - preamble[0]), sec(whole[1] - preamble[1]))
    t.add("a whole pass", sec(whole[0]), sec(whole[1]))
    t.add("xdvipdfmx (the PDF from the last pass)", sec(pdf[0]), sec(pdf[1]))
    t.notes.append("a cold build runs two passes, both beside the figures' saving: pass 1 reads its preamble while "
                   "the figures' placeholders are written, the passes go on on the placeholders until the aux files "
                   "are stable, and only xdvipdfmx waits for the figures (docs/build.md)")
    t.notes.append(f"load average at the end: {os.getloadavg()[0]:.1f} (1 min) on {os.cpu_count()} processors")
    return t
