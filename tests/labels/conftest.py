"""The examples the label checks run on, and the scopes of other work that still fails them."""
from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml"))

#: Known label defects still open, by (example, sheet stem or note-figure group): reason. A case
#: listed here must still fail (strict xfail): whoever fixes it removes it from here. Empty: sheet 1's
#: and section 1's plan labels (issue 12) were the last and pass now.
REWORKED: dict[tuple[str, str], str] = {}


def case(example: str, what: str):
    """A pytest param for ``(example, what)``, marked xfail where another scope owns the defect."""
    reason = REWORKED.get((example, what))
    marks = [pytest.mark.xfail(strict=True, reason=reason)] if reason else []
    return pytest.param(example, what, id=f"{example}-{what}", marks=marks)
