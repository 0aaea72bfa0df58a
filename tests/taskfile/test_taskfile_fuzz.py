"""Loader fuzz (issue #8 item 4): any TOML-like data either loads or raises ReportgenInputError."""
from __future__ import annotations

import datetime as dt

from hypothesis import HealthCheck, given, settings, strategies as st

from reportgen.errors import ReportgenInputError, TaskError
from reportgen.task import Task
from reportgen.taskfile import (DOCUMENT_KEYS, LINK_KEYS, LOAD_KEYS, MECHANISM_KEYS, PLANETARY_KEYS,
                                GEARS_KEYS, TOP_KEYS, parse_task)

from taskfile_cases import FULL, SLOTTED, example

KNOWN_KEYS = sorted(set(TOP_KEYS + DOCUMENT_KEYS + MECHANISM_KEYS + LINK_KEYS + LOAD_KEYS + GEARS_KEYS
                        + PLANETARY_KEYS + ("through", "angle_deg", "shape", "delta", "positions", "start",
                                            "O", "A", "B", "C", "D", "OA", "CB", "lenght")))
keys = st.one_of(st.sampled_from(KNOWN_KEYS), st.text(max_size=6))
scalars = st.one_of(
    st.booleans(),
    st.integers(),
    st.integers(min_value=-3, max_value=30),
    st.integers(min_value=10**300, max_value=10**400),
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(min_value=-2, max_value=2),
    st.text(max_size=8),
    st.sampled_from(["auto", "extreme", "max-load", "disk", "rim", "crank", "slider", "resistance",
                     "force", "moment", "working", "O", "A", "B", "D", "ru", "two-row-ext-int"]),
    st.dates(), st.datetimes(), st.times(),
)
toml_values = st.recursive(
    scalars,
    lambda children: st.one_of(st.lists(children, max_size=4), st.dictionaries(keys, children, max_size=5)),
    max_leaves=25,
)


def _check(data) -> None:
    try:
        result = parse_task(data)
    except ReportgenInputError as exc:
        assert isinstance(str(exc), str)
        if isinstance(exc, TaskError):
            assert isinstance(exc.path, str)
        return
    assert isinstance(result, Task)


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.dictionaries(st.sampled_from(TOP_KEYS), toml_values, max_size=6))
def test_random_documents(data):
    _check(data)


@settings(max_examples=200, deadline=None)
@given(toml_values)
def test_random_top_level(data):
    _check(data)


def _paths(node, prefix=()):
    """Every key/index path of a nested dict/list."""
    yield prefix
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _paths(v, prefix + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _paths(v, prefix + (i,))


def _mutate(data, path, op, new_value, new_key):
    if not path:
        return new_value if op == "replace" else data
    parent = data
    for step in path[:-1]:
        parent = parent[step]
    last = path[-1]
    if op == "delete":
        del parent[last]
    elif op == "replace":
        parent[last] = new_value
    elif op == "rename" and isinstance(parent, dict):
        parent[new_key] = parent.pop(last)
    elif op == "duplicate" and isinstance(parent, list):
        parent.append(parent[last])
    elif op == "wrap":
        parent[last] = [parent[last]]
    elif op == "stringify":
        parent[last] = str(parent[last])
    return data


@st.composite
def mutated_examples(draw):
    data = example(draw(st.sampled_from([FULL, SLOTTED])))
    for _ in range(draw(st.integers(1, 3))):
        paths = list(_paths(data))
        path = draw(st.sampled_from(paths))
        op = draw(st.sampled_from(["delete", "replace", "rename", "duplicate", "wrap", "stringify"]))
        data = _mutate(data, path, op, draw(toml_values), draw(keys))
        if not isinstance(data, dict):
            break
    return data


@settings(max_examples=600, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated_examples())
def test_mutated_valid_tasks(data):
    _check(data)


def test_unmutated_examples_load():
    assert isinstance(parse_task(example()), Task)
    assert isinstance(parse_task(example(SLOTTED)), Task)
    # a date where a number belongs is an input error, not a crash
    data = example()
    data["gears"]["module"] = dt.date(2026, 1, 1)
    try:
        parse_task(data)
    except TaskError as exc:
        assert exc.path == "gears.module" and "date" in str(exc)
    else:  # pragma: no cover
        raise AssertionError("a date was accepted as a module")
