"""Issue 11: `kind` of a link is optional ("wording only" in the task format): left out, it is
inferred from the structure; given, it is still accepted (and a wrong word still refused).
Was: a task without `kind` was refused before any real check."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from reportgen.errors import TaskError
from reportgen.project import Project
from reportgen.results import build_results
from reportgen.taskfile import loads_task

EXAMPLES = sorted(p for p in (Path(__file__).resolve().parents[2] / "examples").glob("*/task.toml")
                  if "[mechanism]" in p.read_text(encoding="utf-8"))
KIND_LINE = re.compile(r'^kind = "(crank|coupler|rocker|slider|block|slotted)".*\n', re.M)


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.parent.name for p in EXAMPLES])
def test_every_example_without_kind_is_the_same_task(path):
    text = path.read_text(encoding="utf-8")
    stripped, n = KIND_LINE.subn("", text)
    assert n >= 3 and "kind = \"crank\"" not in stripped
    assert loads_task(stripped, source="t") == loads_task(text, source="t")


def test_press_without_kind_gives_the_same_results():
    path = next(p for p in EXAMPLES if p.parent.name == "press")
    text = path.read_text(encoding="utf-8")
    a = build_results(Project(loads_task(text, source="t")))
    b = build_results(Project(loads_task(KIND_LINE.sub("", text), source="t")))
    assert a == b


def test_given_kind_is_kept_and_a_wrong_one_refused():
    path = next(p for p in EXAMPLES if p.parent.name == "press")
    text = path.read_text(encoding="utf-8")
    # link 4 (a coupler by structure) called a rocker: wording only, accepted as given
    odd = text.replace('id = 4\nkind = "coupler"', 'id = 4\nkind = "rocker"')
    assert odd != text
    assert loads_task(odd).mechanism.link(4).kind == "rocker"
    with pytest.raises(TaskError, match=r"mechanism.link\[3\].kind"):
        loads_task(text.replace('id = 4\nkind = "coupler"', 'id = 4\nkind = "lever"'))
