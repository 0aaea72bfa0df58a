"""The sheets' lettering measured in the core: the room the arrangement reserves for a view's lines
comes from the lines themselves, measured as the sheet measures them (issue 12: the table
«Масштабы» had a fixed measured room per language, which a task with more plan positions sharing a
scale, or longer values, than any example's would overrun).

The sheets measure a text with DejaVu Sans Mono (``drawings.style.MEASURE_FONT``: its advance is
nearly LibreCAD's OpenGost type B and wider than osifont's) times ``drawings.style.WIDTH_MARGIN``.
That font is monospaced: every character, Cyrillic, Greek and the rest, advances
``SHEET_ADVANCE`` of the letters' height, so the font's metric table is this one number
(tests/scenes/test_lettering.py checks it against the sheet's measure for every line of every
catalogue). The words are the catalogue's, which the core does not read: what the core keeps of
them is the number of characters of each line's fixed part (its words, its values left out), per
language, which the same test derives from the catalogues.
"""
from __future__ import annotations

from typing import Iterable, Mapping, Sequence

#: DejaVu Sans Mono's advance (1233/2048 em) per mm of capital height (its capitals are 1493/2048 em
#: high, ezdxf scales the em so that they are ``height`` mm), times the sheets' WIDTH_MARGIN 1,1.
SHEET_ADVANCE = 0.825853985264568 * 1.1


def text_width(text: str, height: float) -> float:
    """The width (mm) the sheet measures for a one-line ``text`` lettered ``height`` mm high (a blank
    text measures 0, as the sheet's font does)."""
    return len(text) * SHEET_ADVANCE * height if text.strip() else 0.0


#: The table «Масштабы»: letters 3,5 mm high, 2,5 mm of a cell's 5 mm pad on each side of a column
#: (drawings.sheets.kinematics.fill_scales_table).
TABLE_TEXT_MM, TABLE_CELL_PAD_MM = 3.5, 5.0
#: The fixed part of each line of the table (the catalogue's words; the values a task puts in left
#: out), in characters, per language: the symbol column's header «Обозн.», the name column's lines
#: by their catalogue key (``*_given``: the control work's one position), the value column's by their unit («0,0025 м/мм» is the value and 5
#: characters); the diagrams' (``_m`` a slider's s, v, a; ``_rad`` a rocker's ψ, ω, ε) the longest
#: of the three. tests/scenes/test_lettering.py derives them from the catalogues.
SCALES_TABLE_CHARS: Mapping[str, Mapping[str, int]] = {
    "ru": {"symbol": 6, "header_name": 8, "header_value": 7, "scheme": 9, "vplan": 25, "vplans": 26,
           "aplan": 25, "aplans": 26, "vplan_given": 34, "aplan_given": 34, "small": 28, "phi_axis": 16, "t_axis": 16, "pole": 19,
           "diagrams_m": 21, "diagrams_rad": 28, "value_l": 5, "value_v": 9, "value_a": 10, "value_phi": 7,
           "value_t": 5, "value_mm": 3, "value_m": 10, "value_rad": 12},
    "uk": {"symbol": 5, "header_name": 8, "header_value": 7, "scheme": 9, "vplan": 26, "vplans": 26,
           "aplan": 26, "aplans": 26, "vplan_given": 34, "aplan_given": 34, "small": 28, "phi_axis": 16, "t_axis": 16, "pole": 16,
           "diagrams_m": 20, "diagrams_rad": 29, "value_l": 5, "value_v": 9, "value_a": 10, "value_phi": 7,
           "value_t": 5, "value_mm": 3, "value_m": 10, "value_rad": 12},
    "en": {"symbol": 6, "header_name": 8, "header_value": 5, "scheme": 14, "vplan": 29, "vplans": 31,
           "aplan": 33, "aplans": 35, "vplan_given": 38, "aplan_given": 42, "small": 33, "phi_axis": 16, "t_axis": 16, "pole": 13,
           "diagrams_m": 20, "diagrams_rad": 28, "value_l": 5, "value_v": 9, "value_a": 10, "value_phi": 7,
           "value_t": 5, "value_mm": 3, "value_m": 10, "value_rad": 12},
}


def scales_table_width(language: str, names: Iterable[tuple[str, str]], values: Iterable[tuple[str, str]],
                       symbols: Sequence[str] = ()) -> float:
    """The width (mm) of the table «Масштабы» whose name column holds the lines ``names`` (the
    catalogue key of a line's words, the text the task puts in it: «1:2,5», «2, 8, 11», «» for none)
    and whose value column holds ``values`` (key of the unit, the number), ``symbols`` its symbols:
    each column as wide as its longest line and its pad (the sheet's measure, :func:`text_width`)."""
    chars = SCALES_TABLE_CHARS.get(language) or {k: max(t[k] for t in SCALES_TABLE_CHARS.values())
                                                 for k in SCALES_TABLE_CHARS["ru"]}

    def column(lines: Iterable[int]) -> float:
        return max(lines) * SHEET_ADVANCE * TABLE_TEXT_MM + TABLE_CELL_PAD_MM

    first = column([chars["symbol"], *(len(s) for s in symbols)])
    second = column([chars["header_name"], *(chars[k] + len(t) for k, t in names)])
    third = column([chars["header_value"], *(chars[k] + len(t) for k, t in values)])
    return first + second + third


#: Sheet 1's small velocity plans (drawings.scenes.kinematics_plans): their title «Планы скоростей
#: положений 0–N» and caption «μv = … (м/с)/мм», 5 mm high. Per language, the characters of each word
#: of the title (split at single spaces; the last word takes the last position's number) and of the
#: caption's fixed part (its μv left out). tests/scenes/test_lettering.py derives them from the
#: catalogues.
SMALL_PLANS_CHARS: Mapping[str, Mapping[str, tuple[int, ...]]] = {
    "ru": {"title": (5, 9, 9, 2), "caption": (14,)},
    "uk": {"title": (5, 10, 8, 2), "caption": (14,)},
    "en": {"title": (8, 8, 2, 9, 2), "caption": (14,)},
}
#: The small plans' title and caption letters, mm, and the room beside a line of them (5 mm each side).
SMALL_TITLE_H, SMALL_TITLE_PAD_MM = 5.0, 10.0


def title_lines(words: Sequence[int], width: float, height: float = SMALL_TITLE_H) -> tuple[int, ...]:
    """The characters of each line of a title whose words have ``words`` characters, lettered
    ``height`` mm high over a view ``width`` mm wide: one line if it fits with its pad
    (``SMALL_TITLE_PAD_MM``) or has no space, else two, split at the space that makes the longer
    line shortest (as drawings.scenes.kinematics_plans.title_lines splits the text itself)."""
    one = sum(words) + len(words) - 1
    if one * SHEET_ADVANCE * height + SMALL_TITLE_PAD_MM <= width or len(words) < 2:
        return (one,)
    splits = [(sum(words[:k]) + k - 1, sum(words[k:]) + len(words) - k - 1) for k in range(1, len(words))]
    return min(splits, key=max)


def small_plans_lettering(last: str, mu: str, width: float) -> tuple[int, float]:
    """The lines of the small plans' title (the last position ``last``) over a grid ``width`` mm wide
    and the width its title and caption (``mu`` the μv as printed) need, mm, in every catalogue
    language at once: a construction's size (and so its scale) must not depend on the language of
    its words (issue 12), so the room reserved is the widest language's."""
    lines, need = 1, 0.0
    for chars in SMALL_PLANS_CHARS.values():
        title = (*chars["title"][:-1], chars["title"][-1] + len(last))
        split = title_lines(title, width)
        lines = max(lines, len(split))
        need = max(need, text_width("x" * max(split), SMALL_TITLE_H) + SMALL_TITLE_PAD_MM,
                   text_width("x" * (chars["caption"][0] + len(mu)), SMALL_TITLE_H) + SMALL_TITLE_PAD_MM)
    return lines, need
