"""The ``crane`` block of results.json (docs/results.md): the duty's coefficients, and for each
mechanism every record's value (by its key, in the units of the note) and every check."""
from __future__ import annotations

from typing import Any

from . import CraneCalc


def crane_block(calc: CraneCalc) -> dict[str, Any]:
    r = calc.rules
    out: dict[str, Any] = {
        "rules": {"group": r.group, "rules": r.rules, "iso_class": r.iso_class, "regime": r.regime,
                  "pv_percent": r.pv_percent, "rope_factor": r.rope_factor, "block_ratio": r.block_ratio,
                  "drum_ratio": r.drum_ratio, "brake_factor": r.brake_factor},
        "passed": calc.passed,
    }
    for name, mech in calc.mechanisms:
        out[name] = {
            "values": {k: {"value": rec.value, "unit": rec.unit} for k, rec in mech.records.items()},
            "checks": [{"key": c.key, "value": c.value, "relation": c.relation, "limit": c.limit,
                        "unit": c.unit, "passed": c.passed, "advice": c.advice or None,
                        "advice_value": c.advice_value} for c in mech.checks],
            "passed": mech.passed,
        }
    return out
