"""Shared helpers of the task-loader tests: the valid examples as dicts and a way to edit them."""
from __future__ import annotations

import copy
import tomllib
from pathlib import Path
from typing import Any

import pytest

from reportgen.errors import TaskError
from reportgen.taskfile import parse_task

DATA = Path(__file__).parent / "data"
FULL = DATA / "full.toml"
SLOTTED = DATA / "slotted.toml"

_CACHE: dict[Path, dict] = {}
class _Delete:
    """Marker: remove the key (a stable repr, so test ids are the same in every process)."""

    def __repr__(self) -> str:
        return "DELETE"


DELETE = _Delete()


def example(path: Path = FULL) -> dict:
    """A fresh deep copy of a valid example, parsed by tomllib."""
    if path not in _CACHE:
        _CACHE[path] = tomllib.loads(path.read_text(encoding="utf-8"))
    return copy.deepcopy(_CACHE[path])


def edit(data: dict, where: tuple, value: Any = DELETE) -> dict:
    """Set (or delete, with DELETE) the value at key/index path ``where``; returns ``data``."""
    node = data
    for step in where[:-1]:
        node = node[step]
    if value is DELETE:
        del node[where[-1]]
    else:
        node[where[-1]] = value
    return data


def expect_error(data: dict, path: str, *fragments: str) -> TaskError:
    """parse_task(data) must raise a TaskError at ``path`` whose message holds every fragment."""
    with pytest.raises(TaskError) as info:
        parse_task(data)
    err = info.value
    assert err.path == path, f"path {err.path!r} != {path!r}; message: {err}"
    for frag in fragments:
        assert frag in str(err), f"{frag!r} not in message: {err}"
    return err
