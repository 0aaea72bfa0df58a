"""The examples the checks of issue 12 read (every one: course projects in ru, uk and en, the crane
and the control work); the builds come from ``built`` of tests/conftest.py (one per session)."""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml"))
