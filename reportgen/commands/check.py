"""``reportgen check TASK ANSWERS [--tolerance PCT]``: a student's values against the exact ones.

ANSWERS is a small TOML (``omega2 = 3.9``) or CSV (rows ``name,value``, or a header of names and one
row of values); the names are those of answers.csv (``reportgen batch``). A CSV may be separated by
``;`` or a tab, as a spreadsheet in a Russian or Ukrainian locale saves it, and then its numbers may
carry a decimal comma (``vB;4,3``). The table is printed in the task's language and decimal mark. Each value is compared by
magnitude with the exact one within the tolerance of a graphical construction (``--tolerance``, else
``[control_work] tolerance_percent``, else 5 %); a sign given by the student must match too.
Exit 0 if every value passes, 1 if any fails, 2 for bad input.
"""
from __future__ import annotations

import argparse
import csv
import math
import re
import tomllib
from pathlib import Path

from ..errors import OptionError
from ..tolerances import ABS_ZERO

#: The tolerance of a graphical construction when neither the option nor the task gives one, %.
DEFAULT_TOLERANCE_PERCENT = 5.0
#: Below this magnitude an exact value counts as zero (a student's value passes if as small).
ZERO = ABS_ZERO


def register(sub) -> None:
    p = sub.add_parser("check", help="mark a student's answers against the exact values")
    p.add_argument("task", help="the task file (TOML)")
    p.add_argument("answers", help="the student's values: TOML (name = value) or CSV")
    p.add_argument("--tolerance", type=float, metavar="PCT", help="accepted deviation, %% (default: the task's, or 5)")
    p.set_defaults(func=run)


def read_answers(path: str) -> dict[str, float]:
    p = Path(path)
    if not p.is_file():
        raise OptionError("ANSWERS", f"{path} is not a file", "a TOML or CSV file of name = value")
    text = p.read_text(encoding="utf-8")
    out: dict[str, float] = {}
    if p.suffix.lower() == ".toml":
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            hint = " (TOML numbers take a decimal point: vB = 4.3)" if _DECIMAL_COMMA.search(text) else ""
            raise OptionError("ANSWERS", f"{path} is not valid TOML: {exc}{hint}", "lines name = number") from None
        items = list(data.items())
    else:
        lines = text.splitlines()
        rows = [r for r in csv.reader(lines, delimiter=_delimiter(lines)) if r and any(c.strip() for c in r)]
        pairs = bool(rows) and all(len(r) == 2 for r in rows) and \
            (_is_num(rows[0][1]) or [c.strip().lower() for c in rows[0]] == ["name", "value"])
        if pairs:
            items = [(r[0].strip(), r[1].strip()) for r in rows if not (r[0].strip().lower() == "name" and
                                                                        not _is_num(r[1]))]
        elif len(rows) == 2:
            items = list(zip((c.strip() for c in rows[0]), (c.strip() for c in rows[1])))
        else:
            raise OptionError("ANSWERS", f"{path}: {len(rows)} rows", 'rows "name,value" or a header and one row')
    for k, v in items:
        if isinstance(v, bool) or not _is_num(v):
            raise OptionError("ANSWERS", f"{k} = {v!r}", "a number")
        out[str(k)] = float(str(v).replace(",", ".")) if isinstance(v, str) else float(v)
    if not out:
        raise OptionError("ANSWERS", f"{path} holds no values", "lines name = number")
    return out


#: ``name = 4,3``: a number written with a decimal comma, which TOML reads as an array's start.
_DECIMAL_COMMA = re.compile(r"=\s*[-+]?\d+,\d")
#: The separators of a CSV, in the order they are tried: a spreadsheet in a ru/uk locale writes ``;``.
_DELIMITERS = (";", "\t", ",")


def _delimiter(lines: list[str]) -> str:
    """The CSV's separator: the first of ``;``, tab, ``,`` found on every non-empty line."""
    filled = [line for line in lines if line.strip()]
    for d in _DELIMITERS:
        if filled and all(d in line for line in filled):
            return d
    return ","


def _is_num(v) -> bool:
    if isinstance(v, bool):
        return False
    if isinstance(v, (int, float)):
        return math.isfinite(v)
    try:
        return math.isfinite(float(str(v).replace(",", ".")))
    except ValueError:
        return False


def mark(student: dict[str, float], exact: dict, tolerance: float) -> list[tuple[str, float, float, float, bool]]:
    """(name, student, exact, deviation %, ok) per student value; unknown names are bad input."""
    unknown = [k for k in student if k not in exact or not isinstance(exact[k], (int, float))]
    if unknown:
        valid = ", ".join(k for k, v in exact.items() if isinstance(v, (int, float)))
        raise OptionError("ANSWERS", f"unknown name(s) {', '.join(unknown)}", f"names of answers.csv: {valid}")
    rows = []
    for k, s in student.items():
        e = float(exact[k])
        if abs(e) < ZERO:
            dev = 0.0 if abs(s) < ZERO else math.inf
        else:
            dev = 100.0 * (abs(s) - abs(e)) / abs(e)
        sign_ok = s == 0 or abs(e) < ZERO or (s > 0) == (e > 0) or not _signed(k)
        rows.append((k, s, e, dev, abs(dev) <= tolerance and sign_ok))
    return rows


def _signed(name: str) -> bool:
    """ω, ε, P_у, M_у carry a direction (sign); speeds and accelerations are magnitudes."""
    return name.startswith(("omega", "eps", "Py", "My"))


def run(args: argparse.Namespace) -> int:
    from latex_templates.render import Strings

    from ..control.analysis import control_work_of
    from ..project import Project
    from ..taskfile import load_task
    if args.tolerance is not None and not (0 < args.tolerance <= 100):
        raise OptionError("--tolerance", f"got {args.tolerance}", "a percentage in (0, 100]")
    student = read_answers(args.answers)
    task = load_task(args.task)
    tol = args.tolerance if args.tolerance is not None else (
        task.control_work.tolerance_percent if task.control_work else DEFAULT_TOLERANCE_PERCENT)
    exact = control_work_of(Project(task)).answers()
    rows = mark(student, exact, tol)
    s = Strings(task.document.language or "ru")
    point = s.decimal_mark()
    head = [str(h) for h in s.get("control.check.header")]
    print(f"{head[0]:<18}{head[1]:>14}{head[2]:>14}{head[3]:>16}{head[4]:>12}  {head[5]}")
    for k, v, e, dev, ok in rows:
        d = "∞" if math.isinf(dev) else f"{dev:+.2f}"
        word = str(s.get("control.check.ok" if ok else "control.check.wrong"))
        cells = [f"{v:.6g}", f"{e:.6g}", d, f"{tol:g}"]
        v_, e_, d_, t_ = (c.replace(".", point) for c in cells)
        print(f"{k:<18}{v_:>14}{e_:>14}{d_:>16}{t_:>12}  {word}")
    n_ok = sum(r[4] for r in rows)
    print(str(s.get("control.check.summary")).replace("{ok}", str(n_ok)).replace("{total}", str(len(rows))))
    return 0 if n_ok == len(rows) else 1
