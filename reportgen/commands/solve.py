"""``reportgen solve TASK --json OUT [--at DEG ...] [--force-at DEG]``: numbers only."""
from __future__ import annotations

import argparse
import math
import os
import tempfile

from ..errors import OptionError
from ..project import Project
from ..results import build_results, dumps
from ..taskfile import load_task
from .modes import as_made_ordinarily


def register(sub) -> None:
    p = sub.add_parser("solve", help="solve the task and write results.json (no PDF, no DXF)")
    p.add_argument("task", help="the task file (TOML)")
    p.add_argument("--json", metavar="OUT", help="write results.json here")
    p.add_argument("--at", metavar="DEG", type=float, nargs="+", help="analyse these crank angles φ1 instead of [analysis] positions")
    p.add_argument("--force-at", metavar="DEG", type=float, help="kinetostatics at this crank angle")
    p.add_argument("--quiet", action="store_true", help="no summary on stdout")
    p.set_defaults(func=run)


def write_atomic(path: str, text: str, option: str = "--json") -> None:
    """Write through a temporary file in the same folder, so no half-written file is left
    (``option`` names the command-line option of ``path`` in the error)."""
    folder = os.path.dirname(os.path.abspath(path)) or "."
    if not os.path.isdir(folder):
        raise OptionError(option, f"the folder {folder} does not exist", "a path in an existing folder")
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".reportgen-", suffix=os.path.splitext(path)[1] or ".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        as_made_ordinarily(tmp)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def summary(project: Project, force_at_deg: float | None = None) -> str:
    lines = []
    if project.task.mechanism is not None:
        s = project.structure
        lines.append(f"{project.task.mechanism.name}")
        lines.append(f"  W = 3·{s.n} − 2·{s.p1} − {s.p2} = {s.W} (numerical: {s.W_numeric}, redundant constraints: {s.redundant})")
        lines.append(f"  structural formula: {s.formula}; mechanism of class {s.mechanism_class}")
        for g in s.groups[1:]:
            lines.append(f"    group {g.label}: class {g.group_class}, order {g.order}, kind {g.kind}")
        st = project.strokes
        if st is not None:
            unit = "m" if st.output.kind == "slider" else "rad"
            lines.append(f"  output link {st.output.link} ({st.output.kind}): stroke {st.stroke:.5g} {unit}; "
                         f"working stroke {st.working_deg:.3f}° from φ1 = {math.degrees(st.phi_start):.3f}°, "
                         f"idle stroke {st.idle_deg:.3f}°, K = {st.time_ratio:.4f}")
        kin = project.kinematics
        lines.append(f"  {len(kin.phi)} positions analysed; minimum transmission angle " +
                     ", ".join(f"{k}: {v.min():.1f}°" for k, v in kin.transmission_deg.items()))
        for i, gkey, mu in kin.near_singular:
            lines.append(f"  warning: position {i} (φ1 = {math.degrees(kin.phi[i]) % 360:.2f}°) is near a singular "
                         f"position of group {gkey}: μ = {mu:.2f}°")
        from ..kinetostatics.results import kinetostatics_of
        ks = kinetostatics_of(project, force_at_deg)
        lines.append(f"  kinetostatics at φ1 = {ks.phi_deg:.3f}°: balancing moment {ks.balancing_moment:.6g} N·m "
                     f"(groups), {ks.balancing_moment_zhukovsky:.6g} N·m (Zhukovsky's lever), discrepancy "
                     f"{ks.discrepancy_percent:.1e} %; graphical replica {ks.graphical.discrepancy_percent:+.3f} %")
        lines.extend(f"  warning: {w}" for w in ks.warnings)
        if project.task.dynamics is not None:
            from ..dynamics import dynamics_of
            d = dynamics_of(project)
            lines.append(f"  flywheel: J = {d.J_flywheel:.4g} kg·m² ({d.flywheel.shape}, R = {d.flywheel.radius:.3f} m, "
                         f"m = {d.flywheel.mass:.4g} kg); δ achieved {d.delta_achieved:.5f} (target {d.delta_target:g})")
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    for v in args.at or ():
        if not math.isfinite(v):
            raise OptionError("--at", f"got {v}", "finite crank angles in degrees")
    task = load_task(args.task)
    project = Project(task, at_deg=args.at)
    results = build_results(project, force_at_deg=args.force_at)
    if args.json:
        write_atomic(args.json, dumps(results))
    if not args.quiet:
        print(summary(project, args.force_at))
        if args.json:
            print(f"results: {args.json}")
    return 0
