"""Compiled templates kept in the build cache (latex_templates/jinja_cache.py): the same text as
compiling anew, read back instead of compiled on the next build, used only while a build has a
cache, and a broken entry is compiled again. The package's code compiled at install time
(latex_templates/precompiled.py): the same text, no compilation of what it holds, anything else
compiled as before, an unreadable store ignored."""
from __future__ import annotations

import pytest

from latex_templates import jinja_cache, precompiled
from latex_templates.render import make_environment

TEMPLATE = (r"\BLOCK{for x in xs}\VAR{x|num(3)}\BLOCK{if not loop.last}, \BLOCK{endif}\BLOCK{endfor}"
            "\n%# a line comment\n" r"\VAR{name|e} — \VAR{t_value}" "\n")
CONTEXT = {"xs": [1.23456, 2.5, -0.000123], "name": "a_b & c", "t_value": 7}


@pytest.fixture(autouse=True)
def no_precompiled_store(monkeypatch):
    """The tests of the build cache count compilations: the install-time store would answer first."""
    monkeypatch.setattr(precompiled, "enabled", False)


def _compiles(monkeypatch) -> list[str]:
    """Count real compilations (Jinja's code generator)."""
    import jinja2

    seen: list[str] = []
    original = jinja2.Environment._generate

    def counting(self, source, name, filename, defer_init=False):
        seen.append(name or "<string>")
        return original(self, source, name, filename, defer_init=defer_init)

    monkeypatch.setattr(jinja2.Environment, "_generate", counting)
    return seen


def test_cached_code_renders_the_text_of_fresh_code(tmp_path, monkeypatch):
    seen = _compiles(monkeypatch)
    fresh = make_environment().from_string(TEMPLATE).render(CONTEXT)
    assert len(seen) == 1
    with jinja_cache.active(tmp_path):
        first = make_environment().from_string(TEMPLATE).render(CONTEXT)     # compiled, stored
        again = make_environment().from_string(TEMPLATE).render(CONTEXT)     # read back
        package = make_environment().get_template("sections/composite.tex.j2")
        package_again = make_environment().get_template("sections/composite.tex.j2")
    assert first == again == fresh
    assert len(seen) == 3               # the fresh one, then each source once; none read back
    assert package.render(parts=[]) == package_again.render(parts=[])
    assert len(list((tmp_path / "jinja").glob("*.code"))) == 2


def test_no_cache_unless_a_build_has_one(tmp_path, monkeypatch):
    seen = _compiles(monkeypatch)
    env = make_environment()
    env.from_string(TEMPLATE)
    env.from_string(TEMPLATE)
    assert len(seen) == 2 and not (tmp_path / "jinja").exists()


def test_a_broken_entry_is_compiled_again(tmp_path, monkeypatch):
    with jinja_cache.active(tmp_path):
        expected = make_environment().from_string(TEMPLATE).render(CONTEXT)
        (entry,) = (tmp_path / "jinja").glob("*.code")
        entry.write_bytes(b"not marshal data")
        seen = _compiles(monkeypatch)
        assert make_environment().from_string(TEMPLATE).render(CONTEXT) == expected
    assert len(seen) == 1


def test_a_different_syntax_is_a_different_entry(tmp_path):
    with jinja_cache.active(tmp_path):
        import jinja2

        a = jinja_cache.use_cache(jinja2.Environment(block_start_string=r"\BLOCK{", block_end_string="}",
                                                     trim_blocks=True))
        b = jinja_cache.use_cache(jinja2.Environment(block_start_string=r"\BLOCK{", block_end_string="}",
                                                     trim_blocks=False))
        text_a = a.from_string("\\BLOCK{if 1}\nx\\BLOCK{endif}\n").render()
        text_b = b.from_string("\\BLOCK{if 1}\nx\\BLOCK{endif}\n").render()
    assert text_a != text_b
    assert len(list((tmp_path / "jinja").glob("*.code"))) == 2


@pytest.mark.parametrize("cache", [True, False])
def test_a_build_uses_the_cache_only_with_one(tmp_path, monkeypatch, cache):
    """build(cache=...) sets the folder for its duration and leaves none set after."""
    from reportgen.commands import build as build_cmd
    from reportgen.commands import pipeline

    monkeypatch.setenv("REPORTGEN_CACHE", str(tmp_path / "cache"))
    used = []
    monkeypatch.setattr(pipeline, "run", lambda *a, **k: used.append(jinja_cache._ROOT))
    build_cmd.build(str(pytest.importorskip("pathlib").Path(__file__).resolve().parents[2]
                        / "examples" / "press" / "task.toml"), tmp_path / "out", quiet=True, cache=cache)
    assert used == [tmp_path / "cache" if cache else None]
    assert jinja_cache._ROOT is None



def _use_store(monkeypatch, store) -> None:
    monkeypatch.setattr(precompiled, "STORE", store)
    monkeypatch.setattr(precompiled, "_LOADED", None)
    monkeypatch.setattr(precompiled, "enabled", True)


def _code_of(template) -> bytes:
    import marshal

    return marshal.dumps(template.root_render_func.__code__)


def test_the_store_answers_for_every_template_and_snippet_with_the_same_code(tmp_path, monkeypatch):
    """Every package template and every catalogue snippet of every language comes from the store,
    as the code Jinja makes of it now; a source the store does not hold is compiled."""
    import latex_templates.render as render

    env = make_environment()
    names = env.list_templates()
    snippets = [v for lang in render.LANGUAGES for v in precompiled._snippets(render._load_strings(lang))]
    fresh = [env.get_template(n) for n in names] + [env.from_string(v) for v in snippets]
    assert len(names) > 10 and len(snippets) > 100
    precompiled.write(tmp_path / "store.marshal")
    _use_store(monkeypatch, tmp_path / "store.marshal")
    seen = _compiles(monkeypatch)
    env = make_environment()
    kept = [env.get_template(n) for n in names] + [env.from_string(v) for v in snippets]
    assert seen == []
    assert [_code_of(t) for t in kept] == [_code_of(t) for t in fresh]
    assert env.get_template("sections/composite.tex.j2").render(parts=[]) == \
        make_environment().get_template("sections/composite.tex.j2").render(parts=[])
    assert env.from_string(TEMPLATE).render(CONTEXT) == make_environment().from_string(TEMPLATE).render(CONTEXT)
    assert seen == ["<string>", "<string>"]     # not in the store: compiled, as the fresh one


def test_an_unreadable_store_is_ignored(tmp_path, monkeypatch):
    expected = make_environment().from_string(TEMPLATE).render(CONTEXT)
    (tmp_path / "store.marshal").write_bytes(b"not marshal data")
    _use_store(monkeypatch, tmp_path / "store.marshal")
    seen = _compiles(monkeypatch)
    assert make_environment().from_string(TEMPLATE).render(CONTEXT) == expected
    assert seen == ["<string>"]
