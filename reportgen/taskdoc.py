"""Writes the task-format reference and its JSON Schema from ``reportgen.taskspec``.

``python -m reportgen.taskdoc`` (or ``make generated``) rewrites ``docs/task-format.md`` and
``examples/task.schema.json`` and copies ``examples/`` into ``reportgen/examples/`` (the copy that
ships in the package). ``markdown()`` and ``schema()`` return the texts, so a test can compare them
with the committed files.
"""
from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path
from typing import Any

from .errors import InternalError
from .taskfile_values import Spec
from .taskspec import OPTIONAL, SECTION, SECTIONS, Key, Section

__all__ = ["markdown", "schema", "schema_text", "write", "SCHEMA_NAME", "SCHEMA_LINE"]

#: File name of the schema, beside the examples (``examples/task.schema.json`` and, in the
#: package, ``reportgen/examples/task.schema.json``): ``#:schema ../task.schema.json`` in an
#: example resolves in both places.
SCHEMA_NAME = "task.schema.json"
#: The first line of every example task file (read by taplo and VS Code's Even Better TOML).
SCHEMA_LINE = f"#:schema ../{SCHEMA_NAME}"
SCHEMA_ID = "https://reportgen.invalid/task.schema.json"

_ROOT = Path(__file__).resolve().parent.parent


# ------------------------------------------------------------------------------------------ schema
def _value_schema(spec: Spec, key: Key) -> dict[str, Any]:
    out = dict(spec.schema())
    out["description"] = key.doc + (f" ({key.unit()})" if key.unit() else "")
    if not key.required and key.default is not OPTIONAL and key.default is not None:
        out["default"] = key.default
    if key.example is not None:
        out["examples"] = [key.example]
    return out


def _table_schema(sec: Section) -> dict[str, Any]:
    """The schema of one table; sub-tables are inlined (editors show them best that way)."""
    props: dict[str, Any] = {}
    for key in sec.keys:
        if key.table:
            sub = _table_schema(SECTION[key.table])
            sub["description"] = key.doc
            props[key.name] = ({"type": "array", "minItems": 1, "items": sub, "description": key.doc}
                               if SECTION[key.table].shape == "array" else sub)
        else:
            assert key.spec is not None, f"{sec.path}.{key.name}: a value key needs a spec"
            props[key.name] = _value_schema(key.spec, key)
    out: dict[str, Any] = {"type": "object", "description": sec.doc or sec.title, "properties": props,
                           "additionalProperties": False}
    kinds = {k.name: k.kinds for k in sec.keys if k.kinds}
    all_kinds = kinds.get("kind", ())
    required = [k.name for k in sec.keys if k.required and (not k.kinds or set(k.kinds) == set(all_kinds))]
    if required:
        out["required"] = required
    if kinds:  # [[mechanism.load]]: each kind takes its own keys, some of them required
        rules = []
        for kd in all_kinds:
            then: dict[str, Any] = {"propertyNames": {"enum": [n for n, ks in kinds.items() if kd in ks]}}
            own = [k.name for k in sec.keys if k.required and k.kinds and kd in k.kinds
                   and k.name not in required]
            if own:
                then["required"] = own
            rules.append({"if": {"properties": {"kind": {"const": kd}}, "required": ["kind"]}, "then": then})
        out["allOf"] = rules
    return out


def schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a task file."""
    out = _table_schema(SECTION[""])
    return {"$schema": "https://json-schema.org/draft/2020-12/schema", "$id": SCHEMA_ID,
            "title": "reportgen task file", **out}


def schema_text() -> str:
    return json.dumps(schema(), ensure_ascii=False, indent=2) + "\n"


# ---------------------------------------------------------------------------------------- markdown
def _toml(value: Any) -> str:
    """A value as written in TOML (for the examples and defaults columns)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_toml(v)}" for k, v in value.items()) + " }"
    raise InternalError("an example or default of reportgen/taskspec.py", f"no TOML form for {value!r}")


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _default(key: Key) -> str:
    if key.required:
        return "**required**"
    if key.default is OPTIONAL or key.default is None:
        return key.default_text or "—"
    text = f"`{_toml(key.default)}`"
    return text + (f" ({key.default_text})" if key.default_text else "")


def _header(sec: Section) -> str:
    return {"array": f"[[{sec.path}]]", "inline": f"{sec.path} = {{ … }}"}.get(sec.shape, f"[{sec.path}]")


def _section_md(sec: Section) -> list[str]:
    out = [f"## `{_header(sec)}` — {sec.title}", ""]
    if sec.doc:
        out += [sec.doc, ""]
    out += ["| key | meaning | type | unit | valid values | default | example |",
            "|---|---|---|---|---|---|---|"]
    for key in sec.keys:
        if key.table:
            sub = SECTION[key.table]
            out.append(f"| `{key.name}` | {_cell(key.doc)} | table | | see `{_header(sub)}` | "
                       f"{_cell(_default(key))} | |")
            continue
        assert key.spec is not None, f"{sec.path}.{key.name}: a value key needs a spec"
        typ, valid = key.spec.type_name(), key.spec.expected
        kinds = f" (kind = {', '.join(key.kinds)})" if key.kinds and len(key.kinds) < 3 else ""
        out.append(f"| `{key.name}` | {_cell(key.doc + kinds)} | {typ} | {_cell(key.unit())} | "
                   f"{_cell(valid)} | {_cell(_default(key))} | `{_cell(_toml(key.example))}` |")
    out.append("")
    return out


def _example_md(sec: Section) -> list[str]:
    """A TOML snippet with every key of the section at its example value."""
    lines: list[str] = [_header(sec)]
    if sec.shape != "table" or any(k.table and SECTION[k.table].shape == "array" for k in sec.keys):
        return []  # arrays of tables hold keys that exclude each other: see the examples
    for key in sec.keys:
        if key.table and SECTION[key.table].shape == "inline":
            sub = SECTION[key.table]
            lines.append(f"{key.name} = " + _toml({k.name: k.example for k in sub.keys}))
        elif not key.table and key.example is not None:
            lines.append(f"{key.name} = {_toml(key.example)}")
    return ["```toml", *lines, "```", ""]


def markdown() -> str:
    """``docs/task-format.md``."""
    out = [
        "# Task file format",
        "",
        "<!-- Generated by `python -m reportgen.taskdoc` (`make generated`) from reportgen/taskspec.py:",
        "     edit the spec, not this page. tests/taskfile/test_taskspec.py fails when they differ. -->",
        "",
        "A task file is the student's assignment («задание на курсовой проект») written in TOML. One file",
        "drives everything: the solvers, the explanatory note (PDF), the drawing sheets (DXF) and",
        "results.json. Units are SI (m, kg, s, N, rad) unless a key's name says otherwise (`_deg`, `_rpm`);",
        "gear sizes are in millimetres. The examples in `examples/` (shipped in the package as",
        "`reportgen/examples/`) are complete task files to copy.",
        "",
        "- An unknown key is an error that names the key and suggests the nearest known one.",
        "- Every error names the TOML path of the value (`mechanism.link[3].length`, array indices",
        "  0-based) and says what would be valid, in the words of the column *valid values* below;",
        "  `reportgen` then exits with status 2.",
        "- The column *valid values* is the loader's own text; *default* is what is used when the key",
        "  is left out.",
        "- Rules that tie keys together, and decisions the format leaves open, are in",
        "  `docs/task-format-notes.md`.",
        "",
        "## Checking as you type",
        "",
        f"The JSON Schema `examples/{SCHEMA_NAME}` (also `reportgen/examples/{SCHEMA_NAME}` in the",
        "installed package) describes the same keys. Editors that read TOML with a schema (taplo, VS Code",
        "with *Even Better TOML*) complete keys and flag wrong values when the file's first line names it:",
        "",
        "```toml",
        SCHEMA_LINE,
        "```",
        "",
        "(a path relative to the task file, as in the examples). The schema is a help for typing; the",
        "loader is the judge: it also checks what a schema cannot (a point name that exists, a crank with",
        "one ground point, triangle sides, `force_position` below `positions`, and an integer written as",
        "`3.0` where a count is due).",
        "",
    ]
    for sec in SECTIONS:
        if sec.path == "":
            out += ["## Sections", "", sec.doc, ""]
            out += ["| section | what | if left out |", "|---|---|---|"]
            out += [f"| `[{k.name}]` | {_cell(k.doc)} | {_cell(k.default_text)} |" for k in sec.keys]
            out.append("")
            continue
        out += _section_md(sec)
        out += _example_md(sec)
    out += ["## Complete task files", "",
            "`examples/<name>/task.toml` (in the package: `reportgen/examples/<name>/task.toml`), "
            "commented: see the list in README.md.", ""]
    return "\n".join(out).rstrip("\n") + "\n"


# ------------------------------------------------------------------------------------------- write
def write(root: Path = _ROOT) -> list[Path]:
    """Rewrite the generated files under the source tree ``root``; return those that changed."""
    changed: list[Path] = []

    def put(path: Path, text: str) -> None:
        if not path.exists() or path.read_text(encoding="utf-8") != text:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
            changed.append(path)

    put(root / "docs" / "task-format.md", markdown())
    put(root / "examples" / SCHEMA_NAME, schema_text())
    # The package's copy of the examples: the same files, byte for byte (a file only in the copy is
    # left for a person to remove: tests/taskfile/test_examples_shipped.py names it).
    src, dst = root / "examples", root / "reportgen" / "examples"
    for path in sorted(p for p in src.rglob("*") if p.is_file()):
        rel = path.relative_to(src)
        if path.read_bytes() != (dst / rel).read_bytes() if (dst / rel).exists() else True:
            (dst / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(path, dst / rel)
            changed.append(dst / rel)
    return changed


def main() -> int:
    for path in write():
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
