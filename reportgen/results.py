"""results.json (``docs/results.md``): the numbers the note prints and the sheets draw.

Vectors are [x, y] in SI units, angles in degrees, angular speeds in rad/s (positive =
counter-clockwise); position-wise lists follow ``kinematics.phi_deg``. Keys beyond the contract are
documented in docs/results.md.
"""
from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from .kinematics import KinematicsResult
from .kinematics.extremes import Strokes
from .project import Project
from .errors import InternalError

FORMAT = "reportgen-results/1"


def _clean(x: Any) -> Any:
    """Plain JSON values; never NaN or infinity."""
    if isinstance(x, np.ndarray):
        return _clean(x.tolist())
    if isinstance(x, (list, tuple)):
        return [_clean(v) for v in x]
    if isinstance(x, dict):
        return {str(k): _clean(v) for k, v in x.items()}
    if isinstance(x, (np.floating, float)):
        f = float(x)
        if not math.isfinite(f):
            raise InternalError("results.json", "a non-finite number reached it")
        return 0.0 if f == 0.0 else f
    if isinstance(x, np.integer):
        return int(x)
    return x


def kinematics_block(kin: KinematicsResult, strokes: Strokes | None = None) -> dict:
    block: dict[str, Any] = {
        "phi_deg": np.mod(kin.phi_deg, 360.0),
        "points": {name: {"pos": m.pos, "vel": m.vel, "acc": m.acc} for name, m in kin.points.items()},
        "centers_of_mass": {str(k): {"pos": m.pos, "vel": m.vel, "acc": m.acc} for k, m in kin.coms.items()},
        "links": {str(k): {"angle_deg": np.mod(np.degrees(m.angle), 360.0), "omega": m.omega, "epsilon": m.epsilon}
                  for k, m in kin.links.items()},
        "transmission_angle_deg": dict(kin.transmission_deg),
        "near_singular": [{"position": i, "group": g, "transmission_angle_deg": mu} for i, g, mu in kin.near_singular],
    }
    if strokes is not None:
        block["extremes"] = {
            "output_link": strokes.output.link,
            "output_kind": strokes.output.kind,
            "output_point": strokes.output.point,
            "phi_start_deg": math.degrees(strokes.phi_start),
            "phi_end_deg": math.degrees(strokes.phi_end),
            "working_stroke_deg": strokes.working_deg,
            "idle_stroke_deg": strokes.idle_deg,
            "stroke": strokes.stroke,
            "time_ratio": strokes.time_ratio,
        }
    return block


def plans_block(project: Project) -> list[dict]:
    """The plans drawn in full (``[analysis] plan_positions``): by plan position, the analysed one
    first — its index in ``phi_deg``, crank angle, stroke and the scales μv, μa the note and sheet 1
    print."""
    from .plan_positions import stroke_of
    kin = project.kinematics
    strokes = project.strokes if project.full_cycle else None
    sgn = 1.0 if project.model.omega >= 0 else -1.0
    out = []
    for j, (v, a) in project.plans_by_position.items():
        out.append({"position": j, "phi_deg": float(np.mod(kin.phi_deg[j], 360.0)),
                    "stroke": stroke_of(float(kin.phi[j]), strokes, sgn),
                    "velocity_scale": v.scale, "acceleration_scale": a.scale})
    return out


ALL_SECTIONS = ("structure", "kinematics", "kinetostatics", "dynamics", "gears", "planetary", "crane")


def build_results(project: Project, sections: tuple[str, ...] = ALL_SECTIONS,
                  force_at_deg: float | None = None) -> dict:
    """The results dictionary of the stages asked for (a section the task leaves out is absent);
    ``force_at_deg``: the crank angle of the kinetostatics (default: [analysis] force_position)."""
    out: dict[str, Any] = {"format": FORMAT}
    if project.task.mechanism is not None:
        if "structure" in sections:
            out["structure"] = project.structure.to_dict()
        if "kinematics" in sections:
            out["kinematics"] = kinematics_block(project.kinematics, project.strokes)
            out["kinematics"]["plans"] = plans_block(project)
        if "kinetostatics" in sections:
            from .kinetostatics.results import kinetostatics_block, kinetostatics_of
            out["kinetostatics"] = kinetostatics_block(kinetostatics_of(project, force_at_deg), project)
    if project.task.mechanism is not None and project.task.document.kind == "control-work" \
            and "kinetostatics" in sections:
        from .control.analysis import control_work_of
        cw = project.task.control_work
        out["control_work"] = {"table": cw.table if cw else None, "variant": cw.variant if cw else None,
                               **control_work_of(project).answers()}
    if "dynamics" in sections and project.task.mechanism is not None and project.task.dynamics is not None:
        from .dynamics import dynamics_block, dynamics_of
        out["dynamics"] = dynamics_block(dynamics_of(project))
    if "gears" in sections and project.task.gears is not None:
        from .gears.results import gears_block
        out["gears"] = gears_block(project.gears)
    if "planetary" in sections and project.task.planetary is not None:
        from .planetary.results import planetary_block
        st = project.planetary
        assert st is not None  # the task has [planetary]
        out["planetary"] = planetary_block(st.design, st.triangle, st.check)
    if "crane" in sections and getattr(project.task, "crane", None) is not None:
        from .crane.results import crane_block
        out["crane"] = crane_block(project.crane)
    return _clean(out)


def dumps(results: dict) -> str:
    """Deterministic JSON text (stable key order as built, no NaN)."""
    return json.dumps(results, ensure_ascii=False, indent=1, allow_nan=False) + "\n"
