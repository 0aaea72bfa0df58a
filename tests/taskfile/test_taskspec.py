"""The task format as data (issue 13 item 6): the generated reference and JSON Schema match the
loader's own key specification, the examples carry the schema line, validate and load, and the
examples shipped in the package are the examples of the repository."""
from __future__ import annotations

import copy
import json
import tomllib
from pathlib import Path
from typing import Any

import jsonschema
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from reportgen import taskdoc
from reportgen.errors import TaskError, UnknownKeyError
from reportgen.taskfile import parse_task
from reportgen.taskspec import OPTIONAL, SECTION, SECTIONS, Key

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
SHIPPED = ROOT / "reportgen" / "examples"
EXAMPLE_FILES = sorted(EXAMPLES.glob("*/task.toml"))
HINT = "run `make generated` (python -m reportgen.taskdoc) and commit the result"


def _strict_validator(schema: dict) -> jsonschema.protocols.Validator:
    """Draft 2020-12 with TOML's types: an integer is an int (3.0 is a float), booleans are no numbers."""
    base = jsonschema.Draft202012Validator
    checker = base.TYPE_CHECKER.redefine_many({
        "integer": lambda _c, v: isinstance(v, int) and not isinstance(v, bool),
        "number": lambda _c, v: isinstance(v, (int, float)) and not isinstance(v, bool),
    })
    return jsonschema.validators.extend(base, type_checker=checker)(schema)


SCHEMA = taskdoc.schema()
VALIDATOR = _strict_validator(SCHEMA)


def _load(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


# ------------------------------------------------------------------------------ generated files
def test_reference_is_generated_from_the_spec() -> None:
    committed = (ROOT / "docs" / "task-format.md").read_text(encoding="utf-8")
    assert committed == taskdoc.markdown(), f"docs/task-format.md differs from the spec: {HINT}"


def test_schema_is_generated_from_the_spec() -> None:
    committed = (EXAMPLES / taskdoc.SCHEMA_NAME).read_text(encoding="utf-8")
    assert committed == taskdoc.schema_text(), f"examples/{taskdoc.SCHEMA_NAME} differs: {HINT}"
    jsonschema.Draft202012Validator.check_schema(json.loads(committed))


def test_reference_lists_every_key() -> None:
    text = taskdoc.markdown()
    for sec in SECTIONS:
        for key in sec.keys:
            assert f"| `{key.name}` |" in text or f"`[{key.name}]`" in text, f"{sec.path}.{key.name}"


# ----------------------------------------------------------------------------------- examples
def test_examples_shipped_in_the_package_are_identical() -> None:
    """reportgen/examples/ (package data) is a byte copy of examples/, both ways."""
    ours = {p.relative_to(EXAMPLES) for p in EXAMPLES.rglob("*") if p.is_file()}
    shipped = {p.relative_to(SHIPPED) for p in SHIPPED.rglob("*") if p.is_file()}
    assert ours == shipped, f"files differ: only in examples/ {sorted(map(str, ours - shipped))}, " \
                            f"only in reportgen/examples/ {sorted(map(str, shipped - ours))}: {HINT}"
    for rel in sorted(ours):
        assert (EXAMPLES / rel).read_bytes() == (SHIPPED / rel).read_bytes(), f"{rel}: {HINT}"


def test_package_data_ships_the_examples() -> None:
    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    globs = cfg["tool"]["setuptools"]["package-data"]["reportgen"]
    shipped = {p.relative_to(ROOT / "reportgen") for p in SHIPPED.rglob("*") if p.is_file()}
    for rel in shipped:
        assert any(rel.match(g) and len(rel.parts) == len(Path(g).parts) for g in globs), rel


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.parent.name)
def test_example_names_the_schema_validates_and_loads(path: Path) -> None:
    first = path.read_text(encoding="utf-8").splitlines()[0]
    assert first == taskdoc.SCHEMA_LINE
    assert (path.parent / first.split(maxsplit=1)[1]).resolve() == (EXAMPLES / taskdoc.SCHEMA_NAME)
    data = _load(path)
    errors = [f"{'.'.join(map(str, e.absolute_path))}: {e.message}" for e in VALIDATOR.iter_errors(data)]
    assert not errors
    parse_task(data, str(path))


# ------------------------------------------------------------------- schema and loader agree on keys
def _tables(data: dict) -> list[tuple[str, list[Any]]]:
    """(spec path, TOML path in ``data``) of every table of a task: [key, index, key, …]."""
    out: list[tuple[str, list[Any]]] = [("", [])]
    for sec in SECTIONS:
        for key in sec.keys:
            if not key.table:
                continue
            for spec_path, where in list(out):
                if spec_path != sec.path:
                    continue
                node = _at(data, where)
                if key.name not in node:
                    continue
                if SECTION[key.table].shape == "array":
                    out += [(key.table, where + [key.name, i]) for i in range(len(node[key.name]))]
                else:
                    out.append((key.table, where + [key.name]))
    return out


def _at(data: Any, where: list[Any]) -> Any:
    for step in where:
        data = data[step]
    return data


def _known_keys_of(data: dict, where: list[Any]) -> set[str]:
    """The keys the loader accepts in the table at ``where``: asked of the loader itself."""
    probe = copy.deepcopy(data)
    _at(probe, where)["zz_not_a_key"] = 1
    with pytest.raises(UnknownKeyError) as err:
        parse_task(probe)
    return set(err.value.known)


def test_loader_and_spec_accept_the_same_keys_in_every_table() -> None:
    seen: set[str] = set()
    for path in EXAMPLE_FILES:
        data = _load(path)
        for spec_path, where in _tables(data):
            seen.add(spec_path)
            assert _known_keys_of(data, where) == set(SECTION[spec_path].names), (path.parent.name, where)
    tables = {s.path for s in SECTIONS}
    assert seen == tables, f"no example has the tables {sorted(tables - seen)}"


def test_schema_has_the_spec_keys_and_refuses_others() -> None:
    data = _load(EXAMPLES / "press" / "task.toml")
    assert VALIDATOR.is_valid(data)
    for _, where in _tables(data):
        probe = copy.deepcopy(data)
        _at(probe, where)["zz_not_a_key"] = 1
        assert not VALIDATOR.is_valid(probe), where


def test_required_keys_agree() -> None:
    """Leaving out a key the spec calls required fails in the loader and in the schema alike."""
    for path in EXAMPLE_FILES:
        data = _load(path)
        for spec_path, where in _tables(data):
            node = _at(data, where)
            for key in SECTION[spec_path].keys:
                if key.name not in node or not key.required:
                    continue
                probe = copy.deepcopy(data)
                del _at(probe, where)[key.name]
                with pytest.raises(TaskError):
                    parse_task(probe)
                assert not VALIDATOR.is_valid(probe), (path.parent.name, where, key.name)


def test_defaults_are_the_loaders() -> None:
    """A key left out reads as the spec's default (one section at a time, from an empty table)."""
    given_keys = {"analysis": {}, "document": {}, "gears": {"z1": 13, "z2": 26, "module": 9.0},
                  "planetary": {"scheme": "single-row", "motor_rpm": 1500}, "dynamics": {"delta": 0.05}}
    task = parse_task(given_keys)
    objs = {"document": task.document, "analysis": task.analysis, "gears": task.gears,
            "planetary": task.planetary, "dynamics": task.dynamics,
            "dynamics.flywheel": task.dynamics.flywheel if task.dynamics else None}
    for path, obj in objs.items():
        for key in SECTION[path].keys:
            if key.required or key.table or key.name in given_keys.get(path, {}):
                continue
            want = None if key.default is OPTIONAL else key.default
            assert getattr(obj, key.name) == want, f"{path}.{key.name}"


# ---------------------------------------------------------------- one value: spec and schema agree
_text = st.text(alphabet=st.sampled_from(list("abcDEF xyz-_019АБВгде\t\n")), max_size=6)
_scalar = st.one_of(st.booleans(), st.integers(-20, 2000), st.integers(-10**6, 10**6),
                    st.floats(allow_nan=False, allow_infinity=False), st.floats(-2, 2),
                    st.sampled_from([0, 0.0, 1, 1.0, -1, 3, 12, 13, 360, 359, 1000, 1000.0, 1e4, -1e4, 50,
                                     "auto", "extreme", "max-load", "disk", "rim", "ru", "crank", "working",
                                     "force", "single-row", ""]),
                    _text)
_value = st.recursive(_scalar, lambda c: st.one_of(st.lists(c, max_size=4),
                                                   st.dictionaries(_text, c, max_size=3)), max_leaves=8)
_KEYS: list[tuple[str, Key]] = [(s.path, k) for s in SECTIONS for k in s.keys if k.spec is not None]


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(_KEYS), _value)
def test_a_value_passes_the_loader_spec_iff_it_passes_the_schema(entry: tuple[str, Key], value: Any) -> None:
    path, key = entry
    assert key.spec is not None
    try:
        key.spec.read(value, "x")
        loader_ok = True
    except TaskError:
        loader_ok = False
    schema_ok = _strict_validator(key.spec.schema()).is_valid(value)
    assert loader_ok == schema_ok, f"{path}.{key.name} = {value!r}: loader {loader_ok}, schema {schema_ok}"


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(EXAMPLE_FILES), st.data())
def test_the_schema_never_refuses_a_file_the_loader_accepts(path: Path, data: st.DataObject) -> None:
    """One value of an example replaced by anything: if the loader takes the file, so does the schema."""
    task = _load(path)
    tables = _tables(task)
    spec_path, where = data.draw(st.sampled_from(tables))
    node = _at(task, where)
    keys = [k for k in SECTION[spec_path].keys if not k.table and k.name in node]
    if not keys:
        return
    key = data.draw(st.sampled_from(keys))
    node[key.name] = data.draw(st.one_of(_value, st.just(copy.deepcopy(node[key.name]))))
    try:
        parse_task(task)
    except TaskError:
        return
    errors = [e.message for e in VALIDATOR.iter_errors(task)]
    assert not errors, f"{'.'.join(map(str, where))}.{key.name} = {node[key.name]!r}"
