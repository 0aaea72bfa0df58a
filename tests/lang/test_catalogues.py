"""The strings catalogues: the same keys in every language, every key the code asks for exists,
a missing key is an error that names key and language, numeral agreement, the per-language
notation (subscripts, units, decimal mark)."""
from __future__ import annotations

import re
import tomllib
from pathlib import Path

import jinja2
import pytest

from latex_templates.render import (LANGUAGES, MissingString, Strings, make_environment, plural_index)

ROOT = Path(__file__).resolve().parents[2]
STRINGS = ROOT / "latex_templates" / "strings"
#: Tables only the non-Russian catalogues have (Russian notation is the canonical one; the crane's
#: symbols per quantity, ``crane_symbols``, replace the solver's Russian ones).
NOTATION = ("subscripts", "units", "format", "crane_symbols")


def _keys(table, prefix=""):
    for k, v in table.items():
        if isinstance(v, dict) and not (prefix == "" and k in NOTATION):
            yield from _keys(v, f"{prefix}{k}.")
        elif not (prefix == "" and k in NOTATION):
            yield prefix + k


def _catalogue(lang: str) -> dict:
    from latex_templates.render import _load_strings
    return _load_strings(lang)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_same_keys_in_every_language(lang):
    """Every key of every area, the crane's (``crane.``) and the control work's (``control.``) too."""
    ru = set(_keys(_catalogue("ru")))
    other = set(_keys(_catalogue(lang)))
    assert not ru - other, f"missing in {lang}: {sorted(ru - other)[:20]}"
    assert not other - ru, f"only in {lang}: {sorted(other - ru)[:20]}"
    for area in ("crane.", "control."):
        assert any(k.startswith(area) for k in other), area      # the areas are really compared


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_lists_have_the_russian_length(lang):
    """A list (a table's header, the references, the introduction's paragraphs) has as many items
    as the Russian one: a header with a column less would shift the sheet's table."""
    def lists(node, prefix=""):
        for k, v in node.items():
            if isinstance(v, dict):
                yield from lists(v, f"{prefix}{k}.")
            elif isinstance(v, list):
                yield prefix + k, len(v)
    ru = dict(lists(_catalogue("ru")))
    other = dict(lists(_catalogue(lang)))
    bad = {k: (n, other.get(k)) for k, n in ru.items()
           if k in other and other[k] != n and not k.startswith(("words.", "crane.note.references", "references"))}
    assert not bad, bad


def test_plural_forms_per_language():
    for lang, n_forms in (("ru", 3), ("uk", 3), ("en", 2)):
        words = _catalogue(lang)["words"]
        for key, forms in words.items():
            assert isinstance(forms, list) and len(forms) == n_forms, (lang, key, forms)


_KEY_CALL = re.compile(r"""\b(?:tr|t|s\.get|strings\.get|S\.text|strings\.text|_t)\(\s*["']([a-z_]+\.[A-Za-z0-9_.\-]+)["']""")


def _referenced_keys() -> set[str]:
    keys = set()
    for folder in ("latex_templates", "drawings", "reportgen"):
        for path in (ROOT / folder).rglob("*"):
            if path.suffix in (".py", ".j2", ".toml") and path.name != "render.py":
                keys.update(_KEY_CALL.findall(path.read_text(encoding="utf-8")))
    # keys built at run time ("structure.motion." ~ kind): their tables are checked by the key parity
    return {k for k in keys if not k.endswith((".", "_"))}


def test_every_key_the_code_names_exists_in_every_language():
    keys = _referenced_keys()
    assert len(keys) > 300, len(keys)           # the scan sees the code's keys
    assert any(k.startswith("crane.") for k in keys) and any(k.startswith("control.") for k in keys)
    for lang in LANGUAGES:
        s = Strings(lang)
        missing = sorted(k for k in keys if not s.has(k))
        assert not missing, f"{lang}: {missing[:20]}"


def test_scheme_names_of_the_solver_have_words():
    from reportgen.planetary.schemes import SCHEMES
    for lang in LANGUAGES:
        for name in SCHEMES:
            assert Strings(lang).has(f"planetary_schemes.{name}"), (lang, name)


def test_missing_key_is_an_error_naming_key_and_language():
    with pytest.raises(MissingString) as exc:
        Strings("uk").get("kinematics.no_such_sentence")
    assert "kinematics.no_such_sentence" in str(exc.value) and "'uk'" in str(exc.value)
    from reportgen.errors import InternalError
    assert isinstance(exc.value, InternalError) and isinstance(exc.value, KeyError)   # a defect: exit 1
    # in a template too (no fallback to Russian)
    env = make_environment()
    tpl = env.from_string(r"\VAR{t('headings.nonexistent')}")
    with pytest.raises(MissingString, match="headings.nonexistent"):
        tpl.render(s=Strings("en"))


def test_a_snippet_sees_the_callers_context_and_arguments():
    env = make_environment()
    tpl = env.from_string(r"\VAR{t('kinematics.m06', k=3)}; \VAR{n|count('words.equal_intervals')}")
    assert tpl.render(s=Strings("ru"), n=24) == "угловая скорость звена 3; 24~равных участка"
    assert tpl.render(s=Strings("uk"), n=5) == "кутова швидкість ланки 3; 5~рівних ділянок"
    assert tpl.render(s=Strings("en"), n=1) == "angular velocity of link 3; 1~equal interval"


@pytest.mark.parametrize("n, ru, uk, en", [
    (1, 0, 0, 0), (2, 1, 1, 1), (4, 1, 1, 1), (5, 2, 2, 1), (11, 2, 2, 1), (12, 2, 2, 1), (14, 2, 2, 1),
    (21, 0, 0, 1), (22, 1, 1, 1), (24, 1, 1, 1), (25, 2, 2, 1), (111, 2, 2, 1), (0, 2, 2, 1), (2.5, 1, 1, 1),
])
def test_plural_index(n, ru, uk, en):
    assert (plural_index("ru", n), plural_index("uk", n), plural_index("en", n)) == (ru, uk, en)


def test_numeral_agreement_words():
    ru, uk, en = Strings("ru"), Strings("uk"), Strings("en")
    assert [str(ru.plural(n, "words.equal_intervals")) for n in (1, 3, 24, 5)] == \
        ["равный участок", "равных участка", "равных участка", "равных участков"]
    assert [str(uk.plural(n, "words.equal_intervals")) for n in (1, 3, 5)] == \
        ["рівну ділянку", "рівні ділянки", "рівних ділянок"]
    assert [str(en.plural(n, "words.conditions")) for n in (1, 2)] == ["condition", "conditions"]


def test_notation_per_language():
    src = r"$F_{\text{ур}} = 1{,}5~\text{Н}$, $J_\text{пр} = 2~\text{кг·м²}$, $M_{\text{и}2}$, $\operatorname{tg}\alpha$"
    assert Strings("ru").localize_latex(src) == src
    uk = Strings("uk").localize_latex(src)
    assert r"F_{\text{зр}}" in uk and r"J_\text{зв}" in uk and r"1{,}5" in uk and r"\text{Н}" in uk
    en = Strings("en").localize_latex(src)
    assert en == r"$F_{\text{b}} = 1.5~\text{N}$, $J_\text{red} = 2~\text{kg·m²}$, $M_{\text{in}2}$, $\tan\alpha$"
    assert Strings("en").math_word("(м/с²)/мм") == "(m/s²)/mm"
    assert Strings("en").symbol("Fи4'") == "Fin4'"
    with pytest.raises(MissingString, match="subscripts.щщ"):
        Strings("en").localize_latex(r"$x_{\text{щщ}}$")


def test_catalogue_values_compile_as_templates():
    """Every snippet is valid Jinja (a syntax error would only show for the example that reaches it)."""
    env = make_environment()
    for lang in LANGUAGES:
        def walk(node, prefix=""):
            for k, v in node.items():
                if isinstance(v, dict):
                    yield from walk(v, f"{prefix}{k}.")
                elif isinstance(v, str) and ("\\VAR{" in v or "\\BLOCK{" in v):
                    yield prefix + k, v
        for key, value in walk(_catalogue(lang)):
            try:
                env.parse(value)
            except jinja2.TemplateSyntaxError as exc:
                pytest.fail(f"{lang} {key}: {exc}")


def test_ukrainian_catalogue_has_no_russian_letters():
    """Ukrainian has no ы, э, ъ, ё: none in the uk catalogue's text (Russian symbols like M_\\text{ур}
    are mapped by the subscripts table; the cited Russian book is the one exception)."""
    for path in sorted((STRINGS / "uk").glob("*.toml")) + [STRINGS / "uk.toml"]:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        # the crane's bibliography cites the Russian books it follows (Казак, ПБ 10-382-00) in their
        # original language, as ДСТУ 8302 asks: each such item is a citation with its year
        cited = data.get("crane", {}).get("note", {}).pop("references", {}).get("items", [])
        for item in cited:
            if re.search("[ыэъёЫЭЪЁ]", item):
                assert re.search(r"(19|20)\d\d|--\d\d\.", item), item
        text = repr(data)
        text = text.replace("Артоболевский", "")
        assert not re.search("[ыэъёЫЭЪЁ]", text), path.name


def test_english_catalogue_has_cyrillic_only_in_symbols():
    """English text: Cyrillic only inside \\text{…} of the canonical symbols (mapped by the notation
    tables) and as the keys of those tables."""
    for path in sorted((STRINGS / "en").glob("*.toml")) + [STRINGS / "en.toml"]:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        data.pop("subscripts", None)
        data.pop("units", None)
        text = re.sub(r"\\\\?text\{[^{}]*\}", "", repr(data))
        text = text.replace('== "м"', "")        # a comparison with the solver's unit, not text
        assert not re.search("[\u0400-\u04FF]", text), (path.name, re.findall(".{30}[\u0400-\u04FF]+.{10}", text)[:3])


@pytest.mark.parametrize("lang", ["uk", "en"])
@pytest.mark.parametrize("example", ["crane-hoist", "control-work"])
def test_crane_and_control_work_accept_every_language(lang, example):
    """The crane note and the control work are translated (they were refused in uk/en while their
    words existed only in Russian)."""
    from reportgen.taskfile import parse_task
    data = tomllib.loads((ROOT / "examples" / example / "task.toml").read_text(encoding="utf-8"))
    data.setdefault("document", {})["language"] = lang
    assert parse_task(data).document.language == lang


# A display (a calculation record, a displayed equation) ends its sentence: the where-list after it
# ends with a full stop, and a teacher reads what follows as a new sentence (issue 12: «что
# совпадает с заданным…», «на плане — отрезок 0,9 мм», «что на схеме составляет»).
_DISPLAY_LINE = re.compile(r"^\s*(\\VAR\{\s*(m\.calc|eq|m\.balance)\(|\\VAR\{[\w.]*equation\w*\}\s*$|\\\]\s*$|\\end\{(equation|align|gather|multline)\*?\}\s*$)")
_CONTROL = re.compile(r"^\s*(\\BLOCK\{[^{}]*\}\s*)+")
#: a line opening another branch of the same condition (its text never follows the display before it)
_OTHER_BRANCH = re.compile(r"^\s*\\BLOCK\{\s*(elif|else)\b")
#: the words that may continue a sentence after its display (the where-list and its kin)
_CONTINUES = {"ru": ("где",), "uk": ("де",), "en": ("where",)}


def _sentence_after_display(lang: str, text: str) -> list[str]:
    bad = []
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if not _DISPLAY_LINE.match(line):
            continue
        for nxt in lines[i + 1:]:
            if _OTHER_BRANCH.match(nxt):
                break                # the display ended its branch; the text after it is another branch's
            rest = _CONTROL.sub("", nxt).strip()
            if not rest or rest.startswith(("\\VAR{m.calc", "\\VAR{eq(", "\\VAR{m.figure", "\\VAR{m.table", "%")):
                continue                                     # the next display, a figure, a loop's end
            word = re.match(r"[~\s]*([^\W\d_]+)", rest)
            if word and word.group(1)[0].islower() and word.group(1) not in _CONTINUES[lang]:
                bad.append(rest[:60])
            break
    return bad


@pytest.mark.parametrize("lang", LANGUAGES)
def test_no_sentence_starts_in_lower_case_after_a_display(lang):
    """In every catalogue snippet and template, the line after a display starts a new sentence
    (a capital letter) or continues it with the where-list's word («где», «де», «where»)."""
    def walk(node, prefix=""):
        for k, v in node.items():
            if isinstance(v, dict):
                yield from walk(v, f"{prefix}{k}.")
            elif isinstance(v, str):
                yield prefix + k, v
    bad = [(key, b) for key, v in walk(_catalogue(lang)) for b in _sentence_after_display(lang, v)]
    if lang == "ru":
        for path in sorted((ROOT / "latex_templates" / "templates").rglob("*.j2")):
            bad += [(path.name, b) for b in _sentence_after_display(lang, path.read_text(encoding="utf-8"))]
    assert not bad, bad


def test_the_display_check_sees_a_lower_case_continuation():
    assert _sentence_after_display("ru", "\\VAR{m.calc(e.h)}\nчто на~схеме составляет\n")
    assert _sentence_after_display("en", "\\VAR{eq(r.x)}\n\\BLOCK{endif}\nwhich on the scheme is\n")
    assert not _sentence_after_display("ru", "\\VAR{m.calc(e.h)}\nНа~схеме это плечо\n")
    assert not _sentence_after_display("uk", "\\VAR{m.calc(e.h)}\nде $x$~--- ...\n")


@pytest.mark.parametrize("rules", ["1969", "PB-10-382-00"])
def test_every_crane_quantity_has_a_symbol_in_uk_and_en(rules):
    """Under both sets of rules, every quantity the crane solver prints has its Ukrainian and English
    symbol (crane_symbols); in English no Cyrillic is left, in Ukrainian no ы/э/ъ/ё; two different
    quantities of one mechanism never share a symbol unless the Russian one is shared too."""
    import re as _re

    from latex_templates.parts.crane_common import symbol_in
    from reportgen.project import Project
    from reportgen.taskfile import parse_task
    text = (ROOT / "examples" / "crane-hoist" / "task.toml").read_text(encoding="utf-8")
    text = _re.sub(r'(?m)^rules = "[^"]*"', f'rules = "{rules}"', text)
    crane = Project(parse_task(tomllib.loads(text))).crane
    assert crane.rules.rules == rules
    for lang in ("uk", "en"):
        s = Strings(lang)
        for mech in ("hoist", "trolley"):
            calc = getattr(crane, mech)
            quantities = {**{k: v.latex for k, v in calc.vars.items()},
                          **{k: r.symbol for k, r in calc.records.items()}}
            shown: dict[str, tuple[str, str]] = {}
            for key, ru in quantities.items():
                sym = symbol_in(s, mech, key, ru)
                localized = s.localize_latex("$" + sym + "$")
                if lang == "en":
                    assert not _re.search("[\u0400-\u04FF]", localized), (mech, key, localized)
                else:
                    assert not _re.search("[ыэъёЫЭЪЁ]", localized), (mech, key, localized)
                if sym in shown and shown[sym][1] != ru:
                    pytest.fail(f"{lang} {mech}: {key} and {shown[sym][0]} are both {sym}")
                shown[sym] = (key, ru)
    assert symbol_in(Strings("ru"), "hoist", "D_bl", "D_{\\text{бл}}") == "D_{\\text{бл}}"   # Russian as solved
