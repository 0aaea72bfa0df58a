"""The measurements of ``reportgen bench``: every approximation of the project against a converged
reference computed in the same run, with its time.

Each function returns a :class:`~reportgen.bench.tables.Table` and, where the approximation depends
on a number of positions, the series for the plot as ``{label: [(n, error, seconds), …]}``.
The per-stage scripts in ``benchmarks/`` measure the same solvers in more detail (every example);
this module measures the press example (or the example given) across the stages in one run.
"""
from __future__ import annotations

import math
import shutil
import tempfile
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
    from ..diagrams import build_diagrams
    from ..kinematics.extremes import output_coordinate

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
        dt, d = best_time(lambda: build_diagrams(model, st, phi0, n=n), 3)
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
    from ..dynamics import EnergyProfile, ProjectCycle, graphical_replica, wittenbauer_exact

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
        t_tab, (W_tab, J_tab) = best_time(lambda: _table_flywheel(cycle, th, delta), 3)
        t_gl, (W_gl, J_gl) = best_time(lambda: exact(n), 1)
        t_gr, gr = best_time(lambda: graphical_replica(cycle, delta, n), 1)
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
    from ..kinetostatics import kinetostatics_at
    from ..plans import build_plans

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
        from ..dynamics import dynamics_of
        dt, d = best_time(lambda: dynamics_of(project), 1)
        t.add(f"Wittenbauer construction ({d.graphical.theta.size - 1} points)",
              "J_fly", rel(abs(d.graphical.J_fly / d.exact.J_fly - 1)), ms(dt))
        t.notes.append("the Wittenbauer time is the whole dynamics stage (exact, Мерцалов, replica, motion)")
    t.notes.append("plans and polygons: every drawn length read to 0.1 mm, the value read back against the "
                   "exact one; vectors shorter than 20 mm are left out (their reading error is a larger share)")
    return t


# -- 4. planetary search -------------------------------------------------------------------------------

def planetary_table(project, bounds) -> Table:
    from ..planetary.search import search, synthesize

    p = project.task.planetary
    st = project.planetary
    scheme, target, tol = p.scheme, st.target, p.tolerance
    t = Table("planetary", f"Planetary search: time against the range searched ({scheme}, u = {target:.4f} "
              f"± {tol * 100:g} %, K auto)",
              ["largest z searched", "time, ms", "valid sets", "most compact set", "ratio error"])
    for b in bounds:
        dt, found = best_time(lambda: search(scheme, target, tol, p.satellites, count=10 ** 9, max_teeth=b), 1)
        if found:
            c = found[0]
            t.add(b, ms(dt), len(found), "/".join(map(str, c.z)) + f", K = {c.satellites}", pct(abs(c.deviation), 3))
        else:
            t.add(b, ms(dt), 0, "—", "—")
    dt, d = best_time(lambda: synthesize(scheme, target, tol, p.satellites, p.module), 3)
    t.notes.append(f"what `build` runs (synthesize: bounds grow from 128 until 6 sets are found): {ms(dt)} ms, "
                   f"z = {'/'.join(map(str, d.z))}, K = {d.satellites}")
    return t


# -- 5. stages of `reportgen build` --------------------------------------------------------------------

def build_table(task_path: Path, quick: bool, build) -> Table:
    """``build`` is :func:`reportgen.commands.build.build` (passed in by the command layer)."""
    pdf = not quick and shutil.which("latexmk") is not None
    t = Table("build", f"Wall time of the stages of `reportgen build {task_path.parent.name}/{task_path.name}`",
              ["stage", "time, s"])
    with tempfile.TemporaryDirectory(prefix="reportgen-bench-") as tmp:
        out = Path(tmp) / "out"
        try:
            times = build(str(task_path), out, quiet=True, pdf=pdf, sheets=not quick)
        except Exception as exc:  # a benchmark reports a failed build, it does not hide the other tables
            t.notes.append(f"the build failed: {type(exc).__name__}: {str(exc).splitlines()[0][:300]}")
            return t
    for k, v in times.items():
        t.add(k, sec(v))
    t.add("total", sec(sum(times.values())))
    if not pdf:
        t.notes.append("LaTeX not run (" + ("--quick" if quick else "latexmk not found") + ")")
    if quick:
        t.notes.append("sheets not drawn (--quick)")
    t.notes.append("one cold run in a fresh process's first build: imports and caches count here")
    return t


# -- 6. pylinkage side by side -------------------------------------------------------------------------

FOUR_BAR = (0.1, 0.35, 0.3, 0.4)   # crank, coupler, rocker, frame (m): a Grashof crank–rocker


def _four_bar_model(a, b, c, d, omega):
    from ..kinematics import build_model
    from ..taskfile import loads_task
    from ..zoo import four_bar
    # sketch at φ1 = 0: A = (a, 0); B above the frame
    text = four_bar(a, b, c, d, phi_deg=0.0, omega=omega, name=None, analysis=None)
    return build_model(loads_task(text).mechanism)


def pylinkage_table(n: int = 360) -> Table:
    t = Table("pylinkage", f"The same four-bar (crank–rocker {'/'.join(f'{v:g}' for v in FOUR_BAR)} m, "
              f"ω1 = 10 rad/s) over {n} positions: pylinkage and reportgen",
              ["solver", "positions + v + a, ms", "time / reportgen", "max |Δ pos|, m", "max |Δ v|, m/s",
               "max |Δ a|, m/s²"])
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
    model = _four_bar_model(a, b, c, d, omega)
    t_rg, r = best_time(lambda: model.solve(phi), 7)
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

    def py_fast():
        p, v, acc = make().step_fast_with_kinematics(iterations=n)
        return p[:, 3], v[:, 3], acc[:, 3]

    t.add("reportgen (vectorised closed form + linear systems)", ms(t_rg), "1", "—", "—", "—")
    P, V, A = r.points["B"].pos, r.points["B"].vel, r.points["B"].acc
    for label, fn in (("pylinkage step_with_derivatives", py_loop), ("pylinkage step_fast_with_kinematics", py_fast)):
        try:
            dt, (p, v, acc) = best_time(fn, 5)
        except Exception as exc:  # an optional third-party path: report it, do not fail the run
            t.add(label, "failed", "", type(exc).__name__, "", "")
            continue
        t.add(label, ms(dt), f"{dt / t_rg:.1f}", rel(float(np.abs(p - P).max())), rel(float(np.abs(v - V).max())),
              rel(float(np.abs(acc - A).max())))
    t.notes.append(f"pylinkage {getattr(pylinkage, '__version__', '?')}; Δ = the largest difference of point B "
                   f"between the two (|a_B| up to {float(np.hypot(*A.T).max()):.1f} m/s²); best of 5–7 runs, the "
                   "model built once outside the timing for reportgen, inside it for pylinkage (its linkage is "
                   "stateful)")
    try:
        import numba  # noqa: F401
    except ImportError:
        t.notes.append("numba is not installed, so pylinkage's fast path runs as plain Python")
    return t
