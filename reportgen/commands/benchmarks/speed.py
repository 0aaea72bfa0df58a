"""The speed tables of ``reportgen bench`` (issue 16): the build's critical path, cold / warm /
incremental builds as whole processes, the solver in process and as a process, and the four-bar
against pylinkage with and without the model build.

Times of whole processes are medians of a few runs (the machine is shared: the spread is printed);
in-process times are medians of interleaved runs, and a ratio is the median of the ratios taken
pair by pair (A, B, A, B, …) so that a drift of the machine's speed cancels.
"""
from __future__ import annotations

import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from typing import cast
from pathlib import Path

import numpy as np

from ...errors import ComputationError
from .tables import Table, ms, rel, sec


def _median_spread(xs: list[float]) -> tuple[float, float, float]:
    return statistics.median(xs), min(xs), max(xs)


def _fmt_s(xs: list[float]) -> str:
    m, lo, hi = _median_spread(xs)
    return f"{m:.2f} ({lo:.2f}–{hi:.2f})"


def _run(args: list[str], env: dict[str, str], cwd: Path, cpu: list[float] | None = None,
         stdout: list[str] | None = None) -> float:
    """Wall time of ``reportgen ARGS`` as a process; its CPU time (user + system, with its children:
    the sheets' and figures' processes, latexmk and xelatex) appended to ``cpu`` when given, its
    standard output to ``stdout``."""
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "reportgen", *args], env=env, cwd=cwd,
                       capture_output=True, text=True, timeout=1800)
    dt = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise ComputationError("reportgen " + " ".join(args[:1]), (r.stderr or r.stdout).strip().splitlines()[-1][:300])
    if cpu is not None:
        cpu.append((after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime))
    if stdout is not None:
        stdout.append(r.stdout)
    return dt


# -- the build: critical path, cold, warm, incremental --------------------------------------------------

def critical_path_table(task_path: Path, quick: bool) -> Table:
    """One cold build in process with the spans of its stages: what ran in parallel, what waited."""
    from ..build import build
    from ..pipeline import Timeline

    pdf = not quick and shutil.which("latexmk") is not None
    t = Table("critical-path", f"The stages of `reportgen build {task_path.parent.name}/{task_path.name}`: "
              "what runs in parallel, what waits (one cold build in process)",
              ["lane", "stage", "start, s", "end, s", "time, s"])
    timeline = Timeline(quiet=True)
    with tempfile.TemporaryDirectory(prefix="reportgen-bench-") as tmp:
        try:
            build(str(task_path), Path(tmp) / "out", quiet=True, pdf=pdf, sheets=not quick, cache=False,
                  timeline=timeline)
        except Exception as exc:  # a benchmark reports a failed build, it does not hide the other tables
            t.notes.append(f"the build failed: {type(exc).__name__}: {str(exc).splitlines()[0][:300]}")
            return t
    end = 0.0
    for lane, name, a, b in timeline.critical_path():
        t.add(lane, name, sec(a), sec(b), sec(b - a))
        end = max(end, b)
    t.notes.append(f"the whole build: {end:.2f} s in this process (its imports done before); lanes: main = the "
                   "Python process (solve, the note's sections and report.tex, then its figures: half of them saved "
                   "by a second forked process meanwhile; results.json, then it waits), sheets = a forked process "
                   "at a lower priority (DXF + PNG preview of each sheet), LaTeX = xelatex's passes and xdvipdfmx "
                   "(latex_templates/passes.py; pass 1 reads its preamble while the placeholders of the figures' sizes are "
                   "written, then the passes run on them while the figures are saved, until the aux files are stable; "
                   "xdvipdfmx once the figures are there)")
    t.notes.append("the critical path is main (solve → note's sections → figure sizes → figures) → xdvipdfmx, with LaTeX's "
                   "passes beside the figures (on the critical path when they end later); the sheets overlap the note and LaTeX")
    t.notes.append(_load_note())
    t.notes.append(_compiled_note())
    if not pdf:
        t.notes.append("LaTeX not run (" + ("--quick" if quick else "latexmk not found") + ")")
    return t


def builds_table(task_path: Path, quick: bool, runs: int = 3) -> Table:
    """Cold, warm (unchanged task) and incremental (one number changed) builds as whole processes."""
    t = Table("builds", f"`reportgen build {task_path.parent.name}/{task_path.name}` as a process, "
              "all outputs (PDF, sheets, previews, results.json)",
              ["build", "wall, s: median (min–max)", "CPU, s: median", "runs"])
    if shutil.which("latexmk") is None or quick:
        t.notes.append("not measured: " + ("--quick" if quick else "latexmk not found"))
        return t
    with tempfile.TemporaryDirectory(prefix="reportgen-bench-") as tmp:
        base = Path(tmp)
        task = base / "task.toml"
        text = task_path.read_text(encoding="utf-8")
        task.write_text(text, encoding="utf-8")
        env = dict(os.environ, REPORTGEN_CACHE=str(base / "cache"))
        cold, warm = [], []
        edits = _one_number_changed(text, runs)
        inc: dict[str, list[float]] = {name: [] for name in edits}
        cpu: dict[str, list[float]] = {"cold": [], "warm": [], **{name: [] for name in edits}}
        said: dict[str, list[str]] = {name: [] for name in edits}
        try:
            for i in range(runs):
                cold.append(_run(["build", str(task), "-o", str(base / f"cold{i}"), "--quiet", "--no-cache"], env, base,
                                 cpu["cold"]))
            _run(["build", str(task), "-o", str(base / "fill"), "--quiet"], env, base)
            for i in range(runs):
                warm.append(_run(["build", str(task), "-o", str(base / f"warm{i}"), "--quiet"], env, base, cpu["warm"]))
            for name, texts in edits.items():
                for i, changed in enumerate(texts):
                    task.write_text(changed, encoding="utf-8")
                    inc[name].append(_run(["build", str(task), "-o", str(base / f"inc-{len(said[name])}-{i}")],
                                          env, base, cpu[name], said[name]))
        except Exception as exc:  # noqa: BLE001 - report, do not hide the other tables
            t.notes.append(f"a build failed: {exc}")
        rows = [("cold (no cache)", "cold", cold), ("warm (unchanged task, from the cache)", "warm", warm)]
        rows += [(f"incremental ({name} changed)", name, inc[name]) for name in edits]
        for label, key, xs in rows:
            if xs:
                t.add(label, _fmt_s(xs), f"{statistics.median(cpu[key]):.2f}" if cpu[key] else "—", str(len(xs)))
        for name, outs in said.items():
            reuse = [line.strip() for out in outs[-1:] for line in out.splitlines() if line.strip().startswith("figures:")]
            if reuse:
                t.notes.append(f"{name} changed, the last run: {reuse[0]}")
            counts = [m.group(1) for out in outs for m in [re.search(r"xelatex passes: (\d+)", out)] if m]
            if counts:      # a run whose pages moved needs a second pass: the spread of the wall times
                t.notes.append(f"{name} changed: xelatex passes of each run: {', '.join(counts)}")
    t.notes.append("each run a fresh process (imports included); the machine is shared, so the spread is shown; "
                   "CPU: user + system time of the process and its children (the sheets' and figures' processes, "
                   "latexmk, xelatex) — on 2 processors the wall time cannot be less than half of it")
    t.notes.append("incremental: each run changes one number of the task file (δ; the last link's mass) to a value "
                   "not built before, in the same file, after the builds above; the figures, the note's sections and "
                   "the sheets whose inputs did not change come from the cache (keyed by content and by what they read: "
                   "docs/build.md), LaTeX's first pass starts before the solve on the last build's preamble and aux "
                   "files and is the only one unless the aux files change")
    t.notes.append("cold: `--no-cache`, nothing read from or written to the cache (compiled templates, previews, "
                   "LaTeX's aux files); warm and incremental: the cache as a student's second build has it")
    t.notes.append(_load_note())
    t.notes.append(_compiled_note())
    return t


def _compiled_note() -> str:
    """Whether the install-time compilation (``make compiled``: the modules' bytecode, the Jinja
    store of latex_templates/precompiled.py) was there: without it each process compiles them."""
    import importlib.util

    from latex_templates.precompiled import STORE

    def fresh(module: str) -> bool:
        spec = importlib.util.find_spec(module)
        if spec is None or spec.origin is None:
            return False
        cached = Path(importlib.util.cache_from_source(spec.origin))
        return cached.is_file() and cached.stat().st_mtime >= Path(spec.origin).stat().st_mtime

    code = all(fresh(m) for m in ("reportgen.project", "latex_templates.note", "drawings.sheet"))
    return ("compiled at install time (`make compiled`, docs/build.md): modules' bytecode "
            f"{'there' if code else 'NOT there (each process compiles its modules)'}, Jinja store "
            f"{'there' if STORE.is_file() else 'NOT there (each build compiles the templates)'}")


def _load_note() -> str:
    """The machine's load when a table was measured (other work shares the processors)."""
    try:
        one, five, _ = os.getloadavg()
    except OSError:
        return "load average: not known on this system"
    return (f"load average at the end: {one:.1f} (1 min), {five:.1f} (5 min) on {os.cpu_count()} processors — "
            "above the processor count the wall times are mostly waiting; compare the CPU times")


def _one_number_changed(text: str, runs: int) -> dict[str, list[str]]:
    """The task with one number changed to a new value for each run (a value met before would be
    a cache hit): δ (the first ``delta = …``), the last link's mass (the last ``mass = …``: the press's
    slider, link 5); an edit the task has no line for is left out."""
    import re
    out: dict[str, list[str]] = {}
    for name, pattern, last in (("δ", r"(?m)^delta\s*=\s*([0-9.]+)", False), ("mass", r"(?m)^mass\s*=\s*([0-9.]+)", True)):
        found = list(re.finditer(pattern, text))
        if not found:
            continue
        m = found[-1] if last else found[0]
        v = float(m.group(1))
        out[name] = [text[:m.start(1)] + repr(round(v * (0.80 + 0.03 * i), 6)) + text[m.end(1):] for i in range(runs)]
    return out


# -- the solver -----------------------------------------------------------------------------------------

def solver_table(task_path: Path, quick: bool) -> Table:
    """All stages over 360 positions in process (model included) and `reportgen solve` as a process."""
    from ...project import Project
    from ...taskfile import load_task

    t = Table("solver", f"The solver on {task_path.parent.name}/{task_path.name}",
              ["what", "time, ms: median (min–max)", "CPU, ms: median", "runs"])
    task = load_task(task_path)

    import dataclasses

    def linkage_stages():
        from ...dynamics.solve import solve_dynamics
        from ...kinetostatics.analysis import balancing_cycle
        an = dataclasses.replace(task.analysis, positions=360)
        p = Project(dataclasses.replace(task, analysis=an))
        balancing_cycle(p, p.phi)          # reactions group by group and Zhukovsky's lever at every position
        if task.dynamics is not None:
            solve_dynamics(p)
        return p

    def gear_stages():
        p = Project(task)
        if task.gears is not None:
            _ = p.gears         # the stage is computed on first access
        if task.planetary is not None:
            _ = p.planetary
        return p

    rows = []
    if task.mechanism is not None:
        rows.append(("in process: model, kinematics, kinetostatics (both methods), dynamics over 360 positions",
                     linkage_stages))
    if task.gears is not None or task.planetary is not None:
        rows.append(("in process: gear pair and planetary synthesis", gear_stages))
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    for label, fn in rows:
        fn()
        xs, cpu = [], []
        for _ in range(3 if quick else 15):
            t0, c0 = time.perf_counter(), time.process_time()
            fn()
            xs.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
        m, lo, hi = _median_spread([x * 1e3 for x in xs])
        t.add(label, f"{m:.1f} ({lo:.1f}–{hi:.1f})", f"{statistics.median(cpu) * 1e3:.1f}", str(len(xs)))
    env = dict(os.environ, REPORTGEN_CACHE="off")
    ps: list[float] = []
    ps_cpu: list[float] = []
    with tempfile.TemporaryDirectory(prefix="reportgen-bench-") as tmp:
        for _ in range(2 if quick else 5):
            try:
                ps.append(_run(["solve", str(task_path.resolve()), "--json", str(Path(tmp) / "r.json"), "--quiet"], env,
                               Path(tmp), ps_cpu))
            except Exception as exc:  # noqa: BLE001
                t.notes.append(f"`reportgen solve` failed: {exc}")
                break
    if ps:
        m, lo, hi = _median_spread([x * 1e3 for x in ps])
        t.add("`reportgen solve TASK --json OUT` as a process (imports included)", f"{m:.0f} ({lo:.0f}–{hi:.0f})",
              f"{statistics.median(ps_cpu) * 1e3:.0f}", str(len(ps)))
        t.notes.append(f"`reportgen solve` as a process: CPU (user + system) {statistics.median(ps_cpu) * 1e3:.0f} ms "
                       "median; its wall time above that is the wait for a processor on a shared machine; "
                       f"BLAS threads: {os.environ.get('OPENBLAS_NUM_THREADS', 'not set')} (the command line asks "
                       "for one: OpenBLAS's second thread spun on the free processor, CPU above the wall time, "
                       "docs/build.md «BLAS threads»)")
    t.notes.append("in process: a new Project each run (the model built again), [analysis] positions set to "
                   "360; the kinetostatics at all of them, the dynamics on its own 360-step grid; CPU: the "
                   f"process's own time (`time.process_time`), comparable on a loaded machine (1-minute load "
                   f"average at the start: {load:.2f} on {os.cpu_count()} processors)")
    t.notes.append("where the in-process time goes: the dynamics asks the kinematics for M_red and J_red at "
                   "≈ 8 500 distinct angles (the energy's Gauss–Legendre nodes, the extreme search's samples and "
                   "their nodes, the graphical replica), each angle once per project "
                   "(`reportgen/dynamics/memo.py`), without accelerations where dJ_red is not read; the dead "
                   "centres' Brent searches run in lockstep (one solve per step for both)")
    return t


# -- pylinkage ----------------------------------------------------------------------------------------

FOUR_BAR = (0.1, 0.35, 0.3, 0.4)   # crank, coupler, rocker, frame (m): a Grashof crank–rocker


def pylinkage_table(n: int = 360, pairs: int = 15) -> Table:
    """The same four-bar in both, interleaved: reportgen's solve alone, with its model build (from
    the Mechanism, and from the task's TOML text), and pylinkage's two paths (its linkage is
    stateful, so it is built inside every run)."""
    from ...kinematics import build_model
    from ...task import Mechanism
    from ...taskfile import loads_task
    from ...zoo import four_bar

    t = Table("pylinkage", f"The same four-bar (crank–rocker {'/'.join(f'{v:g}' for v in FOUR_BAR)} m, "
              f"ω1 = 10 rad/s) over {n} positions with v and a: pylinkage and reportgen",
              ["solver", "ms: median (min–max)", "pylinkage / this: median of pairs", "fastest / fastest",
               "CPU, ms: median", "pylinkage / this, CPU: median of pairs", "max |Δ pos|, m",
               "max |Δ v|, m/s", "max |Δ a|, m/s²"])
    try:
        import pylinkage
        from pylinkage.actuators import Crank
        from pylinkage.components import Ground
        from pylinkage.dyads import RRRDyad
        from pylinkage.simulation import Linkage
    except ImportError:
        t.notes.append("pylinkage is not installed: `pip install 'reportgen[bench]'` (or `pip install pylinkage`) "
                       "to compare")
        return t
    a, b, c, d = FOUR_BAR
    omega = 10.0
    phi = np.arange(1, n + 1) * 2 * math.pi / n      # pylinkage turns the crank before it solves
    text = four_bar(a, b, c, d, phi_deg=0.0, omega=omega, name=None, analysis=None)
    mech = loads_task(text).mechanism
    assert mech is not None  # four_bar writes a [mechanism]
    model = build_model(mech)
    r = model.solve(phi)
    B0 = r.points["B"].pos[-1]

    def make():
        O, C = Ground(0.0, 0.0, name="O"), Ground(d, 0.0, name="C")
        cr = Crank(O, a, angular_velocity=2 * math.pi / n, initial_angle=0.0, name="A")
        rr = RRRDyad(cr.output, C, distance1=b, distance2=c, x=float(B0[0]), y=float(B0[1]), name="B")
        lk = Linkage([O, C, cr, rr], name="four-bar")
        lk.set_input_velocity(cr, omega=omega)
        return lk

    def py_loop():
        out = list(make().step_with_derivatives(iterations=n))
        return (np.array([o[0][3] for o in out]), np.array([o[1][3] for o in out]),
                np.array([o[2][3] for o in out]))

    def rg(result):
        pm = result.points["B"]
        return pm.pos, pm.vel, pm.acc

    ours = {
        "reportgen, model built once outside the timing": lambda: rg(model.solve(phi)),
        "reportgen, model built inside (from the Mechanism)": lambda: rg(build_model(mech).solve(phi)),
        "reportgen, task text parsed and model built inside": lambda: rg(build_model(cast(Mechanism, loads_task(text).mechanism)).solve(phi)),
    }
    times: dict[str, list[float]] = {k: [] for k in ours}
    cpus: dict[str, list[float]] = {k: [] for k in ours}
    py_times: list[float] = []
    py_cpus: list[float] = []
    ratios: dict[str, list[float]] = {k: [] for k in ours}
    cpu_ratios: dict[str, list[float]] = {k: [] for k in ours}
    py_out = None
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    for _ in range(pairs):
        t0, c0 = time.perf_counter(), time.process_time()
        py_out = py_loop()
        tp, cp = time.perf_counter() - t0, time.process_time() - c0
        py_times.append(tp)
        py_cpus.append(cp)
        for k, fn in ours.items():
            t0, c0 = time.perf_counter(), time.process_time()
            fn()
            tk, ck = time.perf_counter() - t0, time.process_time() - c0
            times[k].append(tk)
            cpus[k].append(ck)
            ratios[k].append(tp / tk)
            cpu_ratios[k].append(cp / ck if ck > 0 else float("nan"))
    P, V, A = rg(r)
    for k in ours:
        m, lo, hi = _median_spread([x * 1e3 for x in times[k]])
        t.add(k, f"{ms(m / 1e3)} ({ms(lo / 1e3)}–{ms(hi / 1e3)})", f"{statistics.median(ratios[k]):.1f}",
              f"{min(py_times) / min(times[k]):.1f}", ms(statistics.median(cpus[k])),
              f"{statistics.median(cpu_ratios[k]):.1f}", "—", "—", "—")
    assert py_out is not None  # the loop above ran at least once
    p, v, acc = py_out
    m, lo, hi = _median_spread([x * 1e3 for x in py_times])
    t.add("pylinkage step_with_derivatives (linkage built inside)", f"{ms(m / 1e3)} ({ms(lo / 1e3)}–{ms(hi / 1e3)})",
          "1", "1", ms(statistics.median(py_cpus)), "1", rel(float(np.abs(p - P).max())), rel(float(np.abs(v - V).max())),
          rel(float(np.abs(acc - A).max())))
    t.notes.append(f"pylinkage {getattr(pylinkage, '__version__', '?')}; {pairs} interleaved rounds (pylinkage, then "
                   "each reportgen variant); ratios: the median of the per-round ratios, and the fastest run of each "
                   "against the fastest of the other (the least disturbed by other load); Δ = the largest "
                   f"difference of point B between the two (|a_B| up to {float(np.hypot(*A.T).max()):.1f} m/s²); "
                   "CPU: each call's own processor time (`time.process_time`), which a loaded machine does not "
                   "inflate as it does the wall time (pylinkage's longer pure-Python loop is interrupted more "
                   f"often); 1-minute load average at the start: {load:.2f} on {os.cpu_count()} processors. "
                   "Issue 16's target: ≥ 5× with the model built inside")
    t.notes.append("reportgen solves positions (closed form), then velocities and accelerations (one linear system "
                   "per group and position, the Jacobian shared); point motions are derived from q, q̇, q̈ when "
                   "read (here: B)")
    try:
        import numba  # noqa: F401
    except ImportError:
        t.notes.append("numba is not installed, so pylinkage's fast path (step_fast_with_kinematics) is not compared")
    return t
