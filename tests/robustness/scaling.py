"""An example's task scaled: lengths × k, masses × m, the crank's speed × w, the given forces × f.

Every number of the linkage's sections is scaled by the unit the task format gives its key
(``reportgen.taskspec``: ``Key.unit()``), so a key added to the format with a unit is scaled too
(and one with a unit this table does not know fails the test instead of being left as it was):

=========  ==========  ===============================================================
unit       factor      keys (today)
=========  ==========  ===============================================================
m          k           points, link length(s), a guide's ``through``
kg         m           link masses
kg·m²      m·k²        link inertias, ``dynamics.crank_inertia``
kg/m       m/k         ``mass_rules.q`` (masses by the rule q·l scale as m)
rad/s      w           the drive's ω
rpm        w           the planetary's motor speed (the reducer's ratio stays)
N          f           forces of the loads
N·m        f·k         moments of the loads (a force × a length)
m/s²       g_factor    g: 1, or 0 for dynamic similarity (no weights)
=========  ==========  ===============================================================

Left as they are: angles, fractions, counts, δ, the flywheel's density, and the gears (their
module in mm describes a gear pair that does not depend on the linkage).

With ``f = m·k·w²`` and ``g_factor = 0`` the task is dynamically similar to the example: every
force (given, weight, inertia, reaction) scales with f, every moment with f·k (:func:`similar`).
"""
from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from reportgen.taskspec import SECTIONS
from reportgen.zoo import toml_value

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
#: The examples with a linkage, one of each mechanism (press-en, shaper-uk: the same numbers).
LINKAGE_EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3", "control-work")
#: Hypothesis examples per property test: few by default (each solves or draws a whole example);
#: ``ROBUSTNESS_EXAMPLES=200`` for a longer hunt.
EXAMPLES_PER_TEST = int(os.environ.get("ROBUSTNESS_EXAMPLES", "8"))
#: The suite draws the same examples every run (derandomized: CI does not turn red by chance);
#: ``ROBUSTNESS_RANDOM=1`` draws new ones (with ``--hypothesis-seed=N`` to repeat a hunt).
RANDOM = bool(os.environ.get("ROBUSTNESS_RANDOM"))


def robustness_settings(max_examples: int = EXAMPLES_PER_TEST):
    """Few examples, no shrinking (a solve or a drawing takes a second or more: shrinking one failure
    took minutes; a failure prints the example's name and factors, enough to reproduce it with
    :func:`scaled`), derandomized unless ``ROBUSTNESS_RANDOM`` is set."""
    from hypothesis import HealthCheck, Phase, settings
    return settings(max_examples=max_examples, deadline=None, derandomize=not RANDOM,
                    phases=(Phase.explicit, Phase.reuse, Phase.generate) if RANDOM else (Phase.explicit, Phase.generate),
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
#: The sections whose numbers are scaled; the others (document, gears, crane …) are copied.
SCALED_SECTIONS = ("mechanism", "dynamics", "planetary")
#: Units that are not scaled (angles, shares, a density, gear sizes in mm).
UNSCALED_UNITS = ("", "degrees", "degrees (a crank angle)", "kg/m³", "mm", "%", "a share of the module")


@dataclass(frozen=True)
class Factors:
    k: float = 1.0          # lengths
    m: float = 1.0          # masses
    w: float = 1.0          # the crank's speed
    f: float = 1.0          # the given forces
    g: float = 1.0          # gravity

    def of(self, unit: str) -> float:
        table = {"m": self.k, "kg": self.m, "kg·m²": self.m * self.k ** 2, "kg/m": self.m / self.k,
                 "rad/s": self.w, "rpm": self.w, "N": self.f, "N·m": self.f * self.k, "m/s²": self.g}
        if unit in table:
            return table[unit]
        assert unit in UNSCALED_UNITS, f"a key in {unit!r}: tests/robustness/scaling.py does not know how to scale it"
        return 1.0


def similar(k: float, m: float, w: float) -> Factors:
    """Dynamic similarity: forces × m·k·w² (given ones too), without gravity (g = 0: a scaled g,
    k·w²·9.81, leaves the loader's range 0 … 50 m/s² at once)."""
    return Factors(k, m, w, m * k * w * w, 0.0)


def _units() -> dict[tuple[str, str], str]:
    return {(s.path, key.name): key.unit() for s in SECTIONS for key in s.keys}


UNITS = _units()


def _scale_numbers(value: Any, factor: float) -> Any:
    if isinstance(value, bool) or isinstance(value, str):
        return value
    if isinstance(value, (int, float)):
        return float(value) * factor
    if isinstance(value, list):
        return [_scale_numbers(v, factor) for v in value]
    if isinstance(value, dict):
        return {k: _scale_numbers(v, factor) for k, v in value.items()}
    return value


def _walk(table: dict, path: str, fac: Factors) -> dict:
    out: dict = {}
    for key, value in table.items():
        unit = UNITS.get((path, key))
        sub = f"{path}.{key}"
        if unit:
            out[key] = _scale_numbers(value, fac.of(unit))
        elif isinstance(value, dict):
            out[key] = _walk(value, sub, fac)
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            out[key] = [_walk(v, sub, fac) for v in value]
        else:
            out[key] = value
    return out


def dumps(data: dict) -> str:
    """TOML text of a task read by tomllib: one ``[section]`` per top-level table, everything
    under it inline (arrays of tables as arrays of inline tables)."""
    lines = []
    for name, table in data.items():
        lines.append(f"[{name}]")
        lines += [f"{k} = {toml_value(v)}" for k, v in table.items()]
        lines.append("")
    return "\n".join(lines)


def example_data(name: str) -> dict:
    return tomllib.loads((EXAMPLES / name / "task.toml").read_text(encoding="utf-8"))


def scaled(name: str, fac: Factors, drop: tuple[str, ...] = ()) -> str:
    """The task text of example ``name`` scaled by ``fac`` (sections in ``drop`` left out)."""
    data = example_data(name)
    out = {}
    for section, table in data.items():
        if section in drop:
            continue
        out[section] = _walk(table, section, fac) if section in SCALED_SECTIONS else table
    _scaled_defaults(out, fac)
    return dumps(out)


def _scaled_defaults(data: dict, fac: Factors) -> None:
    """A key left out takes the loader's default, which is not scaled: write it, scaled (the mass
    rule's q of crank-slider, g). Tables (not arrays of tables) under a scaled section only."""
    for section in SECTIONS:
        if section.shape == "array" or section.path.split(".")[0] not in SCALED_SECTIONS:
            continue
        *parents, leaf = section.path.split(".")
        holder = data
        for name in parents:
            holder = holder.get(name) if isinstance(holder, dict) else None
            if holder is None:
                break
        if not isinstance(holder, dict):
            continue
        for key in section.keys:
            default = key.default
            if not key.unit() or isinstance(default, bool) or not isinstance(default, (int, float)):
                continue
            if fac.of(key.unit()) == 1.0:
                continue
            table = holder.setdefault(leaf, {}) if parents else holder[leaf] if leaf in holder else None
            if table is None:
                continue
            if key.name not in table:
                table[key.name] = float(default) * fac.of(key.unit())
