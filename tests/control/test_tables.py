"""The 22 assignment tables of seed 001 (§8) as shipped data: every printed value of every table, in
order, against the seed text (when ../shared is beside the clone, as in CI), and their shape."""
from __future__ import annotations

import glob
import os
import re

import pytest

from reportgen.control.tables import VARIANTS, tables

SEEDS = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "seeds")


def _seed_tokens() -> list[str] | None:
    files = glob.glob(os.path.join(SEEDS, "001_*.txt"))
    if not files:
        return None
    text = open(files[0], encoding="utf-8").read()
    return [t for t in (line.replace("\xa0", " ").strip() for line in text.split("\n")) if t]


def test_22_tables_of_10_variants():
    ts = tables()
    assert [t.number for t in ts] == list(range(1, 23))
    assert [t.page for t in ts] == list(range(13, 35))
    for t in ts:
        keys = [k for c in t.columns for k in c.keys]
        assert "phi_deg" in keys and "omega1" in keys and "l_AB" in keys
        for c in t.columns:
            assert len(c.printed) == VARIANTS
            for v in range(1, VARIANTS + 1):
                assert c.value(v) > 0
        assert [t.variant(v).phi_deg for v in range(1, 11)] == [30, 60, 100, 130, 160, 200, 230, 260, 300, 330]


def test_every_printed_value_in_order_in_the_seed():
    tokens = _seed_tokens()
    if tokens is None:
        pytest.skip("seed 001 is not beside the clone (../shared/seeds)")
    pos = 0
    for t in tables():
        pos = tokens.index(f"Таблица {t.number}", pos)
        for c in t.columns:
            pos = tokens.index(c.label, pos)          # the heading as printed …
            got = tokens[pos + 1:pos + 1 + VARIANTS]  # … followed by its ten values
            assert got == list(c.printed), (t.number, c.label)
            pos += 1 + VARIANTS
        # the next line of the seed is the page number: nothing of the table was left out
        assert tokens[pos] == str(t.page), (t.number, tokens[pos])


def test_a_second_reading_of_the_seed_gives_the_same_numbers():
    """An independent reading: the numbers between "Таблица N" and the page number, by regex."""
    tokens = _seed_tokens()
    if tokens is None:
        pytest.skip("seed 001 is not beside the clone (../shared/seeds)")
    text = "\n".join(tokens)
    for t in tables():
        start = text.index(f"Таблица {t.number}\n")
        nxt = f"\nЗадание {t.number + 1}\n"
        end = text.index(nxt, start) if nxt in text else len(text)
        body = text[start:end].split("\n")[1:]
        assert body[-1] == str(t.page)                  # the page number closes the table
        body = body[:-1]
        body = body[body.index("10") + 1:]              # after the header "Варианты 1 … 10"
        nums = [x for x in body if re.fullmatch(r"\d+(,\d+)?", x)]
        assert nums == [p for c in t.columns for p in c.printed], t.number


def test_flags_are_exactly_the_variants_that_cannot_be_built():
    from reportgen.control.sketch import VariantGeometryError, sketch
    for t in tables():
        for v in t.variants:
            try:
                sketch(t.scheme, v)
                built = True
            except VariantGeometryError:
                built = False
            assert built == (v.flag is None), (t.number, v.number)
    assert {(t.number, n) for t in tables() for n in t.flags} == {(5, 7)}
