"""docs/results.md is a complete reference (issue 13 item 6): every key that an example writes to
results.json is named, in backticks, in the section of its block."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from reportgen.project import Project
from reportgen.results import build_results
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "results.md"
# Dicts whose keys are names from the task (points, link ids, groups, reactions, wheels), not keys.
_NAMED = {"points", "centers_of_mass", "links", "transmission_angle_deg", "reactions", "pairs", "polygons",
          "diameters_mm", "radii_mm", "points_mm", "cuts_mm"}


def _sections(text: str) -> dict[str, str]:
    parts = re.split(r"^## `(\w+)`", text, flags=re.M)
    return {parts[i]: parts[i + 1] for i in range(1, len(parts), 2)}


def _keys(value, parent: str = ""):
    """Every key name below ``value``, except the names of the dicts in ``_NAMED``."""
    if isinstance(value, dict):
        for k, v in value.items():
            if parent not in _NAMED:
                yield k
            yield from _keys(v, "" if parent in _NAMED else k)
    elif isinstance(value, list):
        for v in value:
            yield from _keys(v, parent)


@pytest.mark.parametrize("example", ["press", "shaper"])
def test_every_key_of_results_json_is_documented(example: str) -> None:
    project = Project(load_task(ROOT / "examples" / example / "task.toml"))
    results = build_results(project)
    sections = _sections(DOC.read_text(encoding="utf-8"))
    assert f'`"{results["format"]}"`' in DOC.read_text(encoding="utf-8")
    missing = []
    for block, value in results.items():
        if block == "format":
            continue
        assert block in sections, f"no section ## `{block}` in docs/results.md"
        text = sections[block]
        missing += [f"{block}: {k}" for k in sorted(set(_keys(value))) if f"`{k}`" not in text
                    and not re.search(rf"[{{,(\[]\s*{re.escape(k)}[,}})\s\]]", text)]
    assert not missing, "keys of results.json not in docs/results.md: " + ", ".join(missing)
