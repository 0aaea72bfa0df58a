"""The measurements of ``reportgen bench``: every approximation of the project against a converged
reference computed in the same run, with its time.

Each function returns a :class:`~reportgen.bench.tables.Table` and, where the approximation depends
on a number of positions, the series for the plot as ``{label: [(n, error, seconds), …]}``.
The per-stage scripts in ``benchmarks/`` measure the same solvers in more detail (every example);
this module measures the press example (or the example given) across the stages in one run.
"""
from __future__ import annotations

import math
import os
import shutil
import tempfile
import time
from pathlib import Path

import numpy as np

from .tables import Table, best_time, ms, pct, rel, sec

#: Numbers of positions compared for every position-count approximation.
POSITIONS = (8, 12, 24, 72, 360, 720)
QUICK_POSITIONS = (8, 12, 24)
#: The reference grid of the dynamics (piecewise Gauss–Legendre, 8 nodes per piece).
REFERENCE_N = 1440

Series = dict[str, list[tuple[int, float, float]]]


# -- 1. graphical differentiation of the s–v–a diagrams ---------------------------------------------

def diagrams_table(project, ns) -> tuple[Table, Series]:
    """The chord construction of the kinematic diagrams (as drawn, ordinates measured to 0.1 mm on a
    240 mm axis, and the bare chords without the measuring) against the exact v and a at the same
    angles (linear systems of the differentiated constraints)."""
    from ...diagrams import build_diagrams
    from ...kinematics.extremes import output_coordinate

    model, st = project.model, project.strokes
    phi0 = float(project.phi[0])
    sign = 1.0 if model.omega >= 0 else -1.0
    w = abs(model.omega)
    t = Table("diagrams", "Kinematic diagrams: graphical differentiation against the exact v, a "
              "(largest deviation / largest |exact|)",
              ["positions", "time, ms", "v drawn", "a drawn", "v chords", "a chords"])
    series: Series = {"diagrams v (drawn)": [], "diagrams a (drawn)": [], "diagrams v (chords)": [],
                      "diagrams a (chords)": []}
    for n in ns:
        dt, d = best_time(lambda n=n: build_diagrams(model, st, phi0, n=n), 3)
        # the bare chords: exact s at the division points, no measuring
        h = 2 * math.pi / n
        nodes = np.asarray(d.nodes)
        q, _ = model.positions(phi0 + sign * nodes)
        s = output_coordinate(model, st.output, q) * st.direction
        v_ch = np.diff(s) / h * w
        a_ch = (np.roll(v_ch, -1) - v_ch) / h * w
        vmax, amax = float(np.abs(d.v).max()), float(np.abs(d.a).max())
        ev_ch = float(np.abs(v_ch - d.v_mid_exact).max() / vmax)
        ea_ch = float(np.abs(a_ch - d.a_mid_exact).max() / amax)
        t.add(n, ms(dt), pct(d.v_deviation), pct(d.a_deviation), pct(ev_ch, 3), pct(ea_ch, 3))
        for k, e in (("diagrams v (drawn)", d.v_deviation), ("diagrams a (drawn)", d.a_deviation),
                     ("diagrams v (chords)", ev_ch), ("diagrams a (chords)", ea_ch)):
            series[k].append((n, e, dt))
    t.notes.append("drawn: the replica on the sheet (ordinates read to 0.1 mm, pole distances 10…80 mm); "
                   "chords: the same construction with exact ordinates. The chords converge as h²; the "
                   "drawing's 0.1 mm reading is divided by a chord of 240/n mm, so more positions make "
                   "the drawn replica worse beyond ~24 (the sheet uses 24).")
    return t, series


# -- 2. work integral and flywheel by number of positions --------------------------------------------

def _table_flywheel(cycle, theta: np.ndarray, delta: float) -> tuple[float, float]:
    """(work of a cycle, J_fly) from the n-position table the course fills in: the work by the
    periodic trapezoid rule on the positions, the Wittenbauer extremes taken at the positions only."""
    r = cycle.reduced(theta)
    h = 2 * math.pi / theta.size
    M = r.M
    A = np.concatenate(([0.0], np.cumsum((M[:-1] + M[1:]) / 2 * h)))
    work = float(A[-1] + (M[-1] + M[0]) / 2 * h)
    E = -work / (2 * math.pi) * theta + A
    wm = cycle.omega_m
    hi, lo = wm * (1 + delta / 2), wm * (1 - delta / 2)
    J = (np.max(E - r.J * hi * hi / 2) - np.min(E - r.J * lo * lo / 2)) / (wm * wm * delta)
    return work, float(J)


def dynamics_tables(project, ns) -> tuple[list[Table], Series]:
    from ...dynamics import EnergyProfile, ProjectCycle, graphical_replica, wittenbauer_exact
    from ...scenes.boxes import DEFAULT as DEFAULT_BOXES

    dyn = project.task.dynamics
    cycle = ProjectCycle(project, dyn.crank_inertia)
    delta = dyn.delta

    def exact(n, order=8):
        th = np.arange(n) * 2 * math.pi / n
        prof = EnergyProfile(cycle, th, order)
        return prof.work_cycle, wittenbauer_exact(cycle, prof, delta).J_fly

    t_ref, (W_ref, J_ref) = best_time(lambda: exact(REFERENCE_N), 1)
    W_half, J_half = exact(REFERENCE_N // 2)
    closed = None
    if project.strokes is not None:
        law_work = 0.0
        for ld in project.task.mechanism.loads:
            if ld.kind == "resistance" and ld.force is not None:
                xs = np.array([p[0] for p in ld.law])
                ys = np.array([p[1] for p in ld.law])
                law_work -= ld.force * project.strokes.stroke * float(np.sum(np.diff(xs) * (ys[:-1] + ys[1:]) / 2))
        closed = law_work if law_work else None

    tw = Table("work", "Work of the resistance over one cycle against the reference",
               ["positions", "trapezoid: time, ms", "error", "piecewise GL-8: time, ms", "error"])
    tj = Table("flywheel", f"Flywheel J against the reference (δ = {delta:g})",
               ["positions", "table: time, ms", "error", "exact (GL-8 + Brent): time, ms", "error",
                "graphical replica: time, ms", "error"])
    series: Series = {"work, trapezoid": [], "work, piecewise GL-8": [], "J, table of positions": [],
                      "J, exact method": [], "J, graphical replica": []}
    for n in ns:
        th = np.arange(n) * 2 * math.pi / n
        t_tab, (W_tab, J_tab) = best_time(lambda th=th: _table_flywheel(cycle, th, delta), 3)
        t_gl, (W_gl, J_gl) = best_time(lambda n=n: exact(n), 1)
        t_gr, gr = best_time(lambda n=n: graphical_replica(cycle, delta, n, layout=DEFAULT_BOXES.diagrams), 1)
        ew_tab, ew_gl = abs(W_tab / W_ref - 1), abs(W_gl / W_ref - 1)
        ej_tab, ej_gl, ej_gr = abs(J_tab / J_ref - 1), abs(J_gl / J_ref - 1), abs(gr.J_fly / J_ref - 1)
        tw.add(n, ms(t_tab), rel(ew_tab), ms(t_gl), rel(ew_gl))
        tj.add(n, ms(t_tab), pct(ej_tab, 3), ms(t_gl), rel(ej_gl), ms(t_gr), pct(ej_gr, 3))
        series["work, trapezoid"].append((n, ew_tab, t_tab))
        series["work, piecewise GL-8"].append((n, ew_gl, t_gl))
        series["J, table of positions"].append((n, ej_tab, t_tab))
        series["J, exact method"].append((n, ej_gl, t_gl))
        series["J, graphical replica"].append((n, ej_gr, t_gr))
    ref = (f"reference: piecewise Gauss–Legendre (8 nodes) on {REFERENCE_N} positions and the break angles, "
           f"J by the exact Wittenbauer equivalent with the extremes refined between nodes ({sec(t_ref)} s); "
           f"it moves by {rel(abs(W_half / W_ref - 1))} (work) and {rel(abs(J_half / J_ref - 1))} (J) "
           f"from {REFERENCE_N // 2} positions")
    tw.notes.append(ref)
    if closed is not None:
        tw.notes.append(f"closed form −F·s·∫law = {closed:.6f} J (gravity is conservative); the reference "
                        f"{W_ref:.6f} J differs by {rel(abs(W_ref / closed - 1))}")
    tw.notes.append("trapezoid: the periodic rule on the positions (the resistance switches on and off at "
                    "the stroke ends, so it converges algebraically); GL-8: 8 Gauss–Legendre nodes on every "
                    "piece between positions and the switching angles (what results.json uses, n = 360)")
    tj.notes.append(f"reference J = {J_ref:.6f} kg·m²; table: ΔE by the trapezoid rule and the tangents' "
                    "extremes taken at the positions only (a hand calculation on n positions); exact: what "
                    "results.json reports; graphical replica: the construction with its mm readings and the "
                    "course's (1 ± δ) tangent slopes (errs by ~δ²/4 even when converged)")
    return [tw, tj], series


# -- 3. graphical replicas at the sheet's scales -----------------------------------------------------

def replicas_table(project) -> Table:
    from ...kinetostatics import kinetostatics_at
    from ...plans import build_plans

    t = Table("replicas", "Graphical replicas at the sheet's scales against the exact values",
              ["replica", "compared", "largest relative deviation", "time, ms"])
    kin = project.kinematics
    n = len(kin.phi)

    def plans():
        return [build_plans(project.linkage, project.structure, kin, i) for i in range(n)]

    dt, pl = best_time(plans, 3)
    for j, name in ((0, "velocity plans"), (1, "acceleration plans")):
        devs = [abs(p[j].deviation(c)) for p in pl for c in p[j].components if p[j].length_mm(c) >= 20.0]
        t.add(f"{name} ({n} positions)", f"{len(devs)} vectors ≥ 20 mm", rel(max(devs)), ms(dt / 2))
    dt, ks = best_time(lambda: kinetostatics_at(project), 1)
    g = ks.graphical
    vecs = [v for poly in [gg.polygon for gg in g.groups] + [g.crank.polygon]
            for v in poly.vectors + poly.extra if not v.known and v.length_mm > 20]
    t.add(f"force polygons (φ1 = {ks.phi_deg:.1f}°)", f"{len(vecs)} reactions ≥ 20 mm",
          rel(max(abs(v.deviation_percent) for v in vecs) / 100), ms(dt))
    Mx = ks.balancing_moment
    t.add("balancing moment, groups (polygons)", "M_ур", rel(abs(g.crank.balancing_moment_measured / Mx - 1)), "")
    t.add("balancing moment, Zhukovsky's lever", "M_ур", rel(abs(g.lever.balancing_moment_measured / Mx - 1)), "")
    t.add("groups vs lever, exact methods", "M_ур", rel(abs(ks.discrepancy_percent) / 100), "")
    if project.task.dynamics is not None:
        from ...dynamics import dynamics_of
        dt, d = best_time(lambda: dynamics_of(project), 1)
        t.add(f"Wittenbauer construction ({d.graphical.theta.size - 1} points)",
              "J_fly", rel(abs(d.graphical.J_fly / d.exact.J_fly - 1)), ms(dt))
        t.notes.append("the Wittenbauer time is the whole dynamics stage (exact, Мерцалов, replica, motion)")
    t.notes.append("plans and polygons: every drawn length read to 0.1 mm, the value read back against the "
                   "exact one; vectors shorter than 20 mm are left out (their reading error is a larger share)")
    return t


# -- 4. planetary search -------------------------------------------------------------------------------

def planetary_table(project, bounds) -> Table:
    from ...planetary.search import search, synthesize

    p = project.task.planetary
    st = project.planetary
    scheme, target, tol = p.scheme, st.target, p.tolerance
    t = Table("planetary", f"Planetary search: time against the range searched ({scheme}, u = {target:.4f} "
              f"± {tol * 100:g} %, K auto)",
              ["largest z searched", "time, ms", "valid sets", "most compact set", "ratio error"])
    for b in bounds:
        dt, found = best_time(lambda b=b: search(scheme, target, tol, p.satellites, count=10 ** 9, max_teeth=b), 1)
        if found:
            c = found[0]
            t.add(b, ms(dt), len(found), "/".join(map(str, c.z)) + f", K = {c.satellites}", pct(abs(c.deviation), 3))
        else:
            t.add(b, ms(dt), 0, "—", "—")
    dt, d = best_time(lambda: synthesize(scheme, target, tol, p.satellites, p.module), 3)
    t.notes.append(f"what `build` runs (synthesize: bounds grow from 128 until 6 sets are found): {ms(dt)} ms, "
                   f"z = {'/'.join(map(str, d.z))}, K = {d.satellites}")
    return t


# -- 7. the control work: answer keys and notes of many variants (reportgen batch) --------------------

def batch_table(quick: bool) -> Table:
    """Wall time of `reportgen batch`: the answer keys of every variant of the 22 tables, and the full
    notes (PDF + sheet) of one table's 10 variants, with 1 and 2 processes (a cold output folder each)."""
    from ..batch import batch, variant_job
    from ...control.tables import tables

    t = Table("batch", "Wall time of `reportgen batch` (control work, seed 001)",
              ["run", "variants", "processes", "time, s", "per variant, s"])
    every = [variant_job(tb.number, v) for tb in tables() for v in range(1, 11)]
    runs = [("answer keys, all tables", every if not quick else every[:20], True, (1, 2))]
    if not quick and shutil.which("latexmk") is not None:
        runs.append(("full notes (PDF + sheet), table 1", every[:10], False, (1, 2)))
    for name, jobs, answers, procs in runs:
        for j in procs:
            with tempfile.TemporaryDirectory(prefix="reportgen-bench-") as tmp:
                t0 = time.perf_counter()
                out = batch(jobs, Path(tmp) / "out", answers_only=answers, workers=j, quiet=True)
                dt = time.perf_counter() - t0
            failed = sum(o.error is not None for o in out)
            t.add(name, f"{len(jobs)}" + (f" ({failed} failed)" if failed else ""), j, sec(dt), sec(dt / len(jobs)))
    t.notes.append("the failed variant is table 5, variant 7 (its printed triangle cannot be formed)")
    t.notes.append(f"{os.cpu_count()} cores, shared with other work: times vary from run to run")
    return t
