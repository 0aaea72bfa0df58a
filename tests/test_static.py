"""Static checks (issue 13 item 5): ruff (pyflakes, bugbear, unused arguments: the rules in
pyproject.toml) and mypy on the packages report nothing. A finding fails this test with the tool's
own message; `make check` runs the same tools."""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _tool(name: str) -> list[str]:
    """The tool as installed beside this Python (the venv), else on PATH."""
    exe = Path(sys.executable).with_name(name)
    if exe.exists():
        return [str(exe)]
    found = shutil.which(name)
    if found is None:
        pytest.fail(f"{name} is not installed: pip install -e '.[test]' installs it")
    return [found]


def _run(cmd: list[str]) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)


def test_ruff_finds_nothing() -> None:
    r = _run(_tool("ruff") + ["check", "--output-format", "concise", "."])
    assert r.returncode == 0, f"ruff:\n{r.stdout}{r.stderr}"


def test_mypy_finds_nothing() -> None:
    # the packages and options are in pyproject.toml ([tool.mypy]); .mypy_cache makes a re-run fast
    r = _run(_tool("mypy"))
    assert r.returncode == 0, f"mypy:\n{r.stdout}{r.stderr}"
    assert "Success: no issues found" in r.stdout
