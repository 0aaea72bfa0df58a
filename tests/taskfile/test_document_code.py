"""[document] code (issue 13 item 3): one source for the designation «ТММ.КП…» of the note and
the sheets, with today's value as the default."""
from __future__ import annotations

import pytest

from reportgen.commands.build import _designation
from reportgen.errors import TaskError
from reportgen.taskfile import parse_task

#: the smallest task that has something to build (an empty task is refused)
GEARS = {"gears": {"z1": 13, "z2": 26, "module": 9}}


def test_default_is_todays_designation() -> None:
    task = parse_task(dict(GEARS))
    assert task.document.sheet_code(1) == "ТММ.КП.00.00.001"
    assert task.document.note_code() == "ТММ.КП.00.00.000 ПЗ"
    assert _designation(task) == "ТММ.КП.00.00.000 ПЗ"


def test_code_from_the_task_reaches_note_and_sheets() -> None:
    task = parse_task({**GEARS, "document": {"code": "ТММ.КП.12.05"}})
    assert task.document.sheet_code(3) == "ТММ.КП.12.05.003"
    assert _designation(task) == "ТММ.КП.12.05.000 ПЗ"


@pytest.mark.parametrize("bad", ["", "  ", 5, True])
def test_bad_code_names_the_key(bad: object) -> None:
    with pytest.raises(TaskError) as err:
        parse_task({**GEARS, "document": {"code": bad}})
    assert err.value.path == "document.code"


def test_no_sheet_or_note_module_spells_the_designation() -> None:
    """Only reportgen/task.py holds «ТММ.КП» as the default of [document] code (taskspec.py: an
    example of the key, sheet.py: a docstring)."""
    from pathlib import Path
    root = Path(__file__).resolve().parents[2]
    found = [str(p.relative_to(root)) for pkg in ("reportgen", "drawings", "latex_templates")
             for p in (root / pkg).rglob("*") if p.suffix in (".py", ".j2", ".tex") and p.is_file()
             and "ТММ.КП." in p.read_text(encoding="utf-8") and p.name not in ("task.py", "sheet.py", "taskspec.py")]
    assert not found, found
