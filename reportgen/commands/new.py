"""``reportgen new``: start a task file.

    reportgen new --table T --variant V [-o task.toml] [--force]   a control-work variant (seed 001)
    reportgen new --list                                            the 22 tables
    reportgen new --example press|shaper|… [-o task.toml]           a copy of a shipped example

Without ``-o`` the task is printed. An existing file is never overwritten without ``--force``
(exit 2, the file left as it was).
"""
from __future__ import annotations

import argparse
import os
from pathlib import Path

from ..errors import OptionError
from .solve import write_atomic


def register(sub) -> None:
    p = sub.add_parser("new", help="write a task file: a control-work variant or a copy of an example")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--table", type=int, metavar="T", help="a table 1…22 of the control work (with --variant)")
    g.add_argument("--list", action="store_true", help="list the control-work tables and the examples")
    g.add_argument("--example", metavar="NAME", help="copy a shipped example (see --list)")
    p.add_argument("--variant", type=int, metavar="V", help="the variant 1…10 of the table")
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
        text = task_text(t, v)
    if args.out:
        _write(args.out, text, args.force)
        print(f"written: {args.out}")
    else:
        print(text, end="")
    return 0
