"""The ``gears`` block of results.json (RESULTS_FORMAT.md), as a plain dict.

The contract's keys keep their meaning (sizes in mm, angles in degrees); added keys: ``z1``,
``z2``, ``module``, ``alpha_deg``, ``ha``, ``c``, ``a``, ``u``, ``p``, ``ha1``, ``ha2``, ``hf1``,
``hf2``, ``h1``, ``h2``, ``chord_s*``, ``chord_h*``, ``w*``/``zw*`` (base tangent length), ``g``
(N1N2), ``n1a``, ``n1p``, ``n1b``, ``eps_alpha_min``, ``sa_min``, ``checks`` (a list), ``sliding``
(table rows; ±infinity at N1/N2 is written as null), and ``auto`` (the rule and the exact point)
when the shifts were chosen automatically.
"""
from __future__ import annotations

import math

from .pair import GearPair

_CONTRACT = ("aw", "y", "dy", "d1", "d2", "db1", "db2", "dw1", "dw2", "da1", "da2", "df1", "df2",
             "s1", "s2", "sa1", "sa2", "pb", "eps_alpha", "ab", "x1", "x2")
_EXTRA = ("z1", "z2", "a", "u", "p", "x_sum", "inv_alpha_w", "ha1", "ha2", "hf1", "hf2", "h1", "h2",
          "e1", "e2", "sw1", "sw2", "chord_s1", "chord_s2", "chord_h1", "chord_h2", "zw1", "zw2",
          "w1", "w2", "g", "n1a", "n1p", "n1b", "rho_l1", "rho_l2", "rho_p1", "rho_p2", "ha", "c")


def _num(v: float) -> float | None:
    return float(v) if math.isfinite(v) else None


def gears_block(pair: GearPair) -> dict:
    """The JSON-ready dict (no NaN or infinity)."""
    g = pair.geometry
    out: dict = {"alpha_w_deg": g.alpha_w_deg}
    out.update({k: getattr(g, k) for k in _CONTRACT})
    out.update({"module": g.m, "alpha_deg": g.alpha_deg})
    out.update({k: getattr(g, k) for k in _EXTRA})
    out["alpha_a1_deg"] = math.degrees(g.alpha_a1)
    out["alpha_a2_deg"] = math.degrees(g.alpha_a2)
    out["eps_alpha_min"] = pair.eps_min
    out["sa_min"] = pair.sa_min_factor * g.m
    out["checks"] = [c.as_dict() for c in pair.checks]
    out["all_checks_passed"] = pair.all_passed
    out["sliding"] = {
        "lambda1_a": _num(pair.sliding.lambda1_a), "lambda2_b": _num(pair.sliding.lambda2_b),
        "rows": [{"point": r.label, "rho": r.rho, "lambda1": _num(r.lambda1),
                  "lambda2": _num(r.lambda2)} for r in pair.sliding.rows],
    }
    if pair.shift_choice is not None:
        ch = pair.shift_choice
        out["auto"] = {"rule": ch.rule, "x1_exact": ch.x1_exact, "x2_exact": ch.x2_exact}
    return {k: (int(v) if isinstance(v, int) and not isinstance(v, bool) else
                (_num(v) if isinstance(v, float) else v)) for k, v in out.items()}
