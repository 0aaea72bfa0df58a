"""Page breaks of the note's tables: no orphaned single row (issue 12).

A ``longtable`` may break between any two rows, so a page could end with the caption, the header
and one row, or start with the header and the last row alone («Таблица 1.2» pp. 7–8 of the press
note). A teacher marks both. :func:`keep_rows_together` forbids the break after the first body row
and before the last one (``\\\\*``, longtable's unbreakable row end), so each part of a broken
table holds at least two rows, and a table of up to three rows is never broken. It works on the
rendered source, so every table of every template and catalogue snippet is covered, whoever
writes it. :func:`continued_heads` gives a table whose head repeats its whole caption on every page
the head ГОСТ 7.32 asks for on the following pages: «Продолжение таблицы N» above the column
header.
"""
from __future__ import annotations

import re

_LONGTABLE = re.compile(r"(\\begin\{longtable\}.*?)(\\end\{longtable\})", re.S)
# the end of the head (the body starts after the last of these)
_HEAD_END = re.compile(r"\\end(?:lastfoot|foot|head|firsthead)\b")
# a row's end: ``\\`` (not ``\\*``, not ``\\[...]``) closing a line of the body
_ROW_END = re.compile(r"(?<!\\)\\\\(?![*\[])[ \t]*(?=\n|$)")


def _keep(table: str) -> str:
    heads = list(_HEAD_END.finditer(table))
    if not heads:                             # no repeated head: not a table that breaks
        return table
    start = heads[-1].end()
    body = table[start:]
    ends = list(_ROW_END.finditer(body))
    if len(ends) < 2:
        return table
    tie = {0, len(ends) - 2}                  # after the first row, before the last one
    out, last = [], 0
    for i, m in enumerate(ends):
        out.append(body[last:m.start()])
        out.append("\\\\*" if i in tie else m.group(0))
        last = m.end()
    out.append(body[last:])
    return table[:start] + "".join(out)


_HEAD = re.compile(r"(\\begin\{longtable\}(?:\{[^\n]*\})\n)(\\caption\{[^\n]*\\\\\n)(.*?)\\endhead\n", re.S)


def continued_heads(source: str, continued: str) -> str:
    """Every ``longtable`` with a numbered caption in its only head (``\\endhead`` without
    ``\\endfirsthead``) gets a first head (the caption and the column header) and a head of the
    following pages: ``continued`` («Продолжение таблицы») with the table's number above the
    column header."""
    def head(m: re.Match[str]) -> str:
        begin, caption, header = m.groups()
        if "\\endfirsthead" in header:
            return m.group(0)
        columns = 1 + max((ln.count("&") for ln in header.splitlines()), default=0)
        return (f"{begin}{caption}{header}\\endfirsthead\n"
                f"\\multicolumn{{{columns}}}{{@{{}}l}}{{{continued}~\\thetable}}\\\\\n{header}\\endhead\n")
    return _HEAD.sub(head, source)


def keep_rows_together(source: str) -> str:
    """``source`` with the first and the penultimate row of every ``longtable`` body ended by
    ``\\\\*`` (no page break there): no part of a broken table is a single row."""
    return _LONGTABLE.sub(lambda m: _keep(m.group(1)) + m.group(2), source)
