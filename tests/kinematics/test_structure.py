"""Structural analysis: Chebyshev, numerical mobility, Assur groups of every example."""
from __future__ import annotations

import re

import pytest

from reportgen import zoo
from reportgen.errors import StructureError
from reportgen.kinematics import build_model
from reportgen.linkage import compile_linkage
from reportgen.structure import analyse_structure
from reportgen.taskfile import load_task, loads_task

from .zoo import EXAMPLES, four_bar

EXPECTED = {
    "press": ("I(0,1) → II(2,3) → II(4,5)", ["RRR", "RRP"], 2),
    "crank-slider": ("I(0,1) → II(2,3)", ["RRP"], 2),
    "shaper": ("I(0,1) → II(2,3) → II(4,5)", ["RPR", "RRP"], 2),
    "conveyor": ("I(0,1) → II(2,3) → II(4,5)", ["RRR", "RRP"], 2),
    "class3": ("I(0,1) → III(2,3,4,5)", ["triad"], 3),
}


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_examples_decompose(name):
    s = analyse_structure(compile_linkage(load_task(EXAMPLES / name / "task.toml").mechanism))
    formula, kinds, mclass = EXPECTED[name]
    assert s.W == 1 and s.W_numeric == 1 and s.redundant == 0
    assert s.formula == formula
    assert [g.kind for g in s.groups[1:]] == kinds
    assert s.mechanism_class == mclass
    assert all(g.order == (3 if g.group_class == 3 else 2) for g in s.groups[1:])


def test_press_counts():
    s = analyse_structure(compile_linkage(load_task(EXAMPLES / "press" / "task.toml").mechanism))
    assert (s.n, s.p1, s.p2, s.W) == (5, 7, 0, 1)
    d = s.to_dict()
    assert d["groups"][1] == {"links": [2, 3], "class": 2, "order": 2, "kind": "RRR"}
    assert d["groups"][2] == {"links": [4, 5], "class": 2, "order": 2, "kind": "RRP"}


def _renumber(text: str, perm: dict[int, int]) -> str:
    """Change the link ids of a task text (ids in `id =`, `link =`, `guide =` lines)."""
    def sub(m):
        key, val = m.group(1), int(m.group(2))
        return f"{key} = {perm.get(val, val)}"
    return re.sub(r"^(id|link|guide) = (\d+)", sub, text, flags=re.M)


@pytest.mark.parametrize("name", ["press", "shaper", "class3", "conveyor"])
def test_structure_independent_of_link_numbers(name):
    text = (EXAMPLES / name / "task.toml").read_text(encoding="utf-8")
    perm = {1: 4, 2: 5, 3: 1, 4: 2, 5: 3}
    t2 = loads_task(_renumber(text, perm))
    s1 = analyse_structure(compile_linkage(loads_task(text).mechanism))
    s2 = analyse_structure(compile_linkage(t2.mechanism))
    groups1 = [(sorted(perm[k] for k in g.links), g.group_class, g.order, g.kind) for g in s1.groups]
    groups2 = [(sorted(g.links), g.group_class, g.order, g.kind) for g in s2.groups]
    assert groups1 == groups2


def _five_bar() -> str:
    """Two cranks' chain with one driver: W = 2."""
    return zoo.linkage(
        name="five-bar", ground=("O", "E"),
        points={"O": (0.0, 0.0), "E": (0.5, 0.0), "A": (0.0, 0.1), "B": (0.25, 0.3), "D": (0.5, 0.12)},
        links=[{"id": 1, "kind": "crank", "points": ["O", "A"]}, {"id": 2, "kind": "coupler", "points": ["A", "B"]},
               {"id": 3, "kind": "coupler", "points": ["B", "D"]}, {"id": 4, "kind": "rocker", "points": ["E", "D"]}],
        omega=1.0)


def test_two_degrees_of_freedom_is_refused_with_leftover_links():
    with pytest.raises(StructureError) as ei:
        analyse_structure(compile_linkage(loads_task(_five_bar()).mechanism))
    assert set(ei.value.leftover) == {2, 3, 4}
    assert "W = 2" in str(ei.value) and "drivers" in str(ei.value)


def _parallelogram_with_extra_link() -> str:
    """A parallelogram O-A-B-C with a third parallel bar E-F: Chebyshev gives W = 0, the rank W = 1."""
    return zoo.linkage(
        name="parallelogram", ground=("O", "C", "E"),
        points={"O": (0.0, 0.0), "C": (0.4, 0.0), "E": (0.2, 0.0), "A": (0.0, 0.1), "B": (0.4, 0.1), "F": (0.2, 0.1)},
        links=[{"id": 1, "kind": "crank", "points": ["O", "A"]},
               {"id": 2, "kind": "coupler", "points": ["A", "B", "F"]},
               {"id": 3, "kind": "rocker", "points": ["C", "B"]}, {"id": 4, "kind": "rocker", "points": ["E", "F"]}],
        omega=1.0)


def test_redundant_constraint_is_reported():
    lk = compile_linkage(loads_task(_parallelogram_with_extra_link()).mechanism)
    with pytest.raises(StructureError) as ei:
        analyse_structure(lk)
    msg = str(ei.value)
    assert "W = 0" in msg and "redundant" in msg
    from reportgen.structure import chebyshev, numerical_mobility
    assert chebyshev(lk)[3] == 0
    assert numerical_mobility(lk) == (1, 1)


def test_four_bar_is_one_dyad():
    m = build_model(loads_task(four_bar(0.04, 0.12, 0.08, 0.1)).mechanism)
    assert m.structure.formula == "I(0,1) → II(2,3)"
