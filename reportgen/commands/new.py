"""``reportgen new``: start a task file.

    reportgen new --table T --variant V [--language L] [-o task.toml] [--force]   a control-work variant (seed 001)
    reportgen new --list                                                          the 22 tables
    reportgen new --example press|shaper|… [--language L] [-o task.toml]          a copy of a shipped example

Without ``-o`` the task is printed. An existing file is never overwritten without ``--force``
(exit 2, the file left as it was).

``--language`` (ru, uk, en; a control work's default ru, an example's its own) writes the task's
``[document]`` in that language from the note's catalogue (``document_defaults`` of
``latex_templates/strings/<lang>/document.toml``): title, department and designation, so that no
word of another language reaches the title page or the title blocks (issue 12). An example copied
into another language gets that ``[document]`` (the personal fields left empty) and loses its
``[mechanism] name`` (the note then names the mechanism in the language's words); otherwise the
example is copied byte for byte (a control work's mechanism name is written in the language).
"""
from __future__ import annotations

import argparse
import os
import re
import tomllib
from pathlib import Path
from typing import Any

from ..control.task_text import TaskWords
from ..errors import OptionError
from ..task import LANGUAGES
from ..zoo import toml_value
from .solve import write_atomic


def register(sub) -> None:
    p = sub.add_parser("new", help="write a task file: a control-work variant or a copy of an example")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--table", type=int, metavar="T", help="a table 1…22 of the control work (with --variant)")
    g.add_argument("--list", action="store_true", help="list the control-work tables and the examples")
    g.add_argument("--example", metavar="NAME", help="copy a shipped example (see --list)")
    p.add_argument("--variant", type=int, metavar="V", help="the variant 1…10 of the table")
    p.add_argument("--language", choices=LANGUAGES, metavar="L",
                   help="the task's language: " + ", ".join(LANGUAGES) + " (a control work: ru; an example: its own)")
    p.add_argument("-o", "--out", metavar="FILE", help="write the task here (default: print it)")
    p.add_argument("--force", action="store_true", help="overwrite FILE if it exists")
    p.set_defaults(func=run)


def examples_dir() -> Path | None:
    """The shipped examples: the package's copy ``reportgen/examples``, else the source tree's ``examples``."""
    here = Path(__file__).resolve().parents[1]
    for cand in (here / "examples", here.parent / "examples"):
        if cand.is_dir():
            return cand
    return None


def example_names() -> list[str]:
    d = examples_dir()
    return sorted(p.name for p in d.iterdir() if (p / "task.toml").is_file()) if d else []


def listing() -> str:
    from ..control.tables import tables
    lines = ["Control work (course manual, seed 001, §8; schemes reconstructed): reportgen new --table T --variant V"]
    for t in tables():
        dims = ", ".join(c.label.strip() for c in t.dimensions)
        flags = f"  [variant(s) {', '.join(map(str, t.flags))} cannot be assembled]" if t.flags else ""
        lines.append(f"  table {t.number:2d} (p. {t.page}): {dims}{flags}")
    names = example_names()
    lines.append("Examples: reportgen new --example NAME")
    lines.append("  " + (", ".join(names) if names else "(none found)"))
    return "\n".join(lines)


def _defaults(language: str) -> dict[str, str]:
    """The ``document_defaults`` table of the language's catalogue (plain text)."""
    from latex_templates.render import Strings
    return {k: str(v) for k, v in Strings(language).raw("document_defaults").items()}


def task_words(language: str, table: int, variant: int) -> TaskWords:
    """The words of a control-work task in ``language``: its catalogue's title, mechanism name,
    department and designation (``ТММ.КР.TT.VV`` in ru/uk, ``TMM.CW.TT.VV`` in en)."""
    d = _defaults(language)
    return TaskWords(language=language,
                     title=d["control_title"].format(table=table, variant=variant),
                     mechanism=d["control_mechanism"].format(table=table, variant=variant),
                     organization=d["organization"],
                     code=d["control_code"].format(table=table, variant=variant))


_HEADER = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.\-\s]+?)\s*\]\]?\s*(#.*)?$")


def _tables(lines: list[str]) -> list[tuple[int, str]]:
    """(line index, table name) of every table header of a TOML text."""
    out = []
    for i, line in enumerate(lines):
        m = _HEADER.match(line)
        if m:
            out.append((i, m.group(1).replace(" ", "")))
    return out


def _document_block(data: dict[str, Any], language: str) -> list[str]:
    """The ``[document]`` table of a copied example in ``language``: the catalogue's title and
    department for the example's kind, the personal fields empty, the year and kind kept."""
    d = _defaults(language)
    doc = data.get("document", {})
    kind = doc.get("kind", "")
    crane = kind == "crane" or "crane" in data
    out = ["[document]"]
    if kind:
        out.append(f"kind = {toml_value(kind)}")
    if kind == "control-work" and "control_work" in data:
        cw = data["control_work"]
        title = d["control_title"].format(table=cw["table"], variant=cw["variant"])
    else:
        title = d["crane_title" if crane else "title"]
    out += [f"title = {toml_value(title)}",
            'author = ""                          # your name',
            'group = ""',
            'supervisor = ""',
            'university = ""',
            f"organization = {toml_value(d['crane_organization' if crane else 'organization'])}",
            'city = ""']
    if "year" in doc:
        out.append(f"year = {doc['year']!r}")
    out.append(f"language = {toml_value(language)}")
    if kind == "control-work" and "control_work" in data:
        cw = data["control_work"]
        code = d["control_code"].format(table=cw["table"], variant=cw["variant"])
        out.append(f"code = {toml_value(code)}            # designation: the note's ….000, the sheet ….001")
    return out + [""]


def in_language(text: str, language: str) -> str:
    """An example's task file with its ``[document]`` in ``language`` (see the module's docstring);
    the text itself when the example is in that language already."""
    data = tomllib.loads(text)
    if data.get("document", {}).get("language", "ru") == language:
        return text
    lines = text.splitlines()
    heads = _tables(lines)
    block = _document_block(data, language)
    out: list[str] = []
    doc_at = next((i for i, name in heads if name == "document"), None)
    ends = {i: next((j for j, _ in heads if j > i), len(lines)) for i, _ in heads}
    skip: set[int] = set()
    if doc_at is not None:
        end = ends[doc_at]
        while end > doc_at + 1 and (not lines[end - 1].strip() or lines[end - 1].lstrip().startswith("#")):
            end -= 1                   # the comments before the next table stay with it
        skip |= set(range(doc_at, end))
    mech_at = next((i for i, name in heads if name == "mechanism"), None)
    names: set[int] = set()
    if mech_at is not None:
        names = {j for j in range(mech_at + 1, ends[mech_at]) if re.match(r"^\s*name\s*=", lines[j])}
    cw = data.get("control_work")
    # a control work's mechanism keeps a name, in the language (the table's and variant's numbers)
    renamed = (f"name = {toml_value(_defaults(language)['control_mechanism'].format(**cw))}"
               if data.get("document", {}).get("kind") == "control-work" and cw else None)
    first = heads[0][0] if heads else len(lines)
    for i, line in enumerate(lines):
        if doc_at is None and i == first:
            out += block
        if i == doc_at:
            out += block[:-1]          # the blank line before the next table is the text's own
        if i in names and renamed is not None:
            out.append(renamed)
        if i in skip or i in names:
            continue
        out.append(line)
    result = "\n".join(out) + "\n"
    tomllib.loads(result)                  # still a TOML file (an example's layout we did not expect)
    return result


def _write(path: str, text: str, force: bool) -> None:
    p = Path(path)
    if p.exists() and not force:
        raise OptionError("-o", f"{path} exists (reportgen never overwrites a file it may not have written)",
                          "a new file name, or --force to replace it")
    if p.is_dir():
        raise OptionError("-o", f"{path} is a folder", "a file name")
    write_atomic(os.fspath(p), text, option="-o")


def run(args: argparse.Namespace) -> int:
    if args.list:
        print(listing())
        return 0
    if args.example is not None:
        names = example_names()
        if args.example not in names:
            raise OptionError("--example", f"got {args.example!r}", "one of: " + ", ".join(names))
        text = (examples_dir() / args.example / "task.toml").read_text(encoding="utf-8")
        if args.language is not None:
            text = in_language(text, args.language)
    else:
        from ..control.tables import table
        from ..control.task_text import task_text
        if args.variant is None:
            raise OptionError("--variant", "missing", "--variant V (1…10) with --table")
        t = table(args.table)
        v = t.variant(args.variant)
        if v.flag:
            raise OptionError("--variant", f"table {t.number}, variant {v.number} cannot form the mechanism: {v.flag}",
                              "another variant (reportgen new --list shows the flagged ones)")
        text = task_text(t, v, words=task_words(args.language or "ru", t.number, v.number))
    if args.out:
        _write(args.out, text, args.force)
        print(f"written: {args.out}")
    else:
        print(text, end="")
    return 0
