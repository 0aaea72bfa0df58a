"""The ``kinetostatics`` block of results.json (RESULTS_FORMAT.md, + the keys documented in
docs/kinetostatics.md), and one cached solve per project and angle."""
from __future__ import annotations

import math
import weakref
from typing import Any

import numpy as np

from .analysis import Kinetostatics, kinetostatics_at

_CACHE: "weakref.WeakKeyDictionary[Any, dict]" = weakref.WeakKeyDictionary()


def kinetostatics_of(project, force_at_deg: float | None = None) -> Kinetostatics:
    """:func:`kinetostatics_at` computed once per project and ``force_at_deg`` (results.json, the
    command's summary, the note and the sheet share it)."""
    per = _CACHE.setdefault(project, {})
    key = None if force_at_deg is None else float(force_at_deg)
    if key not in per:
        per[key] = kinetostatics_at(project, force_at_deg)
    return per[key]


def _num(x: float) -> float | None:
    """A finite float, or None (a deviation from an exact zero)."""
    x = float(x)
    return x if math.isfinite(x) else None


def _polygon_dict(p) -> dict:
    def vec(v):
        return {"name": v.name, "vector": v.vector, "known": v.known, "length_mm": v.length_mm,
                "measured_mm": v.measured_mm, "start_mm": v.start_mm, "end_mm": v.end_mm,
                "read_value": v.read_value, "exact_value": v.exact_value,
                "deviation_percent": _num(v.deviation_percent)}
    return {"scale": p.scale, "equation": p.equation, "vectors": [vec(v) for v in p.vectors],
            "read": [vec(v) for v in p.extra]}


def kinetostatics_block(ks: Kinetostatics, project=None) -> dict:
    """The block for one analysed position; with ``project``, both methods on ``project.phi`` too."""
    r = ks.reactions
    links: dict[str, Any] = {}
    for k in sorted({k for p in r.pairs for k in (p.lo, p.hi) if k != 0}):
        forces, moments = r.on_link(k)
        links[str(k)] = {
            "forces": [{"name": f.name, "point": np.asarray(f.point)[0], "vector": np.asarray(f.vector)[0],
                        "kind": f.kind} for f in forces],
            "moments": [{"name": m.name, "value": float(np.asarray(m.value)[0]), "kind": m.kind} for m in moments],
        }
    g = ks.graphical
    block: dict[str, Any] = {
        "phi_deg": ks.phi_deg,
        "position": ks.position,
        "reactions": {p.name: p.vector[0] for p in sorted(r.pairs, key=lambda p: (p.lo, p.hi, p.name))},
        "links": links,
        "balancing_moment": ks.balancing_moment,
        "balancing_moment_zhukovsky": ks.balancing_moment_zhukovsky,
        "discrepancy_percent": ks.discrepancy_percent,
        "balancing_force": {"point": r.balancing_point[0], "vector": r.balancing_force[0],
                            "value": ks.balancing_force},
        "frame_reaction_with_moment": r.frame_reaction_with_moment[0],
        "pairs": {p.name: {"kind": p.kind, "links": [p.lo, p.hi], "joint": p.joint, "group": p.group,
                           "point": p.point[0], "sliding_point": p.sliding_point[0],
                           **({"normal": p.normal[0], "couple": float(p.couple[0])} if p.kind == "P" else {})}
                  for p in r.pairs},
        "transmission_angle_deg": dict(ks.transmission_deg),
        "warnings": list(ks.warnings),
        "graphical": {
            "length_scale": g.length_scale,
            "velocity_scale": g.lever.scale,
            "balancing_force_groups": g.crank.balancing_force_measured,
            "balancing_force_zhukovsky": g.lever.balancing_force_measured,
            "discrepancy_percent": _num(g.discrepancy_percent),
            "inertia": [{"link": x.link, "force": x.force_name, "moment": x.moment_name, "h": x.h,
                         "h_mm": x.h_mm, "h_mm_measured": x.h_mm_measured, "point": x.point,
                         "swing_point": x.swing_point, "deviation_percent": _num(x.deviation_percent)}
                        for x in g.inertia],
            "splits": [{"group": gg.key, "name": s.name, "link": s.link, "centre": s.centre, "tau": s.tau,
                        "normal": s.normal, "tau_measured": s.tau_measured,
                        "deviation_percent": _num(s.deviation_percent)}
                       for gg in g.groups for s in gg.splits],
            "polygons": {gg.key: _polygon_dict(gg.polygon) for gg in g.groups} | {
                g.crank.polygon.key: _polygon_dict(g.crank.polygon)},
        },
    }
    if project is not None:
        cyc = project.balancing_cycle
        block["cycle"] = {"phi_deg": np.mod(np.degrees(cyc.phi), 360.0), "balancing_moment": cyc.groups,
                          "balancing_moment_zhukovsky": cyc.zhukovsky}
    return block
