"""The sheets of the course project, one module per sheet, in order (see :data:`SHEETS`).

A sheet module provides::

    NEEDS: tuple[str, ...]                       # project stages it reads
    TITLE: str                                   # the sheet's title for the title block
    def available(project) -> bool
    def draw(project, number: int, count: int) -> drawings.Sheet

A module that does not exist yet is skipped.
"""
from __future__ import annotations

from types import ModuleType

from reportgen.modules import optional_module

#: The sheet modules in the order of the sheets; files are named ``sheet<N>-<name>`` with N the
#: sheet's number among those the task has.
SHEETS: tuple[str, ...] = ("kinematics", "kinetostatics", "dynamics", "gears")


def sheet_module(name: str) -> ModuleType | None:
    return optional_module(f"drawings.sheets.{name}")


def available_sheets(project) -> list[tuple[str, ModuleType]]:
    out: list[tuple[str, ModuleType]] = []
    for name in SHEETS:
        mod = sheet_module(name)
        if mod is not None and mod.available(project):
            out.append((f"sheet{len(out) + 1}-{name}", mod))
    return out
